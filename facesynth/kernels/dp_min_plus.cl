// One step of paper Algorithm 1 (lines 5-7) as a min-plus product:
//   phi_next[j] = min_i (phi_prev[i] + TC[i, j]) + obs[j]
// TC is stored panel-major: panel p holds columns [PANEL*p, PANEL*(p+1)) for every row i,
// each row's PANEL values contiguous, so one work-item streams one panel front to back.
// Only the minimum is kept; the argmin is recomputed along the optimal path afterwards
// (same float32 additions, so the same values; the lowest index wins ties).
// Plain operators only: this PoCL build does not inline fmin/select/vload.

#ifndef PANEL
#error "build with -DPANEL=<columns per panel> (facesynth.domain.search.dp.PANEL)"
#endif
#define NVEC (PANEL / 8)

__kernel void min_plus_panels(__global const float *tc,       // (n_panels_here, n, PANEL)
                              __global const float *phi_prev, // (n,)
                              __global const float *obs,      // (n_cols_padded,) for this step
                              __global float *phi_next,       // (n_cols_padded,)
                              const int n, const int first_panel, const int n_panels_here)
{
    const int p = get_global_id(0);
    if (p >= n_panels_here) return;
    __global const float8 *row = (__global const float8 *)(tc + (size_t)p * (size_t)n * PANEL);
    float8 acc[NVEC];
    for (int v = 0; v < NVEC; ++v) acc[v] = (float8)(INFINITY);
    for (int i = 0; i < n; ++i) {
        const float8 f = (float8)(phi_prev[i]);
        for (int v = 0; v < NVEC; ++v) {
            const float8 x = f + row[v];
            acc[v] = x < acc[v] ? x : acc[v];
        }
        row += NVEC;
    }
    const int base = (first_panel + p) * PANEL;
    for (int v = 0; v < NVEC; ++v) {
        const float8 o = acc[v] + (float8)(obs[base + 8 * v + 0], obs[base + 8 * v + 1], obs[base + 8 * v + 2],
                                           obs[base + 8 * v + 3], obs[base + 8 * v + 4], obs[base + 8 * v + 5],
                                           obs[base + 8 * v + 6], obs[base + 8 * v + 7]);
        phi_next[base + 8 * v + 0] = o.s0; phi_next[base + 8 * v + 1] = o.s1;
        phi_next[base + 8 * v + 2] = o.s2; phi_next[base + 8 * v + 3] = o.s3;
        phi_next[base + 8 * v + 4] = o.s4; phi_next[base + 8 * v + 5] = o.s5;
        phi_next[base + 8 * v + 6] = o.s6; phi_next[base + 8 * v + 7] = o.s7;
    }
}
