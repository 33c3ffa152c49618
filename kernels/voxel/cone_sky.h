/* What a cone leaves open. A cone that leaves the volume takes the ambient
 * light for what it still sees there, but wide cones at coarse levels step
 * over one-voxel walls: inside a closed room they found the sky through its
 * walls. So a ray along the cone's axis, through the acceleration
 * structure, decides: where it meets geometry, the sky is closed that way.
 *
 * Isotropic bricks (no VCT_ANISOTROPIC) average a wall with the empty space
 * beside it, so at every coarse level a cone passes walls in part and lost
 * what it left open: a closed box of albedo 0.5 kept 0.22 of each bounce's
 * light. There the open rest takes the light where the ray meets the scene,
 * at the cone's footprint there, seen from the cone's side (the box keeps
 * 0.504). Directional bricks keep a wall's opacity along its normal; with
 * the same rest that box gained light (0.543), so they keep the sky check
 * alone. */
#ifndef VCT_CONE_SKY_H
#define VCT_CONE_SKY_H

#include "accel/accel.h"
#include "voxel/cone_trace.h"

/* r's radiance, its ambient share dropped where the ray from origin along d
 * meets geometry, and with isotropic bricks that share's light taken where
 * it meets it; tan_half: the cone's aperture. */
inline float3 cone_open_checked(const accel_view *g, CONE_POOLS, __global const uint *child,
                                const vct_cone_desc *c, float3 origin, float3 d, float tan_half,
                                cone_result r) {
#ifdef VCT_ANISOTROPIC
    if (!r.left || all(c->ambient.xyz == 0.0f) || r.alpha >= 1.0f)
        return r.radiance;
    hit_record h;
    if (accel_trace(g, origin, d, 0.0f, INFINITY, 1, &h))
        return r.radiance - (1.0f - r.alpha) * c->ambient.xyz;
    return r.radiance;
#else
    if (!r.left || r.alpha >= 1.0f)
        return r.radiance;
    hit_record h;
    if (!accel_trace(g, origin, d, 0.0f, INFINITY, 0, &h))
        return r.radiance;
    const float open = 1.0f - r.alpha;
    float3 seen = r.radiance - open * c->ambient.xyz;
    /* the level of the cone's diameter at the hit, as cone_trace picks it */
    const uint levels = c->res.y;
    const float voxel = c->volume.w / (float)c->res.x, min_diameter = 2.0f * voxel;
    const float finest = (float)(levels - 1u);
    const float diameter = fmax(2.0f * h.t * tan_half, min_diameter);
    const float level = clamp(finest - native_log2(diameter / min_diameter), 0.0f, finest);
    const float3 at = clamp((origin + h.t * d - c->volume.xyz) * c->ambient.w, 0.0f, 0.99999f);
    const float3 o = (origin - c->volume.xyz) * c->ambient.w - 0.5f;
    cone_path path = cone_path_root();
    const float4 s = cone_sample(CONE_POOLS_PASS, c->res.zw, child, levels, at, level, d, o, &path);
    if (s.w > 0.0f)
        seen += open * s.xyz / s.w;
    return seen;
#endif
}

#endif
