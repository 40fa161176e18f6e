"""``facesynth normalize``: remove head motion from the markers (paper III, Eq. 1-2).

Short gaps are filled; every frame is rigidly aligned onto a neutral closed-mouth reference
frame (:mod:`facesynth.motion.rigid`); the per-frame rigid transform is kept, so
``captured = R_i @ normalized + t_i`` for every marker.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..config import NormalizeSettings, settings_json
from ..errors import InputError
from ..model.corpus import Corpus
from ..model.frames import HeadFrames, NormalizedFrames
from ..model.tables import Phones, Takes
from ..motion.rigid import fill_gaps, rigid_align


def choose_origin(reference_frames: np.ndarray, names: list[str], settings: NormalizeSettings) -> int:
    """The origin marker: the one named in the settings, else the marker nearest the markers'
    centroid in the reference frames (M, 3).
    """
    if settings.origin_marker:
        if settings.origin_marker not in names:
            raise InputError(f"normalize.origin_marker {settings.origin_marker!r} is not a marker of this corpus; pick one of {names[:6]}...")
        return names.index(settings.origin_marker)
    mean = np.nanmean(reference_frames, axis=0)
    return int(np.nanargmin(np.linalg.norm(mean - np.nanmean(mean, axis=0), axis=1)))


def reference_frame(markers: np.ndarray, takes: Takes, phones: Phones, fps: float,
                    settings: NormalizeSettings) -> np.ndarray:
    """Candidate frames for the neutral closed-mouth reference (M,3) positions, raw capture."""
    if settings.reference_take:
        if settings.reference_take not in takes.name:
            raise InputError(f"normalize.reference_take {settings.reference_take!r} is not a take of this corpus.")
        i = takes.index(settings.reference_take)
        frame = settings.reference_frame if settings.reference_frame >= 0 else 0
        if frame >= takes.frame_count[i]:
            raise InputError(f"normalize.reference_frame {frame} is beyond take {settings.reference_take!r} ({takes.frame_count[i]} frames).")
        return markers[takes.frame_start[i] + frame][None]
    candidates = []
    for i in range(len(takes)):
        if takes.emotion[i] != "neutral" or takes.split[i] != "train":
            continue
        rows = np.nonzero(phones.take == i)[0]
        if len(rows) == 0 or phones.phone[rows[0]] != "pau":
            continue
        n = int(min(phones.end[rows[0]], settings.reference_silence_s) * fps)
        candidates.append(markers[takes.frames(i)][: max(n, 1)])
    if not candidates:  # no neutral silence: the first frame of the first take
        candidates = [markers[takes.frames(0)][:1]]
    return np.concatenate(candidates)


def build_reference(candidates: np.ndarray, origin: int, rigid: np.ndarray) -> np.ndarray:
    """Generalized Procrustes mean of the candidate frames (origin marker at 0)."""
    reference = candidates[0] - candidates[0, origin]
    if np.isnan(reference).any():
        reference = np.where(np.isnan(reference), np.nanmean(candidates - candidates[:, origin : origin + 1], axis=0), reference)
    for _ in range(3):
        aligned, _, _ = rigid_align(candidates, reference, origin, rigid)
        reference = np.nanmean(aligned, axis=0)
    return reference


def normalize(markers: np.ndarray, names: list[str], takes: Takes, phones: Phones, fps: float,
              settings: NormalizeSettings):
    """Fill gaps, then remove head motion. Returns (normalized, rotations, translations,
    reference, origin index, list of unfilled gaps (take, marker, start_s, length_s))."""
    filled = markers.astype(np.float64).copy()
    long_gaps = []
    for i in range(len(takes)):
        sl = takes.frames(i)
        for m in range(len(names)):
            track, runs = fill_gaps(filled[sl, m], settings.max_gap_frames)
            filled[sl, m] = track
            long_gaps += [(takes.name[i], names[m], s / fps, n / fps) for s, n in runs]
    if settings.rigid_markers:
        unknown = [n for n in settings.rigid_markers if n not in names]
        if unknown:
            raise InputError(f"normalize.rigid_markers names unknown markers {unknown}; use names from the corpus.")
        rigid = np.array([names.index(n) for n in settings.rigid_markers])
    else:
        rigid = np.arange(len(names))
    candidates = reference_frame(filled, takes, phones, fps, settings)
    origin = choose_origin(candidates, names, settings)
    if np.isnan(filled[:, origin]).any():
        bad = np.nonzero(np.isnan(filled[:, origin, 0]))[0][0]
        take = next(takes.name[i] for i in range(len(takes)) if takes.frames(i).start <= bad < takes.frames(i).stop)
        raise InputError(f"take {take!r}: the origin marker {names[origin]!r} has a gap too long to fill; choose another with --set normalize.origin_marker=NAME.")
    reference = build_reference(candidates, origin, rigid)
    normalized, rotations, translations = rigid_align(filled, reference, origin, rigid)
    return normalized.astype(np.float32), rotations, translations, reference, origin, long_gaps


def run(corpus_path: Path, out: Path, settings: NormalizeSettings, overwrite: bool = False) -> dict:
    """Normalize ``corpus_path`` and write ``out`` (a ``normalized`` artifact); returns a summary."""
    corpus = Corpus.read(corpus_path, audio=False)
    names = corpus.marker_names
    normalized, rotations, translations, reference, origin, long_gaps = normalize(
        corpus.markers, names, corpus.takes, corpus.phones, corpus.fps, settings)
    frames = HeadFrames(normalized, reference.astype(np.float32), rotations.astype(np.float32),
                        translations.astype(np.float32), corpus.fps, names[origin])
    NormalizedFrames(corpus.takes, corpus.phones, names, frames).write(
        out, config=settings_json(settings), inputs=[corpus_path], overwrite=overwrite)
    return {"frames": len(normalized), "origin_marker": names[origin], "long_gaps": long_gaps}
