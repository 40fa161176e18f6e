"""The virtual actress's marker set: about 90 named markers glued to vertices of the face rig.

The face is the production rig of :mod:`facesynth.domain.rig.face` (ICT-FaceKit, millimetres, +y
up, the face looks toward +z, +x is the subject's left). Markers sit where a facial capture
puts them: outer and inner lip lines, mouth corners, chin and jaw line, cheeks and
nasolabial folds, nose, eyelids, brows and forehead, plus eight markers on the upper forehead,
nose bridge, temples and the sides of the head that no blendshape moves by more than
:data:`RIGID_MAX_MM` (``rigid = 1`` in ``markers.csv``; the lips move up to 40 mm): the set a normalizer should fit the
head pose on.

Each marker is placed by a target (x, y) on the front of the neutral face: the
front-most vertex (largest z) within a few millimetres of it. The inner-lip markers are the
68-landmark inner-lip points of the rig (landmarks 60-67), which lie on the line where the
lips touch; the rig's ``mouth`` boundary loop lies deeper, inside the mouth, and stays about
11 mm open even with the lips sealed, so it cannot serve as the contact line. Rigid markers
take, within a small radius of their target, the vertex the blendshapes move least.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .face import Rig

#: The lower-lip marker used for trajectory plots, like the paper's marker #79.
LOWER_LIP_MARKER = "LLO_C"
#: Centre inner-lip markers; their distance is the lip gap (under a millimetre when the lips touch).
LIP_GAP_MARKERS = ("ULI_C", "LLI_C")
#: A marker is rigid when no single blendshape moves its vertex by more than this (mm).
RIGID_MAX_MM = 2.0

# Rig landmarks (Multi-PIE 68 numbering) of the inner lip line: upper 61-63, lower 65-67, corners 60/64.
_INNER_UPPER = {"R1": 61, "C": 62, "L1": 63}
_INNER_LOWER = {"R1": 67, "C": 66, "L1": 65}
_INNER_CORNERS = {"MC_R": 48, "MC_L": 54}


@dataclass(frozen=True)
class MarkerSet:
    """Named markers on rig vertices.

    names : the M marker names, in capture order.
    vertices : (M,) int64, the rig vertex each marker is glued to.
    rigid : (M,) bool, the head-pose markers (no blendshape moves them by more than :data:`RIGID_MAX_MM`).
    lip_pairs : (P, 2) int64 rig vertices (upper, lower) facing each other on the inner lip line.
    lip_upper, lip_lower : rig vertices of the central upper and lower lip (|x| < 12 mm, from
        the inner lip line to the front of the lips): the surfaces whose distance is the lip
        gap on the mesh (:func:`mesh_lip_gap`).
    """

    names: list[str]
    vertices: np.ndarray
    rigid: np.ndarray
    lip_pairs: np.ndarray
    lip_upper: np.ndarray
    lip_lower: np.ndarray

    def binding(self) -> dict[str, int]:
        """Marker name -> vertex index, in marker order."""
        return dict(zip(self.names, self.vertices.tolist()))


def _front_vertex(rig: Rig, x: float, y: float, radius: float = 2.5) -> int:
    """The front-most neutral vertex within ``radius`` mm of (x, y) in the image plane."""
    n = rig.neutral
    for r in (radius, 2 * radius, 4 * radius):
        near = np.nonzero(np.hypot(n[:, 0] - x, n[:, 1] - y) < r)[0]
        if len(near):
            return int(near[np.argmax(n[near, 2])])
    raise ValueError(f"no rig vertex near ({x}, {y}) mm")


def _still_vertex(rig: Rig, x: float, y: float, motion: np.ndarray, radius: float = 12.0) -> int:
    """Among the vertices within ``radius`` mm of (x, y) on the front half of the head (within
    25 mm of the front-most depth there), the one the shapes move least."""
    n = rig.neutral
    near = np.nonzero((np.hypot(n[:, 0] - x, n[:, 1] - y) < radius) & (n[:, 2] > 40.0))[0]
    near = near[n[near, 2] > n[near, 2].max() - 25.0]
    return int(near[np.argmin(motion[near])])


def _layout() -> list[tuple[str, float, float]]:
    """(name, x, y) targets in mm on the neutral face (x: subject's left positive)."""
    m: list[tuple[str, float, float]] = []
    tags7 = ("R3", "R2", "R1", "C", "L1", "L2", "L3")
    for tag, x in zip(tags7, (-17, -11, -5.5, 0, 5.5, 11, 17)):
        m.append((f"ULO_{tag}", x, -24.5 - 0.012 * x * x))  # the vermilion border of the upper lip
    for tag, x in zip(tags7, (-16, -10.5, -5, 0, 5, 10.5, 16)):
        m.append((f"LLO_{tag}", x, -43.5 + 0.012 * x * x))  # the vermilion border of the lower lip
    m += [("MENT_C", 0, -54), ("CHIN_C", 0, -66), ("CHIN_R", -15, -64), ("CHIN_L", 15, -64), ("CHIN_B", 0, -75)]
    for k, (x, y) in enumerate([(30, -67), (42, -60), (53, -48), (60, -32)], 1):
        m += [(f"JAW_R{k}", -x, y), (f"JAW_L{k}", x, y)]
    k = 0
    for y in (-18, -2):
        for x in (28, 38, 48, 58):
            k += 1
            m += [(f"CHK_R{k}", -x, y), (f"CHK_L{k}", x, y)]
    m += [("NOSE_MID", 0, 21), ("NOSE_TIP", 0, 4), ("NOSE_ALA_R", -15, -6), ("NOSE_ALA_L", 15, -6), ("NOSE_BASE", 0, -11)]
    m += [("NLF_R1", -21, -18), ("NLF_L1", 21, -18), ("NLF_R2", -27, -32), ("NLF_L2", 27, -32)]
    for k, x in enumerate((11, 22, 33, 43, 51), 1):
        y = 61.5 - 0.0025 * (x - 25) ** 2
        m += [(f"BROW_R{k}", -x, y), (f"BROW_L{k}", x, y)]
    m += [("FH_R2", -34, 74), ("FH_R1", -17, 78), ("FH_C", 0, 80), ("FH_L1", 17, 78), ("FH_L2", 34, 74)]
    for side, sx in (("R", -1), ("L", 1)):
        m += [(f"EYE_{side}_UP", sx * 31, 45), (f"EYE_{side}_LO", sx * 31, 26),
              (f"EYE_{side}_OUT", sx * 50, 33), (f"EYE_{side}_IN", sx * 12, 30)]
    return m


#: Rigid markers: (name, x, y) targets; each takes the stillest vertex near its target.
_RIGID_LAYOUT = (("FH_T", 0, 100), ("FH_TR", -25, 100), ("FH_TL", 25, 100), ("NOSE_BRIDGE", 0, 32),
                 ("TEMPLE_R", -74, 50), ("TEMPLE_L", 74, 50), ("HEAD_R", -76, 30), ("HEAD_L", 76, 30))


_RIGID_NAMES = frozenset(name for name, _, _ in _RIGID_LAYOUT)


def build_marker_set(rig: Rig) -> MarkerSet:
    """The actress's markers on ``rig``, with their rigid flags and the inner-lip contact pairs."""
    motion = np.linalg.norm(rig.deltas, axis=2).max(axis=0)  # (V,) mm, the largest any shape moves each vertex
    names, vertices = [], []
    landmarks = rig.landmarks68
    if landmarks is None:
        raise ValueError(f"rig {rig.name!r} has no 68-point landmarks to place the inner-lip markers on")
    for name, x, y in _layout():
        names.append(name)
        vertices.append(_front_vertex(rig, x, y))
        if name == "ULO_L3":  # the inner lip line after the upper outer lip
            for tag, k in _INNER_UPPER.items():
                names.append(f"ULI_{tag}")
                vertices.append(int(landmarks[k]))
        if name == "LLO_L3":
            for tag, k in _INNER_LOWER.items():
                names.append(f"LLI_{tag}")
                vertices.append(int(landmarks[k]))
            for corner, k in _INNER_CORNERS.items():
                names.append(corner)
                vertices.append(int(landmarks[k]))
    for name, x, y in _RIGID_LAYOUT:
        names.append(name)
        vertices.append(_still_vertex(rig, x, y, motion))
    vertices = np.array(vertices, np.int64)
    if len(set(vertices.tolist())) != len(vertices):
        raise ValueError("two markers share a rig vertex; move a target")
    rigid = np.array([name in _RIGID_NAMES for name in names])
    if (motion[vertices[rigid]] > RIGID_MAX_MM).any():
        raise ValueError("a rigid marker's vertex moves with the blendshapes; move its target")
    lip_pairs = np.array([[landmarks[_INNER_UPPER[t]], landmarks[_INNER_LOWER[t]]] for t in ("R1", "C", "L1")], np.int64)
    upper, lower = lip_surfaces(rig)
    return MarkerSet(names, vertices, rigid, lip_pairs, upper, lower)


def lip_surfaces(rig: Rig) -> tuple[np.ndarray, np.ndarray]:
    """Vertices of the central upper and lower lip: those within 12 mm of the midline around
    the lip line, split by whether the jaw carries them (jawOpen moves the lower lip ~35 mm)."""
    n = rig.neutral
    jaw_dy = rig.deltas[rig.shape_index("jawOpen")][:, 1]
    centre = (np.abs(n[:, 0]) < 12.0) & (n[:, 2] > 104.0)
    upper = np.nonzero(centre & (jaw_dy > -6.0) & (n[:, 1] > -34.5) & (n[:, 1] < -27.0))[0]
    lower = np.nonzero(centre & (jaw_dy < -20.0) & (n[:, 1] > -41.0) & (n[:, 1] < -33.0))[0]
    return upper, lower


def mesh_lip_gap(rig: Rig, weights: np.ndarray, upper: np.ndarray, lower: np.ndarray) -> np.ndarray:
    """The lip gap on the posed mesh: per frame, the smallest distance (mm) between the upper
    and the lower lip surface (vertex sets ``upper``, ``lower``; 0.7 mm at rest, where the
    lips touch). weights : (T, E) rig weights. Returns (T,)."""
    weights = np.atleast_2d(weights)
    a = rig.evaluate(weights, vertices=upper)
    b = rig.evaluate(weights, vertices=lower)
    return np.array([np.sqrt(((a[t][:, None] - b[t][None]) ** 2).sum(-1).min()) for t in range(len(weights))])
