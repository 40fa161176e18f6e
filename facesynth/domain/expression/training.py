"""Fitting the expression model (Chuang & Bregler 2005, §3) on marker motion: the takes of each
sentence in every emotion are time-warped phone by phone onto one timeline (the neutral take's
when there is one; pauses placed differently are warped over), so that frame c is the same
speech in every emotion; the aligned frames are projected on their PCA (Eq. 1) and factored by
Eq. 4-6 (:mod:`.bilinear`).
"""

from __future__ import annotations

import numpy as np

from facesynth.base.config import ExpressionSettings
from facesynth.base.errors import InputError
from facesynth.base.phonemes import PAU
from facesynth.model.frames import NormalizedFrames

from . import bilinear


def aligned_data(norm: NormalizedFrames, splits, frame_step: int) -> tuple[np.ndarray, list[str], list[str], list[str]]:
    """Every sentence's takes warped onto one timeline.

    Returns X (S, C, M, 3) mm (style, aligned frame), the S emotions, the sentences used and
    notes on the sentences skipped (not in every emotion, or different spoken phones).
    """
    blocks, emotions, used, notes = aligned_blocks(norm, splits, frame_step)
    return np.concatenate(blocks, axis=1), emotions, used, notes


def aligned_blocks(norm: NormalizedFrames, splits, frame_step: int
                   ) -> tuple[list[np.ndarray], list[str], list[str], list[str]]:
    """As :func:`aligned_data`, one (S, n, M, 3) block per sentence used."""
    takes, phones, fr = norm.takes, norm.phones, norm.frames
    use = [i for i in range(len(takes)) if takes.split[i] in splits]
    if not use:
        raise InputError(f"no takes in the splits {', '.join(splits)}; set expression.splits to splits the corpus has.")
    emotions = sorted({takes.emotion[i] for i in use}, key=lambda e: (e != "neutral", e))
    by_sentence: dict[str, dict[str, int]] = {}
    for i in use:
        by_sentence.setdefault(takes.sentence[i], {})[takes.emotion[i]] = i
    spoken = np.array([p != PAU for p in phones.phone])
    rows_of = {i: np.nonzero((phones.take == i) & spoken)[0] for i in use}
    blocks, used, notes = [], [], []
    for sentence, takes_of in sorted(by_sentence.items()):
        missing = [e for e in emotions if e not in takes_of]
        if missing:
            notes.append(f"sentence {sentence}: no take in {', '.join(missing)}")
            continue
        seqs = {e: [phones.phone[r] for r in rows_of[takes_of[e]]] for e in emotions}
        ref = takes_of[emotions[0]]
        if any(seqs[e] != seqs[emotions[0]] for e in emotions):
            notes.append(f"sentence {sentence}: the spoken phones differ between emotions")
            continue
        rr = rows_of[ref]
        t0, t1 = float(phones.start[rr[0]]), float(phones.end[rr[-1]])
        times = np.arange(int(np.ceil(t0 * fr.fps)), int(np.floor(t1 * fr.fps)), frame_step) / fr.fps
        warped = []
        for e in emotions:
            i = takes_of[e]
            r = rows_of[i]
            warped.append(bilinear.warp_take(fr.loaded_markers()[takes.frames(i)], fr.fps, (phones.start[r], phones.end[r]),
                                             (phones.start[rr], phones.end[rr]), times))
        block = np.stack(warped)                                   # (S, n, M, 3)
        ok = np.isfinite(block).all(axis=(0, 2, 3))
        blocks.append(block[:, ok])
        used.append(sentence)
    if not blocks:
        raise InputError("no sentence has takes in every emotion with the same phones ("
                         + "; ".join(notes[:3]) + "); the bilinear fit needs the same sentences in each emotion.")
    return blocks, emotions, used, notes


def fit_model(X: np.ndarray, emotions: list[str], settings: ExpressionSettings) -> bilinear.BilinearModel:
    """PCA of the aligned frames (Eq. 1), then the bilinear fit (Eq. 4-6). X : (S, C, M, 3) mm."""
    S, C = X.shape[:2]
    flat = X.reshape(S * C, -1).astype(np.float64)
    mean = flat.mean(axis=0)
    centred = flat - mean
    values, vectors = np.linalg.eigh(centred.T @ centred)    # the PCA of Eq. 1 from the (3M, 3M) scatter
    basis = vectors[:, ::-1][:, :min(settings.components, len(values))].T
    Y = ((flat - mean) @ basis.T).reshape(S, C, -1)
    return bilinear.fit(Y, emotions, mean, basis, content_dim=settings.content_dim,
                        max_iterations=settings.max_iterations, tolerance=settings.tolerance)
