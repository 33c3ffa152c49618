/* One more diffuse bounce into the voxels: cones from each voxel gather the
 * filtered radiance of the bounces so far, and the voxel's radiance becomes
 * its direct radiance plus albedo times that (Lambert: albedo / pi times the
 * irradiance, pi times the cosine-weighted mean radiance). Starting again
 * from the direct part each time counts every path once: k calls give the
 * light of paths up to k + 1 bounces. The same cones, weights and march as
 * the renderer's indirect diffuse light.
 *
 * Surfaces are two-sided and each side of a voxel keeps its own light
 * (voxel_side.h): the cones gather on both sides of its plane, each side adds
 * what it receives to its own direct light, and the brighter of the two
 * becomes the voxel's radiance. Behind a closed room's wall it stays dark,
 * whichever way the wall is wound. A voxel whose fragments face every way
 * (no normal) gathers on both sides of z and sends the brighter both ways. */
#include "scene/bsdf.h"
#include "conetrace/cone_trace.h"
#include "conetrace/cone_near.h"
#include "conetrace/cone_sky.h"
#include "voxel/octree.h"
#include "voxel/voxel_side.h"
#include "vct_types.h"

/* The cosine-weighted radiance arriving at `centre` from the side n faces. */
inline float3 gather_side(const accel_view *acc, CONE_POOLS, __global const uint *child,
                          const vct_cone_desc *cd, __global const vct_cone_dir *cones,
                          uint cone_count, float3 centre, float3 n, int near_rays, float3 surface) {
    float3 t, b;
    basis_of(n, &t, &b);
    const float3 origin = cone_origin(cd, centre, n);
    float3 gathered = (float3)(0.0f);
    for (uint i = 0; i < cone_count; ++i) {
        const vct_cone_dir c = cones[i];
        const float3 d = normalize(c.dir.x * t + c.dir.y * b + c.dir.z * n);
        float3 near;
        float near_t;
        if (near_rays && cone_near_light(acc, CONE_POOLS_PASS, child, cd, surface, n, d,
                                         c.aperture.x, 0, &near, &near_t)) {
            gathered += c.dir.w * near;
            continue;
        }
        const cone_result r =
            cone_trace(CONE_POOLS_PASS, child, cd, origin, d, c.aperture.x, INFINITY);
        gathered += c.dir.w * cone_open_checked(acc, CONE_POOLS_PASS, child, cd, origin, d,
                                                c.aperture.x, r, CONE_REST_RAYS_VOXELS);
    }
    return gathered;
}

__kernel void inject_bounce(ACCEL_ARGS, CONE_POOLS, __global const uint *child, vct_cone_desc cd,
                            __global const vct_cone_dir *cones, uint cone_count,
                            __global const uint *keys, uint voxels, __global const float4 *albedo,
                            __global const float4 *direct, __global const float4 *direct_side,
                            __global float4 *voxel_radiance, __global float4 *side,
                            __global const uint *carried_from,
                            __global const float4 *before_radiance,
                            __global const float4 *before_side, uint carry_every,
                            uint carry_phase) {
    const accel_view acc = ACCEL_VIEW();
    const uint v = get_global_id(0);
    if (v >= voxels)
        return;
    /* carried light gathered over carry_every renders: a voxel whose direct
     * light was carried and whose turn it is not keeps all its light before */
    if (carry_every > 0u && carried_from[v] != VCT_NO_VOXEL &&
        (keys[v] * 2654435761u) % carry_every != carry_phase) {
        const uint from = carried_from[v];
        voxel_radiance[v] = before_radiance[from];
        for (uint k = 0; k < VCT_VOXEL_SIDE_FLOAT4S; ++k)
            side[VCT_VOXEL_SIDE_FLOAT4S * v + k] = before_side[VCT_VOXEL_SIDE_FLOAT4S * from + k];
        return;
    }
    const float voxel = cd.volume.w / (float)cd.res.x;
    const float3 centre = cd.volume.xyz + (convert_float3(morton_decode(keys[v])) + 0.5f) * voxel;
    __global const float4 *sides = direct_side + VCT_VOXEL_SIDE_FLOAT4S * v;
    const float4 bright = direct[v], shade = sides[0], plane = sides[1];
    const int has_normal = any(plane.xyz != 0.0f);
    const float3 n = has_normal ? plane.xyz : (float3)(0.0f, 0.0f, 1.0f);
    /* the voxel's plane's point nearest its centre: where near rays start */
    const float3 c_unit = (centre - cd.volume.xyz) * cd.ambient.w - 0.5f;
    const float3 surface =
        cd.volume.xyz + (c_unit - (dot(n, c_unit) - plane.w) * n + 0.5f) * cd.volume.w;
    const float3 front = gather_side(&acc, CONE_POOLS_PASS, child, &cd, cones, cone_count, centre,
                                     n, has_normal, surface);
    const float3 back = gather_side(&acc, CONE_POOLS_PASS, child, &cd, cones, cone_count, centre,
                                    -n, has_normal, surface);
    const float3 rho = albedo[v].xyz;
    /* without a normal both sides send what the brighter side receives */
    const float3 more = side_luminance(front) >= side_luminance(back) ? front : back;
    const float3 toward = has_normal ? front : more, away = has_normal ? back : more;
    voxel_side_store(bright.xyz + rho * toward, bright.xyz - shade.xyz + rho * away, plane.xyz,
                     plane.w * plane.xyz, bright.w, voxel_radiance, side, v);
}
