"""The target rig of retargeting: a linear blendshape rig with a marker binding.

A rig is the built-in ICT-FaceKit rig (:func:`builtin_rig`, the production face of the sample
corpus, bound to the virtual actress's markers) or a user's rig (:func:`read_rig`): a folder with
``neutral.obj`` and one OBJ per shape (the shape's name is the file name without ``.obj``), or a
glTF 2.0 file (``.gltf`` or ``.glb``) whose first mesh has morph targets (names from the mesh's
``extras.targetNames``). A user's rig needs a binding CSV (``marker,vertex``) placing the motion's
markers on its vertices. Units are the rig's own; the motion is carried into them by a similarity
fit, like ``deform``.
"""

from __future__ import annotations

import base64
import hashlib
import json
import struct
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..errors import InputError
from ..facerig import BUILTIN_RIG_NAME, builtin_rig_sha256, load_face_rig
from ..formats.mesh import read_binding, read_mesh
from ..motion.rigid import similarity_fit


@dataclass(frozen=True)
class TargetRig:
    """A linear blendshape rig: ``vertices = neutral + sum_e w[e] * deltas[e]``, w in [0, 1].

    name : the rig's name; sha256 : hex digest of its data.
    neutral : (V, 3) float64 in rig units (mm for the built-in rig); faces : (F, 3) int64.
    shape_names : the E shape names; deltas : (E, V, 3) float32, each shape minus the neutral.
    binding : marker name -> vertex index.
    """

    name: str
    sha256: str
    neutral: np.ndarray
    faces: np.ndarray
    shape_names: tuple[str, ...]
    deltas: np.ndarray
    binding: dict

    def evaluate(self, weights: np.ndarray, vertices: np.ndarray | None = None) -> np.ndarray:
        """(T, V or K, 3) float64 posed vertices for (T, E) weights (optionally only ``vertices``)."""
        w = np.asarray(weights, dtype=np.float64)
        neutral, deltas = self.neutral, self.deltas
        if vertices is not None:
            neutral, deltas = neutral[vertices], deltas[:, vertices]
        return neutral + np.tensordot(w, deltas, axes=(w.ndim - 1, 0))

    def bound(self, marker_names: list[str], where: str) -> tuple[np.ndarray, np.ndarray]:
        """(columns of ``marker_names``, rig vertices) of the markers bound on this rig; three are needed."""
        cols = [i for i, m in enumerate(marker_names) if m in self.binding]
        if len(cols) < 3:
            raise InputError(f"{where}: fewer than three of the motion's markers are bound on rig {self.name!r}; "
                             f"give a binding CSV that names the motion's markers.")
        bad = [m for m in self.binding if not 0 <= self.binding[m] < len(self.neutral)]
        if bad:
            raise InputError(f"{where}: marker {bad[0]!r} is bound to vertex {self.binding[bad[0]]}, but rig "
                             f"{self.name!r} has {len(self.neutral)} vertices; use the binding made for this rig.")
        return np.array(cols), np.array([self.binding[marker_names[c]] for c in cols])


#: The ``--rig`` value naming the built-in rig.
BUILTIN = "builtin"


def builtin_rig(binding: dict | None = None) -> TargetRig:
    """The ICT-FaceKit rig shipped with facesynth, in mm, bound to the virtual actress's markers,
    or to ``binding`` (marker name -> vertex, e.g. a user's capture placed by ``facesynth bind``)."""
    from ..corpus.markers import build_marker_set

    rig = load_face_rig()
    return TargetRig(BUILTIN_RIG_NAME, builtin_rig_sha256(), rig.neutral, rig.faces, rig.shape_names, rig.deltas,
                     build_marker_set(rig).binding() if binding is None else binding)


def load_rig(path: Path | None, binding: Path | None) -> TargetRig:
    """The built-in rig when ``path`` is None or ``builtin`` (with its own binding, or ``binding``:
    a user's markers placed on it), else :func:`read_rig`."""
    if path is None or str(path) == BUILTIN:
        return builtin_rig(read_binding(Path(binding)) if binding is not None else None)
    return read_rig(Path(path), binding)


#: The shape whose displacement tells which vertices the jaw carries (ARKit's name, ICT's too).
JAW_SHAPE = "jawOpen"


def load_rig_mesh(path: Path | None) -> tuple[str, np.ndarray, np.ndarray, np.ndarray | None]:
    """(name, neutral (V, 3) in rig units, faces (F, 3), the (V,) displacement length of its
    ``jawOpen`` shape or None without one) of the built-in rig (``path`` None or ``builtin``) or
    a user's rig (an OBJ folder or a glTF file), no binding needed."""
    if path is None or str(path) == BUILTIN:
        rig = load_face_rig()
        return BUILTIN_RIG_NAME, rig.neutral, rig.faces, np.linalg.norm(rig.deltas[rig.shape_index(JAW_SHAPE)], axis=1)
    rig_files = _read_rig_files(Path(path), "a folder of OBJ files, a .gltf/.glb file or 'builtin'")
    name, _, neutral, faces, names, deltas = rig_files
    jaw = np.linalg.norm(deltas[list(names).index(JAW_SHAPE)], axis=1) if JAW_SHAPE in names else None
    return name, neutral, faces, jaw


def _read_rig_files(path: Path, what: str):
    """(name, digest, neutral, faces, shape names, deltas) of a user's rig: an OBJ folder or a
    glTF file; ``what`` names the accepted kinds in the error."""
    if not path.exists():
        raise InputError(f"{path}: rig not found; give {what}.")
    if path.is_dir():
        return _read_obj_folder(path)
    if path.suffix.lower() in (".gltf", ".glb"):
        return _read_gltf(path)
    raise InputError(f"{path}: unsupported rig {path.suffix!r}; give a folder of OBJ files or a .gltf/.glb file.")


def read_rig(path: Path, binding_path: Path | None) -> TargetRig:
    """A user's rig: an OBJ folder or a glTF file, with its marker binding CSV."""
    path = Path(path)
    if path.exists() and binding_path is None:
        raise InputError(f"{path}: a user's rig needs --binding, a CSV of marker,vertex placing the motion's markers on it.")
    name, digest, neutral, faces, names, deltas = _read_rig_files(path, "a folder of OBJ files or a .gltf/.glb file")
    binding = read_binding(Path(binding_path))
    return TargetRig(name, digest, neutral, faces, tuple(names), deltas, binding)


def _read_obj_folder(folder: Path):
    """neutral.obj plus one OBJ per shape, every one with the neutral's vertex count and triangles."""
    neutral_path = folder / "neutral.obj"
    if not neutral_path.exists():
        raise InputError(f"{folder}: no neutral.obj; a rig folder holds neutral.obj and one OBJ per shape.")
    files = sorted(p for p in folder.glob("*.obj") if p.name != "neutral.obj")
    if not files:
        raise InputError(f"{folder}: no shape OBJ files beside neutral.obj; add one OBJ per blendshape.")
    digest = hashlib.sha256()
    for p in [neutral_path, *files]:
        digest.update(p.name.encode("utf-8") + b"\0" + p.read_bytes())
    neutral, faces = read_mesh(neutral_path)
    deltas = np.empty((len(files), len(neutral), 3), np.float32)
    for e, p in enumerate(files):
        v, f = read_mesh(p)
        if len(v) != len(neutral):
            raise InputError(f"{p}: {len(v)} vertices, but {neutral_path.name} has {len(neutral)}; export every shape "
                             f"from the same mesh as the neutral.")
        if f.shape != faces.shape or not np.array_equal(f, faces):
            raise InputError(f"{p}: its triangles differ from {neutral_path.name}'s (topology changed); export every "
                             f"shape with the neutral's vertex order and faces.")
        deltas[e] = v - neutral
    return folder.name, digest.hexdigest(), neutral, faces, [p.stem for p in files], deltas


# ---------------------------------------------------------------- glTF 2.0 (read only what a morph rig needs)

_COMPONENT = {5121: np.uint8, 5123: np.uint16, 5125: np.uint32, 5126: np.float32}
_WIDTH = {"SCALAR": 1, "VEC3": 3}


def _read_gltf(path: Path):
    """The first mesh's first primitive: POSITION, triangle indices and POSITION morph targets.

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


@dataclass(frozen=True)
class MarkerMap:
    """How the motion's markers sit on a rig.

    columns : (B,) rows of the motion's marker order that are bound; vertices : (B,) their rig
    vertices; scale, rotation : the similarity taking the motion's head frame (mm) into the rig's
    frame and units, fitted from the motion's neutral reference to the rig's neutral at the bound
    vertices.
    """

    columns: np.ndarray
    vertices: np.ndarray
    scale: float
    rotation: np.ndarray

    def displacements(self, markers: np.ndarray, reference: np.ndarray) -> np.ndarray:
        """(T, B, 3) displacements from the reference, in the rig's frame and units, for (T, M, 3) mm markers."""
        return (np.asarray(markers, np.float64)[:, self.columns] - reference[self.columns]) @ (self.scale * self.rotation).T


def marker_map(rig: TargetRig, marker_names: list[str], reference: np.ndarray, where: str) -> MarkerMap:
    """Bind the motion's markers to ``rig`` (see :class:`MarkerMap`); ``where`` names the motion in errors."""
    cols, verts = rig.bound(marker_names, where)
    s, r, _, _ = similarity_fit(np.asarray(reference, np.float64)[cols], rig.neutral[verts])
    return MarkerMap(cols, verts, s, r)


def read_keymorphs(path: Path, names: list[str], rig: TargetRig) -> tuple[np.ndarray | None, np.ndarray | None]:
    """Artist-made keymorphs for the key-shapes ``names``: a folder with ``<name>.obj`` per key-shape
    (meshes in the rig's vertex order and triangles) or a CSV with a ``keyshape`` column and one
    column per rig shape (weights in [0, 1]). Returns (weights (K, E) or None, meshes (K, V, 3) or None).
    """
    import csv

    path = Path(path)
    if path.is_dir():
        meshes = np.empty((len(names), len(rig.neutral), 3))
        for k, name in enumerate(names):
            p = path / f"{name}.obj"
            if not p.exists():
                raise InputError(f"{path}: no {name}.obj; the keymorph folder needs one OBJ per key-shape "
                                 f"({', '.join(names[:3])}, ...).")
            v, f = read_mesh(p)
            if len(v) != len(rig.neutral) or f.shape != rig.faces.shape or not np.array_equal(f, rig.faces):
                raise InputError(f"{p}: {len(v)} vertices and {len(f)} triangles, but rig {rig.name!r} has "
                                 f"{len(rig.neutral)} and {len(rig.faces)}; model the keymorph on the rig's mesh.")
            meshes[k] = v
        return None, meshes
    if not path.exists():
        raise InputError(f"{path}: keymorphs not found; give a folder of OBJ files or a CSV of rig weights.")
    rows: dict[str, np.ndarray] = {}
    with open(path, encoding="utf-8-sig", newline="") as fh:
        reader = csv.DictReader(fh)
        fields = reader.fieldnames or []
        if "keyshape" not in fields:
            raise InputError(f"{path}: the keymorph CSV needs a 'keyshape' column and one column per rig shape.")
        unknown = [c for c in fields if c != "keyshape" and c not in rig.shape_names]
        if unknown:
            raise InputError(f"{path}: column {unknown[0]!r} is not a shape of rig {rig.name!r}; use the rig's shape names.")
        for row in reader:
            w = np.zeros(len(rig.shape_names))
            for column, text in row.items():
                if column == "keyshape" or text in (None, ""):
                    continue
                try:
                    value = float(text)
                except ValueError:
                    raise InputError(f"{path}, line {reader.line_num}, column {column!r}: {text!r} is not a number.") from None
                if not 0.0 <= value <= 1.0:
                    raise InputError(f"{path}, line {reader.line_num}, column {column!r}: weight {value:g} is outside "
                                     f"[0, 1]; rig weights run from 0 to 1.")
                w[rig.shape_names.index(column)] = value
            rows[row["keyshape"]] = w
    missing = [n for n in names if n not in rows]
    if missing:
        raise InputError(f"{path}: no row for key-shape {missing[0]!r}; the keymorph CSV needs one row per key-shape.")
    return np.stack([rows[n] for n in names]), None
