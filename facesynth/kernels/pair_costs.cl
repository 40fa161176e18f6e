// Transition costs of paper Table I computed on demand from per-node boundary features, and
// the exact pruned min-plus step of Algorithm 1 that uses them.
//
//   DSC(i, j)  = scale[j] * sum_d (x[i, d] + y[j, d])^2               (Eq. 6, expanded blend)
//   PGap(i, j) = sum_k || first_pos[j, k] - last_pos[i, k] ||          (Eq. 8)
//   VGap(i, j) = sum_k || first_vel[j, k] - last_vel[i, k] ||          (Eq. 9)
//   TC(i, j)   = 0 if pre[j] == i; alpha1 PNT if pre[j] < 0; else
//                ((alpha2 DSC + alpha3 PGap) + VGap) + PNT [viseme(i) != viseme(pre(j))]
//
// Every sum runs front to back in float32 with no contraction, so the values are bit-identical
// to the NumPy reference (facesynth.search.pairs), which does the same operations in the same
// order. The host passes alpha1 * PNT already rounded to float32, as the reference does.
#pragma OPENCL FP_CONTRACT OFF

#ifndef DIMS
#error "build with -DDIMS=<DSC feature length> -DM3=<3 x markers> -DPIVOTS=<pivots>"
#endif

typedef struct {
    float a2, a3, pnt, a1pnt;
} weights;

inline float pair_tc(const int i, const int j,
                     __global const float *x, __global const float *y, __global const float *scale,
                     __global const float *last_pos, __global const float *first_pos,
                     __global const float *last_vel, __global const float *first_vel,
                     __global const int *vis, __global const int *pre, __global const int *pre_vis,
                     const float a2, const float a3, const float pnt, const float a1pnt)
{
    const int p = pre[j];
    if (p == i) return 0.0f;
    if (p < 0) return a1pnt;
    __global const float *xi = x + (size_t)i * DIMS;
    __global const float *yj = y + (size_t)j * DIMS;
    float dsc = 0.0f;
    for (int d = 0; d < DIMS; ++d) {
        const float s = xi[d] + yj[d];
        dsc = dsc + s * s;
    }
    dsc = dsc * scale[j];
    __global const float *lp = last_pos + (size_t)i * M3;
    __global const float *fp = first_pos + (size_t)j * M3;
    __global const float *lv = last_vel + (size_t)i * M3;
    __global const float *fv = first_vel + (size_t)j * M3;
    float pg = 0.0f, vg = 0.0f;
    for (int k = 0; k < M3; k += 3) {
        const float px = fp[k] - lp[k], py = fp[k + 1] - lp[k + 1], pz = fp[k + 2] - lp[k + 2];
        pg = pg + sqrt(px * px + py * py + pz * pz);
        const float vx = fv[k] - lv[k], vy = fv[k + 1] - lv[k + 1], vz = fv[k + 2] - lv[k + 2];
        vg = vg + sqrt(vx * vx + vy * vy + vz * vz);
    }
    float tc = a2 * dsc;
    tc = tc + a3 * pg;
    tc = tc + vg;
    tc = tc + (vis[i] != pre_vis[j] ? pnt : 0.0f);
    return tc;
}

#define PAIR_ARGS x, y, scale, last_pos, first_pos, last_vel, first_vel, vis, pre, pre_vis, a2, a3, pnt, a1pnt
#define FEATURE_PARAMS __global const float *x, __global const float *y, __global const float *scale, \
    __global const float *last_pos, __global const float *first_pos, \
    __global const float *last_vel, __global const float *first_vel, \
    __global const int *vis, __global const int *pre, __global const int *pre_vis, \
    const float a2, const float a3, const float pnt, const float a1pnt

// out[r, c] = TC(rows[r], cols[c]); a (n_rows, n_cols) row-major block.
__kernel void tc_block(FEATURE_PARAMS,
                       __global const int *rows, __global const int *cols, const int n_rows, const int n_cols,
                       __global float *out)
{
    const int c = get_global_id(0);
    const int r = get_global_id(1);
    if (c >= n_cols || r >= n_rows) return;
    out[(size_t)r * n_cols + c] = pair_tc(rows[r], cols[c], PAIR_ARGS);
}

// One step of the exact pruned DP for a list of columns j (one work-item each):
//   best[c] = min(init[c], min_r (phi[r] + TC(rows[r], j)))
// rows are sorted by phi ascending. TC >= 0, so the scan stops at the first row with
// phi >= best; a row whose cheap lower bound (viseme penalty and pivot bounds of PGap and
// VGap, shrunk by 1e-4 relative and `slack` absolute against rounding) already reaches best is skipped without computing
// its cost. The minimum is the same float32 value as the dense min over all rows; evals[c]
// counts the pair costs computed.
// pivots: row_lp/row_lv[i * PIVOTS + q] = mixed-norm distance of node i's last position /
// velocity from pivot q; col_fp/col_fv likewise for first position / velocity.
__kernel void pruned_columns(FEATURE_PARAMS,
                             __global const float *row_lp, __global const float *row_lv,
                             __global const float *col_fp, __global const float *col_fv, const float slack,
                             __global const int *rows, __global const float *phi, const int n_rows,
                             __global const int *cols, __global const float *init, const int n_cols,
                             __global float *best_out, __global int *evals_out)
{
    const int c = get_global_id(0);
    if (c >= n_cols) return;
    const int j = cols[c];
    const int pj = pre[j];
    const int pv = pre_vis[j];
    float best = init[c];
    int evals = 0;
    float fpq[PIVOTS], fvq[PIVOTS];
    for (int q = 0; q < PIVOTS; ++q) {
        fpq[q] = col_fp[(size_t)j * PIVOTS + q];
        fvq[q] = col_fv[(size_t)j * PIVOTS + q];
    }
    for (int r = 0; r < n_rows; ++r) {
        const float p = phi[r];
        if (p >= best) break;
        const int i = rows[r];
        if (i == pj) continue;  // rule 1 is in init
        float lp = 0.0f, lv = 0.0f;
        for (int q = 0; q < PIVOTS; ++q) {
            const float dp = row_lp[(size_t)i * PIVOTS + q] - fpq[q];
            const float dv = row_lv[(size_t)i * PIVOTS + q] - fvq[q];
            const float ap = dp < 0.0f ? -dp : dp;
            const float av = dv < 0.0f ? -dv : dv;
            lp = ap > lp ? ap : lp;
            lv = av > lv ? av : lv;
        }
        const float lb = ((vis[i] != pv ? pnt : 0.0f) + a3 * lp + lv) * 0.9999f - slack;
        if (p + lb >= best) continue;
        const float v = p + pair_tc(i, j, PAIR_ARGS);
        best = v < best ? v : best;
        ++evals;
    }
    best_out[c] = best;
    evals_out[c] = evals;
}
