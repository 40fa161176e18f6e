"""``facesynth retarget``: marker motion onto a rig through key-shapes and keymorphs (Chuang &
Bregler 2005 Eq. 8-9, :mod:`facesynth.domain.retarget.retarget`), written as ``curves``
(``source = "retarget"``), and optionally the mesh animation blended from the keymorph meshes,
linearly or by deformation gradients (Huang et al. §3, :mod:`facesynth.domain.retarget.gradients`).

Keymorphs: an artist's (``--keymorphs``: a folder of ``<keyshape>.obj`` or a CSV of rig weights),
else those stored in the key-shapes artifact when it was fitted on this rig, else fitted here on
the rig by bounded least squares at its marker vertices. OBJ keymorphs give the curves the rig
weights that best reproduce each keymorph mesh over all its vertices.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy import sparse

from facesynth.base.config import KeyshapesSettings, RetargetSettings, settings_json
from facesynth.base.errors import InputError
from facesynth.domain.retarget.gradients import GradientBlender
from facesynth.domain.retarget.retarget import decompose
from facesynth.domain.retarget.solve import fit_rig_weights
from facesynth.domain.rig.face import Rig
from facesynth.domain.rig.loading import load_rig, marker_map, read_keymorphs
from facesynth.model.artifacts import check_output, published_together
from facesynth.model.curves import RigCurves
from facesynth.model.keyshapes import KeyShapes
from facesynth.model.meshanim import MeshAnimation
from facesynth.model.motion import Motion


def keymorphs(keyshapes: KeyShapes, rig: Rig, keymorph_path: Path | None, ridge: float,
              where: str) -> tuple[np.ndarray, np.ndarray]:
    """(K, E) rig weights and (K, V, 3) meshes of every emotion's keymorphs, emotions in order."""
    names = [n for e in keyshapes.emotions.values() for n in e.names]
    if keymorph_path is not None:
        morphs = read_keymorphs(keymorph_path, names, rig)  # (weights, None) or (None, meshes)
        if morphs[0] is not None:  # a CSV of rig weights: the meshes they make
            return morphs[0], rig.evaluate(morphs[0])
        meshes = morphs[1]  # a folder of meshes: the rig weights nearest them
        deltas = (meshes - rig.neutral).reshape(len(meshes), -1)
        weights, _ = fit_rig_weights(deltas, rig.deltas.reshape(len(rig.deltas), -1), ridge)
        return weights, meshes
    stored = all(e.keymorphs is not None for e in keyshapes.emotions.values())
    if stored and keyshapes.rig_sha256 == rig.sha256:
        weights = np.concatenate([e.keymorphs for e in keyshapes.emotions.values()]).astype(np.float64)
    else:
        mmap = marker_map(rig, keyshapes.marker_names, keyshapes.reference, where)
        markers = np.concatenate([e.markers for e in keyshapes.emotions.values()])
        targets = mmap.displacements(markers, keyshapes.reference).reshape(len(markers), -1)
        weights, _ = fit_rig_weights(targets, rig.deltas[:, mmap.vertices].reshape(len(rig.deltas), -1), ridge)
    return weights, rig.evaluate(weights)


def retarget(motion: Motion, keyshapes: KeyShapes, settings: RetargetSettings, emotion: str | None, where: str):
    """Key-shape blend weights of every frame (a :class:`~facesynth.domain.retarget.retarget.Retargeted`)."""
    if list(motion.marker_names) != list(keyshapes.marker_names):
        raise InputError(f"{where}: its markers differ from the key-shapes' ({len(motion.marker_names)} vs "
                         f"{len(keyshapes.marker_names)}); choose key-shapes from the database the motion came from.")
    emotions = list(keyshapes.emotions)
    fixed = None
    if emotion is not None:
        if emotion not in emotions:
            raise InputError(f"--emotion {emotion!r}: the key-shapes have {', '.join(emotions)}; pick one of those.")
        fixed = emotions.index(emotion)
    frames = (motion.markers - motion.reference).reshape(len(motion.markers), -1)
    sets = [(e.markers - keyshapes.reference).reshape(e.count, -1) for e in keyshapes.emotions.values()]
    window = max(1, int(round(settings.emotion_smooth_s * motion.fps)))
    return decompose(frames, sets, settings.emotion_scale_mm, window, fixed)


def rig_animation(vertices: np.ndarray, fps: float, rig: Rig, marker_names: list[str], reference: np.ndarray,
                  where: str) -> MeshAnimation:
    """A ``meshanim`` of rig-made vertices (T, V, 3): its markers are the mesh at the bound marker
    vertices, its deformation weights an empty matrix (the rig, not Eq. 14, moved the mesh)."""
    mmap = marker_map(rig, marker_names, reference, where)
    names = [marker_names[c] for c in mmap.columns]
    empty = sparse.csr_matrix((len(rig.neutral), len(names)), dtype=np.float32)
    markers = vertices[:, mmap.vertices].astype(np.float32)
    return MeshAnimation(vertices.astype(np.float32), fps, rig.neutral.astype(np.float32), rig.faces, markers, names,
                         empty, names, mmap.vertices.astype(np.int64), 0.0,
                         np.full((len(vertices), 2, 2), np.nan, np.float32))


@dataclass(frozen=True)
class RetargetResult:
    """What ``facesynth retarget`` made.

    frames: frames of the curves.
    keyshapes: key-shapes the motion was decomposed into (every emotion's).
    rig: the rig's name.
    residual_rms_mm: RMS of the key-shape fit's residual (mm).
    blend: how the mesh animation was blended ('linear' or 'gradient'), or None without one.
    """

    frames: int
    keyshapes: int
    rig: str
    residual_rms_mm: float
    blend: str | None = None


def run(motion_path: Path, keyshapes_path: Path, out: Path, settings: RetargetSettings, keyshape_settings: KeyshapesSettings,
        rig_path: Path | None = None, binding: Path | None = None, keymorph_path: Path | None = None,
        mesh_out: Path | None = None, emotion: str | None = None, overwrite: bool = False) -> RetargetResult:
    """Retarget ``motion_path`` through ``keyshapes_path`` onto the rig; write ``out`` (and ``mesh_out``)."""
    check_output(out, overwrite)
    if mesh_out is not None:
        check_output(mesh_out, overwrite)
    rig = load_rig(rig_path, binding)
    motion = Motion.read(motion_path)
    keyshapes = KeyShapes.read(keyshapes_path)
    weights_k, meshes_k = keymorphs(keyshapes, rig, keymorph_path, keyshape_settings.keymorph_ridge, str(keyshapes_path))
    result = retarget(motion, keyshapes, settings, emotion, str(motion_path))
    weights = np.clip(result.alpha @ weights_k, 0.0, 1.0)
    names = list(keyshapes.emotions)
    dominant = result.emotion_weights.argmax(1)
    inputs = [motion_path, keyshapes_path] + [p for p in (rig_path, keymorph_path) if p is not None and Path(p).is_file()]
    residual = result.residual[np.arange(len(dominant)), dominant]
    curves = RigCurves(weights, motion.fps, list(rig.shape_names), rig.name, rig.sha256, "retarget", motion.head_rotation,
                       motion.head_translation, [names[i] for i in dominant],
                       result.emotion_weights[np.arange(len(dominant)), dominant],
                       residual=residual,
                       method=f"key-shapes ({keyshapes.method}) and keymorphs, Eq. 9",
                       provenance=motion.frame_provenance(motion_path))
    mesh: tuple[MeshAnimation, Path] | None = None  # the mesh animation and where it goes (mesh_out)
    if mesh_out is not None:
        if settings.blend == "gradient":
            vertices = GradientBlender(rig.neutral, rig.faces, meshes_k, settings.anchor,
                                       use_opencl=settings.use_opencl).blend(result.alpha)
        else:  # linear: rest + sum_k alpha_k (G_k - rest), no factorization needed
            offsets = (meshes_k - rig.neutral).reshape(len(meshes_k), -1)
            vertices = rig.neutral + (result.alpha @ offsets).reshape(len(result.alpha), -1, 3)
        anim = rig_animation(vertices, motion.fps, rig, motion.marker_names, motion.reference, str(motion_path))
        anim.provenance = curves.provenance
        mesh = (anim, mesh_out)
    with published_together():  # the curves and the mesh animation, or neither
        curves.write(out, config=settings_json(settings), inputs=inputs, overwrite=overwrite)
        if mesh is not None:
            mesh[0].write(mesh[1], config=settings_json(settings), inputs=inputs, overwrite=overwrite)
    return RetargetResult(len(weights), int(result.alpha.shape[1]), rig.name,
                          float(np.sqrt(np.nanmean(residual**2))), settings.blend if mesh is not None else None)

