"""Finding contaminated motion nodes (paper V), for ``facesynth prune --auto``.

Contaminated nodes are found in the normalized markers a database carries (:func:`detect`):

* an *excursion* is a marker jumping away (a frame-to-frame step beyond ``jump_z`` robust
  z-scores of that marker's steps) and jumping back (an opposite step of similar size)
  within ``max_excursion_s``; natural facial motion is smooth at the capture rate, marker
  spikes and label swaps are not. Its frames are contaminated; two markers making the same
  excursion together are a swap, one alone a spike; a jump never answered flags its frame;
* a node is an outlier when its mean PCA frame lies more than ``outlier_z`` robust z-scores
  from its phoneme cluster's median.

A node is contaminated when any of its frames is. :func:`contaminated_nodes` reads the sample
corpus's ground truth of injected events, to measure the detection.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from facesynth.base.config import PruneSettings
from facesynth.model.motiondb import Nodes
from facesynth.model.tables import Takes


def robust_z(x: np.ndarray, axis=0) -> np.ndarray:
    """Robust z-scores: (x - median) / (1.4826 * MAD) along ``axis``."""
    med = np.median(x, axis=axis, keepdims=True)
    mad = np.median(np.abs(x - med), axis=axis, keepdims=True) * 1.4826
    return (x - med) / np.maximum(mad, 1e-9)


def excursions(track: np.ndarray, threshold: float, max_len: int) -> list[tuple[int, int]]:
    """Excursions of one marker: frame ranges [a, b) between a jump and its return.

    track : (T, 3) positions; threshold : step size (mm) counted as a jump.
    A jump with no return within ``max_len`` frames gives the range [a, a + 1).
    """
    step = np.diff(track, axis=0, prepend=track[:1])
    size = np.linalg.norm(step, axis=1)
    jumps = np.nonzero(size > threshold)[0]
    out, used = [], set()
    for i, a in enumerate(jumps):
        if a in used:
            continue
        partner = None
        for b in jumps[i + 1 :]:
            if b - a > max_len:
                break
            cos = float(step[a] @ step[b]) / (size[a] * size[b])
            if cos < -0.5 and 0.5 < size[b] / size[a] < 2.0:
                partner = b
                break
        if partner is None:
            out.append((int(a), int(a) + 1))
        else:
            used.add(partner)
            out.append((int(a), int(partner)))
    return out


def hold_gaps(x: np.ndarray) -> np.ndarray:
    """(T, M, 3) with NaN samples replaced by the marker's last seen position (the first seen
    one before it appears); markers never seen become 0."""
    out = x.copy()
    seen = ~np.isnan(out).any(axis=2)  # (T, M)
    index = np.where(seen, np.arange(len(out))[:, None], -1)
    np.maximum.accumulate(index, axis=0, out=index)
    first = np.argmax(seen, axis=0)
    index = np.where(index < 0, first[None, :], index)
    out = out[index, np.arange(out.shape[1])[None, :]]
    return np.nan_to_num(out)


def detect(nodes: Nodes, takes: Takes, markers: np.ndarray, coeffs: np.ndarray, fps: float,
           settings: PruneSettings) -> dict[int, str]:
    """Contaminated nodes -> kind ('spike', 'swap' or 'outlier')."""
    n_frames, n_markers, _ = markers.shape
    filled = markers.astype(np.float64)
    steps = np.zeros((n_frames, n_markers))
    for t in range(len(takes)):
        sl = takes.frames(t)
        filled[sl] = hold_gaps(filled[sl])  # missing data is not contamination: no jump into a gap
        steps[sl][1:] = np.linalg.norm(np.diff(filled[sl], axis=0), axis=2)
    rows = np.concatenate([np.arange(nodes.frame_start[k], nodes.frame_start[k] + nodes.frame_count[k]) for k in range(len(nodes))])
    med = np.median(steps[rows], axis=0)
    mad = np.median(np.abs(steps[rows] - med), axis=0) * 1.4826
    thresholds = med + settings.jump_z * np.maximum(mad, 1e-6)
    max_len = int(round(settings.max_excursion_s * fps))
    flagged = np.zeros((n_frames, n_markers), bool)
    spans: dict[tuple[int, int], int] = {}
    for t in sorted(set(nodes.take.tolist())):
        sl = takes.frames(t)
        for m in range(n_markers):
            for a, b in excursions(filled[sl, m], thresholds[m], max_len):
                flagged[sl.start + a : sl.start + b, m] = True
                key = (sl.start + a, sl.start + b)
                spans[key] = spans.get(key, 0) + 1
    paired = np.zeros(n_frames, bool)
    for (a, b), count in spans.items():
        if count >= 2:
            paired[a:b] = True
    found: dict[int, str] = {}
    for k in range(len(nodes)):
        sl = nodes.frames(k)
        if flagged[sl].any():
            found[k] = "swap" if paired[sl].any() else "spike"
    phones = np.array(nodes.phone)
    means = np.stack([coeffs[nodes.frames(k)].mean(0) for k in range(len(nodes))])
    for phone in np.unique(phones):
        members = np.nonzero(phones == phone)[0]
        if len(members) < 8:
            continue
        d = np.linalg.norm(means[members] - np.median(means[members], axis=0), axis=1)
        for k in members[robust_z(d) > settings.outlier_z]:
            found.setdefault(int(k), "outlier")
    return dict(sorted(found.items()))


def contaminated_nodes(nodes: Nodes, takes: Takes, truth_csv: Path) -> set[int]:
    """Nodes whose frames overlap an injected contamination event (the sample corpus's ground truth)."""
    import csv

    events = list(csv.DictReader(open(truth_csv, encoding="utf-8")))
    out = set()
    for e in events:
        if e["take"] not in takes.name:
            continue
        t = takes.index(e["take"])
        a = takes.frame_start[t] + int(e["start_frame"])
        b = takes.frame_start[t] + int(e["end_frame"])
        hit = np.nonzero((nodes.take == t) & (nodes.frame_start <= b) & (nodes.frame_start + nodes.frame_count - 1 >= a))[0]
        out.update(int(k) for k in hit)
    return out
