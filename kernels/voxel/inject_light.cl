/* Direct light injected into the leaf voxels: the radiance each voxel sends
 * out, Lambert (albedo / pi times irradiance from every punctual light, with
 * hard shadows from any-hit rays through the triangle grid) plus emission.
 * The same conventions as the ray caster and the path tracer.
 *
 * A voxel is lit at its centre, with its mean normal; a voxel whose
 * fragments face every way (zero mean normal) takes light from all sides.
 * The centre can lie up to half a voxel diagonal behind the voxel's own
 * surface, so shadow rays start that far along the mean normal, in front of
 * it (along the light direction for a voxel without one). Shadow edges move
 * by less than a voxel; no voxel shadows itself at grazing light. The rays
 * of hard point and spot lights test the light's own triangle bins
 * (light_bins.h) when it has them, the grid otherwise, with the same answer;
 * they end two lifts short of the light. A light
 * with a radius is seen through INJECT_EXTENT_SAMPLES fixed points of its
 * extent (a spiral), so that its penumbrae reach the voxels too. */
#include "light/direct_light.h"
#include "light/light_bins.h"
#include "voxel/octree.h"
#include "vct_types.h"

#define INJECT_EXTENT_SAMPLES 8u

/* The fraction of light i that p sees, lifted by `lift` along `up`. */
inline float inject_visibility(const grid_view *g, const light_bins_view *bins,
                               __global const vct_light_desc *lights, uint i, float3 p, float3 up,
                               float lift, float3 wi, float dist) {
    if (!light_is_soft(lights, i)) {
        if (isinf(dist)) /* directional */
            return (float)light_visible(g, p, up, lift, wi, dist);
        const float3 o = p + up * lift;
        return (float)(bins->desc[i].info.w
                           ? light_segment_visible_bins(bins, g, i, o, 2.0f * lift)
                           : light_segment_visible_grid(g, o, lights[i].position.xyz, 2.0f * lift));
    }
    uint seen = 0;
    for (uint s = 0; s < INJECT_EXTENT_SAMPLES; ++s) {
        float reach;
        const float u1 = ((float)s + 0.5f) / (float)INJECT_EXTENT_SAMPLES;
        const float u2 = (float)s * 0.618034f;
        const float3 to = light_extent_sample(lights, i, wi, dist, u1, u2 - floor(u2), &reach);
        seen += (uint)light_visible(g, p, up, lift, to, reach);
    }
    return (float)seen / (float)INJECT_EXTENT_SAMPLES;
}

__kernel void inject_direct(GRID_ARGS, LIGHT_BINS_ARGS, vct_volume_desc vol,
                            __global const uint *keys, uint voxels, __global const float4 *albedo,
                            __global const float4 *normal, __global const float4 *emission,
                            __global const vct_light_desc *lights, uint light_count,
                            __global float4 *radiance) {
    const uint v = get_global_id(0);
    if (v >= voxels)
        return;
    const grid_view g = GRID_VIEW();
    const light_bins_view bins = LIGHT_BINS_VIEW();
    const float size = vol.origin.w / (float)vol.res.x;
    const float3 p = vol.origin.xyz + (convert_float3(morton_decode(keys[v])) + 0.5f) * size;
    const float3 n = normal[v].xyz;
    const int oriented = any(n != 0.0f);
    const float lift = 0.8660254f * size + surface_epsilon(&g, p);
    float3 irradiance = (float3)(0.0f);
    for (uint i = 0; i < light_count; ++i) {
        float3 wi, radiant;
        float dist;
        if (!light_incident(lights, i, p, &wi, &dist, &radiant))
            continue;
        const float cos_theta = oriented ? dot(n, wi) : 1.0f;
        if (!(cos_theta > 0.0f) || all(radiant == 0.0f))
            continue;
        irradiance += radiant * cos_theta *
                      inject_visibility(&g, &bins, lights, i, p, oriented ? n : wi, lift, wi, dist);
    }
    /* w: the opacity, so that re-filtering reads one array */
    const float4 a = albedo[v];
    radiance[v] = (float4)(a.xyz * VCT_INV_PI * irradiance + emission[v].xyz, a.w);
}
