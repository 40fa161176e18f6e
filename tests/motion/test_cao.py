"""Cao et al.'s post-processing (their 6.3): blending across jumps and the learned low-pass."""

import numpy as np
import pytest

from facesynth.domain.postprocess.cao import blend_jumps, learned_cutoffs, lowpass
from facesynth.domain.postprocess.concatenation import time_warp

# --- learned cut-offs --------------------------------------------------------------------------

FPS = 128.0  # Welch segments of 32 frames: a frequency grid of 4 Hz, 0 to 64 Hz
BIN = FPS / 32


def _sines(n, *parts):
    """sum of amplitude * sin(2 pi f t + phase) over parts (f Hz, amplitude, phase), n frames at FPS."""
    t = np.arange(n) / FPS
    return sum(a * np.sin(2 * np.pi * f * t + ph) for f, a, ph in parts)


def test_each_component_gets_the_frequency_below_which_99_percent_of_its_energy_lies():
    coeffs = np.stack([_sines(512, (8, 1.0, 0.0)), _sines(512, (20, 3.0, 1.0)), _sines(512, (40, 0.2, 2.0))], 1)
    cut = learned_cutoffs(coeffs, [slice(0, 512)], FPS)
    # one sinusoid per component: its frequency, to the Welch grid (the Hann window spreads a
    # sinusoid over its bin and the next, so the 99% point is at most one bin above it)
    for got, f in zip(cut, (8, 20, 40)):
        assert f <= got <= f + BIN


def test_the_cut_off_moves_with_the_energy_fraction():
    # 8 Hz with amplitude 1 (power 1/2) and 40 Hz with amplitude 1/2 (power 1/8): 80% / 20%
    x = _sines(512, (8, 1.0, 0.0), (40, 0.5, 0.3))[:, None]
    assert 40 <= learned_cutoffs(x, [slice(0, 512)], FPS)[0] <= 40 + BIN  # 99% needs the 40 Hz part
    assert 8 <= learned_cutoffs(x, [slice(0, 512)], FPS, energy=0.5)[0] <= 8 + BIN  # half of it is below 8 Hz
    # a 40 Hz part with 0.04% of the energy is not worth keeping
    faint = _sines(512, (8, 1.0, 0.0), (40, 0.02, 0.3))[:, None]
    assert learned_cutoffs(faint, [slice(0, 512)], FPS)[0] <= 8 + BIN


def test_energy_is_counted_within_captured_runs_not_across_their_joins():
    x = _sines(512, (8, 1.0, 0.0))[:, None]
    x[256:] += 50.0  # two runs of the same motion at different offsets: the join is not motion
    runs = learned_cutoffs(x, [slice(0, 256), slice(256, 512)], FPS)
    assert 8 <= runs[0] <= 8 + BIN
    assert learned_cutoffs(x, [slice(0, 512)], FPS)[0] > 8 + 4 * BIN  # the step's broadband energy


def test_runs_too_short_for_a_spectrum_leave_every_component_unfiltered():
    x = _sines(100, (8, 1.0, 0.0))[:, None].repeat(3, 1)
    np.testing.assert_array_equal(learned_cutoffs(x, [slice(0, 31), slice(40, 71)], FPS), [FPS / 2] * 3)
    # a short run beside a long one is skipped, not allowed to change the answer
    long = learned_cutoffs(x, [slice(0, 100)], FPS)
    np.testing.assert_array_equal(learned_cutoffs(x, [slice(0, 100), slice(0, 20)], FPS), long)


# --- low-pass ----------------------------------------------------------------------------------


def _amplitude(x, f, fps):
    """Amplitude of the f Hz sinusoid in x, measured on its middle 4 s (whole periods of every
    frequency used here), away from the filter's start and end transients."""
    mid = x[len(x) // 2 - 240 : len(x) // 2 + 240]
    k = int(round(f * len(mid) / fps))
    return abs(np.fft.rfft(mid)[k]) * 2 / len(mid)


def _zero_phase_gain(f, fc, fps, order=4):
    """|H(f)|^2 of a digital Butterworth low-pass (bilinear transform, cut-off prewarped), run
    forwards and backwards: 1 / (1 + (tan(pi f / fps) / tan(pi fc / fps))^(2 order))."""
    return 1 / (1 + (np.tan(np.pi * f / fps) / np.tan(np.pi * fc / fps)) ** (2 * order))


def test_lowpass_keeps_a_low_sinusoid_and_removes_a_high_one():
    fps = 120.0
    t = np.arange(720) / fps
    low, high = np.sin(2 * np.pi * 2 * t + 0.4), 0.8 * np.sin(2 * np.pi * 30 * t)
    out = lowpass(np.stack([low + high, 3 * low + high], 1), np.array([6.0, 6.0]), fps)
    assert _zero_phase_gain(2, 6, fps) == pytest.approx(0.99986, abs=1e-5)
    for j, gain in enumerate((1.0, 3.0)):
        assert _amplitude(out[:, j], 2, fps) == pytest.approx(gain * _zero_phase_gain(2, 6, fps), rel=1e-4)
        assert _amplitude(out[:, j], 30, fps) < 1e-5  # 0.8 * |H(30 Hz)|^2 = 2e-6
        # zero phase: the low sinusoid comes out where it went in
        np.testing.assert_allclose(out[120:-120, j], gain * low[120:-120], atol=1e-3 * gain)


def test_lowpass_uses_each_columns_own_cut_off():
    fps = 120.0
    t = np.arange(720) / fps
    x = np.sin(2 * np.pi * 10 * t)
    out = lowpass(np.stack([x, x], 1), np.array([4.0, 20.0]), fps)
    assert _amplitude(out[:, 0], 10, fps) == pytest.approx(_zero_phase_gain(10, 4, fps), rel=1e-3)  # 0.0016
    assert _amplitude(out[:, 1], 10, fps) == pytest.approx(_zero_phase_gain(10, 20, fps), rel=1e-4)  # 0.9978


def test_cut_offs_at_nyquist_or_zero_and_short_signals_are_left_alone():
    fps = 120.0
    x = np.random.default_rng(0).normal(size=(200, 3)).astype(np.float32)
    out = lowpass(x, np.array([fps / 2, 0.45 * fps, 0.0]), fps)
    assert out.dtype == np.float64
    np.testing.assert_array_equal(out, x.astype(np.float64))
    short = x[:26]  # under 3 * (2 * order + 1) frames: too short for filtfilt's padding
    out = lowpass(short, np.array([5.0, 5.0, 5.0]), fps)
    np.testing.assert_array_equal(out, short)
    assert out is not short


def test_lowpass_does_not_change_its_input():
    x = np.random.default_rng(1).normal(size=(100, 2))
    before = x.copy()
    lowpass(x, np.array([5.0, 5.0]), 120.0)
    np.testing.assert_array_equal(x, before)


# --- blending across jumps ---------------------------------------------------------------------
#
# A toy database, one PCA component (a second one is 0.5 * the first + 7, so both columns
# must come out in the same relation). Values by frame f:
#   take 0, frames 0-19:   f              node 0 'aa' (0-9) -> node 1 'b' (10-19)
#   take 1, frames 20-39:  100 + 3 (f-20) node 2 'm' (20-29) -> node 3 'iy' (30-39)
#   take 2, frames 40-59:  45 + (f-40)    node 4 'aa' (40-49) -> node 5 'iy' (50-59)  [an example]
#   take 3, frames 60-79:  1000 + f       node 6 'aa' (60-69) -> node 7 'iy' (70-79)  [a far example]


def _db(with_examples: bool):
    v = np.concatenate([np.arange(20.0), 100 + 3 * np.arange(20.0), 45 + np.arange(20.0), 1000 + np.arange(60.0, 80.0)])
    n_nodes = 8 if with_examples else 4
    n_frames = 20 * (n_nodes // 2)
    return dict(
        node_phone=["aa", "b", "m", "iy", "aa", "iy", "aa", "iy"][:n_nodes],
        node_start=np.arange(0, n_frames, 10), node_count=np.full(n_nodes, 10),
        node_pre=np.array([-1, 0, -1, 2, -1, 4, -1, 6][:n_nodes]),
        node_take_range=np.array([(20 * (k // 2), 20 * (k // 2) + 20) for k in range(n_nodes)]),
        coeffs=np.stack([v[:n_frames], 0.5 * v[:n_frames] + 7], 1).astype(np.float32),
    )


def _concatenate(db, path, ranges):
    """Every step's node time-warped to its frames, as postprocess.concatenate does before the joins."""
    out = np.zeros((ranges[-1][1], 2))
    for node, (a, b) in zip(path, ranges):
        out[a:b], _ = time_warp(db["coeffs"], int(db["node_start"][node]), int(db["node_count"][node]), b - a)
    return out


def _paper_blend(m1, m2):
    """Cao Eq. of 6.3: M[i] = (1 - (i-1)/(n-1)) M1[i] + (i-1)/(n-1) M2[i], i = 1..n."""
    n = len(m1)
    return np.array([(1 - (i - 1) / (n - 1)) * m1[i - 1] + (i - 1) / (n - 1) * m2[i - 1] for i in range(1, n + 1)])


def _run(db, path, phones, ranges):
    out = _concatenate(db, path, ranges)
    before = out.copy()
    changed = blend_jumps(out, ranges, np.array(path), phones, **db)
    np.testing.assert_allclose(out[:, 1], 0.5 * out[:, 0] + 7)
    return before[:, 0], out[:, 0], changed


def test_a_jump_without_an_example_blends_the_extended_segments():
    db = _db(with_examples=False)
    # a pause, then 'aa' of take 0 straight into 'iy' of take 1 (no captured aa -> iy anywhere)
    before, out, changed = _run(db, [0, 0, 3], ["pau", "aa", "iy"], [(0, 5), (5, 15), (15, 25)])
    assert before[15] - before[14] == 130 - 9  # the jump
    # 'aa' extended by the 10 frames that followed it in take 0 (10..19); 'iy' preceded by the
    # 10 frames before it in take 1 (100, 103, ..., 127); the two blended over 20 frames
    ext_a = np.arange(20.0)
    ext_b = 100 + 3 * np.arange(20.0)
    np.testing.assert_allclose(out[5:25], _paper_blend(ext_a, ext_b), atol=1e-4)
    assert out[5] == before[5] and out[24] == pytest.approx(before[24])  # the ends stay where they were
    assert np.abs(np.diff(out[5:25])).max() < 12  # continuous: no step near the 121 of the jump
    np.testing.assert_array_equal(out[:5], before[:5])  # the pause step is not touched
    assert changed.tolist() == [False] * 5 + [True] * 20


def test_frames_past_the_end_of_a_take_are_extrapolated_with_its_velocity():
    db = _db(with_examples=False)
    # 'b' ends take 0 and 'm' starts take 1: nothing follows the one or precedes the other
    _, out, _ = _run(db, [1, 2], ["b", "m"], [(0, 10), (10, 20)])
    ext_a = 10 + np.arange(20.0)  # 10..19 captured, then 20..29 at the last velocity, 1 per frame
    ext_b = 70 + 3 * np.arange(20.0)  # 70..97 before take 1's first frame at its velocity 3, then 100..127
    np.testing.assert_allclose(out, _paper_blend(ext_a, ext_b), atol=1e-4)


@pytest.mark.parametrize("p", [10, 5])
def test_a_jump_with_a_captured_example_follows_the_example(p):
    db = _db(with_examples=True)
    before, out, changed = _run(db, [0, 3], ["aa", "iy"], [(0, p), (p, p + 10)])
    # the closest captured aa -> iy is nodes 4 -> 5 (values 45..54 | 55..64), not 6 -> 7 (1060..)
    warp_m = 45 + np.linspace(0, 9, p)
    warp_n = 55 + np.arange(10.0)
    np.testing.assert_allclose(out[:p], _paper_blend(before[:p], warp_m), atol=1e-4)
    np.testing.assert_allclose(out[p:], _paper_blend(warp_n, before[p:]), atol=1e-4)
    # the join is the example's own captured step, 54 -> 55
    assert out[p - 1] == pytest.approx(54) and out[p] == pytest.approx(55)
    assert out[0] == before[0] and out[-1] == pytest.approx(before[-1])
    assert changed.all()


@pytest.mark.parametrize("path, phones, ranges", [
    ([0, 1], ["aa", "b"], [(0, 10), (10, 20)]),  # captured neighbours (pre(1) = 0)
    ([0, 3], ["pau", "iy"], [(0, 10), (10, 20)]),  # a pause on one side is regenerated later
    ([0, 3], ["aa", "pau"], [(0, 10), (10, 20)]),
    ([0, 3], ["aa", "iy"], [(0, 1), (1, 11)]),  # one frame: nothing to blend over
    ([0, 3], ["aa", "iy"], [(0, 10), (10, 11)]),
])
def test_captured_joins_pauses_and_one_frame_steps_are_left_alone(path, phones, ranges):
    before, out, changed = _run(_db(with_examples=True), path, phones, ranges)
    np.testing.assert_array_equal(out, before)
    assert not changed.any()
