"""Removing head motion from the markers (paper III, Eq. 1-2; ``facesynth normalize``).

Short gaps are filled; every frame is rigidly aligned onto a neutral closed-mouth reference
frame (:mod:`facesynth.domain.geometry.rigid`); the per-frame rigid transform is kept, so
``captured = R_i @ normalized + t_i`` for every marker.

Where the paper translates by one marker and rotates on all of them, translation and rotation
are fitted together by weighted Procrustes on the rigid markers only (those that move with
the head, not with speech: ``normalize.rigid_markers``, else the set the corpus marks rigid,
else the largest group of markers whose mutual distances vary by at most
``normalize.rigid_max_spread_mm`` over the corpus, found from the data with each one's spread
reported), each weighted by the inverse of its residual, so neither
one noisy marker nor jaw opening leaks into the head pose. The origin marker only places the
reference: it is at 0 in the reference frame.

A corpus whose takes were all posed from curves (Live Link Face, another rig's curves:
``Corpus.posed``) carries its rest pose and the head pose of every frame exactly; unless
``normalize.known_pose`` is false or the settings name a reference, the rest pose is the
reference and the known pose is removed (``normalized = R^T (captured - t)``, no fit), and the
artifact says so (``capture = posed``), so that ``solve`` may take the markers as noise-free.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np

from facesynth.base.config import NormalizeSettings
from facesynth.base.errors import InputError
from facesynth.domain.geometry.rigid import RigidChoice, choose_rigid, fill_gaps, head_pose, typical_frame
from facesynth.model.tables import Phones, Takes


def choose_origin(reference_frames: np.ndarray, names: list[str], settings: NormalizeSettings) -> int:
    """The origin marker: the one named in the settings, else the marker nearest the markers'
    centroid in the reference frames (M, 3).
    """
    if settings.origin_marker:
        if settings.origin_marker not in names:
            raise InputError(f"normalize.origin_marker {settings.origin_marker!r} is not a marker of this corpus; pick one of {names[:6]}...")
        return names.index(settings.origin_marker)
    seen = ~np.isnan(reference_frames).any(axis=2).all(axis=0)  # markers seen in some candidate frame
    mean = np.full((reference_frames.shape[1], 3), np.nan)
    mean[seen] = np.nanmean(reference_frames[:, seen], axis=0)
    return int(np.nanargmin(np.linalg.norm(mean - mean[seen].mean(axis=0), axis=1)))


def reference_frame(markers: np.ndarray, takes: Takes, phones: Phones, fps: float,
                    settings: NormalizeSettings) -> np.ndarray:
    """Candidate frames (C, M, 3) mm for the neutral closed-mouth reference, raw capture: the named
    take's frame (a frame without a take: of the first take), else the leading silences of the neutral training takes, else (no silence is
    marked) the first take's most typical frame (:func:`~facesynth.domain.geometry.rigid.typical_frame`)."""
    if settings.reference_take or settings.reference_frame >= 0:  # a frame alone is of the first take
        if settings.reference_take and settings.reference_take not in takes.name:
            raise InputError(f"normalize.reference_take {settings.reference_take!r} is not a take of this corpus.")
        i = takes.index(settings.reference_take) if settings.reference_take else 0
        frame = settings.reference_frame if settings.reference_frame >= 0 else 0
        if frame >= takes.frame_count[i]:
            raise InputError(f"normalize.reference_frame {frame} is beyond take {takes.name[i]!r} ({takes.frame_count[i]} frames).")
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
    if not candidates:  # no neutral silence marked (e.g. a take without phone timing): the first take's most typical frame
        first = markers[takes.frames(0)]
        candidates = [first[typical_frame(first)][None]]
    return np.concatenate(candidates)


def build_reference(candidates: np.ndarray, origin: int, rigid: np.ndarray, frames: np.ndarray,
                    names: list[str]) -> np.ndarray:
    """Generalized Procrustes mean (M, 3) mm of the candidate frames (C, M, 3), fitted on the
    rigid markers, shifted so the origin marker is at 0. A marker unseen in every candidate
    (e.g. one the capture lost at the reference) takes its mean over all ``frames`` (F, M, 3)
    aligned onto the reference; one never seen at all is an error naming it."""
    with np.errstate(invalid="ignore"), warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # nanmean of a marker unseen in every candidate
        reference = candidates[0]
        if np.isnan(reference).any():
            reference = np.where(np.isnan(reference), np.nanmean(candidates, axis=0), reference)
        for _ in range(3):
            aligned, _, _, _ = head_pose(candidates, reference, rigid)
            reference = np.nanmean(aligned, axis=0)
        unseen = np.isnan(reference).any(axis=1)
        if unseen.any():
            aligned, _, _, _ = head_pose(frames, reference, rigid)
            reference[unseen] = np.nanmean(aligned[:, unseen], axis=0)
    never = np.nonzero(np.isnan(reference).any(axis=1))[0]
    if len(never):
        raise InputError(f"marker {names[never[0]]!r} is never seen in the corpus; remove it from the capture.")
    return reference - reference[origin]


def uses_known_pose(settings: NormalizeSettings, known: tuple[np.ndarray, np.ndarray, np.ndarray] | None) -> bool:
    """Whether a corpus with a known rest and head pose (``known``) is normalized with them."""
    return known is not None and settings.known_pose and not (settings.reference_take or settings.reference_frame >= 0)


@dataclass(frozen=True)
class Normalization:
    """Markers with the head motion removed (:func:`normalize`).

    normalized: (F, M, 3) float32 mm, the markers in the head frame (gaps filled where short).
    rotations, translations: (F, 3, 3) and (F, 3) mm, the head pose of every frame:
        ``captured = R_i @ normalized + t_i``.
    reference: (M, 3) mm, the neutral closed-mouth reference, the origin marker at 0.
    origin: index of the origin marker.
    long_gaps: gaps too long to fill, as (take, marker, start_s, length_s).
    rigid: the rigid markers the pose was fitted on and where they came from (source ``known``,
        with no markers, for a known pose removed as it is).
    weights: each rigid marker's weight in that fit (none for a known pose).
    known_pose: whether the corpus's known head pose was removed (no fit).
    """

    normalized: np.ndarray
    rotations: np.ndarray
    translations: np.ndarray
    reference: np.ndarray
    origin: int
    long_gaps: list[tuple[str, str, float, float]]
    rigid: RigidChoice
    weights: np.ndarray
    known_pose: bool


def normalize(markers: np.ndarray, names: list[str], takes: Takes, phones: Phones, fps: float,
              settings: NormalizeSettings, corpus_rigid=(),
              known: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None) -> Normalization:
    """Fill gaps, then remove head motion, fitted on the rigid markers (the settings', else
    ``corpus_rigid``, else found from the data), or with ``known`` (rest pose (M, 3) mm, head
    rotations (F, 3, 3), translations (F, 3) mm of a posed corpus; see :func:`uses_known_pose`)
    removed as it is."""
    filled = markers.astype(np.float64).copy()
    long_gaps = []
    for i in range(len(takes)):
        sl = takes.frames(i)
        for m in range(len(names)):
            track, runs = fill_gaps(filled[sl, m], settings.max_gap_frames)
            filled[sl, m] = track
            long_gaps += [(takes.name[i], names[m], s / fps, n / fps) for s, n in runs]
    if known is not None and uses_known_pose(settings, known):
        rest, r, t = (np.asarray(a, np.float64) for a in known)
        origin = choose_origin(rest[None], names, settings)
        shift = rest[origin]
        # captured = R posed + t and the reference is rest - shift: normalized = R^T (captured - t) - shift,
        # and captured = R normalized + (t + R shift)
        normalized = np.einsum("fji,fmj->fmi", r, filled - t[:, None, :]) - shift
        return Normalization(normalized.astype(np.float32), r, t + r @ shift, rest - shift, origin, long_gaps,
                             RigidChoice(np.zeros(0, np.int64), "known"), np.zeros(0), True)
    unknown = [n for n in settings.rigid_markers if n not in names]
    if unknown:
        raise InputError(f"normalize.rigid_markers names unknown markers {unknown}; use names from the corpus.")
    try:
        choice = choose_rigid(names, settings.rigid_markers, [n for n in corpus_rigid if n in names], filled,
                              max_spread_mm=settings.rigid_max_spread_mm, min_markers=settings.rigid_min_markers)
    except ValueError as exc:
        raise InputError(f"no rigid markers can be found from the data ({exc}); name the markers that move only "
                         f"with the head with --set normalize.rigid_markers=[...].") from None
    rigid = choice.indices
    if len(rigid) < 3:
        raise InputError(f"normalize.rigid_markers names {len(rigid)} markers; a head pose needs at least 3 that do not lie on a line.")
    candidates = reference_frame(filled, takes, phones, fps, settings)
    origin = choose_origin(candidates, names, settings)
    if np.isnan(filled[:, origin]).any():
        bad = np.nonzero(np.isnan(filled[:, origin, 0]))[0][0]
        take = next(takes.name[i] for i in range(len(takes)) if takes.frames(i).start <= bad < takes.frames(i).stop)
        raise InputError(f"take {take!r}: the origin marker {names[origin]!r} has a gap too long to fill; choose another with --set normalize.origin_marker=NAME.")
    reference = build_reference(candidates, origin, rigid, filled, names)
    normalized, rotations, translations, weights = head_pose(filled, reference, rigid)
    return Normalization(normalized.astype(np.float32), rotations, translations, reference, origin, long_gaps, choice,
                         weights, False)
