"""The OpenCL DP against the NumPy reference: identical optimal cost, path and accumulated costs."""

import itertools

import numpy as np
import pytest
from features import tiny_utterance_steps

from facesynth.domain.search.dp import OpenCLDp, dp_numpy, dp_opencl
from facesynth.domain.search.pairs import transition_costs


def _random(n, t, seed):
    rng = np.random.default_rng(seed)
    tc = (rng.random((n, n), dtype=np.float32) * 100).astype(np.float32)
    tc[rng.random((n, n)) < 0.02] = 0.0
    obs = (rng.integers(0, 4, (t, n)) * 25).astype(np.float32)  # coarse values: many ties
    return tc, obs


@pytest.mark.parametrize("n, t", [(1, 3), (5, 4), (95, 6), (96, 6), (97, 9), (500, 14), (1300, 24)])
def test_opencl_equals_reference_on_random_costs(n, t, opencl_device):
    tc, obs = _random(n, t, seed=n)
    ref, cl = dp_numpy(tc, obs), dp_opencl(tc, obs)
    assert cl.cost == ref.cost
    assert cl.path.tolist() == ref.path.tolist()
    assert np.array_equal(cl.phi, ref.phi)


def test_reference_finds_the_brute_force_optimum():
    tc, obs = _random(4, 4, seed=7)
    best = min(
        (sum(obs[t, p[t]] for t in range(4)) + sum(tc[p[t], p[t + 1]] for t in range(3)), p)
        for p in itertools.product(range(4), repeat=4)
    )
    ref = dp_numpy(tc, obs)
    assert ref.cost == pytest.approx(best[0])
    assert tuple(ref.path) == best[1]  # tuples compare lexicographically: lowest index wins ties


def test_ties_go_to_the_lowest_index(opencl_device):
    tc = np.zeros((200, 200), np.float32)
    obs = np.zeros((5, 200), np.float32)
    for result in (dp_numpy(tc, obs), dp_opencl(tc, obs)):
        assert result.path.tolist() == [0] * 5 and result.cost == 0.0


def test_buffers_split_below_the_allocation_limit_give_the_same_answer(monkeypatch, opencl_device):
    tc, obs = _random(700, 8, seed=3)
    ref = dp_numpy(tc, obs)
    monkeypatch.setattr("facesynth.domain.search.dp.max_alloc_bytes", lambda: 3 * 700 * 96 * 4)  # three panels per buffer
    runner = OpenCLDp(tc)
    assert len(runner.groups) == 3
    res = runner.run(obs)
    assert res.cost == ref.cost and res.path.tolist() == ref.path.tolist()


@pytest.mark.parametrize("with_emotions, with_constraints", [(False, False), (True, False), (False, True), (True, True)])
def test_real_database_with_emotions_and_constraints(tiny_db, tiny_corpus, held_out_take, config, with_emotions, with_constraints,
                                                    opencl_device):
    from facesynth.model.motiondb import MotionDatabase

    db = MotionDatabase.read(tiny_db)
    s = config.settings("synthesize")
    tc = transition_costs(db, s).dense()
    steps, constraints = tiny_utterance_steps(db, s, tiny_corpus / "labels" / f"{held_out_take}.TextGrid",
                                              with_emotions, with_constraints)
    ref, cl = dp_numpy(tc, steps.total), dp_opencl(tc, steps.total)
    assert cl.cost == ref.cost and cl.path.tolist() == ref.path.tolist()
    for t, node in constraints.items():
        assert ref.path[t] == node
    if with_constraints:
        assert constraints  # the take shares phones with the database


def test_bounded_dp_is_exact_and_prunes_with_a_tight_bound():
    from facesynth.domain.search.dp import dp_bounded

    tc, obs = _random(300, 12, seed=11)
    ref = dp_numpy(tc, obs)
    for slack in (0.0, 50.0, 1e6):
        res, active = dp_bounded(tc, obs, ref.cost + slack)
        assert res.cost == ref.cost and res.path.tolist() == ref.path.tolist()
    _, tight = dp_bounded(tc, obs, ref.cost)
    _, loose = dp_bounded(tc, obs, 1e9)
    assert tight.mean() < loose.mean() == 1.0


def test_host_work_runs_once_while_the_device_searches(opencl_device):
    tc, obs = _random(300, 7, seed=5)
    calls = []
    res = OpenCLDp(tc).run(obs, while_running=lambda: calls.append(1))
    ref = dp_numpy(tc, obs)
    assert calls == [1]
    assert res.cost == ref.cost and res.path.tolist() == ref.path.tolist()


def test_a_misaligned_host_array_is_copied_into_aligned_memory(opencl_device):
    """NumPy aligns to 16 bytes only; the kernel reads float8s from host memory (USE_HOST_PTR)."""
    from facesynth.base.opencl import aligned_empty, host_aligned
    from facesynth.domain.search.dp import PanelMatrix

    tc, obs = _random(300, 6, seed=21)
    good = PanelMatrix.from_matrix(tc)
    assert good.panels.ctypes.data % 4096 == 0
    raw = aligned_empty(good.panels.size + 16, np.float32)
    bad = raw[4 : 4 + good.panels.size].reshape(good.panels.shape)  # 16 bytes past a page boundary
    bad[:] = good.panels
    assert bad.ctypes.data % 32 == 16
    good.panels = bad
    runner = OpenCLDp(good)
    assert all(host.ctypes.data % 128 == 0 for _, _, _, host in runner.groups)  # what the device reads in place
    res = runner.run(obs)
    ref = dp_numpy(tc, obs)
    assert res.cost == ref.cost and res.path.tolist() == ref.path.tolist()
    assert host_aligned(bad).ctypes.data % 128 == 0 and np.array_equal(host_aligned(bad), bad)
