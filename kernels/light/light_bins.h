/* Light-space triangle bins: exact hard shadows for point and spot lights.
 *
 * Around a light, a cube map of F x F direction cells per face lists, per
 * cell, every triangle whose projection from the light may cover it, sorted
 * by a lower bound of the triangle's distance from the light (quantized, in
 * the low bits of the sort key). A segment that ends at the light lies on one
 * direction from it, so every triangle that can block it sits in one cell,
 * and those that could lie before the segment's far end come first: the test
 * stops at the first farther one. The triangle test and the segment are those
 * of the plain shadow ray (light_segment_visible_accel), so both say the same.
 *
 * Face f = 2 * axis + (component < 0) of a direction w, with m = |w[axis]|,
 * u = w[axis + 1] / m and v = w[axis + 2] / m (axes mod 3) in [-1, 1]. */
#ifndef VCT_LIGHT_BINS_H
#define VCT_LIGHT_BINS_H

#include "accel/accel.h"
#include "vct_types.h"

/* How far short of the light a shadow segment ends, at least, relative to
 * its length plus the scene's extent: there, the rounding of the segment's
 * direction and of the triangle test turn what a hit sees of the light by
 * less than 1e-3 rad, which the bins' padding (LIGHT_BINS_PAD, in face
 * coordinates, which change at least as fast as the angle) covers. */
#define LIGHT_SEGMENT_END 1e-3f
#define LIGHT_BINS_PAD 2e-3f

typedef struct light_bins_view {
    __global const vct_light_bins_desc *desc; /* one per light */
    __global const uint *ranges;              /* (start, end) per cell */
    __global const uint *keys;                /* cell << bits | distance quantum */
    __global const uint *tris;
} light_bins_view;

#define LIGHT_BINS_ARGS                                                                            \
    __global const vct_light_bins_desc *bins_desc, __global const uint *bin_ranges,                \
        __global const uint *bin_keys, __global const uint *bin_tris
#define LIGHT_BINS_VIEW() ((light_bins_view){bins_desc, bin_ranges, bin_keys, bin_tris})

/* The face and (u, v) of direction w (nonzero). */
inline uint light_bins_face(float3 w, float2 *uv) {
    const float3 a = fabs(w);
    if (a.x >= a.y && a.x >= a.z) {
        *uv = (float2)(w.y, w.z) / a.x;
        return w.x < 0.0f ? 1u : 0u;
    }
    if (a.y >= a.z) {
        *uv = (float2)(w.z, w.x) / a.y;
        return w.y < 0.0f ? 3u : 2u;
    }
    *uv = (float2)(w.x, w.y) / a.z;
    return w.z < 0.0f ? 5u : 4u;
}

/* The cell (u or v) of a face coordinate in [-1, 1], clamped to [0, F). */
inline int light_bins_cell_1d(float u, uint face_res) {
    return clamp((int)floor((u + 1.0f) * 0.5f * (float)face_res), 0, (int)face_res - 1);
}

/* The cell, among all lights', of direction w from the light. */
inline uint light_bins_cell(vct_light_bins_desc d, float3 w) {
    float2 uv;
    const uint face = light_bins_face(w, &uv), f = d.info.y;
    return d.info.x + (face * f + (uint)light_bins_cell_1d(uv.y, f)) * f +
           (uint)light_bins_cell_1d(uv.x, f);
}

/* The shadow segment from o towards light position l in a scene of the
 * given extent: its unit direction, length and where it ends, `margin` (or
 * more, see LIGHT_SEGMENT_END) short of the light. Returns 0 when there is
 * nothing to test. */
inline int light_segment(float3 o, float3 l, float margin, float extent, float3 *dir, float *len,
                         float *end) {
    const float3 to = l - o;
    *len = length(to);
    if (!(*len > 0.0f))
        return 0;
    *dir = to / *len;
    *end = *len - fmax(margin, LIGHT_SEGMENT_END * (*len + extent));
    return *end > 0.0f;
}

/* 1 if no triangle blocks the segment from o to light position l (short of
 * it by margin), through the acceleration structure. */
inline int light_segment_visible_accel(const accel_view *g, float3 o, float3 l, float margin) {
    float3 dir;
    float len, end;
    hit_record h;
    return !light_segment(o, l, margin, g->desc.origin.w, &dir, &len, &end) ||
           !accel_trace(g, o, dir, 0.0f, end, 1, &h);
}

/* The same answer from light i's bins (which it must have). */
inline int light_segment_visible_bins(const light_bins_view *b, const accel_view *g, uint i,
                                      float3 o, float margin) {
    const vct_light_bins_desc d = b->desc[i];
    __global const float4 *tri_vertices = g->tri_vertices;
    float3 dir;
    float len, end;
    if (!light_segment(o, d.light.xyz, margin, g->desc.origin.w, &dir, &len, &end))
        return 1;
    const uint cell = light_bins_cell(d, -dir);
    const uint bits = d.info.z, low = (1u << bits) - 1u;
    const uint farthest = (uint)fmin(len * d.light.w, (float)low);
    const ray_shear shear = ray_shear_make(o, dir);
    const uint2 range = vload2(cell, b->ranges);
    for (uint k = range.x; k < range.y; ++k) {
        if ((b->keys[k] & low) > farthest)
            return 1; /* this triangle and all after it lie beyond o */
        const uint t = b->tris[k];
        float th, u, v;
        const float4 a = tri_vertices[3 * t]; /* w: the alpha-mask slot */
        if (ray_triangle(&shear, a.xyz, tri_vertices[3 * t + 1].xyz, tri_vertices[3 * t + 2].xyz,
                         0.0f, end, &th, &u, &v) &&
            !accel_masked(tri_vertices, as_uint(a.w), u, v))
            return 0;
    }
    return 1;
}

#endif
