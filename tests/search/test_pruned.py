"""The exact pruned DP against the dense DP: the same cost, path and (on the live states)
accumulated costs, on random databases with ties, on the tiny preset with constraints and
emotions, and on hand-made cases where the bounds are tight or useless."""

from functools import partial

import numpy as np
import pytest
from features import random_features, tiny_utterance_steps

from facesynth.base.config import Config
from facesynth.domain.search.dp import dp_numpy, dp_opencl
from facesynth.domain.search.pairs import TransitionCosts, transition_costs
from facesynth.domain.search.pruned import _column_minima_numpy, dp_pruned
from facesynth.model.motiondb import TransitionFeatures


def _settings(*overrides):
    return Config.load(None, overrides).settings("synthesize")


def _check(tc: TransitionCosts, obs: np.ndarray):
    """pruned == dense: cost, path, and phi wherever the pruned DP kept the state."""
    ref = dp_numpy(tc.dense(), obs)
    res, stats = dp_pruned(tc, obs)
    assert res.cost == ref.cost
    assert res.path.tolist() == ref.path.tolist()
    live = np.isfinite(res.phi)
    assert np.array_equal(res.phi[live], ref.phi[live])
    return res, stats


def _random_obs(features: TransitionFeatures, t: int, seed: int, s) -> np.ndarray:
    """Observation costs of a random phone string: each node's 'phone' is its viseme here, so
    the Table II constants separate them; coarse values give many ties."""
    rng = np.random.default_rng(seed)
    n = len(features)
    asked = rng.integers(0, 4, t)
    obs = np.where(features.viseme[None, :] == asked[:, None], 0.0, s.alpha5 * s.pnt)
    obs = obs + (rng.random((t, n)) < 0.3) * s.alpha6 * s.pnt  # emotion mismatches
    obs[rng.random(t) < 0.15] = 0.0  # pauses: nothing separates the nodes
    return obs.astype(np.float32)


@pytest.mark.parametrize("n, t, dup", [(1, 3, 0), (2, 5, 0), (40, 6, 10), (150, 12, 30), (300, 9, 0)])
def test_random_databases_with_ties(n, t, dup):
    s = _settings()
    f = random_features(n, seed=n + t, duplicates=dup)
    _check(TransitionCosts(f, s), _random_obs(f, t, seed=n, s=s))


@pytest.mark.parametrize("n, t", [(64, 8), (300, 14)])
def test_opencl_pruned_equals_dense(n, t, opencl_device):
    s = _settings()
    f = random_features(n, seed=3 * n, duplicates=n // 5)
    obs = _random_obs(f, t, seed=t, s=s)
    tc = TransitionCosts(f, s, opencl=True)
    res, _ = _check(tc, obs)
    numpy_res, _ = dp_pruned(TransitionCosts(f, s), obs)
    assert numpy_res.cost == res.cost and numpy_res.path.tolist() == res.path.tolist()
    cl_dense = dp_opencl(tc.dense(), obs)
    assert cl_dense.cost == res.cost and cl_dense.path.tolist() == res.path.tolist()


def test_all_ties_go_to_the_lowest_index():
    # Every node a copy of node 0 with no predecessor: every path costs the same.
    s = _settings()
    f = random_features(50, seed=1)
    for a in (f.first_pos, f.last_pos, f.first_vel, f.last_vel, f.dsc_out):
        a[:] = a[0]
    f.pre[:] = -1
    f.dsc_in[:] = 0
    f.dsc_scale[:] = 0
    obs = np.zeros((6, 50), np.float32)
    res, _ = _check(TransitionCosts(f, s), obs)
    assert res.path.tolist() == [0] * 6


@pytest.mark.parametrize("weights", [("synthesize.pnt=1e-6",), ("synthesize.alpha5=0", "synthesize.alpha6=0"),
                                     ("synthesize.alpha1=0",), ("synthesize.alpha3=0", "synthesize.alpha2=0")])
def test_weights_that_weaken_the_bounds_stay_exact(weights):
    s = _settings(*weights)
    f = random_features(120, seed=9, duplicates=20)
    _check(TransitionCosts(f, s), _random_obs(f, 10, seed=2, s=s))


def test_a_tight_case_kills_other_phones_without_evaluating_them():
    # Large observation constants: only the asked viseme's nodes are ever evaluated.
    s = _settings("synthesize.pnt=1000")
    f = random_features(400, seed=4)
    obs = _random_obs(f, 10, seed=4, s=s)
    obs[obs == 0.0] = 0.0
    _, stats = _check(TransitionCosts(f, s), obs)
    assert stats.fraction < 0.05


@pytest.mark.parametrize("with_emotions, with_constraints", [(False, False), (True, False), (False, True), (True, True)])
def test_tiny_preset_with_emotions_and_constraints(tiny_db, tiny_corpus, held_out_take, config, with_emotions,
                                                   with_constraints):
    from facesynth.model.motiondb import MotionDatabase

    db = MotionDatabase.read(tiny_db)
    s = config.settings("synthesize")
    tc = transition_costs(db, s, opencl=False)
    steps, constraints = tiny_utterance_steps(db, s, tiny_corpus / "labels" / f"{held_out_take}.TextGrid",
                                              with_emotions, with_constraints)
    res, stats = _check(tc, steps.total)
    for t, node in constraints.items():
        assert res.path[t] == node
    assert stats.fraction < 0.5


@pytest.mark.parametrize("opencl", [False, True])
def test_backward_values_and_a_kept_last_step_equal_the_dense_dp(opencl):
    if opencl:
        from facesynth.base.opencl import use_opencl

        if not use_opencl(True):
            pytest.skip("no OpenCL device builds facesynth's kernels")
    from facesynth.domain.search.pruned import backward_pruned

    s = _settings()
    f = random_features(150, seed=77, duplicates=30)
    obs = _random_obs(f, 9, seed=5, s=s)
    tc = TransitionCosts(f, s, opencl=opencl)
    dense = tc.dense()
    back = dp_numpy(np.ascontiguousarray(dense.T), obs[::-1].copy())
    for stop in (0, 4, 8):
        beta, _ = backward_pruned(tc, obs, stop)
        assert np.array_equal(beta, back.phi[len(obs) - 1 - stop])
    fwd = dp_numpy(dense, obs[:5])
    res, _ = dp_pruned(tc, obs[:5], keep_last=True)
    assert np.array_equal(res.phi[-1], fwd.phi[-1])


def _clustered(n: int, seed: int) -> TransitionFeatures:
    """Random features whose boundary states sit in a few tight clusters far apart (copies of
    a few poses with small noise, as replicated takes are), so row groups are tight and whole
    groups are skipped; duplicates make exact ties."""
    f = random_features(n, seed=seed, duplicates=n // 6)
    rng = np.random.default_rng(seed)
    centers = rng.normal(0, 200, (5, f.first_pos.shape[1])).astype(np.float32)
    pick = rng.integers(0, 5, n)
    for key in ("first_pos", "last_pos"):
        a = getattr(f, key)
        a[:] = centers[pick] + 0.01 * a
    f.pivot_distances = None
    return f


def _check_column_minima(backward: bool, alpha1: str, opencl: bool) -> None:
    """Every column's minimum from the pruned scan (the kernel, or NumPy) is the brute-force
    float32 minimum, with rows in tight groups, tied values and phi ties; fewer pairs computed."""
    s = _settings(f"synthesize.alpha1={alpha1}")
    f = _clustered(700, seed=5)
    tc = TransitionCosts(f, s, opencl=opencl)
    rng = np.random.default_rng(1)
    rows = rng.choice(len(f), 500, replace=False)
    phi = np.round(rng.random(500) * 50, 0).astype(np.float32)  # many ties
    order = np.argsort(phi, kind="stable")
    rows, phi = rows[order].astype(np.int32), phi[order]
    cols = np.arange(len(f), dtype=np.int32)
    tcb = tc.dense()
    costs = tcb[cols][:, rows] if backward else tcb[rows][:, cols].T  # (cols, rows)
    special = (f.pre[rows][None, :] == cols[:, None]) if backward else (f.pre[cols][:, None] == rows[None, :])
    values = np.where(special, np.float32(np.inf), phi[None, :] + costs)  # rule 1 is init's; rule 4 is scanned
    init = np.full(len(cols), np.inf, np.float32)
    init[::3] = np.min(values[::3], axis=1)  # some columns start at their exact minimum
    minima = tc.device.column_minima if opencl else partial(_column_minima_numpy, tc)
    best, evals = minima(rows, phi, cols, init, backward=backward)
    assert np.array_equal(best, np.minimum(init, values.min(axis=1)))
    assert evals < values.size


@pytest.mark.parametrize("backward", [False, True])
@pytest.mark.parametrize("alpha1", ["1.75", "0.3"])
def test_grouped_column_minima_equal_the_brute_force_minima(backward, alpha1, opencl_device):
    """The kernel's group bounds and seed skip only what cannot lower a minimum, forward and
    backward, with the rule-4 penalty alpha1 PNT above and below PNT."""
    _check_column_minima(backward, alpha1, opencl=True)


@pytest.mark.parametrize("backward", [False, True])
@pytest.mark.parametrize("alpha1", ["1.75", "0.3"])
def test_numpy_column_minima_equal_the_brute_force_minima(backward, alpha1):
    """The NumPy scan's seed and two-stage pivot bounds skip only what cannot lower a minimum."""
    _check_column_minima(backward, alpha1, opencl=False)


def test_clustered_database_pruned_equals_dense_on_opencl(opencl_device):
    s = _settings()
    f = _clustered(600, seed=9)
    obs = _random_obs(f, 10, seed=2, s=s)
    _check(TransitionCosts(f, s, opencl=True), obs)
