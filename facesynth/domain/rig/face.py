"""The rig: :class:`Rig`, the one linear blendshape rig class (the built-in rig, a user's rig
read for retargeting), and the production face rig shipped with facesynth
(:func:`load_face_rig`): ICT-FaceKit's face and head with 55 blendshapes.

The rig is linear: for weights ``w`` (one per shape, 0..1 in the ARKit convention) the
vertices are ``neutral + sum_e w[e] * deltas[e]``. Shapes follow ARKit's naming with
ICT's ``_L``/``_R`` suffixes (the subject's own left is +x). Two ARKit shapes are split
in ICT (``browInnerUp``, ``cheekPuff``: one ARKit weight drives both sides), ``tongueOut``
has no ICT shape, and ``cheekRaiser_L/R`` have no ARKit column.

Frame and units: millimetres (the source is in centimetres; :func:`load_face_rig`
scales by 10), +y up, the face looks toward +z, +x is the subject's left.

Data: ``facesynth/data/ict_face.npz`` and ``ict_face_arkit.tsv``, MIT licensed, with
attribution in ``facesynth/data/ict_face.LICENSE``.
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass, field
from functools import lru_cache
from importlib import resources

import numpy as np

from facesynth.base.errors import InputError

CM_TO_MM = 10.0
#: One unit of ARKit ``eyeLook*`` weight as a rotation of the eye, radians: the slope of the
#: Live Link Face capture's eye yaw and pitch against (out - in) and (up - down) (0.58 to 0.62).
GAZE_RADIANS_PER_WEIGHT = 0.61


@dataclass(frozen=True)
class Rig:
    """A linear blendshape rig: ``vertices = neutral + sum_e w[e] * deltas[e]``, w in [0, 1].

    name : the rig's name; sha256 : hex digest of its data (identifies it in artifacts).
    neutral : (V, 3) float64, the rest mesh in rig units (mm for the built-in rig)
    faces : (F, 3) int64, triangles counter-clockwise seen from outside
    shape_names : the E blendshape names
    deltas : (E, V, 3) float32, each shape minus the neutral mesh, rig units
    binding : marker name -> vertex index (empty for a rig not bound to markers)
    landmarks68 : (68,) int64, Multi-PIE 68-point landmark vertices, or None
    loops : boundary loops by name ('mouth', 'eye_L', 'eye_R', 'neck'), each (n,) int64 in order
    arkit_names : the 52 ARKit blendshape names, in Live Link Face column order (empty: no ARKit map)
    arkit_to_rig : (52, E) float64 matrix taking ARKit weights to rig weights, or None

    The built-in rig (:func:`load_face_rig`) has every field; a user's rig (read by
    :func:`facesynth.domain.rig.loading.read_rig`) has a name, digest, meshes and binding only.
    """

    name: str
    sha256: str
    neutral: np.ndarray
    faces: np.ndarray
    shape_names: tuple[str, ...]
    deltas: np.ndarray
    binding: dict[str, int] = field(default_factory=dict)
    landmarks68: np.ndarray | None = None
    loops: dict[str, np.ndarray] = field(default_factory=dict)
    arkit_names: tuple[str, ...] = ()
    arkit_to_rig: np.ndarray | None = None

    def shape_index(self, name: str) -> int:
        """Index of the shape called ``name`` (ICT spelling, e.g. 'jawOpen', 'mouthSmile_L')."""
        return self.shape_names.index(name)

    def evaluate(self, weights: np.ndarray, vertices: np.ndarray | None = None) -> np.ndarray:
        """Posed vertices.

        weights : (T, E) or (E,) rig weights. vertices : optional (K,) indices to evaluate only
        those (e.g. marker vertices). Returns (T, K or V, 3) float64 in rig units, or (K or V, 3)
        for 1-D weights.
        """
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
                             "place them on it with `facesynth bind CAPTURE --rig RIG -o binding.csv` (CAPTURE: one of "
                             "the takes) and give that CSV with --binding.")
        bad = [m for m in self.binding if not 0 <= self.binding[m] < len(self.neutral)]
        if bad:
            raise InputError(f"{where}: marker {bad[0]!r} is bound to vertex {self.binding[bad[0]]}, but rig "
                             f"{self.name!r} has {len(self.neutral)} vertices; use the binding made for this rig.")
        return np.array(cols), np.array([self.binding[marker_names[c]] for c in cols])

    def arkit_matrix(self) -> np.ndarray:
        """:attr:`arkit_to_rig`, refused for a rig without an ARKit mapping."""
        if self.arkit_to_rig is None:
            raise ValueError(f"rig {self.name!r} has no ARKit mapping")
        return self.arkit_to_rig

    def from_arkit(self, arkit_weights: np.ndarray) -> np.ndarray:
        """Rig weights (..., E) for ARKit weights (..., 52) in :attr:`arkit_names` order."""
        return np.asarray(arkit_weights, dtype=np.float64) @ self.arkit_matrix()

    def to_arkit(self, rig_weights: np.ndarray) -> np.ndarray:
        """ARKit weights (..., 52) for rig weights (..., E): split shapes averaged, tongueOut 0."""
        arkit_to_rig = self.arkit_matrix()
        counts = arkit_to_rig.sum(axis=1)
        return (np.asarray(rig_weights, dtype=np.float64) @ arkit_to_rig.T) / np.maximum(counts, 1.0)


def _read_arkit_table(shape_names: tuple[str, ...]) -> tuple[tuple[str, ...], np.ndarray]:
    """Parse ``ict_face_arkit.tsv``: Live Link Face column -> ICT shapes ('-' for none)."""
    text = resources.files("facesynth").joinpath("data/ict_face_arkit.tsv").read_text(encoding="utf-8")
    names, rows = [], []
    for line in text.splitlines():
        if not line or line.startswith("#"):
            continue
        column, target, *_ = line.split("\t")
        if column in ("Timecode", "BlendShapeCount") or column.startswith(("Head", "LeftEye", "RightEye")):
            continue
        row = np.zeros(len(shape_names))
        if target != "-":
            for ict in target.split("+"):
                row[shape_names.index(ict)] = 1.0
        names.append(column[0].lower() + column[1:])
        rows.append(row)
    return tuple(names), np.array(rows)


@lru_cache(maxsize=1)
def load_face_rig() -> Rig:
    """The ICT-FaceKit rig from the package data, in millimetres, not bound to markers (cached;
    treat as read-only)."""
    with resources.files("facesynth").joinpath("data/ict_face.npz").open("rb") as fh:
        data = np.load(fh, allow_pickle=False)
        shape_names = tuple(str(n) for n in data["expr_names"])
        neutral = data["vertices"].astype(np.float64) * CM_TO_MM
        deltas = data["expr_deltas"].astype(np.float32) * np.float32(CM_TO_MM)
        faces = data["faces"].astype(np.int64)
        landmarks = data["landmarks68"].astype(np.int64)
        loops = {k[len("loop_"):]: data[k].astype(np.int64) for k in data.files if k.startswith("loop_")}
    arkit_names, arkit_to_rig = _read_arkit_table(shape_names)
    for array in (neutral, deltas, faces, landmarks, arkit_to_rig, *loops.values()):
        array.setflags(write=False)
    return Rig(BUILTIN_RIG_NAME, builtin_rig_sha256(), neutral, faces, shape_names, deltas, {}, landmarks, loops,
               arkit_names, arkit_to_rig)


#: The name ``curves`` and ``keyshapes`` artifacts give the built-in rig.
BUILTIN_RIG_NAME = "ict-facekit"


@lru_cache(maxsize=1)
def builtin_rig_sha256() -> str:
    """Hex sha256 identifying the built-in rig: of its two data files' bytes, in order."""
    digest = hashlib.sha256()
    for name in ("data/ict_face.npz", "data/ict_face_arkit.tsv"):
        digest.update(resources.files("facesynth").joinpath(name).read_bytes())
    return digest.hexdigest()


def gaze_from_rig_weights(weights: np.ndarray, shape_names: tuple[str, ...] | list[str]) -> np.ndarray | None:
    """Gaze (T, 2, 2) radians from ARKit-style rig weights (T, E): per eye (the subject's
    left at +x, then right) yaw toward +x and pitch up, from ``eyeLookIn/Out/Up/Down_L/_R``
    at :data:`GAZE_RADIANS_PER_WEIGHT`. None when the rig has no ``eyeLook*`` shapes."""
    names = list(shape_names)
    need = [f"eyeLook{d}_{s}" for s in "LR" for d in ("In", "Out", "Up", "Down")]
    if not all(n in names for n in need):
        return None
    w = np.atleast_2d(np.asarray(weights, np.float64))
    g = lambda n: w[:, names.index(n)]  # noqa: E731
    k = GAZE_RADIANS_PER_WEIGHT
    left = np.stack([k * (g("eyeLookOut_L") - g("eyeLookIn_L")), k * (g("eyeLookUp_L") - g("eyeLookDown_L"))], 1)
    right = np.stack([k * (g("eyeLookIn_R") - g("eyeLookOut_R")), k * (g("eyeLookUp_R") - g("eyeLookDown_R"))], 1)
    return np.stack([left, right], 1)
