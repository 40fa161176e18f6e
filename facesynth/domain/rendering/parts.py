"""What a skin mesh lacks, built from the mesh itself: eyeballs behind the eye holes, a dark
mouth cavity behind the mouth hole, upper and lower teeth and a tongue.

A face scan or rig skin (such as the ICT-FaceKit face) is open at the eyes and the mouth:
drawn alone, one sees into the head. :func:`build_scene` finds the mesh's boundary loops,
decides which are the eyes and the mouth from where they are (:func:`classify_holes`; the
meshes facesynth draws have +y up and look toward +z), and builds, once per clip, the
geometry that fills them. :meth:`FaceScene.positions` then places every part for one frame
of the animated skin:

* **Head and jaw.** The skull moves rigidly with the vertices above the brows (forehead and
  scalp), the jaw with the chin below the mouth; both are least-squares rigid fits
  (Kabsch) of those vertices from the rest mesh to the frame. Without head motion the skull
  fit is the identity.
* **Eyeballs.** A sphere per eye hole: its radius is half the hole's width (a human eye is
  about as wide as its lid opening); its centre is the one that puts the lid rim on the
  sphere as nearly as possible (:func:`eyeball_centre`), so the ball fills the opening and
  the lids rest on it. The cornea's axis is the
  face's forward direction (the mean of both holes' normals), iris and pupil are drawn by
  the shader from each vertex's angle to that axis (``eye`` attribute). The ball moves with
  the skull and turns with the gaze when the animation carries one; without gaze data the
  eyes look straight ahead (nothing is invented).
* **Mouth.** The cavity is a tube glued to the mouth loop: ring 0 *is* the loop (the same
  positions each frame, so there is no gap), deeper rings are fixed offsets from each loop
  vertex (back into the head, away from the lip line vertically, in toward the middle), and
  a fan closes the back. Each offset turns with the skull for the upper lip's half of the
  loop and with the jaw for the lower half, so the tube opens with the lips. Upper teeth
  (an arch behind the upper lip) move with the skull, lower teeth and the tongue with the
  jaw. Sizes are fractions of the mouth hole's width.

A mesh without such holes (any OBJ) is drawn as it is: :attr:`FaceScene.notes` says which
parts were left out and why.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from scipy import sparse
from scipy.spatial import ConvexHull, QhullError, cKDTree

#: ``eye`` attribute of every vertex that is not on an eyeball.
NO_EYE = -2.0

# Display-space (sRGB-like, gamma 2) colours and specular strengths of the materials.
SKIN = (0.87, 0.70, 0.61)
LIPS = (0.78, 0.50, 0.48)
SCLERA = (0.90, 0.88, 0.85)
TEETH = (0.86, 0.83, 0.75)
TOOTH_GAP = (0.66, 0.60, 0.53)
GUM = (0.70, 0.38, 0.40)
TONGUE = (0.74, 0.40, 0.41)
CAVITY = (0.34, 0.12, 0.12)
SPECULAR = {"skin": 0.10, "eye": 0.55, "teeth": 0.25, "tongue": 0.15, "cavity": 0.0}


# --- mesh geometry ---------------------------------------------------------------------------

def face_incidence(n_vertices: int, faces: np.ndarray) -> sparse.csr_matrix:
    """(V, F) sparse vertex-face incidence, to sum face normals onto vertices."""
    faces = np.asarray(faces, np.int64)
    rows = faces.reshape(-1)
    cols = np.repeat(np.arange(len(faces)), 3)
    return sparse.csr_matrix((np.ones(len(rows)), (rows, cols)), shape=(n_vertices, len(faces)))


def vertex_normals(vertices: np.ndarray, faces: np.ndarray, incidence: sparse.csr_matrix) -> np.ndarray:
    """Area-weighted smooth vertex normals (V, 3) float64, unit length (zero where undefined)."""
    a, b, c = vertices[faces[:, 0]], vertices[faces[:, 1]], vertices[faces[:, 2]]
    n = incidence @ np.cross(b - a, c - a)
    return n / (np.linalg.norm(n, axis=1, keepdims=True) + 1e-12)


def boundary_loops(faces: np.ndarray, n_vertices: int) -> list[np.ndarray]:
    """The closed boundary loops of a triangle mesh: each (n,) int64 vertex indices in the
    order of its boundary half-edges (an edge used by one triangle only), ordered by their
    first vertex. Where a vertex starts two boundary half-edges the lower-numbered end is taken."""
    f = np.asarray(faces, np.int64)
    a, b = f.reshape(-1), f[:, [1, 2, 0]].reshape(-1)
    n = np.int64(max(n_vertices, 1))
    boundary = ~np.isin(a * n + b, b * n + a)
    a, b = a[boundary], b[boundary]
    nxt: dict[int, int] = {}
    for s, e in sorted(zip(a.tolist(), b.tolist())):
        nxt.setdefault(s, e)
    seen: set[int] = set()
    loops = []
    for start in sorted(nxt):
        if start in seen:
            continue
        loop, v = [start], nxt[start]
        seen.add(start)
        while v != start and v in nxt and v not in seen:
            loop.append(v)
            seen.add(v)
            v = nxt[v]
        if v == start and len(loop) >= 3:
            loops.append(np.array(loop, np.int64))
    return loops


def rigid_fit(source: np.ndarray, target: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Least-squares rotation R (3, 3) and translation t (3,) with target ~ source @ R.T + t
    (Kabsch), over the rows finite in both; the identity when fewer than 3 are."""
    ok = np.isfinite(source).all(1) & np.isfinite(target).all(1)
    if ok.sum() < 3:
        return np.eye(3), np.zeros(3)
    s, t = source[ok], target[ok]
    ms, mt = s.mean(0), t.mean(0)
    u, _, vt = np.linalg.svd((t - mt).T @ (s - ms))
    d = np.sign(np.linalg.det(u @ vt)) or 1.0
    r = u @ np.diag([1.0, 1.0, d]) @ vt
    return r, mt - ms @ r.T


# --- which holes are eyes and mouth ----------------------------------------------------------

@dataclass(frozen=True)
class Hole:
    """A boundary loop seen as a hole: loop (n,) vertex indices; centre (3,); normal (3,) unit,
    pointing out of the surface; axis (3,) unit, its longest direction (toward +x); width,
    height : extents along the axis and across it, mesh units."""

    loop: np.ndarray
    centre: np.ndarray
    normal: np.ndarray
    axis: np.ndarray
    width: float
    height: float


@dataclass(frozen=True)
class FaceLayout:
    """eyes : (hole at +x = subject's left, hole at -x) or None; mouth : Hole or None;
    notes : why a part is missing (for ``-v``)."""

    eyes: tuple[Hole, Hole] | None
    mouth: Hole | None
    notes: tuple[str, ...]


def _hole(rest: np.ndarray, normals: np.ndarray, loop: np.ndarray) -> Hole:
    p = rest[loop]
    centre = p.mean(0)
    q = p - centre
    # The rim itself often curls into the head (lid margins, inner lips), so the hole faces
    # the way the skin around it does: the vertices 0.6 to 1.0 of its span from its centre.
    span = float(np.ptp(q, axis=0).max())
    d = np.linalg.norm(rest - centre, axis=1)
    ring = (d > 0.6 * span) & (d < 1.0 * span)
    normal = normals[ring].sum(0) if ring.any() else normals[loop].sum(0)
    normal = normal / (np.linalg.norm(normal) + 1e-12)
    q = q - np.outer(q @ normal, normal)
    axis = np.linalg.svd(q, full_matrices=False)[2][0]
    axis = -axis if axis[0] < 0 else axis
    across = np.cross(normal, axis)
    return Hole(loop, centre, normal, axis, float(np.ptp(q @ axis)), float(np.ptp(q @ across)))


def classify_holes(rest: np.ndarray, faces: np.ndarray, normals: np.ndarray | None = None) -> FaceLayout:
    """Find the eye pair and the mouth among the boundary loops of a rest mesh (V, 3) with
    triangles ``faces`` (F, 3), +y up and looking toward +z.

    Candidates face forward (the normal of the skin around them has z > 0.3) and are smaller than half the mesh's
    width (an open mask's outer rim is not a hole). Eyes: two candidates side by side (their
    height and depth differ by less than a quarter of their separation, widths within 1.5x,
    symmetric about the mesh's middle), the highest such pair. Mouth: a candidate wider than
    tall, centred between the eyes and below them (0.4 to 2 eye separations), or, without
    eyes, centred in the mesh's lower half; the widest one."""
    rest = np.asarray(rest, np.float64)
    if normals is None:
        normals = vertex_normals(rest, faces, face_incidence(len(rest), faces))
    lo, hi = rest.min(0), rest.max(0)
    mid_x, size_x = (lo[0] + hi[0]) / 2, hi[0] - lo[0]
    holes = [_hole(rest, normals, loop) for loop in boundary_loops(faces, len(rest))]
    cand = [h for h in holes if h.normal[2] > 0.3 and 0 < h.width < 0.5 * size_x]
    notes = []
    eyes, best = None, -np.inf
    for i, a in enumerate(cand):
        for b in cand[i + 1:]:
            sep = abs(a.centre[0] - b.centre[0])
            if (sep > max(a.width, b.width) and abs(a.centre[1] - b.centre[1]) < 0.25 * sep
                    and abs(a.centre[2] - b.centre[2]) < 0.25 * sep and max(a.width, b.width) < 1.5 * min(a.width, b.width)
                    and abs((a.centre[0] + b.centre[0]) / 2 - mid_x) < 0.2 * sep and a.centre[1] > best):
                eyes, best = ((a, b) if a.centre[0] > b.centre[0] else (b, a)), a.centre[1]
    if eyes is None:
        notes.append("no pair of eye holes found: no eyeballs drawn")
    rest_cand = [h for h in cand if eyes is None or (h is not eyes[0] and h is not eyes[1])]
    if eyes is not None:
        sep = eyes[0].centre[0] - eyes[1].centre[0]
        eye_mid = (eyes[0].centre + eyes[1].centre) / 2
        mouths = [h for h in rest_cand if h.width > h.height and abs(h.centre[0] - eye_mid[0]) < 0.3 * sep
                  and 0.4 * sep < eye_mid[1] - h.centre[1] < 2.0 * sep and 0.3 * sep < h.width < 1.5 * sep]
    else:
        mouths = [h for h in rest_cand if h.width > h.height and abs(h.centre[0] - mid_x) < 0.1 * size_x
                  and h.centre[1] < (lo[1] + hi[1]) / 2]
    mouth = max(mouths, key=lambda h: h.width) if mouths else None
    if mouth is None:
        notes.append("no mouth hole found: no mouth interior, teeth or tongue drawn")
    return FaceLayout(eyes, mouth, tuple(notes))


# --- procedural parts ------------------------------------------------------------------------

def _linear(rgb) -> np.ndarray:
    """Display colour (gamma 2) -> linear albedo."""
    return np.asarray(rgb, np.float64) ** 2


@dataclass
class _Part:
    """Geometry of one procedural part in its rest pose: vertices (n, 3), faces (f, 3) local
    indices, colour (n, 3) display space, specular strength, eye attribute (n,)."""

    vertices: np.ndarray
    faces: np.ndarray
    colour: np.ndarray
    specular: float
    eye: np.ndarray | None = None


def _grid_faces(rows: int, cols: int, closed: bool = False) -> np.ndarray:
    """Two triangles per cell of a (rows, cols) vertex grid, counter-clockwise for row index
    growing along the first tangent and column index along the second."""
    c = cols if closed else cols - 1
    r, k = np.meshgrid(np.arange(rows - 1), np.arange(c), indexing="ij")
    a = r * cols + k
    b = r * cols + (k + 1) % cols
    d, e = a + cols, b + cols
    return np.concatenate([np.stack([a, d, b], -1).reshape(-1, 3), np.stack([b, d, e], -1).reshape(-1, 3)])


def _orient(part: _Part, inside: np.ndarray | None = None, outward: bool = True) -> _Part:
    """Flip the winding if the part's mean normal points the wrong way: away from ``inside``
    (a point) when ``outward``, toward it otherwise."""
    v, f = part.vertices, part.faces
    n = np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])
    centre = v[f].mean(1)
    sign = np.sum(n * (centre - inside)) if inside is not None else 1.0
    if (sign < 0) == outward:
        part.faces = part.faces[:, ::-1].copy()
    return part


def eye_sphere(rings_deg=(0, 4, 7, 9.6, 14, 20, 25, 30, 36, 45, 60, 75, 90, 105, 120), segments: int = 32):
    """Unit front cap of a sphere about +z: vertices (n, 3), faces (f, 3) facing out, and each
    vertex's cosine to +z. Rings sit exactly on the pupil (9.6 deg) and iris (30 deg) edges."""
    theta = np.deg2rad(np.asarray(rings_deg[1:], np.float64))
    phi = np.arange(segments) * 2 * np.pi / segments
    ring = np.stack([np.sin(theta)[:, None] * np.cos(phi), np.sin(theta)[:, None] * np.sin(phi),
                     np.cos(theta)[:, None] * np.ones_like(phi)], -1).reshape(-1, 3)
    verts = np.concatenate([[[0.0, 0.0, 1.0]], ring])
    pole = np.stack([np.zeros(segments, np.int64), 1 + np.arange(segments), 1 + (np.arange(segments) + 1) % segments], 1)
    body = 1 + _grid_faces(len(theta), segments, closed=True)
    faces = np.concatenate([pole, body])
    part = _orient(_Part(verts, faces, np.zeros_like(verts), 0.0), np.zeros(3), outward=True)
    return verts, part.faces, verts[:, 2].copy()


#: Iris and pupil edges as cosines of the angle to the cornea's axis (30 and 9.6 degrees:
#: a 6 mm iris and 2 mm pupil radius on a 12 mm ball).
COS_IRIS, COS_PUPIL = float(np.cos(np.deg2rad(30.0))), float(np.cos(np.deg2rad(9.6)))


def _teeth(width: float, upper: bool) -> _Part:
    """An arch of teeth in the mouth's local frame (x across, y up, z out of the face; origin
    at the rest mouth loop's centre), sized by the mouth ``width``: front face, biting edge
    and back face swept along x, with darker columns between teeth and gum at the root."""
    half = 0.40 * width
    # tooth boundaries from the middle outwards (incisors, lateral incisors, canines, premolars)
    edges = np.cumsum([0.0, 0.185, 0.145, 0.16, 0.15, 0.15]) * width * (0.90 if upper else 0.80)
    edges = edges[edges < half]
    xs, dark = [], []
    for e in np.concatenate([-edges[::-1], edges[1:]]) if len(edges) else []:
        gap = 0.009 * width
        xs += [e - gap, e, e + gap]
        dark += [False, True, False]
    xs = np.concatenate([[-half], xs, [half]])
    dark = np.concatenate([[False], dark, [False]])
    order = np.argsort(xs, kind="stable")
    xs, dark = xs[order], dark[order]
    depth = 0.30 * width * (xs / half) ** 2                                  # the arch curves back
    front = (-0.11 if upper else -0.22) * width
    thick = 0.11 * width
    top, edge = (0.28 * width, -0.02 * width) if upper else (-0.30 * width, -0.07 * width)
    root = edge + 0.72 * (top - edge)
    z = front - depth
    parts_v, parts_f, parts_c = [], [], []
    tooth = np.where(dark[:, None], TOOTH_GAP, TEETH)

    def strip(rows_yz, colours):
        n = len(xs)
        v = np.concatenate([np.stack([xs, np.full(n, y), z + dz], 1) for y, dz in rows_yz])
        f = _grid_faces(len(rows_yz), n)
        base = sum(len(p) for p in parts_v)
        parts_v.append(v)
        parts_f.append(f + base)
        parts_c.append(np.concatenate(colours))

    gum = np.tile(GUM, (len(xs), 1))
    strip([(top, 0.0), (root, 0.0), (edge, 0.0)], [gum, tooth, tooth])          # front
    strip([(edge, 0.0), (edge, -thick)], [tooth, tooth])                         # biting edge
    strip([(edge, -thick), (top, -thick)], [tooth * 0.8, gum])                   # back
    v, c = np.concatenate(parts_v), np.concatenate(parts_c)
    # Each strip faces out of the tooth: the front forward, the biting edge toward the other
    # jaw, the back toward the tongue.
    faces = []
    for fs, want in zip(parts_f, ([0.0, 0.0, 1.0], [0.0, -1.0 if upper else 1.0, 0.0], [0.0, 0.0, -1.0])):
        tri = v[fs]
        n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
        faces.append(fs if np.sum(n @ np.asarray(want)) >= 0 else fs[:, ::-1])
    return _Part(v, np.concatenate(faces), c, SPECULAR["teeth"])


def _tongue(width: float, segments: int = 20, rings: int = 8) -> _Part:
    """The top half of a flattened ellipsoid lying on the mouth's floor behind the lower teeth,
    in the mouth's local frame (as :func:`_teeth`)."""
    centre = np.array([0.0, -0.17 * width, -0.64 * width])
    radii = np.array([0.28, 0.09, 0.34]) * width
    theta = np.linspace(0.0, np.pi / 2, rings + 1)[1:]                      # from +y down to the rim
    phi = np.arange(segments) * 2 * np.pi / segments
    unit = np.stack([np.sin(theta)[:, None] * np.cos(phi), np.cos(theta)[:, None] * np.ones_like(phi),
                     np.sin(theta)[:, None] * np.sin(phi)], -1).reshape(-1, 3)
    verts = np.concatenate([[[0.0, 1.0, 0.0]], unit]) * radii + centre
    pole = np.stack([np.zeros(segments, np.int64), 1 + np.arange(segments), 1 + (np.arange(segments) + 1) % segments], 1)
    faces = np.concatenate([pole, 1 + _grid_faces(rings, segments, closed=True)])
    shade = np.concatenate([[1.0], np.repeat(np.linspace(1.0, 0.55, rings), segments)])  # darker toward the rim
    part = _Part(verts, faces, np.asarray(TONGUE)[None] * shade[:, None], SPECULAR["tongue"])
    return _orient(part, centre - [0.0, radii[1], 0.0], outward=True)


@dataclass
class FaceScene:
    """The skin mesh and its procedural parts, built once per clip by :func:`build_scene`.

    faces : (F, 3) int64 triangles over all vertices (skin first, then the parts);
    albedo : (N, 4) float32 linear RGB and specular strength per vertex;
    eye : (N,) float32 cosine to the cornea's axis on eyeballs, :data:`NO_EYE` elsewhere;
    n_skin : number of skin vertices; notes : parts left out and why.
    """

    faces: np.ndarray
    albedo: np.ndarray
    eye: np.ndarray
    n_skin: int
    notes: tuple[str, ...]
    layout: FaceLayout
    incidence: sparse.csr_matrix = field(repr=False)
    _rest: np.ndarray = field(repr=False)
    _skull: np.ndarray | None = field(repr=False)
    _jaw: np.ndarray | None = field(repr=False)
    _eyes: list = field(repr=False)          # (centre (3,), radius, basis (3, 3), unit verts (m, 3), start)
    _mouth: dict | None = field(repr=False)

    @property
    def n_vertices(self) -> int:
        """All vertices, skin and parts."""
        return len(self.albedo)

    @property
    def eyeball_vertices(self) -> list[tuple[int, int]]:
        """(first vertex, count) of each eyeball's vertices, the +x eye first."""
        return [(int(start), len(unit)) for _, _, _, unit, start in self._eyes]

    def head_and_jaw(self, skin: np.ndarray) -> tuple[tuple[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray]]:
        """Rigid (R, t) of the skull and of the jaw from the rest mesh to ``skin`` (V, 3)."""
        head = rigid_fit(self._rest[self._skull], skin[self._skull]) if self._skull is not None else (np.eye(3), np.zeros(3))
        jaw = rigid_fit(self._rest[self._jaw], skin[self._jaw]) if self._jaw is not None else head
        return head, jaw

    def positions(self, skin: np.ndarray, gaze: np.ndarray | None = None) -> np.ndarray:
        """Every vertex (N, 3) float64 for one frame of the skin (V, 3), mesh units.

        gaze : optional (2, 2) radians, (yaw, pitch) of the eye at +x (subject's left) and of
        the eye at -x; yaw turns the gaze toward +x, pitch up. None (or NaN for an eye) looks
        straight ahead."""
        skin = np.asarray(skin, np.float64)
        out = np.empty((self.n_vertices, 3))
        out[: self.n_skin] = skin
        (hr, ht), (jr, jt) = self.head_and_jaw(skin)
        for e, (centre, radius, basis, unit, start) in enumerate(self._eyes):
            local = unit
            if gaze is not None and np.all(np.isfinite(gaze[e])):
                yaw, pitch = float(gaze[e, 0]), float(gaze[e, 1])
                cy, sy, cp, sp = np.cos(yaw), np.sin(yaw), np.cos(-pitch), np.sin(-pitch)
                turn = np.array([[cy, 0, sy], [0, 1, 0], [-sy, 0, cy]]) @ np.array([[1, 0, 0], [0, cp, -sp], [0, sp, cp]])
                local = unit @ turn.T
            out[start:start + len(unit)] = (centre + radius * local @ basis.T) @ hr.T + ht
        m = self._mouth
        if m is not None:
            loop = skin[m["loop"]]                                            # (n, 3)
            upper = m["upper"]
            rings = [loop]
            for off in m["ring_offsets"]:                                     # (n, 3) rest offsets
                rings.append(loop + np.where(upper[:, None], off @ hr.T, off @ jr.T))
            last = rings[-1]
            back = last.mean(0) + m["back_offset"] @ hr.T
            tube = np.concatenate(rings + [back[None]])
            out[m["tube_start"]:m["tube_start"] + len(tube)] = tube
            s, u = m["upper_teeth"]
            out[s:s + len(u)] = u @ hr.T + ht
            for s, low in (m["lower_teeth"], m["tongue"]):
                out[s:s + len(low)] = low @ jr.T + jt
        return out


#: Where the framed head ends below the mouth, in eye-to-mouth heights: the chin is about 0.75
#: below the mouth's centre on a human face, so the frame holds the chin and a little neck.
CHIN_BELOW_MOUTH = 0.9


def frame_points(scene: FaceScene) -> np.ndarray:
    """The rest-pose points (n, 3) mesh units the camera frames (:meth:`Camera.fit`): on a face
    (eyes and mouth found) the whole head, every skin vertex above
    :data:`CHIN_BELOW_MOUTH` eye-to-mouth heights below the mouth (so a neck or shoulders the
    mesh holds do not shrink the face, and the top of the head is never cut); on other meshes
    every vertex. Only the corners of their convex hull are returned (the camera's fit depends
    on the extreme points only), a few hundred for a head."""
    skin = np.asarray(scene._rest, np.float64)
    layout = scene.layout
    if layout.eyes is not None and layout.mouth is not None:
        eye_y = (layout.eyes[0].centre[1] + layout.eyes[1].centre[1]) / 2
        mouth_y = layout.mouth.centre[1]
        head = skin[skin[:, 1] >= mouth_y - CHIN_BELOW_MOUTH * (eye_y - mouth_y)]
        skin = head if len(head) >= 4 else skin
    skin = skin[np.isfinite(skin).all(1)]
    if len(skin) < 5:
        return skin
    try:
        return skin[ConvexHull(skin).vertices]
    except QhullError:  # a flat mesh (a plane has no 3-D hull): every point
        return skin


def eyeball_centre(rim: np.ndarray, hole: Hole, radius: float, iterations: int = 30) -> np.ndarray:
    """Centre (3,) of a ball of the given radius on which the lid rim (n, 3) lies as nearly as
    possible (least squares of |p - c| - radius, Gauss-Newton from a centre behind the hole),
    then moved back until no rim vertex is more than 3 % of the radius inside the ball, so the
    lids close over the ball instead of the ball showing through them."""
    q = rim - hole.centre
    h = q @ hole.normal
    r2 = float(np.mean(np.sum(q * q, 1) - h * h))
    c = hole.centre - np.sqrt(max(radius**2 - r2, 0.0)) * hole.normal
    for _ in range(iterations):
        d = rim - c
        dist = np.linalg.norm(d, axis=1)
        jac = -d / dist[:, None]                                           # d(dist)/dc
        step = np.linalg.lstsq(jac, -(dist - radius), rcond=None)[0]
        c = c + step
        if np.linalg.norm(step) < 1e-6 * radius:
            break
    if (c - hole.centre) @ hole.normal > 0:                                # the mirror solution in front
        c = c - 2 * ((c - hole.centre) @ hole.normal) * hole.normal
    for _ in range(100):
        if np.min(np.linalg.norm(rim - c, axis=1)) >= 0.97 * radius:
            break
        c = c - 0.01 * radius * hole.normal
    return c


def lip_halves(local: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """For a mouth loop in its local frame (n, 3) (x across, y up): whether each vertex is on
    the upper lip's side of the corners, and how far along its half it is (0 at the corners,
    1 in the middle, a sine of the arc position), robust to a closed slit."""
    n = len(local)
    a, b = int(np.argmin(local[:, 0])), int(np.argmax(local[:, 0]))
    first = [(a + k) % n for k in range((b - a) % n + 1)]
    second = [(b + k) % n for k in range((a - b) % n + 1)]
    upper = np.zeros(n, bool)
    along = np.zeros(n)
    top_first = local[first, 1].mean() >= local[second, 1].mean()
    for path, is_upper in ((first, top_first), (second, not top_first)):
        seg = np.r_[0.0, np.cumsum(np.linalg.norm(np.diff(local[path], axis=0), axis=1))]
        frac = seg / seg[-1] if seg[-1] > 0 else np.linspace(0, 1, len(path))
        along[path] = np.sin(np.pi * frac)
        if is_upper:
            upper[path[1:-1]] = True
    return upper, along


def build_scene(rest: np.ndarray, faces: np.ndarray) -> FaceScene:
    """The skin (rest (V, 3) mesh units, faces (F, 3)) with eyeballs, mouth cavity, teeth and
    tongue wherever :func:`classify_holes` finds the holes for them."""
    rest = np.asarray(rest, np.float64)
    faces = np.asarray(faces, np.int64)
    normals = vertex_normals(rest, faces, face_incidence(len(rest), faces))
    layout = classify_holes(rest, faces, normals)
    n_skin = len(rest)
    colour = np.tile(np.asarray(SKIN, np.float64), (n_skin, 1))
    spec = np.full(n_skin, SPECULAR["skin"])
    eye_attr = np.full(n_skin, NO_EYE)
    all_faces, verts = [faces], [rest]
    count = n_skin

    def add(part: _Part) -> int:
        nonlocal count, colour, spec, eye_attr
        start = count
        all_faces.append(part.faces + start)
        verts.append(part.vertices)
        colour = np.concatenate([colour, part.colour])
        spec = np.concatenate([spec, np.full(len(part.vertices), part.specular)])
        eye_attr = np.concatenate([eye_attr, part.eye if part.eye is not None else np.full(len(part.vertices), NO_EYE)])
        count += len(part.vertices)
        return start

    skull = jaw = None
    eyes = []
    if layout.eyes is not None:
        left, right = layout.eyes
        sep = left.centre[0] - right.centre[0]
        skull = np.nonzero(rest[:, 1] > (left.centre[1] + right.centre[1]) / 2 + 0.35 * sep)[0]
        forward = left.normal + right.normal
        forward /= np.linalg.norm(forward)
        side = np.cross([0.0, 1.0, 0.0], forward)
        side /= np.linalg.norm(side)
        basis = np.stack([side, np.cross(forward, side), forward], 1)        # columns: x, y, cornea axis
        unit, sphere_faces, cosine = eye_sphere()
        for hole in layout.eyes:
            radius = 0.5 * hole.width
            centre = eyeball_centre(rest[hole.loop], hole, radius)
            # The lids shade the ball: the sclera greys away from the cornea.
            shade = 0.7 + 0.3 * np.clip(cosine / COS_IRIS, 0.0, 1.0)
            part = _Part(np.asarray(centre + radius * unit @ basis.T), sphere_faces,
                         np.asarray(SCLERA)[None] * shade[:, None], SPECULAR["eye"], cosine)
            eyes.append((centre, radius, basis, unit, add(part)))
    mouth = None
    if layout.mouth is not None:
        hole = layout.mouth
        w = hole.width
        x_axis = hole.axis
        z_axis = hole.normal - (hole.normal @ x_axis) * x_axis
        z_axis /= np.linalg.norm(z_axis)
        b0 = np.stack([x_axis, np.cross(z_axis, x_axis), z_axis], 1)        # columns: x, y up, z out
        local = (rest[hole.loop] - hole.centre) @ b0
        upper, along = lip_halves(local)
        if skull is None:
            skull = np.nonzero(rest[:, 1] > hole.centre[1] + 1.5 * w)[0]
            skull = skull if len(skull) >= 3 else None
        rel = (rest - hole.centre) @ b0
        chin = ((rel[:, 1] > -1.1 * w) & (rel[:, 1] < -0.55 * w) & (np.abs(rel[:, 0]) < 0.45 * w)
                & (rel[:, 2] > -0.5 * w) & (normals @ z_axis > 0.3))
        jaw = np.nonzero(chin)[0] if chin.sum() >= 3 else None
        # Tube rings: depth back, push away from the lip line, shrink toward the middle.
        depth = np.array([0.05, 0.14, 0.28, 0.48, 0.72]) * w
        push = np.array([0.08, 0.22, 0.32, 0.34, 0.26]) * w
        shrink = np.array([0.03, 0.08, 0.14, 0.24, 0.40])
        sign = np.where(upper, 1.0, -1.0)
        offsets = [np.stack([-local[:, 0] * s, sign * along * p, np.full(len(local), -d)], 1) @ b0.T
                   for d, p, s in zip(depth, push, shrink)]
        n_loop = len(hole.loop)
        rings = [rest[hole.loop]] + [rest[hole.loop] + o for o in offsets]
        back_offset = b0 @ np.array([0.0, 0.0, -0.12 * w])
        tube_v = np.concatenate(rings + [(rings[-1].mean(0) + back_offset)[None]])
        tube_f = [_grid_faces(len(rings), n_loop, closed=True)]
        apex = len(rings) * n_loop
        last = (len(rings) - 1) * n_loop
        tube_f.append(np.stack([last + np.arange(n_loop), np.full(n_loop, apex), last + (np.arange(n_loop) + 1) % n_loop], 1))
        darkness = np.concatenate([np.repeat(np.linspace(0.85, 0.25, len(rings)), n_loop), [0.15]])
        tube = _Part(tube_v, np.concatenate(tube_f), np.asarray(CAVITY)[None] * darkness[:, None], SPECULAR["cavity"])
        # The tube is seen from inside: its normals point toward its axis.
        axis_point = hole.centre - 0.3 * w * z_axis
        tube = _orient(tube, axis_point, outward=False)
        tube_start = add(tube)
        place = lambda p: hole.centre + p.vertices @ b0.T  # noqa: E731
        up_teeth, low_teeth, tongue = _teeth(w, True), _teeth(w, False), _tongue(w)
        for p in (up_teeth, low_teeth, tongue):
            p.vertices = place(p)
        mouth = {"loop": hole.loop, "upper": upper, "ring_offsets": offsets, "back_offset": back_offset,
                 "tube_start": tube_start,
                 "upper_teeth": (add(up_teeth), up_teeth.vertices), "lower_teeth": (add(low_teeth), low_teeth.vertices),
                 "tongue": (add(tongue), tongue.vertices)}
        # Lips a little redder than the skin: within about 4 % of the mouth's width of the
        # inner lip line, fading out over the next 5 %.
        d = cKDTree(rest[hole.loop]).query(rest)[0]
        t = np.clip(1.0 - (d - 0.10 * w) / (0.08 * w), 0.0, 1.0)[:, None]
        colour[:n_skin] = colour[:n_skin] * (1 - t) + np.asarray(LIPS) * t
    all_v = np.concatenate(verts)
    all_f = np.concatenate(all_faces)
    albedo = np.concatenate([_linear(colour), spec[:, None]], 1).astype(np.float32)
    return FaceScene(all_f, albedo, eye_attr.astype(np.float32), n_skin, layout.notes, layout,
                     face_incidence(len(all_v), all_f), rest, skull, jaw, eyes, mouth)
