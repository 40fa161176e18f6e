"""Transition costs computed on demand from per-node features: Table I by hand, the OpenCL
kernel bit-identical to the NumPy reference, and the bounds the pruned DP relies on."""

import numpy as np
import pytest
from features import random_features

from facesynth.base.config import Config
from facesynth.domain.search.pairs import TransitionCosts
from facesynth.model.motiondb import TransitionFeatures


@pytest.fixture(scope="module")
def s():
    return Config.load(None, ("synthesize.pnt=10", "synthesize.alpha1=2", "synthesize.alpha2=0.5", "synthesize.alpha3=3")).settings("synthesize")


def test_table_i_by_hand(s):
    # Two markers; node 1 follows node 0 (rule 1), node 2 follows node 1, node 0 has none (rule 4).
    z = np.zeros((3, 6), np.float32)
    first_pos, last_pos = z.copy(), z.copy()
    last_pos[2] = [3, 4, 0, 0, 0, 1]      # |(0,0,0)-(3,4,0)| + |(0,0,0)-(0,0,1)| = 5 + 1
    x = np.array([[1.0], [0.0], [2.0]], np.float32)
    y = np.array([[0.0], [0.0], [1.0]], np.float32)
    f = TransitionFeatures(first_pos, last_pos, z.copy(), z.copy(), x, y, np.array([0, 0, 2], np.float32),
                           np.array([1, 1, 2]), np.array([-1, 0, 1]))
    tc = TransitionCosts(f, s).dense()
    assert tc[0, 1] == 0.0 and tc[1, 2] == 0.0                       # rule 1
    assert tc[:, 0].tolist() == [20.0, 20.0, 20.0 + 3 * 6]           # rule 4: alpha1 PNT + alpha3 PGap + VGap
    # TC(2, 2): DSC = 2 * (2 + 1)^2 = 18, PGap = 6, VGap = 0; viseme(2) = 2 != viseme(pre(2)) = 1
    assert tc[2, 2] == pytest.approx(0.5 * 18 + 3 * 6 + 0 + 10)
    # TC(0, 2): DSC = 2 * (1 + 1)^2 = 8, PGap 0; viseme(0) = 1 = viseme(pre(2)): rule 2, no PNT
    assert tc[0, 2] == pytest.approx(0.5 * 8)


@pytest.mark.parametrize("n", [1, 33, 257])
def test_opencl_is_bit_identical_to_the_reference(s, n, opencl_device):
    f = random_features(n, seed=n)
    ref = TransitionCosts(f, s).dense()
    cl = TransitionCosts(f, s, opencl=True).dense()
    assert np.array_equal(cl.view(np.uint32), ref.view(np.uint32))
    rows = np.array([n - 1, 0, n // 2])
    assert np.array_equal(TransitionCosts(f, s, opencl=True).block(rows, rows[::-1]), ref[np.ix_(rows, rows[::-1])])


def test_bounds_hold_on_every_pair(s):
    n = 120
    tc = TransitionCosts(random_features(n, seed=5), s)
    d = tc.dense().astype(np.float64)
    i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    assert (tc.upper(i, j) >= d - 1e-4).all()
    true_advantage = (d[:, None, :] - d[None, :, :]).max(axis=-1)  # [r, j] = max_k TC(r, k) - TC(j, k)
    assert (tc.advantage(i, j) >= true_advantage - 1e-4).all()
    assert (tc.reach_row[i] + tc.reach_col[j] >= tc.advantage(i, j) - 1e-4).all()
    # the kernel's cheap lower bound: pivots of the mixed norm
    lp = np.abs(tc.row_lp[:, None, :] - tc.col_fp[None, :, :]).max(-1)
    lv = np.abs(tc.row_lv[:, None, :] - tc.col_fv[None, :, :]).max(-1)
    pgap_vgap = d - s.pnt * (tc.f.viseme[:, None] != tc.pre_viseme[None, :])
    has = (tc.pre[None, :] >= 0) & (tc.pre[None, :] != np.arange(n)[:, None])
    assert (s.alpha3 * lp + lv <= pgap_vgap + 1e-3)[has].all()


def test_pair_tables_give_the_on_demand_costs_bit_for_bit(s):
    from facesynth.domain.search.pairs import DenseCosts, PairTerms

    f = random_features(97, 3, markers=5, dims=6)
    terms = PairTerms(f)
    dense = terms.costs(s)
    assert isinstance(dense, DenseCosts)
    reference = TransitionCosts(f, s).dense()
    assert np.array_equal(dense.dense().view(np.uint32), reference.view(np.uint32))
    # other velocities: DSC and PGap shared, VGap recomputed, still bit-identical
    g = TransitionFeatures(f.first_pos, f.last_pos, f.first_vel * 2, f.last_vel[::-1].copy(), f.dsc_out, f.dsc_in, f.dsc_scale,
                           f.viseme, f.pre)
    again = PairTerms(g, like=terms)
    assert again.dsc is terms.dsc and again.pgap is terms.pgap
    assert np.array_equal(again.costs(s).dense().view(np.uint32), TransitionCosts(g, s).dense().view(np.uint32))
    assert dense[3, 4] == reference[3, 4] and np.array_equal(dense.block([1, 2], [5, 0]), reference[np.ix_([1, 2], [5, 0])])


def test_features_with_other_velocities_get_their_own_lane_layout():
    """The padded copies the pair sums read are kept on the features they were made from: a
    ``dataclasses.replace`` with other velocities (as ``tune`` makes) must not read the old ones."""
    import dataclasses

    from facesynth.domain.search.pairs import pair_terms

    f = random_features(40, seed=3)
    rows = cols = np.arange(len(f))
    _, _, vgap = pair_terms(f, rows, cols)  # all nodes: the layout is made and kept
    assert f.device_layout is not None
    g = dataclasses.replace(f, first_vel=f.first_vel * 2, last_vel=f.last_vel[::-1].copy())
    assert g.device_layout is None
    fresh = TransitionFeatures(f.first_pos, f.last_pos, g.first_vel, g.last_vel, f.dsc_out, f.dsc_in, f.dsc_scale,
                               f.viseme, f.pre)
    expected = pair_terms(fresh, rows, cols)[2]
    few = np.arange(3)  # few nodes: laid out on the spot, no layout kept
    np.testing.assert_array_equal(pair_terms(g, few, few)[2], expected[:3, :3])
    assert g.device_layout is None
    np.testing.assert_array_equal(pair_terms(g, rows, cols)[2], expected)
    assert g.device_layout is not None and g.device_layout is not f.device_layout
    assert not np.array_equal(expected, vgap)


def test_a_database_reads_back_the_features_build_db_wrote(tiny_artifacts, tiny_db, config):
    """One class for the features from build-db to the search: what ``build`` computes is what
    ``MotionDatabase.transition_features`` reads, with the nodes' visemes and predecessors."""
    from facesynth.model.motiondb import MotionDatabase
    from facesynth.model.pca import PcaFrames
    from facesynth.stages.build_db import build

    _, built, _ = build(PcaFrames.read(tiny_artifacts["pca"]), config.settings("build_db"))
    db = MotionDatabase.read(tiny_db)
    read = db.transition_features()
    assert isinstance(read, TransitionFeatures) and len(read) == len(db.nodes)
    for name in ("first_pos", "last_pos", "first_vel", "last_vel", "dsc_out", "dsc_in", "dsc_scale", "viseme", "pre"):
        np.testing.assert_array_equal(getattr(read, name), getattr(built, name), err_msg=name)
    assert built.pivot_distances is not None and read.pivot_distances is not None
    for a, b in zip(read.pivot_distances, built.pivot_distances):
        np.testing.assert_array_equal(a, b)
    np.testing.assert_array_equal(read.viseme, db.nodes.viseme)
