"""glTF 2.0 (``.gltf`` with the buffer embedded, ``.glb`` binary), read and written.

Reading (:func:`read_morph_mesh`, a user's rig for ``--rig``): the first mesh's positions,
triangles and morph targets, by a small reader of the container. Writing (:func:`build` and
:func:`write`, ``facesynth export``), through pygltflib: the rig mesh with one morph target per
rig shape and one animation whose ``weights`` channel follows the
curves, for web pages (three.js, Babylon.js), Blender and game engines.

Units and axes: glTF is metres, +y up, the asset's front toward +z, right-handed; facesynth's
frame is the same but in millimetres, so every position and morph-target offset is scaled by
0.001 and nothing else changes. Head motion (``--head-motion``) animates the mesh node's
``translation`` (m) and ``rotation`` (unit quaternion x, y, z, w) about the rig's origin, the
``x -> R @ x + t`` of the curves. Target names are in ``mesh.extras.targetNames`` (read by
Blender and three.js). glTF has no ratified audio: the WAV is copied beside the file and named
in the animation's ``extras.audio`` (``uri``, ``mimeType``, ``startTime_s``), which the
validator ignores and a player can read. Where each frame came from (phone, emotion, database
node, take: :class:`~facesynth.model.provenance.FrameProvenance`) is in the animation's
``extras.facesynth_provenance``: ``frames`` (one list per field, one entry per keyframe) and
``phones`` (the utterance's phones with start and end in seconds).
"""

from __future__ import annotations

import base64
import hashlib
import json
import struct
from pathlib import Path

import numpy as np

from facesynth.base.errors import InputError

MM_TO_M = 1e-3

_FLOAT, _UINT = 5126, 5125
_ARRAY_BUFFER, _ELEMENT_ARRAY_BUFFER = 34962, 34963


def vertex_normals(vertices: np.ndarray, faces: np.ndarray) -> np.ndarray:
    """(V, 3) float32 unit area-weighted vertex normals; +z for a vertex no face uses."""
    v = np.asarray(vertices, np.float64)
    n = np.zeros_like(v)
    fn = np.cross(v[faces[:, 1]] - v[faces[:, 0]], v[faces[:, 2]] - v[faces[:, 0]])
    for k in range(3):
        np.add.at(n, faces[:, k], fn)
    length = np.linalg.norm(n, axis=1, keepdims=True)
    n = np.where(length > 0, n / np.where(length > 0, length, 1), [0.0, 0.0, 1.0])
    n = n.astype(np.float32)
    return n / np.linalg.norm(n, axis=1, keepdims=True)  # renormalized in float32, as the validator checks


class _Blob:
    """The binary buffer being built: 4-byte aligned views, one accessor each."""

    def __init__(self, gltf):
        self.gltf, self.parts, self.offset = gltf, [], 0

    def add(self, data: np.ndarray, kind: str, component: int, target: int | None = None, bounds: bool = False) -> int:
        from pygltflib import Accessor, BufferView

        raw = np.ascontiguousarray(data).tobytes()
        view = BufferView(buffer=0, byteOffset=self.offset, byteLength=len(raw), target=target)
        self.parts.append(raw)
        pad = (-len(raw)) % 4
        self.parts.append(b"\0" * pad)
        self.offset += len(raw) + pad
        self.gltf.bufferViews.append(view)
        width = {"SCALAR": 1, "VEC3": 3, "VEC4": 4}[kind]
        flat = np.asarray(data).reshape(-1, width)
        accessor = Accessor(bufferView=len(self.gltf.bufferViews) - 1, componentType=component, count=len(flat), type=kind)
        if bounds:
            accessor.min = [float(x) for x in flat.min(axis=0)]
            accessor.max = [float(x) for x in flat.max(axis=0)]
        self.gltf.accessors.append(accessor)
        return len(self.gltf.accessors) - 1

    def bytes(self) -> bytes:
        return b"".join(self.parts)


def build(rest_mm: np.ndarray, faces: np.ndarray, deltas_mm: np.ndarray, target_names, times_s: np.ndarray,
          weights: np.ndarray, head_rotation: np.ndarray | None = None, head_translation_mm: np.ndarray | None = None,
          audio_uri: str | None = None, name: str = "face", provenance=None):
    """A pygltflib ``GLTF2`` (buffer not yet attached; see :func:`write`) and its binary buffer.

    rest_mm : (V, 3) mm; faces : (F, 3) int; deltas_mm : (E, V, 3) mm morph targets named
    ``target_names``; times_s : (T,) s; weights : (T, E) in [0, 1]; head_rotation : optional
    (T, 3, 3), head_translation_mm : (T, 3) mm; audio_uri : the WAV's file name beside the file;
    provenance : optional :class:`~facesynth.model.provenance.FrameProvenance` of the T frames."""
    from pygltflib import (
        GLTF2,
        Animation,
        AnimationChannel,
        AnimationChannelTarget,
        AnimationSampler,
        Asset,
        Attributes,
        Buffer,
        Mesh,
        Node,
        Primitive,
        Scene,
    )

    gltf = GLTF2(asset=Asset(version="2.0", generator="facesynth export"))
    blob = _Blob(gltf)
    rest = (np.asarray(rest_mm, np.float64) * MM_TO_M).astype(np.float32)
    position = blob.add(rest, "VEC3", _FLOAT, _ARRAY_BUFFER, bounds=True)
    normal = blob.add(vertex_normals(rest, faces), "VEC3", _FLOAT, _ARRAY_BUFFER)
    indices = blob.add(np.asarray(faces, np.uint32).reshape(-1), "SCALAR", _UINT, _ELEMENT_ARRAY_BUFFER)
    targets = []
    for delta in deltas_mm:
        targets.append({"POSITION": blob.add((np.asarray(delta, np.float64) * MM_TO_M).astype(np.float32), "VEC3", _FLOAT,
                                             _ARRAY_BUFFER, bounds=True)})
    names = list(target_names)
    gltf.meshes.append(Mesh(name=name, primitives=[Primitive(attributes=Attributes(POSITION=position, NORMAL=normal),
                                                            indices=indices, targets=targets, mode=4)],
                            weights=[0.0] * len(names), extras={"targetNames": names}))
    gltf.nodes.append(Node(name=name, mesh=0))
    gltf.scenes.append(Scene(name=name, nodes=[0]))
    gltf.scene = 0

    times = np.asarray(times_s, np.float32)
    t_in = blob.add(times, "SCALAR", _FLOAT, bounds=True)
    w = np.clip(np.asarray(weights, np.float32), 0.0, 1.0)
    samplers = [AnimationSampler(input=t_in, output=blob.add(w.reshape(-1), "SCALAR", _FLOAT), interpolation="LINEAR")]
    channels = [AnimationChannel(sampler=0, target=AnimationChannelTarget(node=0, path="weights"))]
    if head_rotation is not None:
        from scipy.spatial.transform import Rotation

        quats = Rotation.from_matrix(np.asarray(head_rotation, np.float64)).as_quat().astype(np.float32)  # x, y, z, w
        quats /= np.linalg.norm(quats, axis=1, keepdims=True)
        shift = (np.asarray(head_translation_mm, np.float64) * MM_TO_M).astype(np.float32)
        samplers.append(AnimationSampler(input=t_in, output=blob.add(shift, "VEC3", _FLOAT), interpolation="LINEAR"))
        channels.append(AnimationChannel(sampler=1, target=AnimationChannelTarget(node=0, path="translation")))
        samplers.append(AnimationSampler(input=t_in, output=blob.add(quats, "VEC4", _FLOAT), interpolation="LINEAR"))
        channels.append(AnimationChannel(sampler=2, target=AnimationChannelTarget(node=0, path="rotation")))
    extras: dict[str, object] = {"fps": float(1.0 / np.median(np.diff(times))) if len(times) > 1 else None}
    if audio_uri:
        extras["audio"] = {"uri": audio_uri, "mimeType": "audio/wav", "startTime_s": 0.0}
    if provenance is not None:
        extras["facesynth_provenance"] = provenance.to_json()
    gltf.animations.append(Animation(name=f"{name} animation", samplers=samplers, channels=channels, extras=extras))
    data = blob.bytes()
    gltf.buffers.append(Buffer(byteLength=len(data)))
    return gltf, data


def write(path: Path, gltf, data: bytes, binary: bool) -> None:
    """Write ``gltf`` with its buffer ``data`` to ``path``: a GLB when ``binary``, else a .gltf
    JSON file with the buffer embedded as a base64 data URI (one file to move around)."""
    if binary:
        gltf.set_binary_blob(data)
        gltf.save_binary(str(path))
    else:
        gltf.buffers[0].uri = "data:application/octet-stream;base64," + base64.b64encode(data).decode("ascii")
        Path(path).write_text(gltf.gltf_to_json(), encoding="utf-8")


# ---------------------------------------------------------------- reading (only what a morph rig needs)

_COMPONENT = {5121: np.uint8, 5123: np.uint16, 5125: np.uint32, 5126: np.float32}
_WIDTH = {"SCALAR": 1, "VEC3": 3}


def read_morph_mesh(path: Path) -> tuple[str, str, np.ndarray, np.ndarray, list[str], np.ndarray]:
    """A morph rig from a ``.gltf``/``.glb`` file: (name (the file's stem), hex sha256 of the file,
    neutral (V, 3) float64 and faces (F, 3) int64 of the first mesh's first primitive, the E
    morph-target names, deltas (E, V, 3) float32 of its POSITION morph targets), in the file's units.

    A small reader of the glTF 2.0 container (JSON chunk + binary buffers, embedded ``data:`` URIs
    or files beside it) rather than a dependency: a morph rig needs five of its fields."""
    raw = path.read_bytes()
    digest = hashlib.sha256(raw).hexdigest()
    bin_chunk = None
    try:
        if raw[:4] == b"glTF":
            length = struct.unpack_from("<I", raw, 12)[0]
            doc = json.loads(raw[20:20 + length])
            offset = 20 + length
            if offset + 8 <= len(raw):
                blen = struct.unpack_from("<I", raw, offset)[0]
                bin_chunk = raw[offset + 8: offset + 8 + blen]
        else:
            doc = json.loads(raw.decode("utf-8"))
    except (ValueError, UnicodeDecodeError, struct.error) as exc:
        raise InputError(f"{path}: not a readable glTF file ({exc}); export it again as glTF 2.0.") from None

    buffers = []
    for i, b in enumerate(doc.get("buffers", [])):
        uri = b.get("uri")
        if uri is None:
            if bin_chunk is None:
                raise InputError(f"{path}: buffer {i} has no data; export it again as glTF 2.0.")
            buffers.append(bin_chunk)
        elif uri.startswith("data:"):
            buffers.append(base64.b64decode(uri.split(",", 1)[1]))
        else:
            source = path.parent / uri
            if not source.exists():
                raise InputError(f"{path}: buffer file {uri!r} is missing; keep it beside the .gltf.")
            buffers.append(source.read_bytes())

    def accessor(index: int, where: str) -> np.ndarray:
        try:
            a = doc["accessors"][index]
            view = doc["bufferViews"][a["bufferView"]]
            dtype = np.dtype(_COMPONENT[a["componentType"]])
            width = _WIDTH[a["type"]]
            stride = view.get("byteStride") or dtype.itemsize * width
            start = view.get("byteOffset", 0) + a.get("byteOffset", 0)
            data = buffers[view["buffer"]]
            rows = np.ndarray((a["count"], width), dtype=dtype, buffer=data, offset=start, strides=(stride, dtype.itemsize))
            return np.array(rows, dtype=np.float64 if dtype == np.float32 else np.int64)
        except (KeyError, IndexError, TypeError, ValueError) as exc:
            raise InputError(f"{path}: {where} cannot be read ({type(exc).__name__}: {exc}); export it again as glTF 2.0 "
                             f"with float positions.") from None

    meshes = doc.get("meshes", [])
    if not meshes or not meshes[0].get("primitives"):
        raise InputError(f"{path}: no mesh; export the face with its morph targets.")
    mesh = meshes[0]
    prim = mesh["primitives"][0]
    if prim.get("mode", 4) != 4:
        raise InputError(f"{path}: mesh 0 is not made of triangles (mode {prim.get('mode')}); triangulate it on export.")
    if "POSITION" not in prim.get("attributes", {}) or "indices" not in prim:
        raise InputError(f"{path}: mesh 0 has no positions or no triangle indices; export an indexed mesh.")
    neutral = accessor(prim["attributes"]["POSITION"], "POSITION")
    faces = accessor(prim["indices"], "indices").reshape(-1, 3)
    targets = prim.get("targets", [])
    if not targets:
        raise InputError(f"{path}: mesh 0 has no morph targets; export the blendshapes as morph targets.")
    names = list(mesh.get("extras", {}).get("targetNames") or [f"target{i}" for i in range(len(targets))])
    if len(names) != len(targets):
        raise InputError(f"{path}: {len(names)} targetNames for {len(targets)} morph targets; export them together.")
    deltas = np.empty((len(targets), len(neutral), 3), np.float32)
    for e, t in enumerate(targets):
        if "POSITION" not in t:
            raise InputError(f"{path}: morph target {names[e]!r} has no POSITION displacements; export shape positions.")
        d = accessor(t["POSITION"], f"morph target {names[e]!r}")
        if len(d) != len(neutral):
            raise InputError(f"{path}: morph target {names[e]!r} has {len(d)} vertices, but the mesh has {len(neutral)}; "
                             f"export every target from the same mesh.")
        deltas[e] = d
    if faces.size == 0 or faces.max() >= len(neutral):
        raise InputError(f"{path}: triangle indices beyond the {len(neutral)} vertices; export it again.")
    return path.stem, digest, neutral, faces, names, deltas
