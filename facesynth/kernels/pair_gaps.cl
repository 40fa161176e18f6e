// PGap and VGap of paper Eq. 8-9 for a block of predecessor rows i and all successors j:
//   pgap[i, j] = sum_k || FP_k(o_j) - LP_k(o_i) ||,  vgap[i, j] = sum_k || FV_k(o_j) - LV_k(o_i) ||
// last_pos/last_vel: (n_rows, 3M) row-major for the block's rows i.
// first_pos_t/first_vel_t: (3M, n) transposed, so neighbouring work-items (j) read neighbouring floats.
__kernel void pair_gaps(__global const float *last_pos, __global const float *last_vel,
                        __global const float *first_pos_t, __global const float *first_vel_t,
                        const int n, const int n_rows, const int m3,
                        __global float *pgap, __global float *vgap)
{
    const int j = get_global_id(0);
    const int i = get_global_id(1);
    if (j >= n || i >= n_rows) return;
    float p = 0.0f, v = 0.0f;
    for (int k = 0; k < m3; k += 3) {
        const float px = first_pos_t[k * n + j] - last_pos[i * m3 + k];
        const float py = first_pos_t[(k + 1) * n + j] - last_pos[i * m3 + k + 1];
        const float pz = first_pos_t[(k + 2) * n + j] - last_pos[i * m3 + k + 2];
        p += sqrt(px * px + py * py + pz * pz);
        const float vx = first_vel_t[k * n + j] - last_vel[i * m3 + k];
        const float vy = first_vel_t[(k + 1) * n + j] - last_vel[i * m3 + k + 1];
        const float vz = first_vel_t[(k + 2) * n + j] - last_vel[i * m3 + k + 2];
        v += sqrt(vx * vx + vy * vy + vz * vz);
    }
    pgap[(size_t)i * n + j] = p;
    vgap[(size_t)i * n + j] = v;
}
