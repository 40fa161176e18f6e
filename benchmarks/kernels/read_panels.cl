// The memory-bandwidth floor of one DP step: read every float of the panel-major cost
// matrix once, with the same access pattern as min_plus_panels, and keep a sum so the
// reads cannot be optimized away. Used by benchmarks/dp_table_v.py as the reference.
#ifndef PANEL
#error "build with -DPANEL=<columns per panel> (facesynth.domain.search.dp.PANEL)"
#endif
#define NVEC (PANEL / 8)

__kernel void read_panels(__global const float *tc, const int n, const int n_panels_here, __global float *out)
{
    const int p = get_global_id(0);
    if (p >= n_panels_here) return;
    __global const float8 *row = (__global const float8 *)(tc + (size_t)p * (size_t)n * PANEL);
    float8 acc[NVEC];
    for (int v = 0; v < NVEC; ++v) acc[v] = (float8)(0.0f);
    for (int i = 0; i < n; ++i) {
        for (int v = 0; v < NVEC; ++v) acc[v] += row[v];
        row += NVEC;
    }
    float8 total = (float8)(0.0f);
    for (int v = 0; v < NVEC; ++v) total += acc[v];
    out[p] = total.s0 + total.s1 + total.s2 + total.s3 + total.s4 + total.s5 + total.s6 + total.s7;
}
