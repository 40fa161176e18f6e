"""USD (``.usda`` text, ``.usd`` binary crate) through Pixar's usd-core: for film pipelines
(Houdini, Maya, Omniverse, Blender's USD import); the stage writing of the export format
:mod:`facesynth.domain.exports.usd`.

Layout: ``/Face`` (an Xform; with ``--head-motion`` its ``xformOp:transform`` is time-sampled
with the head pose) holding ``/Face/Mesh``, a UsdGeom mesh. A mesh animation becomes
time-sampled ``points``. Rig curves become the rig's rest mesh with one UsdSkelBlendShape per rig
shape under the mesh and a SkelAnimation whose ``blendShapeWeights`` are time-sampled: ``/Face``
is then a SkelRoot with a joint-less Skeleton ``/Face/Skel`` bound to the mesh, the smallest
UsdSkel layout that carries blendshape animation (no joints, no skinning weights).

Units and axes: facesynth's own, stated in the stage metadata: millimetres
(``metersPerUnit = 0.001``), ``upAxis = "Y"``, the face toward +z, right-handed,
counter-clockwise faces seen from outside. Time: frame i at time code i,
``timeCodesPerSecond`` = ``framesPerSecond`` = the animation's rate, ``startTimeCode`` 0 and
``endTimeCode`` T - 1.

Provenance: where each frame came from is in ``/Face``'s ``customData`` under
``facesynth:provenance`` (a dictionary: ``origin``, ``method``, ``resampling``, per time code the arrays
``phone``, ``emotion``, ``node``, ``take``, ``source_frame``, ``step``, and the utterance's phones
as ``segment_phone``, ``segment_emotion``, ``segment_start`` and ``segment_end`` in seconds,
``segment_node``, ``segment_take``).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np


def available() -> bool:
    """Whether usd-core (``pip install facesynth[usd]``) is installed."""
    import importlib.util

    return importlib.util.find_spec("pxr") is not None


def _stage(path: Path, fps: float, n_frames: int):
    from pxr import Usd, UsdGeom

    stage = Usd.Stage.CreateNew(str(path))
    stage.SetTimeCodesPerSecond(float(fps))
    stage.SetFramesPerSecond(float(fps))
    stage.SetStartTimeCode(0)
    stage.SetEndTimeCode(max(n_frames - 1, 0))
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.y)
    UsdGeom.SetStageMetersPerUnit(stage, 0.001)
    return stage


def _mesh(stage, where: str, rest: np.ndarray, faces: np.ndarray):
    from pxr import UsdGeom, Vt

    mesh = UsdGeom.Mesh.Define(stage, where)
    mesh.CreatePointsAttr(Vt.Vec3fArray.FromNumpy(np.asarray(rest, np.float32)))
    mesh.CreateFaceVertexCountsAttr(Vt.IntArray.FromNumpy(np.full(len(faces), 3, np.int32)))
    mesh.CreateFaceVertexIndicesAttr(Vt.IntArray.FromNumpy(np.asarray(faces, np.int32).reshape(-1)))
    mesh.CreateOrientationAttr(UsdGeom.Tokens.rightHanded)
    mesh.CreateSubdivisionSchemeAttr(UsdGeom.Tokens.none)
    lo, hi = np.asarray(rest).min(axis=0), np.asarray(rest).max(axis=0)
    mesh.CreateExtentAttr(Vt.Vec3fArray.FromNumpy(np.stack([lo, hi]).astype(np.float32)))
    return mesh


def _head(prim_xform, head: tuple[np.ndarray, np.ndarray]) -> None:
    """Time-sample the head pose ``x -> R @ x + t`` (mm; ``head``: rotations (T, 3, 3),
    translations (T, 3)) on an Xformable (USD's row-vector matrices: the transpose, translation
    in the last row)."""
    from pxr import Gf

    op = prim_xform.AddTransformOp()
    for i, (r, t) in enumerate(zip(*head)):
        m = np.eye(4)
        m[:3, :3] = np.asarray(r, np.float64).T
        m[3, :3] = t
        op.Set(Gf.Matrix4d(m.tolist()), float(i))


def _provenance(prim, provenance) -> None:
    """Put a :class:`~facesynth.model.provenance.FrameProvenance` into ``prim``'s customData."""
    from pxr import Vt

    key = "facesynth:provenance:"
    f = provenance.to_json()
    prim.SetCustomDataByKey(key + "origin", f["origin"])
    prim.SetCustomDataByKey(key + "method", f["method"])
    prim.SetCustomDataByKey(key + "resampling", f["resampling"])
    for name, values in f["frames"].items():
        array = Vt.StringArray(values) if name in ("phone", "emotion", "take") else Vt.IntArray(values)
        prim.SetCustomDataByKey(key + name, array)
    segments = f["phones"]
    for name in ("phone", "emotion", "take"):
        prim.SetCustomDataByKey(key + "segment_" + name, Vt.StringArray([s[name] for s in segments]))
    for name in ("start", "end"):
        prim.SetCustomDataByKey(key + "segment_" + name, Vt.DoubleArray([s[name] for s in segments]))
    prim.SetCustomDataByKey(key + "segment_node", Vt.IntArray([s["node"] for s in segments]))


def write_points(path: Path, rest: np.ndarray, faces: np.ndarray, frames, n_frames: int, fps: float,
                 head: tuple[np.ndarray, np.ndarray] | None = None, provenance=None) -> None:
    """A mesh with time-sampled points. rest : (V, 3) mm; faces : (F, 3); frames : a function
    (start, stop) -> (n, V, 3) mm giving the animation in blocks (memory stays one block);
    head : optional head motion, (rotations (T, 3, 3), translations (T, 3) mm);
    provenance : optional FrameProvenance of the frames."""
    from pxr import UsdGeom, Vt

    stage = _stage(path, fps, n_frames)
    root = UsdGeom.Xform.Define(stage, "/Face")
    stage.SetDefaultPrim(root.GetPrim())
    mesh = _mesh(stage, "/Face/Mesh", rest, faces)
    points = mesh.GetPointsAttr()
    block = 64
    lo, hi = np.full(3, np.inf), np.full(3, -np.inf)
    for start in range(0, n_frames, block):
        chunk = np.asarray(frames(start, min(start + block, n_frames)), np.float32)
        lo, hi = np.minimum(lo, chunk.min(axis=(0, 1))), np.maximum(hi, chunk.max(axis=(0, 1)))
        for k, p in enumerate(chunk):
            points.Set(Vt.Vec3fArray.FromNumpy(p), float(start + k))
    mesh.GetExtentAttr().Set(Vt.Vec3fArray.FromNumpy(np.stack([lo, hi]).astype(np.float32)))
    if head is not None:
        _head(root, head)
    if provenance is not None:
        _provenance(root.GetPrim(), provenance)
    stage.GetRootLayer().Save()


def write_blendshapes(path: Path, rest: np.ndarray, faces: np.ndarray, deltas: np.ndarray, shape_names, weights: np.ndarray,
                      fps: float, head: tuple[np.ndarray, np.ndarray] | None = None, provenance=None) -> None:
    """The rig as UsdSkelBlendShapes driven by a SkelAnimation. rest : (V, 3) mm; deltas :
    (E, V, 3) mm; weights : (T, E) in [0, 1]; head : optional head motion, (rotations (T, 3, 3),
    translations (T, 3) mm). Each shape stores only the vertices it moves (``pointIndices``), as
    UsdSkel allows."""
    from pxr import Tf, UsdGeom, UsdSkel, Vt

    names = [str(n) for n in shape_names]
    n_frames = len(weights)
    stage = _stage(path, fps, n_frames)
    root = UsdSkel.Root.Define(stage, "/Face")
    stage.SetDefaultPrim(root.GetPrim())
    skel = UsdSkel.Skeleton.Define(stage, "/Face/Skel")
    skel.CreateJointsAttr(Vt.TokenArray([]))
    anim = UsdSkel.Animation.Define(stage, "/Face/Skel/Anim")
    anim.CreateJointsAttr(Vt.TokenArray([]))
    anim.CreateBlendShapesAttr(Vt.TokenArray(names))
    attr = anim.CreateBlendShapeWeightsAttr()
    for i, w in enumerate(np.clip(np.asarray(weights, np.float32), 0.0, 1.0)):
        attr.Set(Vt.FloatArray.FromNumpy(w), float(i))
    UsdSkel.BindingAPI.Apply(skel.GetPrim()).CreateAnimationSourceRel().SetTargets([anim.GetPath()])

    mesh = _mesh(stage, "/Face/Mesh", rest, faces)
    binding = UsdSkel.BindingAPI.Apply(mesh.GetPrim())
    binding.CreateSkeletonRel().SetTargets([skel.GetPath()])
    binding.CreateBlendShapesAttr(Vt.TokenArray(names))
    targets = []
    for name, delta in zip(names, deltas):
        moved = np.flatnonzero(np.abs(delta).max(axis=1) > 0)
        shape = UsdSkel.BlendShape.Define(stage, mesh.GetPath().AppendChild(Tf.MakeValidIdentifier(name)))
        shape.CreateOffsetsAttr(Vt.Vec3fArray.FromNumpy(np.asarray(delta[moved], np.float32)))
        shape.CreatePointIndicesAttr(Vt.IntArray.FromNumpy(moved.astype(np.int32)))
        targets.append(shape.GetPath())
    binding.CreateBlendShapeTargetsRel().SetTargets(targets)
    if head is not None:
        _head(UsdGeom.Xformable(root.GetPrim()), head)
    if provenance is not None:
        _provenance(root.GetPrim(), provenance)
    stage.GetRootLayer().Save()
