"""Cao et al.'s post-processing (their 6.3), an alternative to Eq. 16 smoothing.

* **Blending across jumps.** For nodes a -> b joined without a captured link, find a
  captured example of the same phone pair (m -> n with pre(n) = m, phone(m) = phone(a),
  phone(n) = phone(b)); the example closest to the segments' boundary frames is used.
  m is time-warped to a's p output frames and n to b's q frames; a's segment is blended
  linearly into m's (weight 0 -> 1 over its frames) and n's into b's, so the join follows a
  captured transition. Without an example, a's segment is extended by the q frames that
  followed it in its capture, b's by the p frames that preceded it (extrapolated with the
  boundary velocity where the capture ends), and the two are blended over p + q frames.
* **Low-pass filter.** Per PCA component, the cut-off is the frequency below which 99% of
  that component's energy (mean removed, Welch spectrum over the database's captured node
  runs, so pauses and pruned nodes do not count) lies; a
  zero-phase Butterworth filter removes what is above it. Cao used independent components;
  PCA components are what this database stores.
"""

from __future__ import annotations

import numpy as np

from .concatenation import time_warp


def learned_cutoffs(coeffs: np.ndarray, segments: list[slice], fps: float, energy: float = 0.99) -> np.ndarray:
    """(K,) cut-off frequencies (Hz) keeping ``energy`` of each component's variance."""
    from scipy.signal import welch  # deferred: scipy.signal costs synthesize's start-up 0.3 s

    k = coeffs.shape[1]
    total, freqs = None, None
    for sl in segments:
        x = coeffs[sl].astype(np.float64)
        if len(x) < 32:
            continue
        freqs, p = welch(x - x.mean(0), fs=fps, nperseg=32, axis=0)  # one frequency grid for every take
        total = p * len(x) if total is None else total + p * len(x)
    if total is None or freqs is None:  # (set together) no segment long enough for a spectrum
        return np.full(k, fps / 2)
    cumulative = np.cumsum(total, axis=0) / np.maximum(total.sum(axis=0), 1e-30)
    return np.array([freqs[min(int(np.searchsorted(cumulative[:, j], energy)), len(freqs) - 1)] for j in range(k)])


def lowpass(frames: np.ndarray, cutoffs: np.ndarray, fps: float, order: int = 4) -> np.ndarray:
    """Zero-phase low-pass of each column at its own cut-off (Hz); columns whose cut-off is
    near the Nyquist frequency are left alone."""
    from scipy.signal import butter, sosfiltfilt  # deferred: scipy.signal costs synthesize's start-up 0.3 s

    out = frames.astype(np.float64).copy()
    if len(out) < 3 * (2 * order + 1):
        return out
    for j, fc in enumerate(cutoffs):
        if 0 < fc < 0.45 * fps:
            sos = butter(order, fc / (fps / 2), output="sos")
            out[:, j] = sosfiltfilt(sos, out[:, j])
    return out


def _blend(m1: np.ndarray, m2: np.ndarray) -> np.ndarray:
    """M[i] = (1 - (i-1)/(n-1)) M1[i] + (i-1)/(n-1) M2[i] (Cao 6.3)."""
    n = len(m1)
    w = np.linspace(0.0, 1.0, n)[:, None] if n > 1 else np.zeros((1, 1))
    return (1 - w) * m1 + w * m2


def _extend(coeffs: np.ndarray, start: int, count: int, n: int, after: bool, lo: int, hi: int) -> np.ndarray:
    """n captured frames after (or before) a node within its take [lo, hi), extrapolated
    with the boundary velocity where the take ends."""
    if after:
        end = start + count
        got = coeffs[end : min(end + n, hi)].astype(np.float64)
        last = coeffs[end - 1].astype(np.float64)
        vel = last - coeffs[max(end - 2, start)]
        base = got[-1] if len(got) else last
        extra = base + vel * np.arange(1, n - len(got) + 1)[:, None]
        return np.concatenate([got, extra])[:n]
    got = coeffs[max(start - n, lo) : start].astype(np.float64)
    first = coeffs[start].astype(np.float64)
    vel = coeffs[min(start + 1, start + count - 1)] - first
    base = got[0] if len(got) else first
    extra = base - vel * np.arange(n - len(got), 0, -1)[:, None]
    return np.concatenate([extra, got])[-n:]


def blend_jumps(out: np.ndarray, ranges: list[tuple[int, int]], path: np.ndarray, phones: list[str],
                node_phone: list[str], node_start: np.ndarray, node_count: np.ndarray, node_pre: np.ndarray,
                node_take_range: np.ndarray, coeffs: np.ndarray, pause: str = "pau") -> np.ndarray:
    """Cao's blending at every jump between spoken steps. Returns a mask of changed frames."""
    changed = np.zeros(len(out), bool)
    phone_arr = np.array(node_phone)
    for t in range(len(path) - 1):
        a, b = int(path[t]), int(path[t + 1])
        if phones[t] == pause or phones[t + 1] == pause or node_pre[b] == a:
            continue
        (a0, a1), (b0, b1) = ranges[t], ranges[t + 1]
        p, q = a1 - a0, b1 - b0
        if p < 2 or q < 2:
            continue
        ns = np.nonzero((node_pre >= 0) & (phone_arr == node_phone[b]))[0]
        ns = ns[phone_arr[node_pre[ns]] == node_phone[a]]
        if len(ns):
            ends = coeffs[node_start[node_pre[ns]] + node_count[node_pre[ns]] - 1].astype(np.float64)
            starts = coeffs[node_start[ns]].astype(np.float64)
            d = np.linalg.norm(ends - out[a1 - 1], axis=1) + np.linalg.norm(starts - out[b0], axis=1)
            n = int(ns[int(np.argmin(d))])
            m = int(node_pre[n])
            warp_m, _ = time_warp(coeffs, int(node_start[m]), int(node_count[m]), p)
            warp_n, _ = time_warp(coeffs, int(node_start[n]), int(node_count[n]), q)
            out[a0:a1] = _blend(out[a0:a1], warp_m)
            out[b0:b1] = _blend(warp_n, out[b0:b1])
        else:
            lo_a, hi_a = node_take_range[a]
            lo_b, hi_b = node_take_range[b]
            ext_a = np.concatenate([out[a0:a1], _extend(coeffs, int(node_start[a]), int(node_count[a]), q, True, lo_a, hi_a)])
            ext_b = np.concatenate([_extend(coeffs, int(node_start[b]), int(node_count[b]), p, False, lo_b, hi_b), out[b0:b1]])
            out[a0:b1] = _blend(ext_a, ext_b)
        changed[a0:b1] = True
    return changed
