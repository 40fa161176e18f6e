// Transition costs of paper Table I computed on demand from per-node boundary features, and
// the exact pruned min-plus step of Algorithm 1 that uses them.
//
//   DSC(i, j)  = scale[j] * sum_d (x[i, d] + y[j, d])^2               (Eq. 6, expanded blend)
//   PGap(i, j) = sum_k || first_pos[j, k] - last_pos[i, k] ||          (Eq. 8)
//   VGap(i, j) = sum_k || first_vel[j, k] - last_vel[i, k] ||          (Eq. 9)
//   TC(i, j)   = 0 if pre[j] == i; (alpha3 PGap + VGap) + alpha1 PNT if pre[j] < 0; else ((alpha2 DSC + alpha3 PGap) + VGap) + PNT [viseme(i) != viseme(pre(j))]
//
// Layout (facesynth.domain.search.pairs.DeviceLayout): x and y are (N, DIMS8 * 8), zero-padded; the
// boundary states are (N, 3, MQ * 8), the x, y and z coordinates of the markers in planes,
// zero-padded (a padded marker adds sqrt(0) = 0). Each sum runs in eight lanes (element or
// marker d goes to lane d % 8, front to back), and the lanes are added as
// ((l0 + l1) + (l2 + l3)) + ((l4 + l5) + (l6 + l7)); no contraction, correctly rounded sqrt.
// The NumPy reference (facesynth.domain.search.pairs) does the same operations in the same order, so
// the values are bit-identical. The host passes alpha1 * PNT already rounded to float32.
#pragma OPENCL FP_CONTRACT OFF

#ifndef DIMS8
#error "build with -DDIMS8=<DSC feature length / 8> -DMQ=<markers / 8, rounded up> -DPIVOTS=<pivots>"
#endif

inline float lanes(const float8 a)
{
    return ((a.s0 + a.s1) + (a.s2 + a.s3)) + ((a.s4 + a.s5) + (a.s6 + a.s7));
}

inline float gap(__global const float *last, __global const float *first)
{
    __global const float8 *l = (__global const float8 *)last;
    __global const float8 *f = (__global const float8 *)first;
    float8 acc = (float8)(0.0f);
    for (int q = 0; q < MQ; ++q) {
        const float8 dx = f[q] - l[q];
        const float8 dy = f[MQ + q] - l[MQ + q];
        const float8 dz = f[2 * MQ + q] - l[2 * MQ + q];
        acc = acc + sqrt(dx * dx + dy * dy + dz * dz);
    }
    return lanes(acc);
}

inline float pair_tc(const int i, const int j,
                     __global const float *x, __global const float *y, __global const float *scale,
                     __global const float *last_pos, __global const float *first_pos,
                     __global const float *last_vel, __global const float *first_vel,
                     __global const int *vis, __global const int *pre, __global const int *pre_vis,
                     const float a2, const float a3, const float pnt, const float a1pnt)
{
    const int p = pre[j];
    if (p == i) return 0.0f;
    __global const float8 *xi = (__global const float8 *)(x + (size_t)i * DIMS8 * 8);
    __global const float8 *yj = (__global const float8 *)(y + (size_t)j * DIMS8 * 8);
    float8 acc = (float8)(0.0f);
    for (int d = 0; d < DIMS8; ++d) {
        const float8 s = xi[d] + yj[d];
        acc = acc + s * s;
    }
    const float dsc = lanes(acc) * scale[j];
    const size_t stride = (size_t)3 * MQ * 8;
    const float pg = gap(last_pos + (size_t)i * stride, first_pos + (size_t)j * stride);
    const float vg = gap(last_vel + (size_t)i * stride, first_vel + (size_t)j * stride);
    float tc = a2 * dsc;
    tc = tc + a3 * pg;
    tc = tc + vg;
    if (p < 0) {  // rule 4: (alpha3 PGap + VGap) + alpha1 PNT
        float r4 = a3 * pg;
        r4 = r4 + vg;
        return r4 + a1pnt;
    }
    tc = tc + (vis[i] != pre_vis[j] ? pnt : 0.0f);
    return tc;
}

// pair_tc for rule 2/3 pairs, abandoned as soon as a lower bound of TC reaches `limit`: the
// viseme penalty, then PGap and then VGap in lane partial sums (all non-negative, so a partial sum
// never exceeds the full one), shrunk by 1e-4 relative and `slack` absolute against rounding.
// Returns INFINITY when abandoned, else exactly pair_tc's value (the same sums in the same
// order; the three sums are independent, so computing DSC last changes nothing).
inline float pair_tc_below(const int i, const int j, const float limit, const float slack,
                           __global const float *x, __global const float *y, __global const float *scale,
                           __global const float *last_pos, __global const float *first_pos,
                           __global const float *last_vel, __global const float *first_vel,
                           __global const int *vis, __global const int *pre, __global const int *pre_vis,
                           const float a2, const float a3, const float pnt, const float a1pnt)
{
    const bool rule4 = pre[j] < 0;  // (alpha3 PGap + VGap) + alpha1 PNT, no DSC
    const float pen = rule4 ? a1pnt : (vis[i] != pre_vis[j] ? pnt : 0.0f);
    const size_t stride = (size_t)3 * MQ * 8;
    __global const float8 *l = (__global const float8 *)(last_pos + (size_t)i * stride);
    __global const float8 *f = (__global const float8 *)(first_pos + (size_t)j * stride);
    float8 acc = (float8)(0.0f);
    for (int q = 0; q < MQ; ++q) {
        const float8 dx = f[q] - l[q];
        const float8 dy = f[MQ + q] - l[MQ + q];
        const float8 dz = f[2 * MQ + q] - l[2 * MQ + q];
        acc = acc + sqrt(dx * dx + dy * dy + dz * dz);
        if ((q & 3) == 3 && (pen + a3 * lanes(acc)) * 0.9999f - slack >= limit) return INFINITY;
    }
    const float pg = lanes(acc);
    const float known = pen + a3 * pg;
    l = (__global const float8 *)(last_vel + (size_t)i * stride);
    f = (__global const float8 *)(first_vel + (size_t)j * stride);
    acc = (float8)(0.0f);
    for (int q = 0; q < MQ; ++q) {
        const float8 dx = f[q] - l[q];
        const float8 dy = f[MQ + q] - l[MQ + q];
        const float8 dz = f[2 * MQ + q] - l[2 * MQ + q];
        acc = acc + sqrt(dx * dx + dy * dy + dz * dz);
        if ((q & 3) == 3 && (known + lanes(acc)) * 0.9999f - slack >= limit) return INFINITY;
    }
    const float vg = lanes(acc);
    if ((pen + a3 * pg + vg) * 0.9999f - slack >= limit) return INFINITY;
    if (rule4) {  // the same float32 operations as pair_tc
        float r4 = a3 * pg;
        r4 = r4 + vg;
        return r4 + a1pnt;
    }
    __global const float8 *xi = (__global const float8 *)(x + (size_t)i * DIMS8 * 8);
    __global const float8 *yj = (__global const float8 *)(y + (size_t)j * DIMS8 * 8);
    acc = (float8)(0.0f);
    for (int d = 0; d < DIMS8; ++d) {
        const float8 s = xi[d] + yj[d];
        acc = acc + s * s;
    }
    const float dsc = lanes(acc) * scale[j];
    float tc = a2 * dsc;
    tc = tc + a3 * pg;
    tc = tc + vg;
    tc = tc + pen;
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

// One step of the exact pruned DP for a list of nodes (one work-item each):
//   forward (backward == 0):  best[c] = min(init[c], min_r (phi[r] + TC(rows[r], cols[c])))
//   backward (backward == 1): best[c] = min(init[c], min_r (phi[r] + TC(cols[c], rows[r])))
// Pairs of Table I rule 1 are left to init (the captured link costs 0); a rule-4 pair (no
// captured predecessor) is bounded below by alpha1 PNT instead of the viseme penalty. The minimum is the same float32 value as the dense min over
// all rows (only rows whose lower bound reaches the current best are skipped, and best only
// takes computed values); evals[c] counts the pair costs computed.
//
// The rows come in groups of rows close in pivot space (facesynth.domain.search.pairs.row_groups):
// group g is rows[group_start[g] .. group_start[g + 1]), sorted by phi ascending inside, the
// groups by their smallest phi. Per group the host gives the range [lo, hi] of each pivot
// distance over its rows and the set of row visemes (a bit mask; all bits when a viseme is
// past 31). Since | d(x, p) - d(y, p) | >= the distance from d(y, p) to any range holding
// d(x, p), a group's lower bound of phi + TC over its rows is its smallest phi plus the
// viseme penalty unless the column's viseme is in the set, plus alpha3 and 1 times the
// largest pivot-range distances of the positions and velocities. Every bound is shrunk by
// 1e-4 relative and `slack` absolute against rounding. The scan: first the one row of the
// smallest phi plus its own pivot bound (a seed, to get a good best early), then the groups
// in order, stopping at the first whose smallest phi reaches best and skipping any whose
// bound does; inside a group the scan stops when phi plus the group's TC bound reaches best,
// and skips a row whose own pivot bound does.
//
// What the scan needs of each row comes gathered in row order by the host, so it is read
// front to back: row_p/row_v[r * PIVOTS + q] = pivot distances of rows[r] (forward: of its
// last position / velocity; backward: of its first), row_vis[r] = its viseme (forward) or
// its predecessor's viseme (backward), row_pre[r] = its predecessor (backward only).
// col_p/col_v[c * PIVOTS + q] = those of cols[c] (forward: first; backward: last).
// group_lo/hi_p/v[g * PIVOTS + q]: the ranges; group_vis[g]: the viseme set.
//
// All of these come in one buffer, `step` (one host-to-device copy per launch instead of
// sixteen: on a CPU device each copy is a command of its own): step[0 .. STEP_PARTS) are the
// word offsets of the arrays below (each 32-byte aligned), then n_groups, n_cols, backward.
// The results go to `out`: best[c] = out[c] (float bits), evals[c] = out[n_cols + c].
#ifndef MAX_GROUPS
#define MAX_GROUPS 256
#endif

inline float range_gap(const float x, const float lo, const float hi)
{
    return x < lo ? lo - x : (x > hi ? x - hi : 0.0f);
}

// A row's own lower bound of TC against the column (phi not included): the viseme penalty
// (alpha1 PNT for rule 4, pj < 0) plus alpha3 and 1 times the largest pivot-distance gaps of
// the positions and velocities, shrunk by 1e-4 relative and `slack` absolute.
inline float row_bound(const int r, const int pj, const int me_vis, const float *mq_p, const float *mq_v,
                       __global const float *row_p, __global const float *row_v, __global const int *row_vis,
                       const float a3, const float pnt, const float a1pnt, const float slack)
{
    float lp = 0.0f, lv = 0.0f;
    for (int q = 0; q < PIVOTS; ++q) {
        const float dp = row_p[(size_t)r * PIVOTS + q] - mq_p[q];
        const float dv = row_v[(size_t)r * PIVOTS + q] - mq_v[q];
        const float ap = dp < 0.0f ? -dp : dp;
        const float av = dv < 0.0f ? -dv : dv;
        lp = ap > lp ? ap : lp;
        lv = av > lv ? av : lv;
    }
    const float pen = pj < 0 ? a1pnt : (row_vis[r] != me_vis ? pnt : 0.0f);
    return (pen + a3 * lp + lv) * 0.9999f - slack;
}

inline float scan_group(const int g, const float gap, float best, int *evals, const int me, const int me_pre,
                        const int me_vis, const float *mq_p, const float *mq_v, const float slack, const int backward,
                        __global const float *row_p, __global const float *row_v,
                        __global const int *row_vis, __global const int *row_pre,
                        __global const int *rows, __global const float *phi, __global const int *group_start,
                        __global const float *x, __global const float *y, __global const float *scale,
                        __global const float *last_pos, __global const float *first_pos,
                        __global const float *last_vel, __global const float *first_vel,
                        __global const int *vis, __global const int *pre, __global const int *pre_vis,
                        const float a2, const float a3, const float pnt, const float a1pnt)
{
    const int end = group_start[g + 1];
    for (int r = group_start[g]; r < end; ++r) {
        const float p = phi[r];
        if (p + gap >= best) break;
        const int other = rows[r];
        const int i = backward ? me : other;
        const int pj = backward ? row_pre[r] : me_pre;
        if (pj == i) continue;  // rule 1 is in init
        const float lb = row_bound(r, pj, me_vis, mq_p, mq_v, row_p, row_v, row_vis, a3, pnt, a1pnt, slack);
        if (p + lb >= best) continue;
        const int j = backward ? other : me;
        // best - p rounds by at most 2^-24 best (costs are >= 0); the limit allows for that
        const float v = p + pair_tc_below(i, j, (best - p) + best * 2.4e-7f, slack, PAIR_ARGS);
        best = v < best ? v : best;
        ++*evals;
    }
    return best;
}

#define STEP_PARTS 16
#define STEP_F(k) ((__global const float *)(step + step[k]))
#define STEP_I(k) ((__global const int *)(step + step[k]))

__kernel void pruned_columns(FEATURE_PARAMS, const float slack, __global const uint *step, __global uint *out)
{
    const int n_groups = (int)step[STEP_PARTS];
    const int n_cols = (int)step[STEP_PARTS + 1];
    const int backward = (int)step[STEP_PARTS + 2];
    const int c = get_global_id(0);
    if (c >= n_cols) return;
    __global const int *rows = STEP_I(0);
    __global const float *phi = STEP_F(1);
    __global const int *row_vis = STEP_I(2);
    __global const int *row_pre = STEP_I(3);
    __global const float *row_p = STEP_F(4);
    __global const float *row_v = STEP_F(5);
    __global const int *group_start = STEP_I(6);
    __global const float *group_lo_p = STEP_F(7);
    __global const float *group_hi_p = STEP_F(8);
    __global const float *group_lo_v = STEP_F(9);
    __global const float *group_hi_v = STEP_F(10);
    __global const uint *group_vis = step + step[11];
    __global const int *cols = STEP_I(12);
    __global const float *init = STEP_F(13);
    __global const float *col_p = STEP_F(14);
    __global const float *col_v = STEP_F(15);
    const int me = cols[c];
    const int me_pre = pre[me];
    const int me_vis = backward ? vis[me] : pre_vis[me];
    const uint me_bit = (me_vis >= 0 && me_vis < 32) ? (1u << me_vis) : 0u;
    float best = init[c];
    int evals = 0;
    float mq_p[PIVOTS], mq_v[PIVOTS];
    for (int q = 0; q < PIVOTS; ++q) {
        mq_p[q] = col_p[(size_t)c * PIVOTS + q];
        mq_v[q] = col_v[(size_t)c * PIVOTS + q];
    }
    // the groups' TC lower bounds (without phi), for the groups that can matter: those whose
    // smallest phi is below best (the groups come by their smallest phi; TC >= 0)
    float gap[MAX_GROUPS];
    int reach = 0;
    while (reach < n_groups && phi[group_start[reach]] < best) ++reach;
    for (int g = 0; g < reach; ++g) {
        float lp = 0.0f, lv = 0.0f;
        for (int q = 0; q < PIVOTS; ++q) {
            const float ap = range_gap(mq_p[q], group_lo_p[(size_t)g * PIVOTS + q], group_hi_p[(size_t)g * PIVOTS + q]);
            const float av = range_gap(mq_v[q], group_lo_v[(size_t)g * PIVOTS + q], group_hi_v[(size_t)g * PIVOTS + q]);
            lp = ap > lp ? ap : lp;
            lv = av > lv ? av : lv;
        }
        // rule 4 (no captured predecessor: alpha1 PNT instead of the viseme penalty): forward, the
        // column's own; backward, any row's, so the smaller of the two bounds the group
        const float vpen = (group_vis[g] & me_bit) ? 0.0f : pnt;
        const float gpen = backward ? (a1pnt < vpen ? a1pnt : vpen) : (me_pre < 0 ? a1pnt : vpen);
        gap[g] = (gpen + a3 * lp + lv) * 0.9999f - slack;
    }
    // seed: the row of the smallest phi + its own bound is computed first, so that best is
    // near its final value before the scan (the scan then computes it again: one pair)
    int seed = -1;
    float seed_lb = best;
    for (int g = 0; g < reach; ++g) {
        const float p0 = phi[group_start[g]];
        if (p0 >= seed_lb) break;
        if (p0 + gap[g] >= seed_lb) continue;
        const int end = group_start[g + 1];
        for (int r = group_start[g]; r < end; ++r) {
            const float p = phi[r];
            if (p + gap[g] >= seed_lb) break;
            const int i = backward ? me : rows[r];
            const int pj = backward ? row_pre[r] : me_pre;
            if (pj == i) continue;
            const float lb = p + row_bound(r, pj, me_vis, mq_p, mq_v, row_p, row_v, row_vis, a3, pnt, a1pnt, slack);
            if (lb < seed_lb) { seed_lb = lb; seed = r; }
        }
    }
    if (seed >= 0) {
        const int i = backward ? me : rows[seed];
        const int j = backward ? rows[seed] : me;
        const float p = phi[seed];
        const float v = p + pair_tc_below(i, j, (best - p) + best * 2.4e-7f, slack, PAIR_ARGS);
        best = v < best ? v : best;
        ++evals;
    }
    for (int g = 0; g < reach; ++g) {
        const float p0 = phi[group_start[g]];
        if (p0 >= best) break;
        if (p0 + gap[g] >= best) continue;
        best = scan_group(g, gap[g], best, &evals, me, me_pre, me_vis, mq_p, mq_v, slack, backward,
                          row_p, row_v, row_vis, row_pre, rows, phi, group_start, PAIR_ARGS);
    }
    out[c] = as_uint(best);
    out[n_cols + c] = (uint)evals;
}

// The device layout of a boundary state: (n, 3M) interleaved x, y, z per marker ->
// (n, 3, MQ * 8) coordinate planes, zero-padded (facesynth.domain.search.pairs.DeviceLayout).
__kernel void to_planes(__global const float *src, const int n, const int m, __global float *dst)
{
    const int node = get_global_id(0);
    if (node >= n) return;
    __global const float *s = src + (size_t)node * 3 * m;
    __global float *d = dst + (size_t)node * 3 * MQ * 8;
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k < MQ * 8; ++k)
            d[c * MQ * 8 + k] = k < m ? s[3 * k + c] : 0.0f;
}
