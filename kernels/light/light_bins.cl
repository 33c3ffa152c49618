/* Light-space triangle bins (see light_bins.h): count -> scan -> write ->
 * sort -> ranges, like the triangle grid, over the cube-map cells of every
 * light that has bins.
 *
 * A triangle goes into the cells of the bounding box, in face coordinates,
 * of its part inside each face's pyramid. The pyramid is widened by
 * LIGHT_BINS_PAD, so a direction on a face's edge finds the triangle in
 * either face, and the box by LIGHT_BINS_PAD plus the rounding of the
 * projection, which grows as a point nears the light: a triangle that
 * passes that close covers the whole face. Its sort key is the cell above
 * the distance from the light to its bounding box, shortened by 1e-4 of it
 * and rounded down to a quantum, so that it never exceeds the distance to
 * any of its points. */
#include "light/light_bins.h"

#define CLIP_VERTICES 8 /* a triangle clipped by 4 planes has at most 7 */

/* A point relative to the light in face f's frame: (m, u, v) as in
 * light_bins_face, m along the face's axis. */
inline float3 light_bins_local(float3 x, uint face) {
    const float s = (face & 1u) ? -1.0f : 1.0f;
    const uint axis = face >> 1;
    if (axis == 0u)
        return (float3)(s * x.x, x.y, x.z);
    if (axis == 1u)
        return (float3)(s * x.y, x.z, x.x);
    return (float3)(s * x.z, x.x, x.y);
}

/* Keeps the part of polygon `in` (n vertices) where dot(plane, p) >= 0. */
inline uint clip_polygon(const float3 *in, uint n, float3 *out, float3 plane) {
    uint k = 0;
    for (uint i = 0; i < n; ++i) {
        const float3 a = in[i], b = in[i + 1u == n ? 0u : i + 1u];
        const float da = dot(plane, a), db = dot(plane, b);
        if (da >= 0.0f)
            out[k++] = a;
        if ((da >= 0.0f) != (db >= 0.0f))
            out[k++] = a + (b - a) * (da / (da - db));
    }
    return k;
}

/* The cells [lo, hi] (u in x, v in y) of face f that triangle (a, b, c),
 * relative to the light, may cover; 0 if none. */
inline int light_bins_face_box(float3 a, float3 b, float3 c, uint face, uint face_res, int2 *lo,
                               int2 *hi) {
    float3 p[CLIP_VERTICES], q[CLIP_VERTICES];
    p[0] = light_bins_local(a, face);
    p[1] = light_bins_local(b, face);
    p[2] = light_bins_local(c, face);
    const float w = 1.0f + LIGHT_BINS_PAD;
    const float3 planes[4] = {(float3)(w, 1.0f, 0.0f), (float3)(w, -1.0f, 0.0f),
                              (float3)(w, 0.0f, 1.0f), (float3)(w, 0.0f, -1.0f)};
    /* Most triangles lie wholly outside one plane or inside all four. */
    int inside = 1;
    for (uint k = 0; k < 4u; ++k) {
        const float d0 = dot(planes[k], p[0]), d1 = dot(planes[k], p[1]), d2 = dot(planes[k], p[2]);
        if (d0 < 0.0f && d1 < 0.0f && d2 < 0.0f)
            return 0;
        inside &= d0 >= 0.0f && d1 >= 0.0f && d2 >= 0.0f;
    }
    uint n = 3u;
    if (!inside) {
        n = clip_polygon(p, n, q, planes[0]);
        n = clip_polygon(q, n, p, planes[1]);
        n = clip_polygon(p, n, q, planes[2]);
        n = clip_polygon(q, n, p, planes[3]);
    }
    if (n == 0u)
        return 0;
    const float size = fmax(length(a), fmax(length(b), length(c)));
    float2 mn = (float2)(INFINITY), mx = (float2)(-INFINITY);
    for (uint i = 0; i < n; ++i) {
        /* rounding of the clipped point, over its distance along the axis */
        const float pad = LIGHT_BINS_PAD + 1e-6f * size / p[i].x;
        if (!(p[i].x > 0.0f) || !(pad < 1.0f)) {
            mn = (float2)(-1.0f);
            mx = (float2)(1.0f);
            break;
        }
        const float2 uv = p[i].yz / p[i].x;
        mn = fmin(mn, uv - pad);
        mx = fmax(mx, uv + pad);
    }
    *lo = (int2)(light_bins_cell_1d(mn.x, face_res), light_bins_cell_1d(mn.y, face_res));
    *hi = (int2)(light_bins_cell_1d(mx.x, face_res), light_bins_cell_1d(mx.y, face_res));
    return 1;
}

/* Walks every (light, face, cell) triangle t may cover; with `write`
 * stores its keys and t from out. Returns the count, so that the counting
 * and writing passes cannot disagree. */
inline uint light_bins_visit(__global const float4 *tri_vertices, uint t,
                             __global const vct_light_bins_desc *desc, uint lights, int write,
                             __global uint *keys, __global uint *ids, uint out) {
    const float3 a = tri_vertices[3 * t].xyz, b = tri_vertices[3 * t + 1].xyz,
                 c = tri_vertices[3 * t + 2].xyz;
    const float3 box_lo = fmin(a, fmin(b, c)), box_hi = fmax(a, fmax(b, c));
    uint n = 0;
    for (uint i = 0; i < lights; ++i) {
        const vct_light_bins_desc d = desc[i];
        if (!d.info.w)
            continue;
        const float3 l = d.light.xyz;
        const uint bits = d.info.z, low = (1u << bits) - 1u, f = d.info.y;
        const float near = length(fmax(fmax(box_lo - l, l - box_hi), 0.0f)) * (1.0f - 1e-4f);
        const uint quantum = (uint)fmin(near * d.light.w, (float)low);
        for (uint face = 0; face < 6u; ++face) {
            int2 lo, hi;
            if (!light_bins_face_box(a - l, b - l, c - l, face, f, &lo, &hi))
                continue;
            if (write)
                for (int v = lo.y; v <= hi.y; ++v)
                    for (int u = lo.x; u <= hi.x; ++u) {
                        const uint cell = d.info.x + (face * f + (uint)v) * f + (uint)u;
                        keys[out + n] = cell << bits | quantum;
                        ids[out + n] = t;
                        ++n;
                    }
            else
                n += (uint)((hi.x - lo.x + 1) * (hi.y - lo.y + 1));
        }
    }
    return n;
}

__kernel void light_bins_count(__global const float4 *tri_vertices, uint triangles,
                               __global const vct_light_bins_desc *desc, uint lights,
                               __global uint *counts) {
    const uint t = get_global_id(0);
    if (t < triangles)
        counts[t] = light_bins_visit(tri_vertices, t, desc, lights, 0, counts, counts, 0);
}

__kernel void light_bins_write(__global const float4 *tri_vertices, uint triangles,
                               __global const vct_light_bins_desc *desc, uint lights,
                               __global const uint *offsets, __global uint *keys,
                               __global uint *ids) {
    const uint t = get_global_id(0);
    if (t < triangles)
        light_bins_visit(tri_vertices, t, desc, lights, 1, keys, ids, offsets[t]);
}

/* Each cell's [start, end) in the sorted keys; cells left out stay (0, 0). */
__kernel void light_bins_ranges(__global const uint *keys, uint n, uint bits,
                                __global uint *ranges) {
    const uint i = get_global_id(0);
    if (i >= n)
        return;
    const uint cell = keys[i] >> bits;
    if (i == 0 || keys[i - 1] >> bits != cell)
        ranges[2 * cell] = i;
    if (i == n - 1 || keys[i + 1] >> bits != cell)
        ranges[2 * cell + 1] = i + 1;
}
