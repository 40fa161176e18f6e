"""Z-buffer rasterization with supersampling and smooth shading: ``kernels/raster.cl`` on
OpenCL and the same arithmetic in NumPy (the reference, and the fallback without a device).

Anti-aliasing is supersampling: every pixel is S x S samples (``render.supersample``; 2 by
default) on a regular grid, each sample is z-buffered and shaded on its own, and the pixel
is their mean (a box filter), so silhouettes, the lip line and the iris edge get
intermediate values. Shading is per sample with the vertex normals interpolated across the
triangle (smooth shading): a hemispheric ambient term (brighter from above), a soft key light
from the upper left with wrapped diffuse (light reaching a little past the terminator, as in
skin), a dimmer fill light from the right, and a Blinn highlight of the key light scaled by
each material's specular strength. Colours are computed linear and encoded with gamma 2 (a
square root). A triangle whose winding faces away from the camera (seen through a hole that
no part fills) is drawn dark.

The two implementations agree (tested): the nearest triangle of every sample is the same
wherever the device rounds division like IEEE single precision (PoCL on the CPU does), and
every colour channel is within one level where the device's square root or division rounds
differently.
"""

from __future__ import annotations

import numpy as np

from facesynth.base.opencl import context, kernel, queue, use_opencl

from .parts import COS_IRIS, COS_PUPIL
from .raster_numba import shade_numba, triangle_ids_numba

INT32_MAX = np.iinfo(np.int32).max
UINT64_MAX = np.iinfo(np.uint64).max


def _unit(v) -> np.ndarray:
    v = np.asarray(v, np.float64)
    return v / np.linalg.norm(v)


#: Camera-frame lights (x right, y up, z toward the viewer) and display colours.
KEY = _unit([-0.45, 0.55, 0.70])
FILL = _unit([0.70, 0.05, 0.71])
BACKGROUND = (0.20, 0.22, 0.25)
IRIS_OUTER, IRIS_INNER, PUPIL = (0.22, 0.15, 0.10), (0.45, 0.32, 0.18), (0.03, 0.03, 0.03)


def shading_params() -> np.ndarray:
    """The (32,) float32 parameter block that ``shade_sample`` in ``raster.cl`` reads (and the
    NumPy reference): lights, ambient, background, iris and pupil colours (linear)."""
    p = np.zeros(32, np.float64)
    p[0:3], p[3] = KEY, 0.35                    # key direction, wrap
    p[4:7] = FILL
    p[7], p[8] = 0.22, 0.08                     # ambient, its extra from above (per unit n.y)
    p[9], p[10], p[11] = 0.80, 0.25, 0.35       # key, fill, highlight strength
    p[12:15] = _unit(KEY + [0.0, 0.0, 1.0])     # Blinn half vector, viewer along +z
    p[15] = 0.05                                # back faces: dark
    p[16:19] = np.asarray(BACKGROUND) ** 2
    p[19], p[20] = COS_IRIS, COS_PUPIL
    p[21:24], p[24:27], p[27:30] = (np.asarray(c) ** 2 for c in (IRIS_OUTER, IRIS_INNER, PUPIL))
    return p.astype(np.float32)


# --- NumPy reference -------------------------------------------------------------------------

def _edge(ax, ay, bx, by, px, py):
    """``edge_fn`` of raster.cl, operation for operation in float32."""
    return (bx - ax) * (py - ay) - (by - ay) * (px - ax)


def _cover(screen: np.ndarray, faces: np.ndarray, f: np.ndarray, x: np.ndarray, y: np.ndarray):
    """``cover`` of raster.cl for samples (triangle f, sample x, y): (covered, w0, w1, w2, z, area), float32."""
    a, b, c = (screen[faces[f, k]] for k in range(3))
    area = _edge(a[..., 0], a[..., 1], b[..., 0], b[..., 1], c[..., 0], c[..., 1])
    px = x.astype(np.float32) + np.float32(0.5)
    py = y.astype(np.float32) + np.float32(0.5)
    e0 = _edge(b[..., 0], b[..., 1], c[..., 0], c[..., 1], px, py)
    e1 = _edge(c[..., 0], c[..., 1], a[..., 0], a[..., 1], px, py)
    e2 = _edge(a[..., 0], a[..., 1], b[..., 0], b[..., 1], px, py)
    pos = (e0 >= 0) & (e1 >= 0) & (e2 >= 0)
    neg = (e0 <= 0) & (e1 <= 0) & (e2 <= 0)
    inside = (area != 0) & np.where(area > 0, pos, neg)
    with np.errstate(divide="ignore", invalid="ignore"):
        w0, w1, w2 = e0 / area, e1 / area, e2 / area
    z = w0 * a[..., 2] + w1 * b[..., 2] + w2 * c[..., 2]
    return inside & (z > 0), w0, w1, w2, z, area


def triangle_ids_numpy(screen: np.ndarray, faces: np.ndarray, width: int, height: int) -> np.ndarray:
    """The z-buffer of ``kernels/raster.cl`` in NumPy: per sample the nearest triangle (lowest
    id on equal depth), -1 where none.

    screen : (V, 4) float32, sample x, sample y, depth (> 0 in front), 0; width, height : the
    sample grid. Returns (height, width) int64. Coverage and depth use the kernel's float32
    operations in the kernel's order. Triangles are rasterized in groups of similar bounding-box
    size, all fragments of a group at once, and the nearest fragment of each sample is found
    with one sort.
    """
    screen = np.ascontiguousarray(screen, np.float32)
    faces = np.asarray(faces, np.int64)
    corners = screen[faces]                                              # (F, 3, 4)
    with np.errstate(invalid="ignore"):
        lo_x, hi_x = corners[:, :, 0].min(1), corners[:, :, 0].max(1)
        lo_y, hi_y = corners[:, :, 1].min(1), corners[:, :, 1].max(1)
        visible = ((lo_x < width) & (hi_x >= 0) & (lo_y < height) & (hi_y >= 0) & (corners[:, :, 2] > 0).all(1))
    idx = np.nonzero(visible)[0]
    x0 = np.clip(np.floor(lo_x[idx]), 0, None).astype(np.int64)
    y0 = np.clip(np.floor(lo_y[idx]), 0, None).astype(np.int64)
    x1 = np.clip(np.ceil(hi_x[idx]), None, width - 1).astype(np.int64)
    y1 = np.clip(np.ceil(hi_y[idx]), None, height - 1).astype(np.int64)
    # Buckets by bounding box size rounded up to a power of two, so padding stays below 4x.
    bw = 1 << np.ceil(np.log2(x1 - x0 + 1)).astype(np.int64)
    bh = 1 << np.ceil(np.log2(y1 - y0 + 1)).astype(np.int64)
    pixels, depths, ids = [], [], []
    for w, h in sorted(set(zip(bw.tolist(), bh.tolist()))):
        sel = np.nonzero((bw == w) & (bh == h))[0]
        for part in np.array_split(sel, max(1, len(sel) * w * h // (1 << 22))):  # bounded memory
            ox, oy = np.meshgrid(np.arange(w), np.arange(h))
            x = x0[part, None] + ox.reshape(1, -1)
            y = y0[part, None] + oy.reshape(1, -1)
            f = np.broadcast_to(idx[part, None], x.shape)
            inside = (x <= x1[part, None]) & (y <= y1[part, None])
            x, y, f = x[inside], y[inside], f[inside]
            covered, _, _, _, z, _ = _cover(screen, faces, f, x, y)
            pixels.append((y * width + x)[covered])
            depths.append(z[covered])
            ids.append(f[covered])
    out = np.full(height * width, -1, np.int64)
    if pixels:
        pixel, depth, face = np.concatenate(pixels), np.concatenate(depths), np.concatenate(ids)
        order = np.lexsort((face, depth, pixel))                        # nearest, then lowest id
        first = order[np.r_[True, pixel[order][1:] != pixel[order][:-1]]] if len(order) else order
        out[pixel[first]] = face[first]
    return out.reshape(height, width)


def _shade_points(screen, faces, normals, albedo, eye, f, px, py, P) -> np.ndarray:
    """``shade_sample`` of ``kernels/raster.cl``: linear colours (n, 3) float32 of triangles
    ``f`` (n,) at points ``px``, ``py`` (n,) float32 in sample units."""
    f32 = np.float32
    a, b, c = (screen[faces[f, k]] for k in range(3))
    area = _edge(a[:, 0], a[:, 1], b[:, 0], b[:, 1], c[:, 0], c[:, 1])
    with np.errstate(divide="ignore", invalid="ignore"):
        w0 = _edge(b[:, 0], b[:, 1], c[:, 0], c[:, 1], px, py) / area
        w1 = _edge(c[:, 0], c[:, 1], a[:, 0], a[:, 1], px, py) / area
        w2 = _edge(a[:, 0], a[:, 1], b[:, 0], b[:, 1], px, py) / area
    i0, i1, i2 = faces[f, 0], faces[f, 1], faces[f, 2]
    v0, v1, v2 = w0[:, None], w1[:, None], w2[:, None]
    al = v0 * albedo[i0] + v1 * albedo[i1] + v2 * albedo[i2]
    base = al[:, :3].copy()
    nn = v0 * normals[i0] + v1 * normals[i1] + v2 * normals[i2]
    length = np.sqrt(nn[:, 0] * nn[:, 0] + nn[:, 1] * nn[:, 1] + nn[:, 2] * nn[:, 2]) + f32(1e-12)
    nx, ny, nz = nn[:, 0] / length, nn[:, 1] / length, nn[:, 2] / length
    e = w0 * eye[i0] + w1 * eye[i1] + w2 * eye[i2]
    on_eye = e > f32(-1.5)
    pupil = on_eye & (e > P[20])
    iris = on_eye & ~pupil & (e > P[19])
    with np.errstate(invalid="ignore"):
        t = ((e - P[19]) / (P[20] - P[19]))[:, None]
    base[iris] = (P[21:24] + (P[24:27] - P[21:24]) * t)[iris]
    base[pupil] = P[27:30]
    ambient = P[7] + P[8] * ny
    d1 = np.maximum((nx * P[0] + ny * P[1] + nz * P[2] + P[3]) / (f32(1) + P[3]), f32(0))
    d2 = np.maximum(nx * P[4] + ny * P[5] + nz * P[6], f32(0))
    s = np.maximum(nx * P[12] + ny * P[13] + nz * P[14], f32(0))
    for _ in range(5):  # ^32
        s = s * s
    light = ambient + P[9] * d1 + P[10] * d2
    shine = P[11] * al[:, 3] * s
    lit = base * light[:, None] + shine[:, None]
    return np.where((area > 0)[:, None], al[:, :3] * P[15], lit).astype(f32)


def shade_numpy(screen: np.ndarray, faces: np.ndarray, normals: np.ndarray, albedo: np.ndarray, eye: np.ndarray,
                ids: np.ndarray, samples: int, params: np.ndarray | None = None) -> np.ndarray:
    """``resolve_ids`` of ``kernels/raster.cl`` in NumPy: (H, W, 3) uint8 from the per-sample
    triangle ids (H * S, W * S) of :func:`triangle_ids_numpy` (-1 for none), the same float32
    operations: a pixel whose samples all show one triangle is shaded once at its centre, any
    other pixel is the mean of its samples' colours."""
    f32 = np.float32
    P = shading_params() if params is None else params
    screen, faces = np.asarray(screen, f32), np.asarray(faces, np.int64)
    normals, albedo, eye = np.asarray(normals, f32), np.asarray(albedo, f32), np.asarray(eye, f32)
    S = samples
    sh, sw = ids.shape
    h, w = sh // S, sw // S
    per_pixel = ids.reshape(h, S, w, S).transpose(0, 2, 1, 3).reshape(h, w, S * S)   # sample i = sy * S + sx
    uniform = (per_pixel == per_pixel[:, :, :1]).all(2)
    background = P[16:19]
    out = np.empty((h, w, 3), f32)
    # uniform pixels: one colour at the pixel's centre
    uy, ux = np.nonzero(uniform)
    fu = per_pixel[uy, ux, 0]
    colour = np.broadcast_to(background, (len(fu), 3)).copy()
    hit = fu >= 0
    colour[hit] = _shade_points(screen, faces, normals, albedo, eye, fu[hit],
                                (ux[hit] * S).astype(f32) + f32(0.5 * S), (uy[hit] * S).astype(f32) + f32(0.5 * S), P)
    out[uy, ux] = colour
    # edge pixels: the mean of their samples, added in sample order
    ey, ex = np.nonzero(~uniform)
    acc = np.zeros((len(ey), 3), f32)
    for i in range(S * S):
        fi = per_pixel[ey, ex, i]
        c = np.broadcast_to(background, (len(fi), 3)).copy()
        hit = fi >= 0
        X, Y = ex[hit] * S + i % S, ey[hit] * S + i // S
        c[hit] = _shade_points(screen, faces, normals, albedo, eye, fi[hit], X.astype(f32) + f32(0.5),
                               Y.astype(f32) + f32(0.5), P)
        acc = acc + c
    out[ey, ex] = acc / f32(S * S)
    out = np.clip(out, f32(0), f32(1))
    return (np.sqrt(out) * f32(255) + f32(0.5)).astype(np.uint8)


class NumpyRasterizer:
    """The NumPy implementation of :class:`OpenCLRasterizer` (reference and fallback).

    faces : (F, 3) int; albedo : (N, 4) float32 linear RGB + specular; eye : (N,) float32;
    width, height : output pixels; samples : S, samples per pixel along each axis."""

    def __init__(self, faces: np.ndarray, albedo: np.ndarray, eye: np.ndarray, width: int, height: int, samples: int = 2):
        self.faces = np.asarray(faces, np.int64)
        self.albedo = np.asarray(albedo, np.float32)
        self.eye = np.asarray(eye, np.float32)
        self.width, self.height, self.samples = width, height, samples
        self.ids = np.full((height * samples, width * samples), -1, np.int64)
        self.params = shading_params()

    def render(self, screen: np.ndarray, normals: np.ndarray) -> np.ndarray:
        """One RGB frame (H, W, 3) uint8 from projected vertices ``screen`` (N, 4) float32 in
        sample units (a camera at S times the resolution) and camera-frame ``normals`` (N, 4)."""
        s = self.samples
        self.ids = triangle_ids_numpy(screen, self.faces, self.width * s, self.height * s)
        return shade_numpy(screen, self.faces, np.asarray(normals, np.float32), self.albedo, self.eye, self.ids, s,
                           self.params)

    def triangle_ids(self) -> np.ndarray:
        """(H * S, W * S) int32 triangle per sample of the last frame, INT32_MAX where none."""
        return np.where(self.ids < 0, INT32_MAX, self.ids).astype(np.int32)


class NumbaRasterizer(NumpyRasterizer):
    """:class:`NumpyRasterizer` with its two steps compiled by numba (``raster_numba.py``): the
    same float32 operations in the same order, so the same triangle ids and frames, bit for bit,
    about 13 times faster (the fallback without a device; NumPy stays the reference)."""

    def render(self, screen: np.ndarray, normals: np.ndarray) -> np.ndarray:

        s = self.samples
        self.ids = triangle_ids_numba(screen, self.faces, self.width * s, self.height * s)
        return shade_numba(screen, self.faces, normals, self.albedo, self.eye, self.ids, s, self.params)


class OpenCLRasterizer:
    """Rasterizer on the chosen OpenCL device (``kernels/raster.cl``); one instance per scene
    and size. Uses the one-pass 64-bit-atomic z-buffer where the device has
    ``cl_khr_int64_extended_atomics`` (unless ``wide_atomics`` is False), else two 32-bit
    passes (the same result)."""

    def __init__(self, faces: np.ndarray, albedo: np.ndarray, eye: np.ndarray, width: int, height: int, samples: int = 2,
                 wide_atomics: bool | None = None):
        import pyopencl as cl

        self.ctx, self.q = context(), queue()
        self.width, self.height, self.samples = width, height, samples
        self.n_faces = len(faces)
        has_wide = all("cl_khr_int64_extended_atomics" in d.extensions for d in self.ctx.devices)
        self.wide = has_wide if wide_atomics is None else bool(wide_atomics) and has_wide
        names = ("raster_keys", "resolve_keys") if self.wide else ("raster_depth", "raster_ids", "resolve_ids")
        self.kernels = {k: kernel("raster", k, SAMPLES=samples) for k in names}
        mf = cl.mem_flags
        n_vertices, n_samples = len(albedo), width * height * samples * samples

        def const(a):
            return cl.Buffer(self.ctx, mf.READ_ONLY | mf.COPY_HOST_PTR, hostbuf=np.ascontiguousarray(a))

        self.faces = const(np.asarray(faces, np.int32).ravel())
        self.albedo, self.eye = const(np.asarray(albedo, np.float32)), const(np.asarray(eye, np.float32))
        self.params = const(shading_params())
        self.screen = cl.Buffer(self.ctx, mf.READ_ONLY, 16 * n_vertices)
        self.normals = cl.Buffer(self.ctx, mf.READ_ONLY, 16 * n_vertices)
        self.rgb = cl.Buffer(self.ctx, mf.WRITE_ONLY, 3 * width * height)
        if self.wide:
            self.keys = cl.Buffer(self.ctx, mf.READ_WRITE, 8 * n_samples)
        else:
            self.zbuf = cl.Buffer(self.ctx, mf.READ_WRITE, 4 * n_samples)
            self.ids = cl.Buffer(self.ctx, mf.READ_WRITE, 4 * n_samples)
        self.n_samples = n_samples

    def render(self, screen: np.ndarray, normals: np.ndarray) -> np.ndarray:
        """One RGB frame (H, W, 3) uint8, as :meth:`NumpyRasterizer.render`."""
        import pyopencl as cl

        q, k, s = self.q, self.kernels, self.samples
        cl.enqueue_copy(q, self.screen, np.ascontiguousarray(screen, np.float32))
        cl.enqueue_copy(q, self.normals, np.ascontiguousarray(normals, np.float32))
        sw, sh = np.int32(self.width * s), np.int32(self.height * s)
        w, h, n = np.int32(self.width), np.int32(self.height), np.int32(self.n_faces)
        common = (self.screen, self.faces, self.normals, self.albedo, self.eye, self.params)
        if self.wide:
            cl.enqueue_fill_buffer(q, self.keys, np.uint64(UINT64_MAX), 0, 8 * self.n_samples)
            k["raster_keys"](q, (self.n_faces,), None, self.screen, self.faces, n, sw, sh, self.keys)
            k["resolve_keys"](q, (self.width, self.height), None, *common, self.keys, w, h, self.rgb)
        else:
            cl.enqueue_fill_buffer(q, self.zbuf, np.int32(INT32_MAX), 0, 4 * self.n_samples)
            cl.enqueue_fill_buffer(q, self.ids, np.int32(INT32_MAX), 0, 4 * self.n_samples)
            k["raster_depth"](q, (self.n_faces,), None, self.screen, self.faces, n, sw, sh, self.zbuf)
            k["raster_ids"](q, (self.n_faces,), None, self.screen, self.faces, n, sw, sh, self.zbuf, self.ids)
            k["resolve_ids"](q, (self.width, self.height), None, *common, self.ids, w, h, self.rgb)
        out = np.empty((self.height, self.width, 3), np.uint8)
        cl.enqueue_copy(q, out, self.rgb)
        return out

    def triangle_ids(self) -> np.ndarray:
        """(H * S, W * S) int32 triangle per sample of the last frame, INT32_MAX where none."""
        import pyopencl as cl

        s = self.samples
        if self.wide:
            keys = np.empty(self.n_samples, np.uint64)
            cl.enqueue_copy(self.q, keys, self.keys)
            ids = np.where(keys == UINT64_MAX, INT32_MAX, (keys & np.uint64(0xFFFFFFFF)).astype(np.int64)).astype(np.int32)
        else:
            ids = np.empty(self.n_samples, np.int32)
            cl.enqueue_copy(self.q, ids, self.ids)
        return ids.reshape(self.height * s, self.width * s)


def rasterizer(faces: np.ndarray, albedo: np.ndarray, eye: np.ndarray, width: int, height: int, samples: int = 2,
               wanted: bool = True):
    """The OpenCL rasterizer when a device builds (and ``wanted``), else the numba one (the NumPy
    reference's frames, bit for bit)."""
    cls = OpenCLRasterizer if use_opencl(wanted) else NumbaRasterizer
    return cls(faces, albedo, eye, width, height, samples)
