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

import dataclasses
import hashlib
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from facesynth.base.errors import InputError
from facesynth.domain.geometry.rigid import similarity_fit
from facesynth.domain.rig.face import gaze_from_rig_weights
from facesynth.formats.gltf import read_morph_mesh
from facesynth.formats.mesh import read_binding, read_mesh
from facesynth.model.curves import RigCurves
from facesynth.model.meshanim import MeshAnimation

from .face import BUILTIN_RIG_NAME, Rig, load_face_rig
from .markers import build_marker_set

#: The ``--rig`` value naming the built-in rig.
BUILTIN = "builtin"


def builtin_rig(binding: dict | None = None) -> Rig:
    """The ICT-FaceKit rig shipped with facesynth, in mm, bound to the virtual actress's markers,
    or to ``binding`` (marker name -> vertex, e.g. a user's capture placed by ``facesynth bind``)."""
    rig = load_face_rig()
    return dataclasses.replace(rig, binding=build_marker_set(rig).binding() if binding is None else binding)


def load_rig(path: Path | None, binding: Path | None, need_binding: bool = True) -> Rig:
    """The built-in rig when ``path`` is None or ``builtin`` (with its own binding, or ``binding``:
    a user's markers placed on it), else :func:`read_rig` (``need_binding`` False: a user's rig
    without ``binding`` is read unbound, for posing it with curves)."""
    if path is None or str(path) == BUILTIN:
        return builtin_rig(read_binding(Path(binding)) if binding is not None else None)
    return read_rig(Path(path), binding, need_binding)


def pose_rig(curves: RigCurves, rig: Rig, where: str, head_motion: bool = False) -> MeshAnimation:
    """The rig posed by ``curves`` as a mesh animation: vertices (T, V, 3) float32
    ``neutral + sum_e w_e deltas_e`` in the rig's frame and units; with ``head_motion`` each
    frame also moved by the head pose the curves carry (``x -> R @ x + t``, in the rig's frame,
    as the exports and the player apply it). The markers are the rig's bound vertices; the gaze
    comes from the rig's ``eyeLook*`` shapes (unknown, NaN, without them). ``where`` names the
    curves in errors: curves made for another rig, or with other shape names, are refused."""
    from scipy import sparse

    if curves.rig_sha256 != rig.sha256:
        raise InputError(f"{where}: the curves were made for rig {curves.rig_name!r}, not {rig.name!r}; "
                         f"give that rig with --rig.")
    if list(curves.shape_names) != list(rig.shape_names):
        raise InputError(f"{where}: its shape names differ from rig {rig.name!r}'s; remake the curves on this rig.")
    vertices = rig.evaluate(curves.weights).astype(np.float32)
    if head_motion and curves.head_rotation is not None and curves.head_translation is not None:
        r = np.asarray(curves.head_rotation, np.float32)
        t = np.asarray(curves.head_translation, np.float32)
        vertices = np.einsum("tij,tvj->tvi", r, vertices) + t[:, None, :]
    names = list(rig.binding)
    verts = np.array([rig.binding[n] for n in names], np.int64)
    gaze = gaze_from_rig_weights(curves.weights, rig.shape_names)
    if gaze is None:
        gaze = np.full((len(vertices), 2, 2), np.nan)
    empty = sparse.csr_matrix((len(rig.neutral), len(names)), dtype=np.float32)
    return MeshAnimation(vertices, curves.fps, rig.neutral.astype(np.float32), rig.faces, vertices[:, verts], names,
                         empty, names, verts, 0.0, gaze.astype(np.float32))


def arkit_to_rig(rig: Rig, where: str) -> tuple[tuple[str, ...], np.ndarray]:
    """(the 52 ARKit names, the (52, E) matrix taking ARKit weights to ``rig``'s weights): the
    built-in rig's own table, or for a user's rig each ARKit shape onto the rig shape of the
    same name (case aside; ARKit channels it lacks drive nothing). ``where`` names the rig in
    the error for a rig none of whose shapes has an ARKit name."""
    if rig.arkit_to_rig is not None:
        return rig.arkit_names, rig.arkit_to_rig
    names = load_face_rig().arkit_names
    index = {n.lower(): e for e, n in enumerate(rig.shape_names)}
    matrix = np.zeros((len(names), len(rig.shape_names)))
    for a, name in enumerate(names):
        if name.lower() in index:
            matrix[a, index[name.lower()]] = 1.0
    if not matrix.any():
        raise InputError(f"{where}: none of the shapes of rig {rig.name!r} has an ARKit name (jawOpen, mouthClose, "
                         f"eyeBlinkLeft, ...); name its blendshapes as ARKit does to drive it with ARKit curves.")
    return names, matrix


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
        return read_morph_mesh(path)
    raise InputError(f"{path}: unsupported rig {path.suffix!r}; give a folder of OBJ files or a .gltf/.glb file.")


def read_rig(path: Path, binding_path: Path | None, need_binding: bool = True) -> Rig:
    """A user's rig: an OBJ folder or a glTF file, with its marker binding CSV (``need_binding``
    False: optional, the rig unbound without it)."""
    path = Path(path)
    if path.exists() and binding_path is None and need_binding:
        raise InputError(f"{path}: a user's rig needs --binding, a CSV of marker,vertex placing the motion's markers on it.")
    name, digest, neutral, faces, names, deltas = _read_rig_files(path, "a folder of OBJ files or a .gltf/.glb file")
    binding = read_binding(Path(binding_path)) if binding_path is not None else {}
    return Rig(name, digest, neutral, faces, tuple(names), deltas, binding)


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


def marker_map(rig: Rig, marker_names: list[str], reference: np.ndarray, where: str) -> MarkerMap:
    """Bind the motion's markers to ``rig`` (see :class:`MarkerMap`); ``where`` names the motion in errors."""
    cols, verts = rig.bound(marker_names, where)
    s, r, _, _ = similarity_fit(np.asarray(reference, np.float64)[cols], rig.neutral[verts])
    return MarkerMap(cols, verts, s, r)


def read_keymorphs(path: Path, names: list[str], rig: Rig) -> tuple[np.ndarray, None] | tuple[None, np.ndarray]:
    """Artist-made keymorphs for the key-shapes ``names``: a folder with ``<name>.obj`` per key-shape
    (meshes in the rig's vertex order and triangles) or a CSV with a ``keyshape`` column and one
    column per rig shape (weights in [0, 1]). Returns (weights (K, E), None) for a CSV,
    (None, meshes (K, V, 3)) for a folder.
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
