/* The sky a cone sees. A cone that leaves the volume takes the ambient
 * light for what it still sees there, but wide cones at coarse levels step
 * over one-voxel walls: inside a closed room they found the sky through its
 * walls. So a ray along the cone's axis, through the acceleration
 * structure, decides: where it meets geometry, the sky is closed that way. */
#ifndef VCT_CONE_SKY_H
#define VCT_CONE_SKY_H

#include "accel/accel.h"
#include "voxel/cone_trace.h"

/* r's radiance, its ambient share dropped where the ray from origin along
 * d meets geometry. */
inline float3 cone_sky_checked(const accel_view *g, const vct_cone_desc *c, float3 origin, float3 d,
                               cone_result r) {
    if (!r.left || all(c->ambient.xyz == 0.0f) || r.alpha >= 1.0f)
        return r.radiance;
    hit_record h;
    if (accel_trace(g, origin, d, 0.0f, INFINITY, 1, &h))
        return r.radiance - (1.0f - r.alpha) * c->ambient.xyz;
    return r.radiance;
}

#endif
