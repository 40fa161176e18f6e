"""One view of every exportable artifact: marker motion, mesh animation or rig curves, with
what each carries (markers, a mesh, rig weights, head motion, gaze, emotion, where each frame
came from) and what it does not, so a format that needs something missing can say what to run
first."""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np

from facesynth.base.errors import InputError
from facesynth.domain.rig.face import BUILTIN_RIG_NAME, Rig, builtin_rig_sha256, gaze_from_rig_weights, load_face_rig
from facesynth.formats.mesh import read_mesh
from facesynth.model.artifacts import PRODUCERS, artifact_kind
from facesynth.model.curves import RigCurves
from facesynth.model.meshanim import MeshAnimation
from facesynth.model.motion import Motion
from facesynth.model.provenance import FrameProvenance, PhoneSegment

#: Artifact kinds ``facesynth export`` and ``facesynth player`` read.
EXPORTABLE = ("motion", "meshanim", "curves")


#: One phone of a synthesized utterance, for the player's timeline (the provenance's segments).
Phone = PhoneSegment


@dataclass
class Exportable:
    """An animation ready to write, at ``fps`` frames/s over ``n_frames`` frames.

    kind : the artifact kind it came from ('motion', 'meshanim' or 'curves'); path : its file.
    markers : (T, M, 3) float32 mm in the head frame, marker_names : M names (motion, meshanim).
    rest : (V, 3) float64 mm and faces : (F, 3) int64, the mesh (meshanim, curves).
    vertices : (T, V, 3) float32 mm, the animated mesh without head motion for curves (evaluated
        on demand, :meth:`mesh_frames`), as stored for meshanim (which holds head motion only
        where ``deform`` put it into the vertices).
    weights : (T, E) float32 rig weights in [0, 1] and rig : the built-in rig (curves).
    head_rotation : (T, 3, 3), head_translation : (T, 3) mm, ``x -> R @ x + t`` (motion, curves).
    gaze : (T, 2, 2) radians, per eye (+x eye first) yaw toward +x and pitch up; None if unknown.
    emotion : T per-frame emotion names or None; phones : the synthesized utterance's phones.
    provenance : where each frame came from (phone, emotion, node, take), or None.
    """

    kind: str
    path: Path
    fps: float
    n_frames: int
    markers: np.ndarray | None = None
    marker_names: list[str] | None = None
    rest: np.ndarray | None = None
    faces: np.ndarray | None = None
    vertices: np.ndarray | None = None
    weights: np.ndarray | None = None
    rig: Rig | None = None
    head_rotation: np.ndarray | None = None
    head_translation: np.ndarray | None = None
    gaze: np.ndarray | None = None
    emotion: list[str] | None = None
    phones: list[Phone] = field(default_factory=list)
    provenance: FrameProvenance | None = None

    @property
    def duration_s(self) -> float:
        """Length in seconds: ``n_frames / fps`` (frame i covers [i/fps, (i+1)/fps))."""
        return self.n_frames / self.fps

    @property
    def times(self) -> np.ndarray:
        """(T,) float64 s, the time of each frame (frame i at i/fps)."""
        return np.arange(self.n_frames, dtype=np.float64) / self.fps

    @property
    def has_mesh(self) -> bool:
        return self.rest is not None

    # What a format writes, for after ExportFormat.check has refused an animation without it:
    # each names what is missing and what to run, should a caller skip that check.

    def mesh(self) -> tuple[np.ndarray, np.ndarray]:
        """(rest (V, 3) mm, faces (F, 3)) of a mesh animation or curves."""
        if self.rest is None or self.faces is None:
            raise InputError(f"{self.path}: marker motion has no mesh; run `facesynth deform` (or `facesynth solve`) first.")
        return self.rest, self.faces

    def rig_weights(self) -> tuple[Rig, np.ndarray]:
        """(the rig, its weights (T, E)) of curves."""
        if self.rig is None or self.weights is None:
            raise InputError(f"{self.path}: {self.kind} has no rig blendshape weights; run `facesynth solve` on the "
                             "motion and export its curves.")
        return self.rig, self.weights

    def marker_motion(self) -> tuple[np.ndarray, list[str]]:
        """(markers (T, M, 3) mm, their names) of marker motion or a mesh animation."""
        if self.markers is None or self.marker_names is None:
            raise InputError(f"{self.path}: rig curves have no markers; export the motion the curves were solved from.")
        return self.markers, self.marker_names

    def head(self) -> tuple[np.ndarray, np.ndarray]:
        """(rotations (T, 3, 3), translations (T, 3) mm) of the head motion."""
        if self.head_rotation is None or self.head_translation is None:
            raise InputError(f"{self.path}: the {self.kind} has no head motion; export without --head-motion.")
        return self.head_rotation, self.head_translation

    def mesh_frames(self, start: int = 0, stop: int | None = None) -> np.ndarray:
        """(n, V, 3) float32 mm, frames ``start:stop`` of the animated mesh (head motion not applied)."""
        stop = self.n_frames if stop is None else stop
        if self.vertices is not None:
            return np.asarray(self.vertices[start:stop], np.float32)
        if self.weights is not None:
            rig, weights = self.rig_weights()
            return rig.evaluate(weights[start:stop]).astype(np.float32)
        raise InputError(f"{self.path}: marker motion has no mesh; run `facesynth deform` (or `facesynth solve`) first.")

    def with_head(self, points: np.ndarray, start: int = 0) -> np.ndarray:
        """``points`` (n, P, 3) mm of frames ``start:start+n`` with the head motion applied."""
        n = len(points)
        rotation, translation = self.head()
        r = rotation[start:start + n].astype(np.float64)
        t = translation[start:start + n].astype(np.float64)
        return (np.einsum("tij,tpj->tpi", r, points) + t[:, None, :]).astype(np.float32)

    def resampled(self, fps: float) -> "Exportable":
        """This animation at ``fps`` frames/s over the same duration: weights, vertices, markers
        and gaze interpolated linearly, head rotations by spherical interpolation, emotion by the
        nearest earlier frame, the provenance by the nearest frame. Returns self when the rate is unchanged."""
        if abs(fps - self.fps) < 1e-9 * self.fps:
            return self
        n = max(1, int(np.floor(self.duration_s * fps + 1e-6)))
        t_out = np.arange(n) / fps
        src = np.clip(t_out * self.fps, 0, self.n_frames - 1)
        lo = np.floor(src).astype(int)
        hi = np.minimum(lo + 1, self.n_frames - 1)
        a = (src - lo).astype(np.float32)

        def lerp(x):
            if x is None:
                return None
            x = np.asarray(x)
            shape = (-1,) + (1,) * (x.ndim - 1)
            return ((1 - a).reshape(shape) * x[lo] + a.reshape(shape) * x[hi]).astype(x.dtype)

        rotation = None
        if self.head_rotation is not None:
            from scipy.spatial.transform import Rotation, Slerp

            if self.n_frames > 1:
                slerp = Slerp(self.times, Rotation.from_matrix(self.head_rotation.astype(np.float64)))
                rotation = slerp(np.clip(t_out, 0, self.times[-1])).as_matrix().astype(np.float32)
            else:
                rotation = np.repeat(self.head_rotation[:1], n, axis=0)
        return replace(self, fps=float(fps), n_frames=n, markers=lerp(self.markers), vertices=lerp(self.vertices),
                       weights=lerp(self.weights), head_rotation=rotation, head_translation=lerp(self.head_translation),
                       gaze=lerp(self.gaze), emotion=None if self.emotion is None else [self.emotion[i] for i in lo],
                       provenance=None if self.provenance is None else self.provenance.resampled(n, self.fps, fps))


def _labelled(out: Exportable, provenance: FrameProvenance | None) -> Exportable:
    """``out`` with ``provenance`` (made at ``out``'s rate or resampled to it): the phones of its
    timeline and, where the artifact has none of its own, the per-frame emotion."""
    if provenance is None:
        return out
    out.provenance = provenance.fitted(out.n_frames)
    out.phones = list(provenance.segments)
    if out.emotion is None and provenance.segments:
        out.emotion = list(out.provenance.emotion)
    return out


def load(path: Path, motion: Path | None = None) -> Exportable:
    """The artifact at ``path`` as an :class:`Exportable`. ``motion`` : optional synthesized
    motion whose phones, emotion and provenance label a mesh animation or curves made from it."""
    path = Path(path)
    kind = artifact_kind(path)
    if kind is None and not path.exists():
        raise InputError(f"{path}: file not found; pass a motion, mesh animation or curves artifact.")
    if kind not in EXPORTABLE:
        found = f"a '{kind}' artifact" if kind else "no facesynth artifact"
        raise InputError(f"{path}: is {found}; export reads a 'motion', 'meshanim' or 'curves' "
                         "artifact (the output of facesynth synthesize, deform or solve, among others).")
    artifact: Motion | MeshAnimation | RigCurves
    if kind == "motion":
        artifact = Motion.read(path, search=True)
    elif kind == "meshanim":
        artifact = MeshAnimation.read(path)
    else:
        artifact = RigCurves.read(path)
    if kind == "motion" or motion is None:
        return of_artifact(artifact, path)
    out = _exportable(artifact, path)
    if artifact_kind(Path(motion)) != "motion":
        raise InputError(f"{motion}: is not a motion artifact; pass the output of {PRODUCERS['motion']}.")
    m = Motion.read(Path(motion))
    given = m.frame_provenance(Path(motion))
    return _labelled(out, None if given is None else given.resampled(out.n_frames, m.fps, out.fps))


def of_artifact(artifact: Motion | MeshAnimation | RigCurves, path: Path) -> Exportable:
    """A motion, mesh animation or rig curves (read from ``path``, or made in memory: then
    ``path`` only names it in messages) as an :class:`Exportable`, labelled with where its frames
    came from (a motion's from the search path and provenance it holds). Curves must drive the
    built-in rig."""
    out = _exportable(artifact, Path(path))
    return _labelled(out, artifact.frame_provenance() if isinstance(artifact, Motion) else out.provenance)


def _exportable(artifact: Motion | MeshAnimation | RigCurves, path: Path) -> Exportable:
    """:func:`of_artifact` before the labels."""
    if isinstance(artifact, Motion):
        m = artifact
        return Exportable("motion", path, m.fps, len(m.markers), markers=m.markers, marker_names=list(m.marker_names),
                          head_rotation=m.head_rotation, head_translation=m.head_translation)
    if isinstance(artifact, MeshAnimation):
        a = artifact
        if a.vertices.shape[1] != len(a.rest):
            raise InputError(f"{path}: /vertices moves {a.vertices.shape[1]} vertices but /rest has {len(a.rest)}; "
                             "make the mesh animation again with `facesynth deform`.")
        return Exportable("meshanim", path, a.fps, len(a.vertices), markers=a.markers, marker_names=list(a.marker_names),
                          rest=a.rest.astype(np.float64), faces=a.faces.astype(np.int64), vertices=a.vertices,
                          gaze=a.gaze, provenance=a.provenance)
    if isinstance(artifact, RigCurves):
        c = artifact
        if c.rig_name != BUILTIN_RIG_NAME or c.rig_sha256 != builtin_rig_sha256():
            raise InputError(f"{path}: the curves drive the rig '{c.rig_name}', not the built-in {BUILTIN_RIG_NAME} rig "
                             "this version exports; solve the motion again on the built-in rig (`facesynth solve`).")
        return from_curves(c, load_face_rig(), path)
    raise TypeError(f"{path}: a {type(artifact).__name__} is not an animation; give a Motion, MeshAnimation or "
                    "RigCurves")


def from_curves(c: RigCurves, rig: Rig, path: Path) -> Exportable:
    """Rig curves ``c`` (read from, or to be written at, ``path``) on ``rig`` as an
    :class:`Exportable`: the rig's neutral mesh and faces, the weights (T, E) in the rig's shape
    order, the head motion, the gaze from the rig's ``eyeLook*`` shapes, emotion and provenance
    (the phones of the timeline are added by :func:`load`). Curves lacking one of the rig's
    shapes are refused."""
    if list(c.shape_names) != list(rig.shape_names):
        index = {n: i for i, n in enumerate(c.shape_names)}
        missing = [n for n in rig.shape_names if n not in index]
        if missing:
            raise InputError(f"{path}: /shape_names lacks the rig's shape '{missing[0]}'; "
                             "write the curves again with `facesynth solve`.")
        weights = c.weights[:, [index[n] for n in rig.shape_names]]
    else:
        weights = c.weights
    return Exportable("curves", Path(path), c.fps, c.n_frames, rest=rig.neutral, faces=rig.faces, weights=weights,
                      rig=rig, head_rotation=c.head_rotation, head_translation=c.head_translation,
                      gaze=gaze_from_rig_weights(weights, rig.shape_names), emotion=c.emotion, provenance=c.provenance)


def use_mesh(anim: Exportable, mesh: Path) -> Exportable:
    """``anim`` with the faces of the mesh file ``mesh`` (e.g. one with the same vertices in another
    tool's layout); its vertex count must match the animation's."""
    vertices, faces = read_mesh(Path(mesh))
    if anim.rest is None:  # not anim.has_mesh
        raise InputError(f"{anim.path}: marker motion has no mesh to replace; run `facesynth deform` with {mesh} first.")
    if len(vertices) != len(anim.rest):
        raise InputError(f"{mesh}: has {len(vertices)} vertices but the animation in {anim.path} moves "
                         f"{len(anim.rest)}; pass the mesh the animation was made on.")
    return replace(anim, faces=np.asarray(faces, np.int64))
