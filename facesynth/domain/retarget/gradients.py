"""Deformation-gradient blending of example meshes (Sumner & Popović 2005 / Sumner et al. 2005
MeshIK; Huang et al. §3, the M(T, alpha) of their Eq. 4).

For each triangle of the rest mesh its deformation gradient in each example (keymorph) mesh is
the 3 x 3 Jacobian taking the rest triangle to the example's (the fourth vertex along the scaled
normal, as in Sumner's deformation transfer). Polar decomposition splits it into a rotation R and
a symmetric stretch S. For blend weights alpha (one per example, not constrained to sum to 1:
the examples enter as offsets from the rest mesh, whose gradient is the identity) the blended
gradient is ``exp(sum_k alpha_k log R_k) (I + sum_k alpha_k (S_k - I))``: rotations blended in
log space (the exponential map), stretch linearly. The vertices follow from one sparse linear
least-squares problem: every triangle's two edges should be its blended gradient times its rest
edges, plus a small pull (``anchor``) toward the linear blend of the examples that fixes each
connected piece's translation. The normal matrix is factorized once per mesh; each frame is a
back-substitution.

Linear blending of the same examples (``rest + sum_k alpha_k (G_k - rest)``) shrinks parts that
rotate (a jaw opening mixed with a pucker); blending the gradients keeps their lengths.

How it is made fast (same results as the formulation above within 5e-5 mm; the tests compare
with it written out frame by frame in float64; on the full rig with real key-shapes the two
differ by 8.5e-6 mm, the rounding of float32 vertex coordinates):

* one-time: the polar decompositions by a written-out Newton iteration on 3 x 3 blocks and a
  closed-form log map (:func:`_polar`) rather than an SVD and scipy's rotation conversions per
  matrix; the normal matrix, symmetric positive definite, factorized by SuperLU in single
  precision with a minimum degree ordering of ``A + A^T`` in symmetric mode (half the fill of
  the default COLAMD and fewer operations per back-substitution);
* per clip, 32 frames at a time: the unknowns are the departures from the linear blend (whose
  anchor term then drops out of the right-hand side), small where the blended gradients agree
  with the linear blend, so float32 right-hand sides and back-substitutions lose digits of the
  departures only; one matrix product gives every frame's blended rotation vectors and
  stretched rest edges, Rodrigues' formula rotates the edges without forming matrices, and the
  edges are summed onto the vertices;
* on OpenCL (``kernels/gradient_rhs.cl``; NumPy and SuperLU without a device, the same numbers
  to float32 rounding): the rotations 8 frames per work-item (Taylor series instead of sin for
  angles up to 1 rad), the sum onto vertices as a gather over each vertex's triangles (no
  atomics), and the back-substitutions by the rows of SuperLU's factors, 16 right-hand sides per
  work-item (one cache line per row; 3 times less CPU than SuperLU's own solve here).
"""

from __future__ import annotations

import numpy as np
from scipy import sparse
from scipy.sparse.linalg import splu

from facesynth.base.blas import one_blas_thread
from facesynth.base.opencl import aligned_empty, context, kernel, queue
from facesynth.base.opencl import use_opencl as device_ok


def _frames(vertices: np.ndarray, faces: np.ndarray) -> np.ndarray:
    """(..., F, 3, 3) columns [e1, e2, n / sqrt|n|] of each triangle (Sumner's fourth vertex)."""
    v0, v1, v2 = (vertices[..., faces[:, i], :] for i in range(3))
    e1, e2 = v1 - v0, v2 - v0
    n = np.cross(e1, e2)
    n = n / np.sqrt(np.maximum(np.linalg.norm(n, axis=-1, keepdims=True), 1e-12))
    return np.stack([e1, e2, n], axis=-1)


def _polar_svd(f: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Rotation vectors (N, 3) and stretches (N, 3, 3) of F = R S for (N, 3, 3) F by SVD, for any
    F (det F <= 0 included: the smallest singular value takes the sign)."""
    from scipy.spatial.transform import Rotation

    u, sig, vt = np.linalg.svd(f)
    det = np.sign(np.linalg.det(u @ vt))
    u[..., :, 2] *= det[..., None]
    sig[..., 2] *= det
    r = u @ vt
    s = np.swapaxes(vt, -1, -2) @ (sig[..., :, None] * vt)
    return Rotation.from_matrix(r).as_rotvec().reshape(-1, 3), s


#: Largest rotation (rad) whose log map is taken in closed form; beyond it (toward pi, where the
#: axis from the skew part loses digits) the SVD route with scipy's quaternions takes over.
_LOG_CLOSED_MAX = 2.5


def _log(r: np.ndarray) -> np.ndarray:
    """(N, 3) rotation vectors of (N, 3, 3) rotation matrices with angles below ``_LOG_CLOSED_MAX``:
    ``theta = atan2(|w| / 2, (tr R - 1) / 2)`` and ``theta / (2 sin theta) w``, w the skew part
    (no arccos, so small angles keep their digits)."""
    w = np.stack([r[:, 2, 1] - r[:, 1, 2], r[:, 0, 2] - r[:, 2, 0], r[:, 1, 0] - r[:, 0, 1]], 1)
    sin2 = np.sqrt((w**2).sum(1))  # 2 sin theta
    theta = np.arctan2(0.5 * sin2, 0.5 * (r[:, 0, 0] + r[:, 1, 1] + r[:, 2, 2] - 1.0))
    small = theta < 1e-4
    factor = np.where(small, 0.5 + theta**2 / 12.0, theta / np.where(small, 1.0, sin2))
    return factor[:, None] * w


def _cofactors(m: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Cofactor matrices (9, N) and determinants (N,) of 3 x 3 matrices given as (9, N) row-major
    entries; ``M^-T = cofactors / det``."""
    m00, m01, m02, m10, m11, m12, m20, m21, m22 = m
    c = np.stack([m11 * m22 - m12 * m21, m12 * m20 - m10 * m22, m10 * m21 - m11 * m20,
                  m02 * m21 - m01 * m22, m00 * m22 - m02 * m20, m01 * m20 - m00 * m21,
                  m01 * m12 - m02 * m11, m02 * m10 - m00 * m12, m00 * m11 - m01 * m10])
    return c, m00 * c[0] + m01 * c[1] + m02 * c[2]


def _polar(f: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Rotation (..., 3) as a rotation vector and stretch (..., 3, 3) of F = R S, for (..., 3, 3) F.

    Higham's scaled Newton iteration ``X <- (g X + X^-T / g) / 2`` (g = |det X|^(-1/3)), written
    out on 3 x 3 blocks, converges to R for every F with det F > 0 (quadratically: 5 to 8 steps
    for the stretches of a face); S = sym(R^T F). Matrices with det F <= 0 (inverted or collapsed
    triangles) or rotations near pi go through :func:`_polar_svd`. The polar factors of an F with
    det F > 0 are unique, so both routes agree to rounding.
    """
    shape = f.shape[:-2]
    fm = np.asarray(f, np.float64).reshape(-1, 3, 3)
    x = fm.reshape(-1, 9).T.copy()  # (9, N)
    _, det0 = _cofactors(x)
    ok = det0 > 1e-9 * np.abs(x).max(0) ** 3
    x[:, ~ok] = np.eye(3).reshape(9, 1)  # identity stand-ins; these matrices go through the SVD
    moved = np.zeros(x.shape[1])
    for _ in range(60):
        cof, det = _cofactors(x)
        gam = np.abs(det) ** (-1.0 / 3.0)
        new = 0.5 * (gam * x + cof / (gam * det))
        moved = np.abs(new - x).max(0)
        x = new
        if moved.max(initial=0.0) <= 1e-15:
            break
    ok &= moved <= 1e-12  # not converged (not seen on meshes): the SVD is the fallback
    r = x.T.reshape(-1, 3, 3)
    s = np.swapaxes(r, 1, 2) @ fm
    stretch = 0.5 * (s + np.swapaxes(s, 1, 2))
    ok &= r[:, 0, 0] + r[:, 1, 1] + r[:, 2, 2] > 1.0 + 2.0 * np.cos(_LOG_CLOSED_MAX)
    rotvec = np.empty((len(fm), 3))
    rotvec[ok] = _log(r[ok])
    if not ok.all():
        rotvec[~ok], stretch[~ok] = _polar_svd(fm[~ok])
    return rotvec.reshape(shape + (3,)), stretch.reshape(shape + (3, 3))


def _exp(rotvec: np.ndarray) -> np.ndarray:
    """(..., 3, 3) rotation matrices of rotation vectors r (Rodrigues, written out:
    ``cos t I + sin t / t [r]x + (1 - cos t) / t^2 r r^T`` with t = |r|)."""
    theta2 = (rotvec**2).sum(-1)
    theta = np.sqrt(theta2)
    small = theta < 1e-4
    safe = np.where(small, 1.0, theta)
    c = np.cos(theta)
    a = np.where(small, 1.0 - theta2 / 6.0, np.sin(theta) / safe)
    b = np.where(small, 0.5 - theta2 / 24.0, (1.0 - c) / np.where(small, 1.0, theta2))
    x, y, z = rotvec[..., 0], rotvec[..., 1], rotvec[..., 2]
    out = np.empty(rotvec.shape[:-1] + (3, 3), rotvec.dtype)
    out[..., 0, 0] = c + b * x * x
    out[..., 1, 1] = c + b * y * y
    out[..., 2, 2] = c + b * z * z
    bxy, bxz, byz = b * x * y, b * x * z, b * y * z
    out[..., 0, 1] = bxy - a * z
    out[..., 1, 0] = bxy + a * z
    out[..., 0, 2] = bxz + a * y
    out[..., 2, 0] = bxz - a * y
    out[..., 1, 2] = byz - a * x
    out[..., 2, 1] = byz + a * x
    return out


def _rotate_edges(g: np.ndarray, out: np.ndarray) -> None:
    """Rotate two edges per triangle and frame by the rotation vector beside them.

    g : (B, 9, T) float32: rotation vector r (rows 0-2), edges u, v (rows 3-5, 6-8), T frames.
    out : (B, 2, 3, T) float32 receives ``R u`` and ``R v``, by ``R x = x + a (r x x) + b (r x (r x x))``
    with a = sin t / t and b = (1 - cos t) / t^2 = (sin(t/2) / t)^2 * 2 (no cancellation).
    The OpenCL kernel ``residual_edges`` (kernels/gradient_rhs.cl) computes the same.
    """
    rx, ry, rz = g[:, 0], g[:, 1], g[:, 2]
    t = np.sqrt(rx * rx + ry * ry + rz * rz)
    small = t < 1e-3
    safe = np.where(small, np.float32(1.0), t)
    half = np.sin(0.5 * safe) / safe
    a = np.where(small, 1.0 - t * t / 6.0, np.sin(safe) / safe).astype(np.float32)
    b = np.where(small, 0.5 - t * t / 24.0, 2.0 * half * half).astype(np.float32)
    for j in range(2):
        x, y, z = g[:, 3 + 3 * j], g[:, 4 + 3 * j], g[:, 5 + 3 * j]
        cx, cy, cz = ry * z - rz * y, rz * x - rx * z, rx * y - ry * x  # r x e
        dx, dy, dz = ry * cz - rz * cy, rz * cx - rx * cz, rx * cy - ry * cx  # r x (r x e)
        o = out[:, j]
        np.add(x, a * cx + b * dx, out=o[:, 0])
        np.add(y, a * cy + b * dy, out=o[:, 1])
        np.add(z, a * cz + b * dz, out=o[:, 2])


class GradientBlender:
    """Blends K example meshes of one topology by their deformation gradients.

    rest : (V, 3) the rest (neutral) mesh; faces : (F, 3) int; examples : (K, V, 3) example meshes
    in the rest's units and vertex order; anchor : weight of the pull toward the linear blend,
    relative to the mean squared rest edge length (small: it only fixes what edges leave free);
    block : triangles per block of the NumPy per-clip work (its arrays stay in cache);
    use_opencl : rotate the edges, sum them onto the vertices and back-substitute with the kernels
    of ``kernels/gradient_rhs.cl`` when a device builds them (else, and with False, NumPy and
    SuperLU; the two agree to float32 rounding); the attribute says which is used.
    Construction does the one-time work (gradients, polar decompositions, the factorization).
    """

    #: Frames per back-substitution (3 right-hand sides each).
    SOLVE_FRAMES = 8
    #: Frames whose right-hand sides are built at once (about 60 MB of work arrays on an
    #: 11,248-vertex mesh).
    GROUP_FRAMES = 32

    def __init__(self, rest: np.ndarray, faces: np.ndarray, examples: np.ndarray, anchor: float = 1e-3,
                 block: int = 512, use_opencl: bool = True):
        self.rest = np.asarray(rest, np.float64)
        self.faces = np.asarray(faces, np.int64)
        ex = np.asarray(examples, np.float64)
        n_k, n_f, n_v = len(ex), len(self.faces), len(self.rest)
        self.offsets = (ex - self.rest).reshape(n_k, -1).astype(np.float32)  # (K, 3V)
        self._offsets_t = np.ascontiguousarray(self.offsets.T)  # (3V, K)
        rest_frames = _frames(self.rest, self.faces)  # (F, 3, 3)
        inv = np.linalg.inv(rest_frames)
        rest_edges = rest_frames[:, :, :2]  # (F, 3, 2): columns e1, e2
        # Per triangle f, the 9 numbers blended linearly in alpha: log R (3) and (S - I) e1, (S - I) e2.
        coef = np.empty((n_f, 9, n_k), np.float32)
        for k in range(n_k):  # one example at a time: its arrays stay small
            rotvec, stretch = _polar(_frames(ex[k], self.faces) @ inv)
            coef[:, :3, k] = rotvec
            stretch[:, [0, 1, 2], [0, 1, 2]] -= 1.0
            coef[:, 3:, k] = np.swapaxes(stretch @ rest_edges, 1, 2).reshape(n_f, 6)
        self._coef = coef.reshape(n_f * 9, n_k)
        self._rest_edges = rest_edges.transpose(0, 2, 1).reshape(n_f, 6).astype(np.float32)  # e1, e2
        rows = np.repeat(np.arange(2 * n_f), 2)
        f0, f1, f2 = self.faces.T
        cols = np.stack([f0, f1, f0, f2], 1).ravel()
        vals = np.tile([-1.0, 1.0, -1.0, 1.0], n_f)
        # rows 2f, 2f+1: edges v1 - v0 and v2 - v0 of triangle f
        self.edges = sparse.csr_matrix((vals, (rows, cols)), shape=(2 * n_f, n_v))
        # Blocks of triangles for NumPy: the vertices their edges touch and E^T restricted to them.
        self._blocks = []
        for lo in range(0, n_f, block):
            hi = min(lo + block, n_f)
            verts = np.unique(self.faces[lo:hi])
            scatter = self.edges[2 * lo:2 * hi][:, verts].T.astype(np.float32).tocsr()  # (Vb, 2B)
            self._blocks.append((lo, hi, verts, scatter))
        # Each vertex's triangles for the gather kernel: 4 f + corner, grouped by vertex.
        order = np.argsort(self.faces.ravel(), kind="stable")
        self._incident = (4 * (order // 3) + order % 3).astype(np.int32)
        self._start = np.searchsorted(self.faces.ravel()[order], np.arange(n_v + 1)).astype(np.int32)
        mean_sq = float((rest_edges**2).sum(1).mean())
        self.anchor = anchor * mean_sq
        normal = (self.edges.T @ self.edges + self.anchor * sparse.identity(n_v)).tocsc()
        # Symmetric positive definite: a minimum degree ordering of A + A^T and no pivoting
        # (SuperLU's symmetric mode) give half the fill of the default COLAMD ordering. Single
        # precision: the solves are for the small departures from the linear blend (see _blend).
        self.factor = splu(normal.astype(np.float32), permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0,
                           options={"SymmetricMode": True})

        self.use_opencl = bool(use_opencl) and n_f > 0 and device_ok(use_opencl)
        if self.use_opencl:  # one-time too: the kernels' build and the factors on the device

            for name in ("residual_edges", "gather_edges", "lu_solve"):
                kernel("gradient_rhs", name)
            self._device_arrays()

    def linear(self, alpha: np.ndarray) -> np.ndarray:
        """(T, V, 3) float32 linear blend ``rest + sum_k alpha_k (G_k - rest)`` for alpha (T, K)."""
        a = np.asarray(alpha, np.float32)
        with one_blas_thread():
            return self.rest.astype(np.float32) + (a @ self.offsets).reshape(len(a), len(self.rest), 3)

    def blend(self, alpha: np.ndarray) -> np.ndarray:
        """(T, V, 3) float32 deformation-gradient blend for alpha (T, K).

        Runs with one BLAS thread: SuperLU's back-substitution calls BLAS on small supernodes, where
        waking threads costs more than the work (3 to 6 times slower on a busy two-core machine)."""
        with one_blas_thread():
            return self._blend(np.asarray(alpha, np.float32))

    def _blend(self, a: np.ndarray) -> np.ndarray:
        """The vertices as the linear blend L plus a departure D: the normal equations
        ``(E^T E + anchor I) X = E^T target + anchor L`` become ``(E^T E + anchor I) D = E^T (target - E L)``,
        whose right-hand side is small where the gradients agree with the linear blend, so the
        back-substitution in float32 loses digits only of D (not of the vertices' coordinates)."""
        n_t, n_v, n_k = len(a), len(self.rest), len(self.offsets)
        used = np.flatnonzero(a.any(0))  # key-shapes no frame uses (weight exactly 0) add nothing
        if 2 * len(used) > n_k:  # copying the used columns costs more than multiplying by zeros
            used = np.arange(n_k)
        coef = self._coef if len(used) == n_k else self._coef[:, used]
        offsets_t = self._offsets_t if len(used) == n_k else self._offsets_t[:, used]
        out = np.empty((n_t, n_v, 3), np.float32)
        step = self.GROUP_FRAMES
        work = self._device_work(min(step, n_t)) if self.use_opencl and n_t else None
        rest = self.rest.astype(np.float32).reshape(-1, 1)
        for lo in range(0, n_t, step):  # bounded memory on long clips
            a_t = np.ascontiguousarray(a[lo:lo + step, used].T)  # (K', T)
            if work is not None:
                self._group_opencl(coef, offsets_t, a_t, work, out[lo:lo + step])
            else:
                lin = (offsets_t @ a_t + rest).reshape(n_v, 3, -1)  # (V, 3, T)
                self._solve(self._rhs_numpy(coef, a_t, lin), lin, out[lo:lo + step])
        return out

    def _rhs_numpy(self, coef: np.ndarray, a_t: np.ndarray, lin: np.ndarray) -> np.ndarray:
        """(V, 3, T) float32 ``E^T (R S e - E L)`` of frames with weights a_t (K', T), L = lin (V, 3, T)."""
        n_t, n_v = a_t.shape[1], len(self.rest)
        rhs = np.zeros((n_v, 3 * n_t), np.float32)  # column i * T + t: coordinate i of frame t
        for lo, hi, verts, scatter in self._blocks:
            n_b = hi - lo
            g = (coef[9 * lo:9 * hi] @ a_t).reshape(n_b, 9, n_t)
            g[:, 3:] += self._rest_edges[lo:hi, :, None]  # S e = e + sum_k alpha_k (S_k - I) e
            target = np.empty((n_b, 2, 3, n_t), np.float32)
            _rotate_edges(g, target)
            f0, f1, f2 = self.faces[lo:hi].T
            target[:, 0] -= lin[f1] - lin[f0]
            target[:, 1] -= lin[f2] - lin[f0]
            rhs[verts] += scatter @ target.reshape(2 * n_b, 3 * n_t)
        return rhs.reshape(n_v, 3, n_t)

    def _solve(self, rhs: np.ndarray, lin: np.ndarray, out: np.ndarray) -> None:
        """SuperLU back-substitutions of (V, 3, T) right-hand sides, ``SOLVE_FRAMES`` frames at a
        time; the departures plus the linear blend lin (V, 3, T) into ``out`` (T, V, 3)."""
        n_v, _, n_t = rhs.shape
        step = self.SOLVE_FRAMES
        for start in range(0, n_t, step):
            stop = min(start + step, n_t)
            chunk = np.asfortranarray(rhs[:, :, start:stop].reshape(n_v, -1))  # (V, 3 k)
            d = self.factor.solve(chunk).reshape(n_v, 3, -1)
            np.add(lin[:, :, start:stop], d, out=out[start:stop].transpose(1, 2, 0))

    def _device_arrays(self):
        """The OpenCL buffers that do not change per clip (made once per context): the mesh's
        rest edges, triangles and vertex-to-triangle lists, the LU factors and permutations."""
        import pyopencl as cl

        ctx = context()
        if getattr(self, "_cl_static", (None,))[0] is not ctx:
            lower = sparse.tril(self.factor.L, -1, format="csr")
            upper = sparse.triu(self.factor.U, 1, format="csr")
            arrays = (self._rest_edges, self.faces.astype(np.int32), self._start, self._incident,
                      self.factor.perm_r, self.factor.perm_c, lower.indptr, lower.indices, lower.data,
                      upper.indptr, upper.indices, upper.data, self.factor.U.diagonal())
            mf = cl.mem_flags
            self._cl_static = (ctx,) + tuple(
                cl.Buffer(ctx, mf.READ_ONLY | mf.COPY_HOST_PTR,
                          hostbuf=np.ascontiguousarray(x, np.float32 if x.dtype.kind == "f" else np.int32))
                for x in arrays)
        return self._cl_static[1:]

    def _device_work(self, n_t: int) -> dict:
        """Host arrays and device buffers of one group of up to ``n_t`` frames (padded to a multiple
        of 16), made once per clip: page-aligned host arrays the device uses in place."""
        import pyopencl as cl

        ctx, mf = context(), cl.mem_flags
        n_p, n_v, n_f = -(-n_t // 16) * 16, len(self.rest), len(self.faces)
        host = {"g": aligned_empty((9 * n_f, n_p), np.float32), "lin": aligned_empty((3 * n_v, n_p), np.float32),
                "out": aligned_empty((n_p, n_v, 3), np.float32)}
        work = dict(host, n_p=n_p)
        for name, flag in (("g", mf.READ_ONLY), ("lin", mf.READ_ONLY), ("out", mf.WRITE_ONLY)):
            work[name + "_buf"] = cl.Buffer(ctx, flag | mf.USE_HOST_PTR, hostbuf=host[name])
        work["edges"] = cl.Buffer(ctx, mf.READ_WRITE, 6 * n_f * n_p * 4)
        work["rhs"], work["scratch"] = (cl.Buffer(ctx, mf.READ_WRITE, 3 * n_v * n_p * 4) for _ in range(2))
        return work

    def _group_opencl(self, coef: np.ndarray, offsets_t: np.ndarray, a_t: np.ndarray, work: dict,
                      out: np.ndarray) -> None:
        """One group of frames (weights a_t (K', T)) on OpenCL (``kernels/gradient_rhs.cl``): the blended
        gradients and the linear blend by matrix products here, then the rotated edges, their sum onto
        the vertices and the back-substitutions (the factors of ``self.factor``) on the device, into
        ``out`` (T, V, 3). Frames are padded with zero weights to a multiple of 16 (the kernels take 8
        or 16 at a time)."""
        import pyopencl as cl

        q = queue()
        n_t, n_v, n_f = a_t.shape[1], len(self.rest), len(self.faces)
        n_p = -(-n_t // 16) * 16
        a_t = np.pad(a_t, ((0, 0), (0, n_p - n_t)))
        (rest_edges, faces, start, incident, perm_r, perm_c, l_start, l_col, l_val, u_start, u_col, u_val,
         u_diag) = self._device_arrays()
        g, lin = (work[k].reshape(-1)[:len(work[k]) * n_p].reshape(-1, n_p) for k in ("g", "lin"))
        np.matmul(coef, a_t, out=g)  # (9F, T)
        np.matmul(offsets_t, a_t, out=lin)  # (3V, T)
        lin += self.rest.astype(np.float32).reshape(-1, 1)
        kernel("gradient_rhs", "residual_edges")(q, (n_p // 8, n_f), None, work["g_buf"], rest_edges, faces,
                                                 work["lin_buf"], work["edges"], np.int32(n_p))
        kernel("gradient_rhs", "gather_edges")(q, (n_p // 8, n_v), None, work["edges"], start, incident, work["rhs"],
                                               np.int32(n_p))
        kernel("gradient_rhs", "lu_solve")(q, (3 * n_p // 16,), None, work["rhs"], work["scratch"], perm_r, perm_c,
                                           l_start, l_col, l_val, u_start, u_col, u_val, u_diag, work["lin_buf"],
                                           work["out_buf"], np.int32(n_v), np.int32(n_p))
        cl.enqueue_copy(q, work["out"], work["out_buf"], is_blocking=True)
        out[:] = work["out"][:n_t]
