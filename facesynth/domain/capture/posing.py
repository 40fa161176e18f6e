"""From curves to markers: what the readers of takes that are not marker files return
(:class:`CaptureTake`), and the one route from ARKit weights to markers that Live Link Face
takes and another rig's curves share (:func:`pose_markers`).

A :class:`CaptureTake` is a :class:`~facesynth.formats.mocap.MarkerTake` (positions (T, M, 3)
float32 mm, NaN where missing; names; fps) with what ``ingest`` needs beyond markers: the
markers the head pose is to be fitted on (``rigid``), the audio when the take carries its own
(a video) and, for a take posed from curves, the ARKit weights, the rest pose and the known head
pose it was posed with.

Curves become markers as the virtual actress's do: the rig (the built-in ICT-FaceKit rig, or a
user's rig with a marker binding) is posed by the weights (``neutral + sum_e w_e deltas_e``)
and its bound vertices are recorded; on the built-in rig these are the actress's 91 markers
(:func:`facesynth.domain.rig.markers.build_marker_set`), eight of them rigid, so every stage and
method after ``ingest`` works unchanged. A head rotation turns every marker about
:data:`HEAD_PIVOT_MM`, the centre the sample corpus turns the actress's head about.

Such markers carry no measurement noise: ``markers = R (rest + D w) + t`` exactly, with the rest
pose (every weight 0) and the head pose (R, t) known. ``ingest`` records both in the corpus
(``rest_pose``, ``known_head_rotation``, ``known_head_translation``) so that ``normalize``
need not estimate them (a pose fitted on the rigid markers is off by up to a degree, since the
brows move the forehead markers by up to 1.7 mm) and ``solve`` can measure the weights from the
rig's own neutral (see ``solve.posed_captures``).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from facesynth.base.errors import InputError
from facesynth.domain.rig.face import Rig, load_face_rig
from facesynth.domain.rig.loading import arkit_to_rig, builtin_rig
from facesynth.domain.rig.markers import build_marker_set
from facesynth.domain.rig.neutral import NeutralChoice, calibrated_weights, chosen_frames, neutral_weights, quietness
from facesynth.formats.mocap import MarkerTake

#: The point (mm, the rig's head frame: +y up, +z out of the face) a head rotation turns the
#: markers about: the centre behind the face the sample corpus turns the actress's head about
#: (:mod:`facesynth.domain.corpus.generate`). It changes only the head translation
#: ``normalize`` reports, not the normalized markers.
HEAD_PIVOT_MM = (0.0, 0.0, -60.0)


@dataclass
class CaptureTake(MarkerTake):
    """A take read from something other than a marker file (see the module docstring).

    positions : (T, M, 3) float32 mm, NaN in gaps. names : M marker names. fps : frames/s.
    rigid : the markers that move only with the head (recorded as the corpus's rigid set).
    audio : (samples (S,) float32 mono in [-1, 1], rate Hz) when the take carries its own sound
        (a video), else None.
    arkit : (T, 52) float64 ARKit weights in [0, 1] the markers were posed with (NaN in gaps),
        in :attr:`facesynth.domain.rig.face.Rig.arkit_names` order, or None (a video).
    rest : (M, 3) float32 mm, the markers at rest (every weight 0, no head motion) of a take
        posed from curves, or None.
    head_pose : for a take posed from curves, its head pose ((T, 3, 3) rotations R, (T, 3)
        translations t mm; identity and 0 without head motion) with ``positions = R @ x + t``
        for the posed, unmoved markers x; None for a video.
    source : what was read ('live-link-face', 'curves', 'video').
    notes : what the reader assumed or repaired, one sentence each (logged as warnings).
    """

    rigid: list[str] = field(default_factory=list)
    audio: tuple[np.ndarray, int] | None = None
    arkit: np.ndarray | None = None
    rest: np.ndarray | None = None
    head_pose: tuple[np.ndarray, np.ndarray] | None = None
    source: str = ""
    notes: list[str] = field(default_factory=list)


def capture_rig(rig: Rig | None) -> tuple[Rig, list[str], np.ndarray, list[str]]:
    """(rig, marker names, marker vertices, rigid marker names): the rig whose surface is recorded.

    ``rig`` None: the built-in rig bound to the virtual actress's markers, with her eight rigid
    markers. A user's rig (or the built-in one with a user's binding): its bound vertices in the
    binding's order, no rigid set (``normalize`` uses the known head pose). A user's rig is taken
    to be in millimetres, the unit of every capture."""
    if rig is None:
        markers = build_marker_set(load_face_rig())
        rigid = [n for n, r in zip(markers.names, markers.rigid) if r]
        return builtin_rig(markers.binding()), list(markers.names), markers.vertices.copy(), rigid
    if not rig.binding:
        raise InputError(f"rig {rig.name!r} has no marker binding; give --binding, a CSV of marker,vertex placing the "
                         "markers to record on it.")
    names = list(rig.binding)
    return rig, names, np.array([rig.binding[n] for n in names], np.int64), []


def known_pose(head: np.ndarray | None, frames: int) -> tuple[np.ndarray, np.ndarray]:
    """((T, 3, 3) R, (T, 3) t mm) of the rotations ``head`` (T, 3, 3) about :data:`HEAD_PIVOT_MM`
    (identity when None): ``x -> R (x - pivot) + pivot = R x + t``."""
    r = np.broadcast_to(np.eye(3), (frames, 3, 3)).copy() if head is None else np.asarray(head, np.float64)
    centre = np.asarray(HEAD_PIVOT_MM, np.float64)
    return r, centre - r @ centre


def pose_markers(arkit: np.ndarray, rig: Rig | None = None, head: np.ndarray | None = None
                 ) -> tuple[np.ndarray, list[str], list[str], np.ndarray]:
    """Markers of a rig posed by ARKit weights.

    arkit : (T, 52) weights in [0, 1] in ARKit (Live Link Face) order; a row with a NaN is a gap
    (its markers NaN). rig : None for the built-in rig and the actress's markers, else a bound
    rig (a user's rig's shapes are matched to ARKit by name, :func:`~facesynth.domain.rig.loading.arkit_to_rig`).
    head : optional (T, 3, 3) rotations about :data:`HEAD_PIVOT_MM`.
    Returns (positions (T, M, 3) float32 in rig units (mm for the built-in rig), marker names,
    rigid marker names, the rest pose (M, 3) float32: the markers at weights 0, no head motion)."""
    rig, names, vertices, rigid = capture_rig(rig)
    _, matrix = arkit_to_rig(rig, rig.name)
    arkit = np.asarray(arkit, np.float64)
    gap = np.isnan(arkit).any(axis=1)
    positions = rig.evaluate(np.where(gap[:, None], 0.0, arkit) @ matrix, vertices=vertices)  # (T, M, 3)
    if head is not None:
        r, t = known_pose(head, len(arkit))
        positions = np.einsum("tij,tmj->tmi", r, positions) + t[:, None, :]
    positions[gap] = np.nan
    return positions.astype(np.float32), names, rigid, rig.neutral[vertices].astype(np.float32)


def calibrated_arkit(arkit: np.ndarray, fps: float, neutral: NeutralChoice | None, where: str) -> np.ndarray:
    """ARKit weights (T, 52) with the performer's neutral taken off (:mod:`.neutral`): the
    neutral frames are found from the weights themselves (their speed and ``jawOpen`` for
    ``auto``); ``None`` or ``off`` (and ``take``, which only ``solve`` offers) leave them as they
    are."""
    if neutral is None or neutral.kind in ("off", "take") or not len(arkit):
        return arkit
    jaw = list(load_face_rig().arkit_names).index("jawOpen")
    score = quietness(arkit[:, :, None], fps, arkit[:, jaw])
    frames = chosen_frames(neutral, score, fps, where)
    if frames is None:
        return arkit
    return calibrated_weights(arkit, neutral_weights(arkit, frames))


def posed_take(arkit: np.ndarray, fps: float, rig: Rig | None, head: np.ndarray | None, source: str,
               notes: list[str], neutral: NeutralChoice | None = None, where: str = "the take") -> CaptureTake:
    """The :class:`CaptureTake` of a rig posed by ARKit weights (T, 52) at ``fps`` with optional
    head rotations (T, 3, 3) (see :func:`pose_markers`), the performer's ``neutral`` taken off
    first (:func:`calibrated_arkit`; ``where`` names the take in errors)."""
    arkit = calibrated_arkit(np.asarray(arkit, np.float64), fps, neutral, where)
    positions, names, rigid, rest = pose_markers(arkit, rig, head)
    return CaptureTake(positions, names, float(fps), rigid=rigid, arkit=np.asarray(arkit, np.float64), rest=rest,
                       head_pose=known_pose(head, len(arkit)), source=source, notes=list(notes))
