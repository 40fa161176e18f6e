"""The motion nodes of a database and their DSC features (paper III, VI-B; Eq. 6), built by
``facesynth build-db``.

One motion node per phone occurrence in the training takes (:func:`build_nodes`). ``/pau/``
nodes are dropped and a pause splits the sentence: the node after a pause has no captured
predecessor. Each node keeps phone, viseme (Table VI), emotion, take, frame range, triphone
context and its captured predecessor/successor.

DSC (Eq. 6), read as: time-warp o_i onto pre(o_j)'s duration, blend linearly from warp(o_i)
(weight 1 at the start) to pre(o_j) (weight 1 at the end), and integrate the squared second
derivative of the blend over time. Both nodes are resampled to ``dsc_samples`` points in PCA
space (an orthonormal basis, so distances are marker-space millimetres); time is in capture
frames, so DSC is in mm^2 / frame^3. The blend's second differences are ``x_i + y_j``
(:func:`dsc_features`), so each node stores x, y and a scale. A node without predecessor has
y = 0 and scale 0 (Table I rule 4 does not use DSC). :func:`dsc_matrix` and
:func:`pair_gaps_numpy` are the all-pairs references the on-demand costs
(:mod:`facesynth.domain.search.pairs`) are tested against.
"""

from __future__ import annotations

import numpy as np

from facesynth.base.errors import InputError
from facesynth.base.phonemes import PAU, viseme
from facesynth.model.motiondb import Nodes
from facesynth.model.tables import Phones, Takes


def build_nodes(takes: Takes, phones: Phones, fps: float) -> Nodes:
    """One node per non-pause phone of the training takes, with links and triphone context (and
    the IPA phone each pronounces when a training take is in another language than English)."""
    rows: dict[str, list] = {k: [] for k in ("phone", "viseme", "emotion", "take", "frame_start", "frame_count",
                                             "start_s", "end_s", "prev_phone", "next_phone", "pre", "suc", "ipa")}
    phone_emotion = phones.emotions(takes)
    for t in range(len(takes)):
        if takes.split[t] != "train":
            continue
        seg = np.nonzero(phones.take == t)[0]
        n_frames = int(takes.frame_count[t])
        previous_node = -1
        for pos, r in enumerate(seg):
            phone = phones.phone[r]
            if phone == PAU:
                previous_node = -1  # a pause splits the sentence
                continue
            a = int(round(phones.start[r] * fps))
            b = max(int(round(phones.end[r] * fps)), a + 2)  # at least two frames, for velocities
            if b > n_frames:
                a, b = max(0, n_frames - 2), n_frames
            k = len(rows["phone"])
            rows["phone"].append(phone)
            rows["ipa"].append(phones.ipa[r] if phones.ipa is not None else "")
            rows["viseme"].append(viseme(phone))
            rows["emotion"].append(phone_emotion[r])
            rows["take"].append(t)
            rows["frame_start"].append(int(takes.frame_start[t]) + a)
            rows["frame_count"].append(b - a)
            rows["start_s"].append(float(phones.start[r]))
            rows["end_s"].append(float(phones.end[r]))
            rows["prev_phone"].append(phones.phone[seg[pos - 1]] if pos > 0 else PAU)
            rows["next_phone"].append(phones.phone[seg[pos + 1]] if pos + 1 < len(seg) else PAU)
            rows["pre"].append(previous_node)
            rows["suc"].append(-1)
            if previous_node >= 0:
                rows["suc"][previous_node] = k
            previous_node = k
    if not rows["phone"]:
        raise InputError("no training phones: the manifest's split column marks no take 'train', every phone is a pause, "
                         "or the takes have no phone timing (give each an alignment or a transcript in the manifest).")
    if phones.ipa is None or not any(rows["ipa"]):  # every training take English
        rows["ipa"] = None  # type: ignore[assignment]
    ints = ("viseme", "take", "frame_start", "frame_count", "pre", "suc")
    return Nodes(**{k: (np.array(v, np.int64) if k in ints else np.array(v) if k in ("start_s", "end_s") else v)
                    for k, v in rows.items()})  # type: ignore[arg-type]


def warp_to_samples(sequence: np.ndarray, n: int) -> np.ndarray:
    """Linear time-warp of a (c, K) sequence to n samples spanning the same duration."""
    c = len(sequence)
    if c == n:
        return sequence.astype(np.float64)
    x = np.linspace(0.0, c - 1, n)
    lo = np.floor(x).astype(int)
    hi = np.minimum(lo + 1, c - 1)
    w = (x - lo)[:, None]
    return sequence[lo] * (1 - w) + sequence[hi] * w


def dsc_features(coeffs: np.ndarray, nodes: Nodes, samples: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The per-node DSC features of Eq. 6: ``DSC(o_i, pre(o_j)) = scale_j * |x_i + y_j|^2``.

    Returns x ((N, (samples - 2) K) float32, second differences of (1 - s) warp(o_i)),
    y ((N, (samples - 2) K) float32, second differences of s pre(o_j); 0 without predecessor)
    and scale ((N,) float32, 1 / (frames between samples of pre(o_j))^3; 0 without
    predecessor), in PCA space (mm) with time in capture frames.
    """
    n = len(nodes)
    warped = np.stack([warp_to_samples(coeffs[nodes.frames(k)], samples) for k in range(n)])  # (N, S, K)
    s = np.linspace(0.0, 1.0, samples)
    d2 = np.zeros((samples - 2, samples))
    for r in range(samples - 2):
        d2[r, r : r + 3] = (1.0, -2.0, 1.0)
    x = np.einsum("rs,nsk->nrk", d2 * (1 - s), warped).reshape(n, -1)
    has_pre = nodes.pre >= 0
    pre_idx = np.where(has_pre, nodes.pre, 0)
    y = np.einsum("rs,nsk->nrk", d2 * s, warped[pre_idx]).reshape(n, -1)
    y[~has_pre] = 0.0
    step = (nodes.frame_count[pre_idx] - 1) / (samples - 1)  # frames between samples of pre(o_j)
    scale = np.where(has_pre, 1.0 / np.maximum(step, 1e-3) ** 3, 0.0)
    return x.astype(np.float32), y.astype(np.float32), scale.astype(np.float32)


def dsc_matrix(coeffs: np.ndarray, nodes: Nodes, samples: int) -> np.ndarray:
    """All-pairs DSC (Eq. 6) as schema-1 databases stored it, (N, N) float32 (float64 sums,
    rounded once): dsc[i, j] = DSC(o_i, pre(o_j)); 0 where o_j has no predecessor. Kept as the
    reference the on-demand values are tested against; N^2 memory."""
    x, y, scale = (a.astype(np.float64) for a in dsc_features(coeffs, nodes, samples))
    xx = np.einsum("ij,ij->i", x, x)
    yy = np.einsum("ij,ij->i", y, y)
    return (np.maximum(xx[:, None] + yy[None, :] + 2.0 * (x @ y.T), 0.0) * scale[None, :]).astype(np.float32)


def pair_gaps_numpy(first_pos, last_pos, first_vel, last_vel) -> tuple[np.ndarray, np.ndarray]:
    """PGap/VGap (Eq. 8-9) as schema-1 databases stored them, (N, N) float32 each, row i =
    predecessor (NumPy's pairwise sums). Kept as the reference the on-demand values are
    tested against; N^2 memory."""
    n, m3 = first_pos.shape
    pgap = np.empty((n, n), np.float32)
    vgap = np.empty((n, n), np.float32)
    fp = first_pos.reshape(n, -1, 3)
    fv = first_vel.reshape(n, -1, 3)
    block = max(1, (1 << 24) // max(n * m3, 1))
    for a in range(0, n, block):
        lp = last_pos[a : a + block].reshape(-1, 1, m3 // 3, 3)
        lv = last_vel[a : a + block].reshape(-1, 1, m3 // 3, 3)
        pgap[a : a + block] = np.sqrt(((fp[None] - lp) ** 2).sum(-1)).sum(-1)
        vgap[a : a + block] = np.sqrt(((fv[None] - lv) ** 2).sum(-1)).sum(-1)
    return pgap, vgap
