/* One more diffuse bounce into the voxels: cones from each voxel gather the
 * filtered radiance of the bounces so far, and the voxel's radiance becomes
 * its direct radiance plus albedo times that (Lambert: albedo / pi times the
 * irradiance, pi times the cosine-weighted mean radiance). Starting again
 * from the direct part each time counts every path once: k calls give the
 * light of paths up to k + 1 bounces. The same cones, weights and march as
 * the renderer's indirect diffuse light.
 *
 * Surfaces are two-sided and a voxel's normal is an axis (either sign), so
 * the cones gather on both sides of it, and the voxel sends out what the
 * brighter side receives: the side a wall faces into its room, whichever
 * way it is wound (behind a closed room's wall is dark). A voxel whose
 * fragments face every way (no mean normal) gathers about z. */
#include "scene/bsdf.h"
#include "voxel/cone_trace.h"
#include "voxel/octree.h"
#include "vct_types.h"

/* The cosine-weighted radiance arriving at `centre` from the side n faces. */
inline float3 gather_side(CONE_POOLS, __global const uint *child, const vct_cone_desc *cd,
                          __global const vct_cone_dir *cones, uint cone_count, float3 centre,
                          float3 n) {
    float3 t, b;
    basis_of(n, &t, &b);
    const float3 origin = cone_origin(cd, centre, n);
    float3 gathered = (float3)(0.0f);
    for (uint i = 0; i < cone_count; ++i) {
        const vct_cone_dir c = cones[i];
        const float3 d = normalize(c.dir.x * t + c.dir.y * b + c.dir.z * n);
        gathered +=
            c.dir.w *
            cone_trace(CONE_POOLS_PASS, child, cd, origin, d, c.aperture.x, INFINITY).radiance;
    }
    return gathered;
}

__kernel void inject_bounce(CONE_POOLS, __global const uint *child, vct_cone_desc cd,
                            __global const vct_cone_dir *cones, uint cone_count,
                            __global const uint *keys, uint voxels, __global const float4 *albedo,
                            __global const float4 *normal, __global const float4 *direct,
                            __global float4 *voxel_radiance) {
    const uint v = get_global_id(0);
    if (v >= voxels)
        return;
    const float voxel = cd.volume.w / (float)cd.res.x;
    const float3 centre = cd.volume.xyz + (convert_float3(morton_decode(keys[v])) + 0.5f) * voxel;
    const float3 mean = normal[v].xyz;
    const float len = length(mean);
    const float3 n = len > 1e-3f ? mean / len : (float3)(0.0f, 0.0f, 1.0f);
    const float3 front = gather_side(CONE_POOLS_PASS, child, &cd, cones, cone_count, centre, n);
    const float3 back = gather_side(CONE_POOLS_PASS, child, &cd, cones, cone_count, centre, -n);
    const float3 gathered = front.x + front.y + front.z >= back.x + back.y + back.z ? front : back;
    float4 out = direct[v];
    out.xyz += albedo[v].xyz * gathered;
    voxel_radiance[v] = out;
}
