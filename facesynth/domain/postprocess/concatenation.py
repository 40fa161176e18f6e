"""Concatenation and post-processing of a searched node path (paper VII-B).

Order: time-warp each node to its input phone's duration on the 120 Hz grid and
concatenate; smooth the joins without a captured predecessor/successor relation with
Eq. 16; regenerate the frames of input pauses by interpolation; back-project with Eq. 11
(done by the caller); down-sample to the output rate.

Choices where the paper is vague:

* Eq. 16's smoothness term is written ``int g''(t) dt``; a signed integral is not a
  smoothness measure, so the squared second derivative is used (as in the trajectory
  smoothing of Ezzat et al., the paper's [27]), discretized as second differences and
  weighted by ``smoothing_lambda``. The fit is solved per PCA coefficient.
* Pauses at the start or end of the utterance have a non-silence boundary on one side
  only; the other side is the database's neutral closed-mouth rest pose, so the face
  settles to rest in silence.
* Eq. 16 with free ends leaves the window's edges discontinuous and follows the jump at the
  join, so joins pop. The default join smoothing (``join_smoothing = "blend"``,
  :func:`blend_join`) instead adds to each side a smooth displacement that closes the gap in
  position and velocity at the join and fades out (value, slope and curvature 0) at the
  window's edges: the frames keep their captured shape, and position and velocity are
  continuous everywhere. Table IV's weights share the correction: the heavier side moves less.
* Pauses are regenerated between the frames around them; ``silence_interpolation =
  "hermite"`` matches the velocities on both sides too (a cubic Hermite). A pause of at least
  ``rest_after`` frames also passes through the rest pose: the interpolation is blended toward
  rest with a weight that rises from 0 to 1 over ``rest_ramp`` frames after the pause starts
  and falls back to 0 over the ``rest_ramp`` frames before it ends (cosine eases), so the mouth
  relaxes and closes in a silence instead of hanging half open between two phones.
* Down-sampling takes every (capture rate / output rate)-th frame, or interpolates when the
  ratio is not whole; no low-pass filter, so brief lip closures survive.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from facesynth.base.phonemes import PAU


@dataclass
class Concatenated:
    """coeffs : (F, K) at the capture rate; node/source_frame : (F,) provenance (-1 for
    regenerated silence); step : (F,) input phone index of each frame."""

    coeffs: np.ndarray
    node: np.ndarray
    source_frame: np.ndarray
    step: np.ndarray
    smoothed: np.ndarray  # (F,) bool, frame changed by join smoothing


def end_slope_weights(length: int) -> np.ndarray:
    """Weights w ((length,) float64) with ``w @ y[0:length]`` = the slope at frame 0 (units of y
    per frame) of the least-squares polynomial through samples y[0..length-1]: degree 1 for
    up to 3 samples, else degree 2 (a Savitzky-Golay derivative evaluated at the end point).
    length 2 gives the finite difference y[1] - y[0]."""
    if length < 2:
        raise ValueError("a slope needs at least two samples")
    x = np.arange(length, dtype=np.float64)
    degree = 1 if length <= 3 else 2
    vandermonde = x[:, None] ** np.arange(degree + 1)[None, :]
    return np.linalg.pinv(vandermonde)[1]


def frame_ranges(starts: np.ndarray, ends: np.ndarray, fps: float) -> list[tuple[int, int]]:
    """Output frames [a, b) of each input phone on the fps grid (frame f at time f / fps)."""
    edges = np.round(np.concatenate([[starts[0]], ends]) * fps).astype(int)
    edges = np.maximum.accumulate(edges)
    return [(int(edges[k]), int(edges[k + 1])) for k in range(len(starts))]


def time_warp(coeffs: np.ndarray, source_start: int, count: int, n_out: int) -> tuple[np.ndarray, np.ndarray]:
    """Resample a node's ``count`` frames to ``n_out`` frames by linear interpolation.
    Returns (n_out, K) and the nearest source frame of each output frame."""
    if n_out <= 0:
        return np.zeros((0, coeffs.shape[1]), coeffs.dtype), np.zeros(0, np.int64)
    x = np.linspace(0.0, count - 1, n_out) if n_out > 1 else np.array([(count - 1) / 2.0])
    lo = np.floor(x).astype(int)
    hi = np.minimum(lo + 1, count - 1)
    w = (x - lo)[:, None]
    seq = coeffs[source_start : source_start + count].astype(np.float64)
    return seq[lo] * (1 - w) + seq[hi] * w, source_start + np.round(x).astype(np.int64)


def smooth_join(f: np.ndarray, w_left: float, w_right: float, lam: float) -> np.ndarray:
    """Eq. 16 on a window of 2s frames (s before the join, s after): minimize
    sum W (g_i - f_i)^2 + lam * sum (second difference of g)^2. f : (2s, K)."""
    n = len(f)
    s = n // 2
    weights = np.concatenate([np.full(s, w_left), np.full(n - s, w_right)])
    d2 = np.zeros((max(n - 2, 0), n))
    for r in range(n - 2):
        d2[r, r : r + 3] = (1.0, -2.0, 1.0)
    system = np.diag(weights) + lam * d2.T @ d2
    return np.linalg.solve(system, weights[:, None] * f)


def _quintic_fade(n: int) -> np.ndarray:
    """h(u) = 10u^3 - 15u^4 + 6u^5 at u = k / n, k = 1..n: (n,) from near 0 to 1, with value,
    slope and curvature 0 at u = 0 and slope and curvature 0 at u = 1."""
    u = np.arange(1, n + 1) / n
    return u ** 3 * (10 - 15 * u + 6 * u * u)


def _ramp_to(n: int, value: np.ndarray, slope: np.ndarray) -> np.ndarray:
    """(n, K): a displacement over n frames that starts flat at 0 (value, slope and curvature 0
    before frame 0) and ends at frame n - 1 with ``value`` and ``slope`` (per frame), K = len(value).
    The quintic Hermite through (0, 0, 0) and (value, slope * n, 0) in the unit interval."""
    u = (np.arange(1, n + 1) / n)[:, None]
    h_value = u ** 3 * (10 - 15 * u + 6 * u * u)  # 0 -> 1, flat at both ends
    h_slope = u ** 3 * (-4 + 7 * u - 3 * u * u)  # 0 -> 0, slope 1 at u = 1
    return h_value * value[None] + h_slope * (slope * n)[None]


def blend_join(out: np.ndarray, a: int, join: int, b: int, share_left: float, fit_frames: int = 4) -> None:
    """Make ``out`` ((F, K), in place) continuous in position and velocity across the join at
    frame ``join`` (first frame of the right side), changing frames [a, join) and [join, b).

    Each side's velocity at the join is the end slope of a local fit over up to ``fit_frames``
    of its frames (:func:`end_slope_weights`). The left side extrapolated half a frame forward
    and the right side half a frame back disagree by D in position and V in velocity; the left
    side gets a displacement reaching ``share_left * (D, V)`` at the join, the right side one
    reaching ``-(1 - share_left) * (D, V)``, each fading to 0 with zero slope and curvature at
    the window's edge (:func:`_ramp_to`), so nothing jumps there either.
    """
    n_left, n_right = join - a, b - join
    if n_left < 2 or n_right < 2:
        return
    wl = end_slope_weights(min(fit_frames, n_left))
    wr = end_slope_weights(min(fit_frames, n_right))
    v_left = -(wl @ out[join - len(wl) : join][::-1])  # slope backwards in time from join - 1, negated
    v_right = wr @ out[join : join + len(wr)]
    gap = (out[join] - 0.5 * v_right) - (out[join - 1] + 0.5 * v_left)  # position mismatch at join - 1/2
    dv = v_right - v_left
    share_right = 1.0 - share_left
    # left: reaches share_left * (gap, dv) half a frame after its last frame
    left = _ramp_to(n_left, share_left * (gap - 0.5 * dv), share_left * dv)
    # right: reaches -share_right * (gap, dv) at the join; built backwards in time, so its slope flips
    right = _ramp_to(n_right, share_right * (gap + 0.5 * dv), -share_right * dv)[::-1]
    out[a:join] += left
    out[join:b] -= right


def concatenate(path: np.ndarray, phones: list[str], starts: np.ndarray, ends: np.ndarray,
                node_start: np.ndarray, node_count: np.ndarray, node_pre: np.ndarray, node_phone: list[str],
                coeffs: np.ndarray, rest: np.ndarray, fps: float, *, half_window: int, lam: float,
                weight_of, interpolation: str = "linear", joins=None, method: str = "blend",
                pinned: frozenset[str] = frozenset(), rest_after: int | None = None, rest_ramp: int = 1) -> Concatenated:
    """The whole VII-B chain up to (not including) Eq. 11. ``weight_of(phone)`` gives Table IV's
    factor. With the blend, a phone of ``pinned`` keeps its frames at a join with an unpinned
    phone: the other side takes the whole correction (a captured lip closure stays closed). ``method``: "blend" (:func:`blend_join` over ``half_window`` frames each side,
    at most the phone's own frames) or "eq16" (:func:`smooth_join` over 2 ``half_window``
    frames, free-ended). ``joins(out, ranges)``, if given, replaces both (e.g. Cao's blending
    and low-pass, :mod:`facesynth.domain.postprocess.cao`) and returns the mask of frames it changed.
    ``rest_after`` (frames; None: never) and ``rest_ramp`` (frames): pauses that long pass
    through ``rest`` (see the module docstring)."""
    ranges = frame_ranges(starts, ends, fps)
    total = ranges[-1][1]
    k = coeffs.shape[1]
    out = np.zeros((total, k))
    node = -np.ones(total, np.int64)
    source = -np.ones(total, np.int64)
    step = np.zeros(total, np.int64)
    for t, (a, b) in enumerate(ranges):
        j = int(path[t])
        out[a:b], source[a:b] = time_warp(coeffs, int(node_start[j]), int(node_count[j]), b - a)
        node[a:b] = j
        step[a:b] = t
    smoothed = np.zeros(total, bool)
    for t in range(len(path) - 1 if joins is None else 0):
        if phones[t] == PAU or phones[t + 1] == PAU or node_pre[path[t + 1]] == path[t]:
            continue  # captured neighbours need no smoothing; pauses are regenerated below
        join = ranges[t][1]
        a, b = max(ranges[t][0], join - half_window), min(ranges[t + 1][1], join + half_window)
        if b - a < 3:
            continue
        w_left = weight_of(node_phone[path[t]])
        w_right = weight_of(node_phone[path[t + 1]])
        if method == "blend":
            share_left = w_right / (w_left + w_right)  # the heavier side moves less
            left_pinned, right_pinned = node_phone[path[t]] in pinned, node_phone[path[t + 1]] in pinned
            if left_pinned != right_pinned:
                share_left = 0.0 if left_pinned else 1.0
            blend_join(out, a, join, b, share_left)
        else:
            out[a:b] = smooth_join(out[a:b], w_left, w_right, lam)
        smoothed[a:b] = True
    if joins is not None:
        smoothed = joins(out, ranges)
    for t, (a, b) in enumerate(ranges):
        if phones[t] != PAU or b <= a:
            continue
        left = out[a - 1] if a > 0 else rest
        right = out[b] if b < total else rest
        if interpolation == "hermite":
            v_left = out[a - 1] - out[a - 2] if a > 1 else np.zeros_like(rest)
            v_right = out[b + 1] - out[b] if b + 1 < total else np.zeros_like(rest)
            out[a:b] = hermite(left, right, v_left, v_right, b - a)
        else:
            out[a:b] = interpolate(left, right, b - a, interpolation)
        if rest_after is not None and b - a >= rest_after:
            out[a:b] = toward_rest(out[a:b], rest, rest_ramp)
        node[a:b] = -1
        source[a:b] = -1
    return Concatenated(out.astype(np.float32), node, source, step, smoothed)


def toward_rest(frames: np.ndarray, rest: np.ndarray, ramp: int) -> np.ndarray:
    """A pause's frames (n, K) blended toward ``rest`` (K,): the weight of rest eases (a cosine)
    from 0 to 1 over the first ``ramp`` frames and back to 0 over the last ``ramp``."""
    n = len(frames)
    t = np.arange(n)
    w = np.minimum(np.clip((t + 1) / ramp, 0.0, 1.0), np.clip((n - t) / ramp, 0.0, 1.0))
    w = ((1 - np.cos(np.pi * w)) / 2)[:, None]
    return frames * (1 - w) + rest[None] * w


def interpolate(left: np.ndarray, right: np.ndarray, n: int, kind: str) -> np.ndarray:
    """n frames strictly between two boundary frames."""
    u = np.arange(1, n + 1) / (n + 1)
    if kind == "cosine":
        u = (1 - np.cos(np.pi * u)) / 2
    elif kind == "cubic":
        u = u * u * (3 - 2 * u)  # smoothstep: zero velocity at both ends
    return left[None] * (1 - u[:, None]) + right[None] * u[:, None]


def hermite(left: np.ndarray, right: np.ndarray, v_left: np.ndarray, v_right: np.ndarray, n: int) -> np.ndarray:
    """n frames (n, K) strictly between two boundary frames (K,), a cubic Hermite that leaves
    ``left`` with velocity ``v_left`` and reaches ``right`` with ``v_right`` (per frame)."""
    span = n + 1
    u = (np.arange(1, n + 1) / span)[:, None]
    h00, h10 = 2 * u ** 3 - 3 * u ** 2 + 1, u ** 3 - 2 * u ** 2 + u
    h01, h11 = -2 * u ** 3 + 3 * u ** 2, u ** 3 - u ** 2
    return h00 * left[None] + h10 * span * v_left[None] + h01 * right[None] + h11 * span * v_right[None]


def downsample_sources(indices: np.ndarray, ratio: float, n_in: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Where :func:`downsample` by ``ratio`` (fps_in / fps_out) of ``n_in`` frames takes its output
    frames ``indices`` from: input frames lo and hi (int64) and the weight of hi (float64; 0 when
    the ratio is whole, where output frame k is input frame k * ratio)."""
    x = np.asarray(indices) * ratio
    if abs(ratio - round(ratio)) < 1e-9:
        lo = np.asarray(indices, np.int64) * int(round(ratio))
        return lo, lo, np.zeros(len(lo))
    lo = np.floor(x).astype(np.int64)
    return lo, np.minimum(lo + 1, n_in - 1), x - lo


def downsample(frames: np.ndarray, fps_in: float, fps_out: float) -> np.ndarray:
    """Frames at fps_out covering the same duration (frame k at time k / fps_out)."""
    ratio = fps_in / fps_out
    n_out = int(np.floor((len(frames) - 1) / ratio)) + 1
    if abs(ratio - round(ratio)) < 1e-9:
        return frames[:: int(round(ratio))][:n_out].copy()
    lo, hi, w = downsample_sources(np.arange(n_out), ratio, len(frames))
    w = w.reshape(-1, *([1] * (frames.ndim - 1)))
    return (frames[lo] * (1 - w) + frames[hi] * w).astype(frames.dtype)
