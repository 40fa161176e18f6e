// Z-buffer rasterization of a triangle mesh at S x S samples per pixel, then shading and a box
// filter down to pixels. Deterministic by construction: the nearest triangle of a sample wins,
// the lowest triangle id on equal depth, whatever order the work-items run in.
//   raster_keys  (devices with 64-bit atomics): one pass, each triangle atom_min's the key
//                (depth bits << 32 | id) of every sample it covers; depths are positive, so
//                the integer order of their bits is their order;
//   raster_depth + raster_ids (other devices): the same in two 32-bit passes;
//   resolve_keys / resolve_ids: per pixel, shade once if all its S x S samples show one
//                triangle, else shade every sample and average them.
// screen: per vertex (x, y, depth, 0) in sample units; normals: per vertex, camera frame;
// albedo: per vertex linear (r, g, b, specular); eye: per vertex cosine to the cornea's axis
// (< -1.5 off the eyeballs); params: the lights and eye colours (facesynth/domain/rendering/raster.py).
#pragma OPENCL FP_CONTRACT OFF

#ifndef SAMPLES
#define SAMPLES 2
#endif

inline float edge_fn(const float2 a, const float2 b, const float2 p)
{
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// Whether the point (px, py) (sample x, y at x + 0.5, y + 0.5) lies in triangle f (edges inclusive, either winding); its barycentric
// weights, depth and signed area (negative: the triangle faces the camera).
inline int cover(__global const float4 *screen, __global const int *faces, const int f,
                 const float px, const float py, float *w0, float *w1, float *w2, float *z, float *area)
{
    const float4 a = screen[faces[3 * f]], b = screen[faces[3 * f + 1]], c = screen[faces[3 * f + 2]];
    *area = edge_fn(a.xy, b.xy, c.xy);
    if (*area == 0.0f) return 0;
    const float2 p = (float2)(px, py);
    const float e0 = edge_fn(b.xy, c.xy, p), e1 = edge_fn(c.xy, a.xy, p), e2 = edge_fn(a.xy, b.xy, p);
    if (*area > 0.0f) {
        if (e0 < 0.0f || e1 < 0.0f || e2 < 0.0f) return 0;
    } else {
        if (e0 > 0.0f || e1 > 0.0f || e2 > 0.0f) return 0;
    }
    *w0 = e0 / *area;
    *w1 = e1 / *area;
    *w2 = e2 / *area;
    *z = *w0 * a.z + *w1 * b.z + *w2 * c.z;
    return *z > 0.0f;
}

inline int4 bbox(__global const float4 *screen, __global const int *faces, const int f, const int width, const int height)
{
    const float4 a = screen[faces[3 * f]], b = screen[faces[3 * f + 1]], c = screen[faces[3 * f + 2]];
    const float lo_x = a.x < b.x ? (a.x < c.x ? a.x : c.x) : (b.x < c.x ? b.x : c.x);
    const float hi_x = a.x > b.x ? (a.x > c.x ? a.x : c.x) : (b.x > c.x ? b.x : c.x);
    const float lo_y = a.y < b.y ? (a.y < c.y ? a.y : c.y) : (b.y < c.y ? b.y : c.y);
    const float hi_y = a.y > b.y ? (a.y > c.y ? a.y : c.y) : (b.y > c.y ? b.y : c.y);
    // Triangles off the image, behind the camera or not finite cover nothing.
    if (!(lo_x < (float)width && hi_x >= 0.0f && lo_y < (float)height && hi_y >= 0.0f))
        return (int4)(1, 1, 0, 0);
    if (!(a.z > 0.0f && b.z > 0.0f && c.z > 0.0f)) return (int4)(1, 1, 0, 0);
    int x0 = (int)floor(lo_x), x1 = (int)ceil(hi_x), y0 = (int)floor(lo_y), y1 = (int)ceil(hi_y);
    x0 = x0 < 0 ? 0 : x0; y0 = y0 < 0 ? 0 : y0;
    x1 = x1 > width - 1 ? width - 1 : x1; y1 = y1 > height - 1 ? height - 1 : y1;
    return (int4)(x0, y0, x1, y1);
}

#ifdef cl_khr_int64_extended_atomics
#pragma OPENCL EXTENSION cl_khr_int64_extended_atomics : enable

// Narrow [lo, hi] (sample indices) to where edge a->b can pass its test on the row at py:
// edge_fn(a, b, p) * sg >= 0 is linear in p.x, so it holds on one side of a crossing point.
inline void span(const float2 a, const float2 b, const float py, const float sg, float *lo, float *hi)
{
    const float dy = b.y - a.y;
    if (dy == 0.0f) return;                          // the test does not depend on x: keep the row
    const float cross = a.x + (b.x - a.x) * (py - a.y) / dy;   // edge_fn = 0 at p.x = cross
    const float sample = cross - 0.5f;                         // as a sample index
    if (dy * sg > 0.0f) { if (sample + 1.0f < *hi) *hi = sample + 1.0f; }   // passes for p.x <= cross
    else                { if (sample - 1.0f > *lo) *lo = sample - 1.0f; }   // passes for p.x >= cross
}

// cover() with the corners in registers (the atomics would otherwise make the compiler reload
// them for every sample): the same operations in the same order, so the same result.
__kernel void raster_keys(__global const float4 *screen, __global const int *faces, const int n_faces,
                          const int width, const int height, __global ulong *keys)
{
    const int f = get_global_id(0);
    if (f >= n_faces) return;
    const int4 box = bbox(screen, faces, f, width, height);
    const float4 a = screen[faces[3 * f]], b = screen[faces[3 * f + 1]], c = screen[faces[3 * f + 2]];
    const float area = edge_fn(a.xy, b.xy, c.xy);
    if (area == 0.0f) return;
    const float sg = area > 0.0f ? 1.0f : -1.0f;
    const ulong id = (ulong)(uint)f;
    for (int y = box.y; y <= box.w; ++y) {
        const float py = y + 0.5f;
        // The row's span where all three edge tests can pass, widened by a sample on each side
        // against rounding; the exact tests below decide, so the result is that of cover().
        float lo = (float)box.x, hi = (float)box.z;
        span(a.xy, b.xy, py, sg, &lo, &hi);
        span(b.xy, c.xy, py, sg, &lo, &hi);
        span(c.xy, a.xy, py, sg, &lo, &hi);
        const int xs = lo > (float)box.x ? (int)lo : box.x, xe = hi < (float)box.z ? (int)hi : box.z;
        for (int x = xs; x <= xe; ++x) {
            const float2 p = (float2)(x + 0.5f, py);
            const float e0 = edge_fn(b.xy, c.xy, p), e1 = edge_fn(c.xy, a.xy, p), e2 = edge_fn(a.xy, b.xy, p);
            // sign tests of cover(): e * sg >= 0 is e >= 0 for area > 0 and e <= 0 otherwise
            if (e0 * sg < 0.0f || e1 * sg < 0.0f || e2 * sg < 0.0f) continue;
            const float z = (e0 / area) * a.z + (e1 / area) * b.z + (e2 / area) * c.z;
            if (!(z > 0.0f)) continue;
            const ulong key = ((ulong)as_uint(z) << 32) | id;
            // keys only decrease, so a plain read that is already smaller saves the atomic
            if (key < keys[y * width + x]) atom_min(&keys[y * width + x], key);
        }
    }
}
#endif

__kernel void raster_depth(__global const float4 *screen, __global const int *faces, const int n_faces,
                           const int width, const int height, __global int *zbuf)
{
    const int f = get_global_id(0);
    if (f >= n_faces) return;
    const int4 box = bbox(screen, faces, f, width, height);
    float w0, w1, w2, z, area;
    for (int y = box.y; y <= box.w; ++y)
        for (int x = box.x; x <= box.z; ++x)
            if (cover(screen, faces, f, x + 0.5f, y + 0.5f, &w0, &w1, &w2, &z, &area))
                atomic_min(&zbuf[y * width + x], as_int(z));
}

__kernel void raster_ids(__global const float4 *screen, __global const int *faces, const int n_faces,
                         const int width, const int height, __global const int *zbuf, __global int *ids)
{
    const int f = get_global_id(0);
    if (f >= n_faces) return;
    const int4 box = bbox(screen, faces, f, width, height);
    float w0, w1, w2, z, area;
    for (int y = box.y; y <= box.w; ++y)
        for (int x = box.x; x <= box.z; ++x)
            if (cover(screen, faces, f, x + 0.5f, y + 0.5f, &w0, &w1, &w2, &z, &area) && as_int(z) == zbuf[y * width + x])
                atomic_min(&ids[y * width + x], f);
}

// The lit colour (linear) of triangle f at the point (px, py) in sample units. Camera frame: the viewer looks along
// -z, so a normal toward the viewer has z > 0.
inline float3 shade_sample(__global const float4 *screen, __global const int *faces, __global const float4 *normals,
                           __global const float4 *albedo, __global const float *eye, __constant float *P,
                           const int f, const float px, const float py)
{
    float w0, w1, w2, z, area;
    cover(screen, faces, f, px, py, &w0, &w1, &w2, &z, &area);
    const int i0 = faces[3 * f], i1 = faces[3 * f + 1], i2 = faces[3 * f + 2];
    const float4 al = w0 * albedo[i0] + w1 * albedo[i1] + w2 * albedo[i2];
    float3 base = (float3)(al.x, al.y, al.z);
    if (area > 0.0f)                      // a back face, seen through an unfilled hole
        return base * P[15];
    const float4 nn = w0 * normals[i0] + w1 * normals[i1] + w2 * normals[i2];
    const float len = sqrt(nn.x * nn.x + nn.y * nn.y + nn.z * nn.z) + 1e-12f;
    const float nx = nn.x / len, ny = nn.y / len, nz = nn.z / len;
    const float e = w0 * eye[i0] + w1 * eye[i1] + w2 * eye[i2];
    if (e > -1.5f) {
        if (e > P[20]) {
            base = (float3)(P[27], P[28], P[29]);
        } else if (e > P[19]) {
            const float t = (e - P[19]) / (P[20] - P[19]);
            base = (float3)(P[21] + (P[24] - P[21]) * t, P[22] + (P[25] - P[22]) * t, P[23] + (P[26] - P[23]) * t);
        }
    }
    const float ambient = P[7] + P[8] * ny;
    float d1 = (nx * P[0] + ny * P[1] + nz * P[2] + P[3]) / (1.0f + P[3]);
    float d2 = nx * P[4] + ny * P[5] + nz * P[6];
    float s = nx * P[12] + ny * P[13] + nz * P[14];
    d1 = d1 < 0.0f ? 0.0f : d1;
    d2 = d2 < 0.0f ? 0.0f : d2;
    s = s < 0.0f ? 0.0f : s;
    s = s * s; s = s * s; s = s * s; s = s * s; s = s * s;   // ^32
    const float light = ambient + P[9] * d1 + P[10] * d2;
    const float shine = P[11] * al.w * s;
    return base * light + (float3)(shine, shine, shine);
}

inline void store(__global uchar *rgb, const int p, float3 acc)
{
    acc.x = acc.x < 0.0f ? 0.0f : (acc.x > 1.0f ? 1.0f : acc.x);
    acc.y = acc.y < 0.0f ? 0.0f : (acc.y > 1.0f ? 1.0f : acc.y);
    acc.z = acc.z < 0.0f ? 0.0f : (acc.z > 1.0f ? 1.0f : acc.z);
    // gamma 2 encoding
    rgb[3 * p + 0] = (uchar)(sqrt(acc.x) * 255.0f + 0.5f);
    rgb[3 * p + 1] = (uchar)(sqrt(acc.y) * 255.0f + 0.5f);
    rgb[3 * p + 2] = (uchar)(sqrt(acc.z) * 255.0f + 0.5f);
}

// Per pixel: the triangle of each of its S x S samples. A pixel whose samples all show one
// triangle is shaded once, at its centre (as multisampling does); a pixel on an edge is shaded
// per sample and averaged (supersampling), so edges are anti-aliased at S x S.
#define RESOLVE(ID_OF, NONE)                                                                          \
    const int x = get_global_id(0), y = get_global_id(1);                                           \
    if (x >= width || y >= height) return;                                                          \
    const int sw = width * SAMPLES;                                                                 \
    int f[SAMPLES * SAMPLES];                                                                       \
    int uniform = 1;                                                                                \
    for (int sy = 0; sy < SAMPLES; ++sy)                                                            \
        for (int sx = 0; sx < SAMPLES; ++sx) {                                                      \
            const int i = sy * SAMPLES + sx;                                                        \
            f[i] = ID_OF((y * SAMPLES + sy) * sw + x * SAMPLES + sx);                               \
            uniform = uniform && f[i] == f[0];                                                      \
        }                                                                                           \
    float3 acc;                                                                                     \
    if (uniform) {                                                                                  \
        acc = f[0] == NONE ? (float3)(P[16], P[17], P[18])                                          \
            : shade_sample(screen, faces, normals, albedo, eye, P, f[0],                            \
                           (float)(x * SAMPLES) + 0.5f * SAMPLES, (float)(y * SAMPLES) + 0.5f * SAMPLES); \
    } else {                                                                                        \
        acc = (float3)(0.0f, 0.0f, 0.0f);                                                           \
        for (int i = 0; i < SAMPLES * SAMPLES; ++i) {                                               \
            const int X = x * SAMPLES + i % SAMPLES, Y = y * SAMPLES + i / SAMPLES;                 \
            acc = acc + (f[i] == NONE ? (float3)(P[16], P[17], P[18])                               \
                         : shade_sample(screen, faces, normals, albedo, eye, P, f[i], X + 0.5f, Y + 0.5f)); \
        }                                                                                           \
        acc = acc / (float)(SAMPLES * SAMPLES);                                                     \
    }                                                                                               \
    store(rgb, y * width + x, acc);

#ifdef cl_khr_int64_extended_atomics
#define KEY_ID(p) (keys[p] == ULONG_MAX ? -1 : (int)(uint)(keys[p] & 0xffffffffUL))
__kernel void resolve_keys(__global const float4 *screen, __global const int *faces, __global const float4 *normals,
                           __global const float4 *albedo, __global const float *eye, __constant float *P,
                           __global const ulong *keys, const int width, const int height, __global uchar *rgb)
{
    RESOLVE(KEY_ID, -1)
}
#endif

#define ID_ID(p) ids[p]
__kernel void resolve_ids(__global const float4 *screen, __global const int *faces, __global const float4 *normals,
                          __global const float4 *albedo, __global const float *eye, __constant float *P,
                          __global const int *ids, const int width, const int height, __global uchar *rgb)
{
    RESOLVE(ID_ID, INT_MAX)
}
