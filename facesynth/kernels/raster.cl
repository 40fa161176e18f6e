// Z-buffer rasterization of a triangle mesh in three passes, deterministic by construction:
//   raster_depth: each triangle writes min depth per covered pixel (atomic_min on the float's
//                 bits; depths are positive, so integer order is float order);
//   raster_ids:   each triangle whose depth equals the buffer's claims the pixel (lowest id wins);
//   shade:        each pixel interpolates its triangle's vertex normals and applies the lights.
// screen: per vertex (x_px, y_px, depth, 0); normals: per vertex, camera space.
#pragma OPENCL FP_CONTRACT OFF

inline float edge_fn(const float2 a, const float2 b, const float2 p)
{
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// Barycentric weights of pixel (x, y) in triangle f; returns 0 if outside.
inline int cover(__global const float4 *screen, __global const int *faces, const int f,
                 const int x, const int y, float *w0, float *w1, float *w2, float *z)
{
    const float4 a = screen[faces[3 * f]], b = screen[faces[3 * f + 1]], c = screen[faces[3 * f + 2]];
    const float area = edge_fn(a.xy, b.xy, c.xy);
    if (area == 0.0f) return 0;
    const float2 p = (float2)(x + 0.5f, y + 0.5f);
    *w0 = edge_fn(b.xy, c.xy, p) / area;
    *w1 = edge_fn(c.xy, a.xy, p) / area;
    *w2 = edge_fn(a.xy, b.xy, p) / area;
    if (*w0 < 0.0f || *w1 < 0.0f || *w2 < 0.0f) return 0;
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
    int x0 = (int)floor(lo_x), x1 = (int)ceil(hi_x), y0 = (int)floor(lo_y), y1 = (int)ceil(hi_y);
    x0 = x0 < 0 ? 0 : x0; y0 = y0 < 0 ? 0 : y0;
    x1 = x1 > width - 1 ? width - 1 : x1; y1 = y1 > height - 1 ? height - 1 : y1;
    return (int4)(x0, y0, x1, y1);
}

__kernel void raster_depth(__global const float4 *screen, __global const int *faces, const int n_faces,
                           const int width, const int height, __global int *zbuf)
{
    const int f = get_global_id(0);
    if (f >= n_faces) return;
    const int4 box = bbox(screen, faces, f, width, height);
    float w0, w1, w2, z;
    for (int y = box.y; y <= box.w; ++y)
        for (int x = box.x; x <= box.z; ++x)
            if (cover(screen, faces, f, x, y, &w0, &w1, &w2, &z))
                atomic_min(&zbuf[y * width + x], as_int(z));
}

__kernel void raster_ids(__global const float4 *screen, __global const int *faces, const int n_faces,
                         const int width, const int height, __global const int *zbuf, __global int *ids)
{
    const int f = get_global_id(0);
    if (f >= n_faces) return;
    const int4 box = bbox(screen, faces, f, width, height);
    float w0, w1, w2, z;
    for (int y = box.y; y <= box.w; ++y)
        for (int x = box.x; x <= box.z; ++x)
            if (cover(screen, faces, f, x, y, &w0, &w1, &w2, &z) && as_int(z) == zbuf[y * width + x])
                atomic_min(&ids[y * width + x], f);
}

__kernel void shade(__global const float4 *screen, __global const int *faces, __global const float4 *normals,
                    __global const int *ids, const int width, const int height,
                    const float4 base, const float4 background, __global uchar *rgb)
{
    const int x = get_global_id(0), y = get_global_id(1);
    if (x >= width || y >= height) return;
    const int p = y * width + x;
    const int f = ids[p];
    float4 colour = background;
    if (f != INT_MAX) {
        float w0, w1, w2, z;
        cover(screen, faces, f, x, y, &w0, &w1, &w2, &z);
        float4 n = w0 * normals[faces[3 * f]] + w1 * normals[faces[3 * f + 1]] + w2 * normals[faces[3 * f + 2]];
        const float len = sqrt(n.x * n.x + n.y * n.y + n.z * n.z) + 1e-12f;
        n = n / len;
        if (n.z < 0.0f) {          // a back face, seen through a hole: dark interior
            colour = base * 0.12f;
        } else {
            const float4 key = (float4)(-0.35f, 0.45f, 0.82f, 0.0f);   // normalized below
            const float4 fill = (float4)(0.6f, -0.1f, 0.79f, 0.0f);
            const float kl = sqrt(key.x * key.x + key.y * key.y + key.z * key.z);
            const float fl = sqrt(fill.x * fill.x + fill.y * fill.y + fill.z * fill.z);
            float d1 = (n.x * key.x + n.y * key.y + n.z * key.z) / kl;
            float d2 = (n.x * fill.x + n.y * fill.y + n.z * fill.z) / fl;
            d1 = d1 < 0.0f ? 0.0f : d1;
            d2 = d2 < 0.0f ? 0.0f : d2;
            // Blinn specular of the key light, view along +z.
            float4 h = (float4)(key.x / kl, key.y / kl, key.z / kl + 1.0f, 0.0f);
            const float hl = sqrt(h.x * h.x + h.y * h.y + h.z * h.z);
            float s = (n.x * h.x + n.y * h.y + n.z * h.z) / hl;
            s = s < 0.0f ? 0.0f : s;
            s = s * s; s = s * s; s = s * s; s = s * s; s = s * s;   // ^32
            colour = base * (0.18f + 0.72f * d1 + 0.25f * d2) + (float4)(0.25f * s);
        }
    }
    colour = colour < 0.0f ? 0.0f : colour;
    colour = colour > 1.0f ? 1.0f : colour;
    rgb[3 * p + 0] = (uchar)(colour.x * 255.0f + 0.5f);
    rgb[3 * p + 1] = (uchar)(colour.y * 255.0f + 0.5f);
    rgb[3 * p + 2] = (uchar)(colour.z * 255.0f + 0.5f);
}
