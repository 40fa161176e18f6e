"""The virtual actress's face: a mesh, ~90 named markers bound to it, and a rig.

Frame (millimetres): +x is the subject's left, +y up, +z out of the face. The mouth is a
slit at ``MOUTH_Y``: vertices along it are duplicated into an upper and a lower copy, so
the lips part when the jaw opens and mesh-surface distances go around the mouth opening
(paper Fig. 12). The eyes are holes.

The rig maps articulatory and expression parameters to a displacement of any rest point:
the jaw rotates about a pivot near the jaw joint; the lower lip follows the jaw unless the
lip-closure parameter holds it at the rest (closed) position, which is what makes
bilabials close the lips.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

MOUTH_Y = -40.0
MOUTH_HALF_WIDTH = 25.0
EYE_CENTERS = ((-32.0, 30.0), (32.0, 30.0))
EYE_AXES = (13.0, 5.0)
JAW_PIVOT = np.array([0.0, 5.0, -70.0])
JAW_MAX_RAD = 0.12

#: Rig parameters, in the column order of parameter arrays.
PARAMS = ("jaw", "round", "spread", "close", "tuck", "raise", "smile", "sad", "angry")
P = {name: i for i, name in enumerate(PARAMS)}


@dataclass
class FaceModel:
    """A face mesh and its marker binding.

    vertices : (V, 3) float64, mm, rest pose (mouth closed, neutral expression)
    faces : (F, 3) int64, counter-clockwise seen from outside
    lower : (V,) bool, vertex belongs to the lower side of the mouth line
    marker_names : the markers' names
    marker_vertices : (M,) int64, the vertex each marker is bound to
    """

    vertices: np.ndarray
    faces: np.ndarray
    lower: np.ndarray
    marker_names: list[str]
    marker_vertices: np.ndarray


def _surface_z(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Depth of the face surface (mm) over the (x, y) plane."""
    def g(cx, cy, sx, sy):
        return np.exp(-((x - cx) ** 2 / (2 * sx**2) + (y - cy) ** 2 / (2 * sy**2)))

    base = 95.0 * np.sqrt(np.clip(1.0 - (x / 82.0) ** 2 - ((y + 10.0) / 128.0) ** 2, 0.0, None))
    nose_profile = np.interp(y, [-14, -6, 2, 20, 38, 46], [0, 14, 22, 13, 5, 0])
    nose = nose_profile * np.exp(-(x**2) / (2 * (7.0 + 0.25 * np.clip(2 - y, 0, None)) ** 2))
    eyes = -8.0 * (g(-32, 30, 12, 9) + g(32, 30, 12, 9))
    brow = 4.0 * g(-25, 46, 16, 5) + 4.0 * g(25, 46, 16, 5)
    lips = 6.0 * g(0, MOUTH_Y, 24, 9)
    chin = 5.0 * g(0, -82, 16, 10)
    cheeks = 3.0 * (g(-45, -10, 14, 14) + g(45, -10, 14, 14))
    return base + nose + eyes + brow + lips + chin + cheeks


def build_face(spacing: float = 2.0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Build the face mesh. Returns vertices (V,3) mm, faces (F,3), lower (V,) bool."""
    xs = np.arange(-78.0, 78.0 + 1e-9, spacing)
    mouth_row = int(round((MOUTH_Y - (-118.0)) / spacing))
    ys = -118.0 + spacing * np.arange(int(round((98.0 + 118.0) / spacing)) + 1)
    ys[mouth_row] = MOUTH_Y
    gx, gy = np.meshgrid(xs, ys)  # (rows=y, cols=x)
    inside = (gx / 80.0) ** 2 + ((gy + 10.0) / 112.0) ** 2 <= 1.0
    n_rows, n_cols = gx.shape

    index = -np.ones(gx.shape, dtype=np.int64)
    index[inside] = np.arange(inside.sum())
    vx, vy = gx[inside], gy[inside]
    lower = vy < MOUTH_Y - 1e-9
    # Duplicate the slit vertices: the originals serve the upper lip, the copies the lower lip.
    slit_cols = np.nonzero(np.abs(xs) < MOUTH_HALF_WIDTH - 1e-9)[0]
    slit_cols = slit_cols[inside[mouth_row, slit_cols]]
    lower_index = index.copy()
    copies = np.arange(len(vx), len(vx) + len(slit_cols))
    lower_index[mouth_row, slit_cols] = copies
    vx = np.concatenate([vx, xs[slit_cols]])
    vy = np.concatenate([vy, np.full(len(slit_cols), MOUTH_Y)])
    lower = np.concatenate([lower, np.ones(len(slit_cols), bool)])

    faces = []
    for r in range(n_rows - 1):
        # Cells just below the slit take the lower copies as their top row.
        top = (lower_index if r + 1 == mouth_row else index)[r + 1]
        bottom = index[r]
        a, b = bottom[:-1], bottom[1:]
        c, d = top[1:], top[:-1]
        ok = (a >= 0) & (b >= 0) & (c >= 0) & (d >= 0)
        faces.append(np.stack([a[ok], b[ok], c[ok]], 1))
        faces.append(np.stack([a[ok], c[ok], d[ok]], 1))
    faces = np.concatenate(faces)

    vertices = np.stack([vx, vy, _surface_z(vx, vy)], 1)
    centroid = vertices[faces].mean(axis=1)
    in_eye = np.zeros(len(faces), bool)
    for cx, cy in EYE_CENTERS:
        in_eye |= ((centroid[:, 0] - cx) / EYE_AXES[0]) ** 2 + ((centroid[:, 1] - cy) / EYE_AXES[1]) ** 2 < 1.0
    faces = faces[~in_eye]
    used = np.unique(faces)
    remap = -np.ones(len(vertices), np.int64)
    remap[used] = np.arange(len(used))
    return vertices[used], remap[faces], lower[used]


def _marker_layout() -> list[tuple[str, float, float, str]]:
    """(name, x, y, side) targets; side 'u'/'l' pins lip markers to a side of the slit."""
    m: list[tuple[str, float, float, str]] = []
    xs7 = (-18, -12, -6, 0, 6, 12, 18)
    tags7 = ("R3", "R2", "R1", "C", "L1", "L2", "L3")
    for tag, x in zip(tags7, xs7):
        m.append((f"ULO_{tag}", x, MOUTH_Y + 9 - 0.006 * x * x, "u"))
    for tag, x in zip(tags7, xs7):
        m.append((f"LLO_{tag}", x, MOUTH_Y - 11 + 0.008 * x * x, "l"))
    for tag, x in zip(("R2", "R1", "C", "L1", "L2"), (-14, -8, 0, 8, 14)):
        m.append((f"ULI_{tag}", x, MOUTH_Y, "u"))
        m.append((f"LLI_{tag}", x, MOUTH_Y, "l"))
    m += [("MC_R", -MOUTH_HALF_WIDTH - 1, MOUTH_Y, ""), ("MC_L", MOUTH_HALF_WIDTH + 1, MOUTH_Y, "")]
    m += [("MENT_C", 0, -62, ""), ("CHIN_C", 0, -80, ""), ("CHIN_R", -15, -76, ""), ("CHIN_L", 15, -76, ""), ("CHIN_B", 0, -96, "")]
    for k, (x, y) in enumerate([(35, -72), (48, -57), (58, -37), (64, -16)], 1):
        m += [(f"JAW_R{k}", -x, y, ""), (f"JAW_L{k}", x, y, "")]
    k = 0
    for y in (-22, -6):
        for x in (30, 40, 50, 60):
            k += 1
            m += [(f"CHK_R{k}", -x, y, ""), (f"CHK_L{k}", x, y, "")]
    m += [("NOSE_BRIDGE", 0, 40, ""), ("NOSE_MID", 0, 20, ""), ("NOSE_TIP", 0, 2, ""),
          ("NOSE_ALA_R", -14, -3, ""), ("NOSE_ALA_L", 14, -3, ""), ("NOSE_BASE", 0, -13, "")]
    m += [("NLF_R1", -22, -16, ""), ("NLF_L1", 22, -16, ""), ("NLF_R2", -30, -30, ""), ("NLF_L2", 30, -30, "")]
    for k, x in enumerate((10, 20, 30, 40, 50), 1):
        y = 49 - 0.0015 * (x - 20) ** 2
        m += [(f"BROW_R{k}", -x, y, ""), (f"BROW_L{k}", x, y, "")]
    m += [("FH_R2", -32, 70, ""), ("FH_R1", -16, 72, ""), ("FH_C", 0, 73, ""), ("FH_L1", 16, 72, ""), ("FH_L2", 32, 70, ""), ("FH_T", 0, 88, "")]
    for side, sx in (("R", -1), ("L", 1)):
        cx = sx * 32
        m += [(f"EYE_{side}_UP", cx, 38, ""), (f"EYE_{side}_LO", cx, 22, ""),
              (f"EYE_{side}_OUT", sx * 48, 30, ""), (f"EYE_{side}_IN", sx * 17, 31, "")]
    m += [("TEMPLE_R", -66, 42, ""), ("TEMPLE_L", 66, 42, ""), ("HEAD_R", -72, 8, ""), ("HEAD_L", 72, 8, "")]
    return m


#: The lower-lip marker used for trajectory plots, like the paper's marker #79.
LOWER_LIP_MARKER = "LLO_C"
#: Centre inner-lip markers; their distance is the lip gap (0 when the lips touch).
LIP_GAP_MARKERS = ("ULI_C", "LLI_C")


def build_face_model(spacing: float = 2.0) -> FaceModel:
    """The face mesh with its markers bound to the nearest vertices on the right side of the mouth."""
    vertices, faces, lower = build_face(spacing)
    names, bound = [], []
    for name, x, y, side in _marker_layout():
        d = (vertices[:, 0] - x) ** 2 + (vertices[:, 1] - y) ** 2
        if side == "u":
            d = np.where(lower, np.inf, d)
        elif side == "l":
            d = np.where(lower, d, np.inf)
        names.append(name)
        bound.append(int(np.argmin(d)))
    return FaceModel(vertices, faces, lower, names, np.array(bound, np.int64))


class Rig:
    """Displacement fields of the face, evaluated at a fixed set of rest points.

    points : (K, 3) rest positions, mm; lower : (K,) bool side of the mouth line.
    """

    def __init__(self, points: np.ndarray, lower: np.ndarray):
        x, y = points[:, 0], points[:, 1]
        self.points = points.astype(np.float64)

        def g(cx, cy, sx, sy):
            return np.exp(-((x - cx) ** 2 / (2 * sx**2) + (y - cy) ** 2 / (2 * sy**2)))

        ax = np.abs(x)
        in_slit = ax < MOUTH_HALF_WIDTH
        taper = np.clip((MOUTH_HALF_WIDTH - ax) / 4.0, 0.0, 1.0)
        sigma = 2.0 + 10.0 * np.clip((ax - MOUTH_HALF_WIDTH) / 20.0, 0.0, 1.0)
        soft = 1.0 / (1.0 + np.exp(-(MOUTH_Y - y) / sigma))
        hard = lower.astype(float)
        w_jaw = np.where(in_slit, taper * hard + (1 - taper) * soft, soft)
        w_jaw *= np.exp(-np.clip(ax - 50.0, 0, None) ** 2 / (2 * 15.0**2))
        self.w_jaw = w_jaw
        mouth = g(0, MOUTH_Y, 24, 14)
        lip_lo = lower * g(0, MOUTH_Y - 5, 24, 8)
        lip_up = (~lower) * g(0, MOUTH_Y + 5, 24, 8)
        self.lip_lo, self.lip_up = lip_lo, lip_up
        sgn = np.sign(x)
        corner = g(-MOUTH_HALF_WIDTH, MOUTH_Y, 9, 9) + g(MOUTH_HALF_WIDTH, MOUTH_Y, 9, 9)
        zeros = np.zeros_like(x)

        def field(dx, dy, dz):
            return np.stack([dx + zeros, dy + zeros, dz + zeros], 1)

        # Each field has a general part and a lip-separating part (moving the upper and lower
        # lip differently); the latter is scaled by (1 - closure) so a seal stays sealed.
        self.linear = {
            "round": (field(-0.32 * x * mouth, zeros, 7.0 * mouth), field(zeros, -1.2 * lip_up + 1.2 * lip_lo, zeros)),
            "spread": (field(0.16 * x * mouth, 0.8 * corner, -2.0 * mouth), None),
            "tuck": (None, field(zeros, 2.5 * lip_lo, -5.0 * lip_lo)),
            "raise": (None, field(zeros, 3.0 * lip_up, 0.5 * lip_up)),
            "smile": (
                field(
                    5.0 * sgn * corner,
                    5.0 * corner + 4.0 * (g(-42, -15, 15, 14) + g(42, -15, 15, 14)) + 1.5 * (g(-32, 22, 10, 4) + g(32, 22, 10, 4)),
                    -2.0 * corner + 2.0 * (g(-42, -15, 15, 14) + g(42, -15, 15, 14)),
                ),
                field(zeros, 1.0 * lip_up, zeros),
            ),
            "sad": (
                field(
                    zeros,
                    -4.0 * corner + 5.0 * (g(-12, 50, 9, 8) + g(12, 50, 9, 8)) - 1.0 * (g(-38, 47, 10, 8) + g(38, 47, 10, 8)) + 2.0 * g(0, -78, 18, 12),
                    zeros,
                ),
                field(zeros, zeros, 2.0 * lip_lo),
            ),
            "angry": (
                field(
                    -2.0 * sgn * (g(-18, 47, 14, 8) + g(18, 47, 14, 8)) + 2.0 * sgn * (g(-12, -2, 5, 5) + g(12, -2, 5, 5)),
                    -5.0 * (g(-18, 47, 14, 8) + g(18, 47, 14, 8)) + 1.0 * (g(-32, 22, 10, 4) + g(32, 22, 10, 4)),
                    -1.5 * (lip_up + lip_lo),
                ),
                None,
            ),
        }

    def evaluate(self, params: np.ndarray) -> np.ndarray:
        """Positions for each frame's parameters.

        params : (T, len(PARAMS)) float. Returns (T, K, 3) float64, mm.
        """
        params = np.atleast_2d(params)
        theta = JAW_MAX_RAD * params[:, P["jaw"]]
        rel = self.points - JAW_PIVOT
        c, s = np.cos(theta)[:, None], np.sin(theta)[:, None]
        jaw = np.zeros((len(params),) + self.points.shape)
        jaw[:, :, 1] = rel[:, 1] * c - rel[:, 2] * s - rel[:, 1]
        jaw[:, :, 2] = rel[:, 1] * s + rel[:, 2] * c - rel[:, 2]
        close = params[:, P["close"]][:, None]
        # Lip closure holds the lower-lip margin at rest (closed) against the jaw's pull.
        hold = 1.0 - np.clip(close * 1.04, 0.0, 1.0) * np.clip(self.lip_lo * 1.6, 0.0, 1.0)
        out = self.points + jaw * (self.w_jaw * hold)[:, :, None]
        open_lips = 1.0 - np.clip(close[:, 0], 0.0, 1.0)
        for name, (general, lips) in self.linear.items():
            weight = params[:, P[name]]
            if general is not None:
                out += weight[:, None, None] * general[None]
            if lips is not None:
                out += (weight * open_lips)[:, None, None] * lips[None]
        return out
