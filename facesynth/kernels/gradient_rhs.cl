// Right-hand sides of deformation-gradient blending (facesynth/domain/retarget/gradients.py), for a
// group of T frames (a multiple of 16; each work-item takes 8 or 16 neighbouring frames as a vector):
// each triangle's two blended edges R (S e) minus the same edges of the linear blend, then
// summed onto the vertices (E^T) by a gather over each vertex's triangles (no atomics).
//
// residual_edges: work-item (t / 8, f).
//   g: (F, 9, T) blended rotation vector (rows 0-2) and stretch offsets (S - I) e1, (S - I) e2
//      (rows 3-5, 6-8), mm; rest_edges: (F, 6) e1, e2 of the rest mesh, mm; faces: (F, 3);
//   lin: (V, 3, T) linear blend, mm; res: (F, 6, T) R (S e) - (lin edge), mm.
// R x = x + a (r x x) + b (r x (r x x)), a = sin t / t, b = 2 (sin(t/2) / t)^2, t = |r|.
__kernel void residual_edges(__global const float *g, __global const float *rest_edges,
                             __global const int *faces, __global const float *lin,
                             __global float *res, const int T)
{
    const int t = 8 * get_global_id(0);
    const int f = get_global_id(1);
    const size_t T_ = (size_t)T;
    const __global float *gf = g + (size_t)f * 9 * T_ + t;
    const float8 rx = vload8(0, gf), ry = vload8(0, gf + T_), rz = vload8(0, gf + 2 * T_);
    const float8 th2 = rx * rx + ry * ry + rz * rz;
    const float8 th = sqrt(th2);
    float8 a, b;
    if (all(th2 <= 1.0f)) {
        // |r| <= 1 rad (a face's triangles, nearly always): the Taylor series of sin t / t and
        // (1 - cos t) / t^2 in t^2, truncated where the next term is below 1e-9 (float32: 6e-8).
        a = 1.0f + th2 * (-1.0f / 6 + th2 * (1.0f / 120 + th2 * (-1.0f / 5040 + th2 * (1.0f / 362880
              + th2 * (-1.0f / 39916800)))));
        b = 0.5f + th2 * (-1.0f / 24 + th2 * (1.0f / 720 + th2 * (-1.0f / 40320 + th2 * (1.0f / 3628800
              + th2 * (-1.0f / 479001600)))));
    } else {
        // th < 1e-3: the series (sin th / th loses nothing there, but is 0 / 0 at th = 0)
        const int8 small = th < 1e-3f;
        const float8 safe = select(th, (float8)(1.0f), small);
        const float8 hs = sin(0.5f * safe) / safe;
        a = select(sin(safe) / safe, 1.0f - th2 / 6.0f, small);
        b = select(2.0f * hs * hs, 0.5f - th2 / 24.0f, small);
    }
    const __global float *l0 = lin + (size_t)faces[3 * f] * 3 * T_ + t;
    __global float *out = res + (size_t)f * 6 * T_ + t;
    for (int j = 0; j < 2; j++) {
        const float8 x = rest_edges[6 * f + 3 * j] + vload8(0, gf + (3 + 3 * j) * T_);
        const float8 y = rest_edges[6 * f + 3 * j + 1] + vload8(0, gf + (4 + 3 * j) * T_);
        const float8 z = rest_edges[6 * f + 3 * j + 2] + vload8(0, gf + (5 + 3 * j) * T_);
        const float8 cx = ry * z - rz * y, cy = rz * x - rx * z, cz = rx * y - ry * x;
        const float8 dx = ry * cz - rz * cy, dy = rz * cx - rx * cz, dz = rx * cy - ry * cx;
        const __global float *l1 = lin + (size_t)faces[3 * f + 1 + j] * 3 * T_ + t;
        vstore8(x + (a * cx + b * dx) - (vload8(0, l1) - vload8(0, l0)), 0, out + (3 * j) * T_);
        vstore8(y + (a * cy + b * dy) - (vload8(0, l1 + T_) - vload8(0, l0 + T_)), 0, out + (3 * j + 1) * T_);
        vstore8(z + (a * cz + b * dz) - (vload8(0, l1 + 2 * T_) - vload8(0, l0 + 2 * T_)), 0,
                out + (3 * j + 2) * T_);
    }
}

// gather_edges: work-item (t / 8, v). rhs[v, i, t] = sum over v's triangles f of E^T res:
// -(r1 + r2) where v is corner 0 of f, r1 at corner 1, r2 at corner 2.
//   res: (F, 6, T); start: (V + 1) offsets into incident; incident: 4 f + corner, by vertex;
//   rhs: (V, 3, T), mm.
__kernel void gather_edges(__global const float *res, __global const int *start,
                           __global const int *incident, __global float *rhs, const int T)
{
    const int t = 8 * get_global_id(0);
    const int v = get_global_id(1);
    const size_t T_ = (size_t)T;
    float8 sx = 0.0f, sy = 0.0f, sz = 0.0f;
    for (int k = start[v]; k < start[v + 1]; k++) {
        const int code = incident[k];
        const int corner = code & 3;
        const __global float *p = res + (size_t)(code >> 2) * 6 * T_ + t;
        if (corner == 0) {
            sx -= vload8(0, p) + vload8(0, p + 3 * T_);
            sy -= vload8(0, p + T_) + vload8(0, p + 4 * T_);
            sz -= vload8(0, p + 2 * T_) + vload8(0, p + 5 * T_);
        } else {
            const __global float *e = p + (corner - 1) * 3 * T_;
            sx += vload8(0, e);
            sy += vload8(0, e + T_);
            sz += vload8(0, e + 2 * T_);
        }
    }
    __global float *out = rhs + (size_t)v * 3 * T_ + t;
    vstore8(sx, 0, out);
    vstore8(sy, 0, out + T_);
    vstore8(sz, 0, out + 2 * T_);
}

// lu_solve: work-item c / 16 of the C = 3 T columns (column i T + t: coordinate i of frame t; T a
// multiple of 16, a float16 per row: one cache line). Solves N d = rhs for 16 columns with the
// sparse LU factors of Pr N Pc = L U (SuperLU's, as scipy gives them: d = Pc U^-1 L^-1 Pr rhs),
// by rows of L and U (each row's sum kept in registers: a third less CPU than updating by
// columns), and writes the vertices out[t, v, i] = lin[v, i, t] + d[v, i T + t].
//   rhs: (V, C); y: (C / 16, V, 16) scratch, its own rows for each work-item; perm_r, perm_c: (V,);
//   l_start, l_col, l_val: L below its unit diagonal, CSR; u_start, u_col, u_val: U above its
//   diagonal, CSR; u_diag: (V,);
//   lin: (V, 3, T), mm; out: (T, V, 3), mm.
__kernel void lu_solve(__global const float *rhs, __global float *y, __global const int *perm_r,
                       __global const int *perm_c, __global const int *l_start, __global const int *l_col,
                       __global const float *l_val, __global const int *u_start, __global const int *u_col,
                       __global const float *u_val, __global const float *u_diag, __global const float *lin,
                       __global float *out, const int V, const int T)
{
    const int c = 16 * get_global_id(0);
    const size_t C = 3 * (size_t)T;
    __global float *yc = y + (size_t)c * V;  // this work-item's (V, 16) scratch, contiguous
    for (int j = 0; j < V; j++)
        vstore16(vload16(0, rhs + j * C + c), perm_r[j], yc);
    for (int j = 0; j < V; j++) {  // forward: y_j -= L_jk y_k, k < j
        float16 s = vload16(j, yc);
        for (int k = l_start[j]; k < l_start[j + 1]; k++)
            s -= l_val[k] * vload16(l_col[k], yc);
        vstore16(s, j, yc);
    }
    for (int j = V - 1; j >= 0; j--) {  // backward: y_j = (y_j - U_jk y_k) / U_jj, k > j
        float16 s = vload16(j, yc);
        for (int k = u_start[j]; k < u_start[j + 1]; k++)
            s -= u_val[k] * vload16(u_col[k], yc);
        vstore16(s / u_diag[j], j, yc);
    }
    const int i = c / T, t = c % T;
    for (int j = 0; j < V; j++) {
        const float16 x = vload16(perm_c[j], yc) + vload16(0, lin + (size_t)j * C + c);
        float xs[16];
        vstore16(x, 0, xs);
        __global float *o = out + ((size_t)t * V + j) * 3 + i;
        for (int l = 0; l < 16; l++)
            o[(size_t)l * V * 3] = xs[l];
    }
}
