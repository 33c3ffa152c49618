/* A look at the voxels: primary rays marched through the octree, skipping
 * each empty node's whole cell. At the leaf level (show_level = levels) a
 * voxel shows its injected radiance when `radiance` holds it (has_radiance),
 * the side facing the camera (voxel_side.h),
 * else its albedo under a headlight on the averaged normal, plus emission.
 * At a coarser level every node with geometry below it is a grey cube lit
 * by a headlight on the face the ray enters. */
#include "scene/camera.h"
#include "voxel/octree.h"
#include "vct_types.h"

__kernel void voxel_render(vct_camera_desc cam, vct_volume_desc vol, __global const uint *child,
                           __global const float4 *voxel_albedo, __global const float4 *voxel_normal,
                           __global const float4 *voxel_emission,
                           __global const float4 *voxel_radiance, __global const float4 *voxel_side,
                           uint has_radiance, uint show_level, __global float4 *image) {
    const uint x = get_global_id(0), y = get_global_id(1);
    if (x >= cam.size.x || y >= cam.size.y)
        return;
    const float3 dir = camera_ray_dir(&cam, (float)x + 0.5f, (float)camera_row(&cam, y) + 0.5f);
    const float res = (float)vol.res.x;
    const uint levels = vol.res.y;
    /* Voxel space: the cube is [0, res]^3 and t is measured in voxels. */
    const float3 origin = (cam.position.xyz - vol.origin.xyz) * (res / vol.origin.w);
    const float3 inv = 1.0f / dir; /* +-inf on axis-parallel rays is handled by fmin/fmax */
    const float3 t_a = (0.0f - origin) * inv, t_b = (res - origin) * inv;
    const float3 t_near = fmin(t_a, t_b), t_far = fmax(t_a, t_b);
    float t = fmax(0.0f, fmax(t_near.x, fmax(t_near.y, t_near.z)));
    /* The axis of the face the ray last entered a cell through. */
    uint axis =
        t_near.x >= t_near.y && t_near.x >= t_near.z ? 0u : (t_near.y >= t_near.z ? 1u : 2u);
    const float t_exit = fmin(t_far.x, fmin(t_far.y, t_far.z));
    float4 colour = (float4)(0.0f, 0.0f, 0.0f, 1.0f);
    const float nudge = 1e-3f;
    for (uint step = 0; step < 16u * vol.res.x && t < t_exit; ++step) {
        const float3 p = origin + (t + nudge) * dir;
        const uint3 cell = convert_uint3(clamp(floor(p), 0.0f, res - 1.0f));
        uint level;
        const uint node = octree_descend_to(child, cell, levels, show_level, &level);
        if (level == show_level && level < levels && child[node] != OCT_NULL) {
            const float facing = fabs(axis == 0u ? dir.x : (axis == 1u ? dir.y : dir.z));
            colour.xyz = (float3)(0.75f * (0.25f + 0.75f * facing));
            break;
        }
        if (level == levels && child[node] != OCT_NULL) {
            const uint v = child[node];
            const float facing = fabs(dot(voxel_normal[v].xyz, dir));
            const float shade = voxel_normal[v].w > 0.0f ? 0.2f + 0.8f * facing : 0.6f;
            if (has_radiance) {
                /* a ray travelling along the brighter side's normal sees the darker side */
                __global const float4 *sides = voxel_side + VCT_VOXEL_SIDE_FLOAT4S * v;
                const int behind = dot(sides[1].xyz, dir) > 0.0f;
                colour.xyz = voxel_radiance[v].xyz - (behind ? sides[0].xyz : (float3)(0.0f));
            } else {
                colour.xyz = voxel_albedo[v].xyz * shade + voxel_emission[v].xyz;
            }
            break;
        }
        /* Empty at `level` (or an empty leaf): leave that node's cell. */
        const uint shift = levels - level;
        const float size = (float)(1u << shift);
        const float3 base = convert_float3((cell >> shift) << shift);
        const float3 bound = base + select((float3)(0.0f), (float3)(size), dir > 0.0f);
        const float3 t_cell = (bound - origin) * inv;
        const float3 t_valid = select(t_cell, (float3)(INFINITY), dir == 0.0f);
        axis = t_valid.x <= t_valid.y && t_valid.x <= t_valid.z
                   ? 0u
                   : (t_valid.y <= t_valid.z ? 1u : 2u);
        t = fmax(t + nudge, fmin(t_valid.x, fmin(t_valid.y, t_valid.z)));
    }
    image[y * cam.size.x + x] = colour;
}
