"""``facesynth normalize``: remove head motion from the markers (paper III, Eq. 1-2).

Short gaps are filled; every frame is translated so the origin marker is at 0 and rotated
onto a neutral closed-mouth reference frame ``y`` by SVD: ``y^T x_i = U D V^T``,
``R = V U^T`` (a reflection is turned into the nearest rotation). The per-frame rigid
transform is kept, so ``captured = R_i @ normalized + t_i`` for every marker.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from scipy.interpolate import CubicSpline

from ..artifacts import open_artifact, read, read_strings, write_artifact
from ..config import NormalizeSettings, settings_json
from ..errors import InputError
from ..tables import Phones, Takes, copy_tables


def fill_gaps(track: np.ndarray, max_gap: int) -> tuple[np.ndarray, list[tuple[int, int]]]:
    """Fill NaN runs of at most ``max_gap`` frames in one marker's (T, 3) track.

    Interior runs are filled by a cubic spline through the valid samples within
    ``max_gap`` frames on either side (what capture software calls a spline fill), runs at
    the ends by holding the nearest sample. Returns the filled track and the (start, length)
    of runs left unfilled.
    """
    missing = np.isnan(track).any(axis=1)
    if not missing.any():
        return track, []
    valid = np.nonzero(~missing)[0]
    if len(valid) == 0:
        return track, [(0, len(track))]
    out = track.copy()
    long_runs = []
    edges = np.diff(np.concatenate([[0], missing.astype(np.int8), [0]]))
    starts, ends = np.nonzero(edges == 1)[0], np.nonzero(edges == -1)[0]
    for s, e in zip(starts, ends):
        if e - s > max_gap:
            long_runs.append((int(s), int(e - s)))
            continue
        if s == 0 or e == len(track):
            out[s:e] = track[valid[0]] if s == 0 else track[valid[-1]]
            continue
        near = valid[(valid >= s - max_gap) & (valid < e + max_gap)]
        frames = np.arange(s, e)
        if len(near) >= 4:
            out[s:e] = CubicSpline(near, track[near], axis=0)(frames)
        else:
            out[s:e] = np.stack([np.interp(frames, near, track[near, a]) for a in range(3)], 1)
    return out, long_runs


def rigid_align(frames: np.ndarray, reference: np.ndarray, origin: int, rigid: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Align each frame to the reference with Eq. 1-2.

    frames : (T, M, 3) mm; reference : (M, 3) mm with the origin marker at 0;
    origin : index of the origin marker; rigid : indices of the markers used for the SVD.
    Returns normalized (T, M, 3), rotations (T, 3, 3) and translations (T, 3) with
    ``frames[t, m] = rotations[t] @ normalized[t, m] + translations[t]``.
    """
    translations = frames[:, origin, :].copy()
    x = frames - translations[:, None, :]
    xs, ys = x[:, rigid, :], reference[rigid]
    visible = ~np.isnan(xs).any(axis=2)  # (T, K): only markers seen in this frame
    xs0 = np.where(visible[:, :, None], xs, 0.0)
    h = np.einsum("kj,tki->tji", ys, xs0)  # y^T x_i, (T, 3, 3)
    u, _, vt = np.linalg.svd(h)
    v = np.swapaxes(vt, 1, 2)
    r = v @ np.swapaxes(u, 1, 2)  # R = V U^T, maps x_i onto y: x_i R ~ y
    flip = np.linalg.det(r) < 0
    if flip.any():  # nearest proper rotation: flip the axis of the smallest singular value
        v[flip, :, 2] *= -1
        r[flip] = v[flip] @ np.swapaxes(u[flip], 1, 2)
    normalized = np.einsum("tmi,tij->tmj", x, r)  # rows: x_i R, so as columns x = R @ normalized
    return normalized, r, translations


def choose_origin(reference_frames: np.ndarray, names: list[str], settings: NormalizeSettings) -> int:
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


def run(corpus: Path, out: Path, settings: NormalizeSettings, overwrite: bool = False) -> dict:
    with open_artifact(corpus, "corpus") as f:
        markers = read(f, "markers")
        fps = float(f["markers"].attrs["fps"])
        names = read_strings(f, "marker_names")
        takes, phones = Takes.read(f), Phones.read(f)
        normalized, rotations, translations, reference, origin, long_gaps = normalize(markers, names, takes, phones, fps, settings)
        with write_artifact(out, "normalized", config=settings_json(settings), inputs=[corpus], overwrite=overwrite) as g:
            copy_tables(f, g)
            d = g.create_dataset("markers", data=normalized, chunks=(min(len(normalized), 1024), len(names), 3))
            d.attrs["units"] = "mm"
            d.attrs["fps"] = fps
            d.attrs["origin_marker"] = names[origin]
            r = g.create_dataset("head_rotation", data=rotations.astype(np.float32))
            r.attrs["fps"] = fps
            r.attrs["convention"] = "captured = head_rotation @ normalized + head_translation"
            t = g.create_dataset("head_translation", data=translations.astype(np.float32))
            t.attrs["units"] = "mm"
            t.attrs["fps"] = fps
            ref = g.create_dataset("reference", data=reference.astype(np.float32))
            ref.attrs["units"] = "mm"
    return {"frames": len(normalized), "origin_marker": names[origin], "long_gaps": long_gaps}
