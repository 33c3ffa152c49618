/* Light carried from the voxels of the frame before into new voxels after
 * some geometry moved (kernels/voxel/inject_light.cl, carry_direct). A
 * voxel keeps the direct light it had when it was there before and nothing
 * that moved can reach it: it is outside every moved box (the moved
 * geometry's bounds before and after, grown by a margin), and no shadow ray
 * it casts towards a light or an emitter crosses one. Tests are
 * conservative: a voxel called dirty is lit again, never the reverse. */
#ifndef VCT_VOXEL_CARRY_H
#define VCT_VOXEL_CARRY_H

#include "vct_types.h"

/* 1 if the segment from a to b meets the box [lo, hi] (slabs). */
inline int carry_segment_meets_box(float3 a, float3 b, float3 lo, float3 hi) {
    const float3 d = b - a;
    float t0 = 0.0f, t1 = 1.0f;
    for (int k = 0; k < 3; ++k) {
        const float ak = k == 0 ? a.x : k == 1 ? a.y : a.z;
        const float dk = k == 0 ? d.x : k == 1 ? d.y : d.z;
        const float lk = k == 0 ? lo.x : k == 1 ? lo.y : lo.z;
        const float hk = k == 0 ? hi.x : k == 1 ? hi.y : hi.z;
        if (fabs(dk) < 1e-30f) {
            if (ak < lk || ak > hk)
                return 0;
            continue;
        }
        float ta = (lk - ak) / dk, tb = (hk - ak) / dk;
        if (ta > tb) {
            const float t = ta;
            ta = tb;
            tb = t;
        }
        t0 = fmax(t0, ta);
        t1 = fmin(t1, tb);
        if (t0 > t1)
            return 0;
    }
    return 1;
}

inline int carry_boxes_overlap(float3 alo, float3 ahi, float3 blo, float3 bhi) {
    return all(alo <= bhi) && all(blo <= ahi);
}

/* 1 if what moved can change the direct light at p: p in a moved box, or a
 * shadow ray across one, towards a light (to its extent: the box grown by
 * its radius; a directional light's, as far as the box's far corner
 * reaches) or an emitter. For emitters two tests that each hold every ray
 * from p to them, both of which must pass: the box around p and the
 * emitters' box, and the box grown by the radius of the ball around the
 * emitters (rays from p to a ball of radius r stay within r of the ray to
 * its centre). emit_lo.w 0: no emitters; emit_hi.w: the ball's radius.
 * boxes: (lo, hi) pairs, grown by `margin` here. */
inline int carry_dirty(float3 p, float margin, __global const float4 *boxes, uint box_count,
                       __global const vct_light_desc *lights, uint light_count, float4 emit_lo,
                       float4 emit_hi) {
    const float3 emit_centre = 0.5f * (emit_lo.xyz + emit_hi.xyz);
    const float emit_radius = emit_hi.w;
    for (uint b = 0; b < box_count; ++b) {
        const float3 lo = boxes[2u * b].xyz - margin, hi = boxes[2u * b + 1u].xyz + margin;
        if (all(p >= lo) && all(p <= hi))
            return 1;
        for (uint i = 0; i < light_count; ++i) {
            const vct_light_desc l = lights[i];
            float3 to;
            float grow;
            if ((uint)l.position.w == VCT_LIGHT_KIND_DIRECTIONAL) {
                const float far = length(fmax(fabs(lo - p), fabs(hi - p)));
                to = p - l.direction.xyz * (2.0f * far);
                grow = l.shape.x * 2.0f * far;
            } else {
                to = l.position.xyz;
                grow = l.shape.x;
            }
            if (carry_segment_meets_box(p, to, lo - grow, hi + grow))
                return 1;
        }
        if (emit_lo.w > 0.0f &&
            carry_boxes_overlap(fmin(p, emit_lo.xyz), fmax(p, emit_hi.xyz), lo, hi) &&
            carry_segment_meets_box(p, emit_centre, lo - emit_radius, hi + emit_radius))
            return 1;
    }
    return 0;
}

/* The index of `key` among the n sorted keys, or VCT_NO_VOXEL. */
inline uint carry_find(__global const uint *keys, uint n, uint key) {
    uint lo = 0u, hi = n;
    while (lo < hi) {
        const uint mid = lo + (hi - lo) / 2u;
        if (keys[mid] < key)
            lo = mid + 1u;
        else
            hi = mid;
    }
    return lo < n && keys[lo] == key ? lo : VCT_NO_VOXEL;
}

#endif
