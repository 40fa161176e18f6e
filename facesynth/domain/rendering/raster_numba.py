"""Numba versions of the NumPy rasterizer of ``facesynth/domain/rendering/raster.py`` (the reference):
the same float32 operations in the same order, so the same triangle ids and the same colours,
bit for bit (checked by check.py against the snapshot's NumPy reference).

Drop-in replacements:

* :func:`triangle_ids_numba` for ``raster.triangle_ids_numpy`` (same signature and result);
* :func:`shade_numba` for ``raster.shade_numpy`` (same signature, ``params`` required, same result);
* ``NumbaRasterizer`` for ``raster.NumpyRasterizer``: the NumPy class with its ``render``
  calling these two (a subclass in raster.py, see integration.diff; capture.py has the same).

Why the results are identical: every value is a float32 ``+ - * /`` or ``sqrt`` of float32
operands, written as the NumPy reference groups it (``a + b + c`` is ``(a + b) + c``), and numba
compiles without ``fastmath``, so LLVM neither fuses multiply-adds nor reorders. Constants are
made float32 first (a Python float literal would promote the arithmetic to float64).

The z-buffer walks the triangles in increasing id and keeps a sample's triangle only when a
later one is strictly nearer: the reference's "nearest, then lowest id" (its lexsort).
"""

from __future__ import annotations

import numpy as np

from facesynth.base.jit import jit

# -- the z-buffer ---------------------------------------------------------------------------


@jit()
def _edge(ax, ay, bx, by, px, py):
    return (bx - ax) * (py - ay) - (by - ay) * (px - ax)


@jit()
def _zbuffer(screen, faces, width, height, out, depth):
    """out (height * width,) int64 filled with -1 and depth (height * width,) float32 with +inf:
    per sample the nearest covering triangle (lowest id on equal depth)."""
    half = np.float32(0.5)
    zero = np.float32(0.0)
    fw = np.float32(width)
    fh = np.float32(height)
    for f in range(faces.shape[0]):
        i0, i1, i2 = faces[f, 0], faces[f, 1], faces[f, 2]
        ax, ay, az = screen[i0, 0], screen[i0, 1], screen[i0, 2]
        bx, by, bz = screen[i1, 0], screen[i1, 1], screen[i1, 2]
        cx, cy, cz = screen[i2, 0], screen[i2, 1], screen[i2, 2]
        # the reference's visibility: NaN in a corner makes its min/max NaN, so invisible
        if (np.isnan(ax) or np.isnan(bx) or np.isnan(cx) or np.isnan(ay) or np.isnan(by) or np.isnan(cy)):
            continue
        lo_x = min(ax, min(bx, cx))
        hi_x = max(ax, max(bx, cx))
        lo_y = min(ay, min(by, cy))
        hi_y = max(ay, max(by, cy))
        if not (lo_x < fw and hi_x >= zero and lo_y < fh and hi_y >= zero):
            continue
        if not (az > zero and bz > zero and cz > zero):
            continue
        x0 = int(max(np.floor(np.float64(lo_x)), 0.0))
        y0 = int(max(np.floor(np.float64(lo_y)), 0.0))
        x1 = int(min(np.ceil(np.float64(hi_x)), np.float64(width - 1)))
        y1 = int(min(np.ceil(np.float64(hi_y)), np.float64(height - 1)))
        area = _edge(ax, ay, bx, by, cx, cy)
        if area == zero:
            continue
        positive = area > zero
        for y in range(y0, y1 + 1):
            py = np.float32(y) + half
            row = y * width
            for x in range(x0, x1 + 1):
                px = np.float32(x) + half
                e0 = _edge(bx, by, cx, cy, px, py)
                e1 = _edge(cx, cy, ax, ay, px, py)
                e2 = _edge(ax, ay, bx, by, px, py)
                if positive:
                    if not (e0 >= zero and e1 >= zero and e2 >= zero):
                        continue
                else:
                    if not (e0 <= zero and e1 <= zero and e2 <= zero):
                        continue
                w0 = e0 / area
                w1 = e1 / area
                w2 = e2 / area
                z = w0 * az + w1 * bz + w2 * cz
                if not (z > zero):
                    continue
                p = row + x
                if z < depth[p]:  # strictly nearer: equal depth keeps the lower id
                    depth[p] = z
                    out[p] = f


def triangle_ids_numba(screen: np.ndarray, faces: np.ndarray, width: int, height: int) -> np.ndarray:
    """``raster.triangle_ids_numpy``: (height, width) int64, per sample the nearest triangle
    (lowest id on equal depth), -1 where none."""
    screen = np.ascontiguousarray(screen, np.float32)
    faces = np.ascontiguousarray(faces, np.int64)
    out = np.full(height * width, -1, np.int64)
    depth = np.full(height * width, np.inf, np.float32)
    _zbuffer(screen, faces, int(width), int(height), out, depth)
    return out.reshape(height, width)


# -- shading --------------------------------------------------------------------------------


@jit()
def _shade_point(screen, faces, normals, albedo, eye, P, f, px, py, rgb):
    """``_shade_points`` of the reference for one point: the linear colour into rgb (3,) float32."""
    one = np.float32(1.0)
    zero = np.float32(0.0)
    i0, i1, i2 = faces[f, 0], faces[f, 1], faces[f, 2]
    ax, ay = screen[i0, 0], screen[i0, 1]
    bx, by = screen[i1, 0], screen[i1, 1]
    cx, cy = screen[i2, 0], screen[i2, 1]
    area = _edge(ax, ay, bx, by, cx, cy)
    w0 = _edge(bx, by, cx, cy, px, py) / area
    w1 = _edge(cx, cy, ax, ay, px, py) / area
    w2 = _edge(ax, ay, bx, by, px, py) / area
    al0 = w0 * albedo[i0, 0] + w1 * albedo[i1, 0] + w2 * albedo[i2, 0]
    al1 = w0 * albedo[i0, 1] + w1 * albedo[i1, 1] + w2 * albedo[i2, 1]
    al2 = w0 * albedo[i0, 2] + w1 * albedo[i1, 2] + w2 * albedo[i2, 2]
    if area > zero:  # a back face
        rgb[0] = al0 * P[15]
        rgb[1] = al1 * P[15]
        rgb[2] = al2 * P[15]
        return
    al3 = w0 * albedo[i0, 3] + w1 * albedo[i1, 3] + w2 * albedo[i2, 3]
    n0 = w0 * normals[i0, 0] + w1 * normals[i1, 0] + w2 * normals[i2, 0]
    n1 = w0 * normals[i0, 1] + w1 * normals[i1, 1] + w2 * normals[i2, 1]
    n2 = w0 * normals[i0, 2] + w1 * normals[i1, 2] + w2 * normals[i2, 2]
    length = np.sqrt(n0 * n0 + n1 * n1 + n2 * n2) + np.float32(1e-12)
    nx, ny, nz = n0 / length, n1 / length, n2 / length
    e = w0 * eye[i0] + w1 * eye[i1] + w2 * eye[i2]
    b0, b1, b2 = al0, al1, al2
    if e > np.float32(-1.5):
        if e > P[20]:
            b0, b1, b2 = P[27], P[28], P[29]
        elif e > P[19]:
            t = (e - P[19]) / (P[20] - P[19])
            b0 = P[21] + (P[24] - P[21]) * t
            b1 = P[22] + (P[25] - P[22]) * t
            b2 = P[23] + (P[26] - P[23]) * t
    ambient = P[7] + P[8] * ny
    d1 = (nx * P[0] + ny * P[1] + nz * P[2] + P[3]) / (one + P[3])
    d2 = nx * P[4] + ny * P[5] + nz * P[6]
    s = nx * P[12] + ny * P[13] + nz * P[14]
    # np.maximum(v, 0): NaN stays NaN
    if d1 < zero:
        d1 = zero
    if d2 < zero:
        d2 = zero
    if s < zero:
        s = zero
    s = s * s
    s = s * s
    s = s * s
    s = s * s
    s = s * s  # ^32
    light = ambient + P[9] * d1 + P[10] * d2
    shine = P[11] * al3 * s
    rgb[0] = b0 * light + shine
    rgb[1] = b1 * light + shine
    rgb[2] = b2 * light + shine


@jit()
def _to_byte(v):
    """np.clip(v, 0, 1), then (sqrt * 255 + 0.5) as uint8 (NaN: 0, as NumPy's cast gives on x86)."""
    zero = np.float32(0.0)
    one = np.float32(1.0)
    if v != v:
        return np.uint8(0)
    if v < zero:
        v = zero
    elif v > one:
        v = one
    return np.uint8(np.sqrt(v) * np.float32(255.0) + np.float32(0.5))


@jit()
def _resolve(screen, faces, normals, albedo, eye, P, ids, S, out):
    """out (h, w, 3) uint8 from the per-sample ids (h * S, w * S) int64, as ``shade_numpy``."""
    h, w = out.shape[0], out.shape[1]
    n = S * S
    centre = np.float32(0.5 * S)
    half = np.float32(0.5)
    count = np.float32(n)
    rgb = np.empty(3, np.float32)
    acc = np.empty(3, np.float32)
    for y in range(h):
        for x in range(w):
            f0 = ids[y * S, x * S]
            uniform = True
            for i in range(1, n):
                if ids[y * S + i // S, x * S + i % S] != f0:
                    uniform = False
                    break
            if uniform:
                if f0 >= 0:
                    _shade_point(screen, faces, normals, albedo, eye, P, f0, np.float32(x * S) + centre,
                                 np.float32(y * S) + centre, rgb)
                else:
                    rgb[0], rgb[1], rgb[2] = P[16], P[17], P[18]
                out[y, x, 0] = _to_byte(rgb[0])
                out[y, x, 1] = _to_byte(rgb[1])
                out[y, x, 2] = _to_byte(rgb[2])
            else:
                acc[0] = acc[1] = acc[2] = np.float32(0.0)
                for i in range(n):
                    X = x * S + i % S
                    Y = y * S + i // S
                    fi = ids[Y, X]
                    if fi >= 0:
                        _shade_point(screen, faces, normals, albedo, eye, P, fi, np.float32(X) + half,
                                     np.float32(Y) + half, rgb)
                    else:
                        rgb[0], rgb[1], rgb[2] = P[16], P[17], P[18]
                    acc[0] = acc[0] + rgb[0]
                    acc[1] = acc[1] + rgb[1]
                    acc[2] = acc[2] + rgb[2]
                out[y, x, 0] = _to_byte(acc[0] / count)
                out[y, x, 1] = _to_byte(acc[1] / count)
                out[y, x, 2] = _to_byte(acc[2] / count)


def shade_numba(screen: np.ndarray, faces: np.ndarray, normals: np.ndarray, albedo: np.ndarray, eye: np.ndarray,
                ids: np.ndarray, samples: int, params: np.ndarray) -> np.ndarray:
    """``raster.shade_numpy``: (H, W, 3) uint8 from the per-sample triangle ids (H * S, W * S)
    (-1 for none); ``params`` is ``raster.shading_params()`` (given, not defaulted: this module
    imports nothing of facesynth's but the jit helper, so raster.py can import it)."""
    f32 = np.float32
    P = np.ascontiguousarray(params, f32)
    S = int(samples)
    sh, sw = ids.shape
    out = np.empty((sh // S, sw // S, 3), np.uint8)
    _resolve(np.ascontiguousarray(screen, f32), np.ascontiguousarray(faces, np.int64),
             np.ascontiguousarray(normals, f32), np.ascontiguousarray(albedo, f32), np.ascontiguousarray(eye, f32),
             P, np.ascontiguousarray(ids, np.int64), S, out)
    return out
