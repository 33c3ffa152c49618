/* The voxels' light where a ray met the scene, read from the bricks: what
 * the voxels' bounces gather (inject_bounce.cl) and what a camera's gather
 * ray shows where the voxels are all there is to read (a mirror it meets:
 * render/diffuse_rays.h). */
#ifndef VCT_CONE_HIT_H
#define VCT_CONE_HIT_H

#include "conetrace/cone_trace.h"

/* Below this a sample's colour over its opacity is half-float noise. */
#define CONE_HIT_MIN_OPACITY 1e-3f

/* The voxels' light where a ray from `from` along unit d met the scene at
 * distance t: the sample there at `footprint` times the diameter a cone of
 * aperture tan_half has at that distance (1: the level cone_trace would
 * read), seen from `seen_from` (the side of its plane that point lies on,
 * voxel_side.h), un-premultiplied where the half floats still hold it (0
 * elsewhere).
 * A coarse sample takes in surfaces far from the hit: in a closed room,
 * walls on both sides of its cell, whose one-sided planes then disagree, so
 * that it cannot tell the side the ray comes from and shows the brighter
 * one, the outside's (1.8 % of the sky light outside came in, README). So
 * the sample is read one whole level finer until its planes agree
 * (side_coherence 1) or the finest level, as cone_trace's march cannot
 * (it has no hit to look at). */
inline float3 cone_hit_light(CONE_POOLS, __global const uint *child, const vct_cone_desc *c,
                             float3 from, float3 d, float t, float tan_half, float footprint,
                             float3 seen_from) {
    const uint levels = c->res.y;
    const float voxel = c->volume.w / (float)c->res.x, min_diameter = 2.0f * voxel;
    const float level = cone_level(
        (float)(levels - 1u), fmax(footprint * 2.0f * t * tan_half, min_diameter), min_diameter);
    const float3 at = clamp((from + t * d - c->volume.xyz) * c->ambient.w, 0.0f, 0.99999f);
    /* a surface the ray met: no lift, none of it the cone's own */
    const float4 o = (float4)((seen_from - c->volume.xyz) * c->ambient.w - 0.5f, -1.0f);
    cone_path path = cone_path_root();
    float coherence = 1.0f;
    float4 s =
        cone_sample(CONE_POOLS_PASS, c->res.zw, child, levels, at, level, d, o, &path, &coherence);
    for (float finer = floor(level) + 1.0f; coherence < 1.0f && finer <= (float)(levels - 1u);
         finer += 1.0f) {
        coherence = 1.0f;
        s = cone_sample(CONE_POOLS_PASS, c->res.zw, child, levels, at, finer, d, o, &path,
                        &coherence);
    }
    return s.w > CONE_HIT_MIN_OPACITY ? s.xyz / s.w : (float3)(0.0f);
}

#endif
