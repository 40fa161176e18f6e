import numpy as np
import pytest

from facesynth.base.config import Config
from facesynth.domain.search.costs import step_costs, transition_matrix
from facesynth.domain.search.pairs import transition_costs


@pytest.fixture()
def s():
    return Config.load(None, ("synthesize.pnt=10", "synthesize.alpha1=2", "synthesize.alpha2=0.5", "synthesize.alpha3=3",
                              "synthesize.alpha4=0.5", "synthesize.alpha5=4", "synthesize.alpha6=6")).settings("synthesize")


def test_transition_rules_of_table_i(s):
    # nodes: 0 /p/, 1 /b/ (captured predecessor 0), 2 /aa/ (predecessor 1), 3 /m/ (no predecessor)
    vis = np.array([12, 12, 3, 12])
    pre = np.array([-1, 0, 1, -1])
    dsc = np.full((4, 4), 2.0, np.float32)
    pgap = np.full((4, 4), 1.0, np.float32)
    vgap = np.full((4, 4), 0.25, np.float32)
    tc = transition_matrix(dsc, pgap, vgap, vis, pre, s)
    assert tc[0, 1] == 0.0 and tc[1, 2] == 0.0                         # rule 1: captured
    assert tc[3, 1] == pytest.approx(0.5 * 2 + 3 * 1 + 0.25)           # rule 2: same viseme as pre(o_1) = /p/
    assert tc[2, 1] == pytest.approx(0.5 * 2 + 3 * 1 + 0.25 + 10)      # rule 3: /aa/ vs /p/ adds PNT
    # rule 4: alpha1 * PNT + PVC (no DSC, no viseme penalty)
    assert tc[:, 3].tolist() == [23.25] * 4 and tc[:, 0].tolist() == [23.25] * 4


def test_observation_emotion_and_blocking(s):
    c = step_costs(["p", "pau", "aa"], ["happy", "sad", "happy"], ["p", "b", "aa", "sh"], ["happy", "sad", "sad", "happy"],
                   {2: 2}, s)
    assert c.oc[0].tolist() == [0.0, 0.5 * 4 * 10, 4 * 10, 4 * 10]      # Table II rules 1, 2, 3
    assert c.oc[1].tolist() == [0.0] * 4                                  # /pau/ costs nothing
    assert c.emp[0].tolist() == [0.0, 60.0, 60.0, 0.0]                    # Eq. 5
    assert c.block[2].tolist() == [s.huge_penalty, s.huge_penalty, 0.0, s.huge_penalty]  # Eq. 10
    assert c.block[:2].max() == 0.0


@pytest.mark.parametrize("n, block", [(5, 2), (96, 96), (97, 40), (300, 256), (401, 7)])
def test_panel_rows_are_bit_identical_to_the_reference_matrix(s, n, block):
    from facesynth.domain.search.costs import transition_panel_rows
    from facesynth.domain.search.dp import PanelMatrix

    rng = np.random.default_rng(n)
    vis = rng.integers(0, 14, n)
    pre = np.where(rng.random(n) < 0.8, np.arange(n) - 1, -1)
    pre[0] = -1
    dsc, pgap, vgap = (rng.random((n, n), dtype=np.float32) * scale for scale in (50, 20, 3))
    dsc[rng.random((n, n)) < 0.05] = 0.0
    ref = PanelMatrix.from_matrix(transition_matrix(dsc, pgap, vgap, vis, pre, s))
    out = PanelMatrix(n)
    scratch = np.empty((2, block, n), np.float32)
    for a in range(0, n, block):
        rows = slice(a, min(n, a + block))
        transition_panel_rows(out.panels, rows, dsc[rows], pgap[rows], vgap[rows], vis, pre, s,
                              scratch=scratch if a % 2 else None)
    assert np.array_equal(out.panels.view(np.uint32), ref.panels.view(np.uint32))


def test_matrices_of_the_real_database_match_the_schema_1_reference(tiny_db, tiny_artifacts, config):
    """TC from the per-node features against the stored-table formulas of schema 1 (DSC in
    float64 rounded once, NumPy's pairwise PGap/VGap sums): equal to float32 rounding, and the
    panel layout bit-identical to the matrix."""
    from facesynth.domain.search.nodes import build_nodes, dsc_matrix, pair_gaps_numpy
    from facesynth.domain.search.pairs import boundary_states
    from facesynth.model.motiondb import MotionDatabase
    from facesynth.model.pca import PcaFrames

    db = MotionDatabase.read(tiny_db)
    s = config.settings("synthesize")
    pca = PcaFrames.read(tiny_artifacts["pca"])
    nodes = build_nodes(pca.takes, pca.phones, pca.frames.fps)
    dsc = dsc_matrix(pca.coefficients, nodes, config.settings("build_db").dsc_samples)
    states = boundary_states(pca.coefficients, nodes, pca.model, config.settings("build_db").boundary_fit_frames)
    pgap, vgap = pair_gaps_numpy(*(a.astype(np.float32) for a in states))
    ref = transition_matrix(dsc, pgap, vgap, db.nodes.viseme, db.nodes.pre, s)
    tc, panels = transition_costs(db, s).dense(), transition_costs(db, s).panels().panels
    # The documented bound (facesynth.domain.search.pairs): (terms + 2) 2^-24 of each sum.
    np.testing.assert_allclose(tc, ref, rtol=(93 + 2) * 2.0 ** -24, atol=1e-4)
    as_matrix = panels.transpose(1, 0, 2).reshape(len(tc), -1)[:, : len(tc)]
    assert np.array_equal(as_matrix.view(np.uint32), tc.view(np.uint32))
