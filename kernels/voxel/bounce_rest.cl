/* The rest of the bounces, after the last one the voxels gathered.
 *
 * Each bounce adds to a voxel what the bounce before it added, carried one
 * surface further (inject_bounce.cl): in a room whose bounces shrink by a
 * steady ratio r, the bounces still to come add the last one's light times
 * r + r^2 + ... = r / (1 - r). r is the scene's own, per colour channel:
 * the ratio of the last bounce's light, summed over every voxel's two sides,
 * to the one before it (bounce_energy, per work-group, summed by the host
 * in a fixed order), and each voxel adds its own last bounce times
 * r / (1 - r) (bounce_rest): the same extrapolation as the ambient term of
 * progressive radiosity (Cohen et al. 1988), made per voxel. Per channel,
 * because a coloured surface keeps its own colour's light longest: in a
 * room of pale walls over a red carpet, one ratio by luminance left the red
 * light's later bounces 3 % short and gave the blue 1.4 % too much.
 *
 * A voxel's sides are read in the frame of its direct light's plane, which
 * every bounce keeps: `toward` the side that plane's normal points to. */
#include "voxel/voxel_side.h"
#include "vct_types.h"

#define BOUNCE_GROUP 64

/* Voxel v's light on the side plane normal n points to (*toward) and on
 * the other (*away), from its stored brighter side, difference and plane;
 * a voxel without a normal sends its brighter side both ways. */
inline void voxel_side_load(__global const float4 *radiance, __global const float4 *side, uint v,
                            float3 n, float3 *toward, float3 *away) {
    const float3 bright = radiance[v].xyz;
    __global const float4 *s = side + VCT_VOXEL_SIDE_FLOAT4S * v;
    const float3 dark = bright - s[0].xyz;
    const int flipped = dot(s[1].xyz, n) < 0.0f;
    *toward = flipped ? dark : bright;
    *away = flipped ? bright : dark;
}

/* What the last bounce added to voxel v's two sides (never less than 0). */
inline void bounce_added(__global const float4 *radiance, __global const float4 *side,
                         __global const float4 *before, __global const float4 *before_side,
                         __global const float4 *direct_side, uint v, float3 *toward, float3 *away) {
    const float3 n = direct_side[VCT_VOXEL_SIDE_FLOAT4S * v + 1u].xyz;
    float3 t, a, t0, a0;
    voxel_side_load(radiance, side, v, n, &t, &a);
    voxel_side_load(before, before_side, v, n, &t0, &a0);
    *toward = fmax(t - t0, 0.0f);
    *away = fmax(a - a0, 0.0f);
}

/* Per work-group of BOUNCE_GROUP voxels: the light the last bounce added
 * over both sides of its voxels, per colour channel (w 0), summed in a
 * fixed order. */
__kernel __attribute__((reqd_work_group_size(BOUNCE_GROUP, 1, 1))) void
bounce_energy(__global const float4 *radiance, __global const float4 *side,
              __global const float4 *before, __global const float4 *before_side,
              __global const float4 *direct_side, uint voxels, __global float4 *group_sums) {
    __local float4 sums[BOUNCE_GROUP];
    const uint v = get_global_id(0), l = get_local_id(0);
    float4 e = (float4)(0.0f);
    if (v < voxels) {
        float3 toward, away;
        bounce_added(radiance, side, before, before_side, direct_side, v, &toward, &away);
        e.xyz = toward + away;
    }
    sums[l] = e;
    barrier(CLK_LOCAL_MEM_FENCE);
    for (uint width = BOUNCE_GROUP / 2; width > 0u; width /= 2u) {
        if (l < width)
            sums[l] += sums[l + width];
        barrier(CLK_LOCAL_MEM_FENCE);
    }
    if (l == 0u)
        group_sums[get_group_id(0)] = sums[0];
}

/* Each voxel's light plus its last bounce's times `rest` (r / (1 - r) per
 * colour channel; w unused). */
__kernel void bounce_rest(__global float4 *radiance, __global float4 *side,
                          __global const float4 *before, __global const float4 *before_side,
                          __global const float4 *direct_side, uint voxels, float4 rest) {
    const uint v = get_global_id(0);
    if (v >= voxels)
        return;
    __global const float4 *plane = direct_side + VCT_VOXEL_SIDE_FLOAT4S * v + 1u;
    const float3 n = plane->xyz;
    float3 toward, away, added_toward, added_away;
    voxel_side_load(radiance, side, v, n, &toward, &away);
    bounce_added(radiance, side, before, before_side, direct_side, v, &added_toward, &added_away);
    voxel_side_store(toward + rest.xyz * added_toward, away + rest.xyz * added_away, n, plane->w * n,
                     radiance[v].w, radiance, side, v);
}
