/* Unbiased path tracing on the shared acceleration structure: next-event estimation to every
 * punctual light and to emissive triangles (chosen by area, combined with BSDF
 * sampling by the power heuristic), Russian roulette after RR_DEPTH bounces.
 * Each launch adds `samples` samples per pixel to `accum`: per pixel
 * PT_SUMS exact sums (render/exact_sum.h): red, green and blue, the count of
 * samples kept (x), the squares of the samples' luminance (for the variance
 * the denoiser weighs by), then the same for the sample's direct part (red,
 * green, blue, squared luminance) and the squared luminance of the rest,
 * the indirect part. The direct part is what the first surface emits or
 * receives from the lights and emitters (next-event estimation, and the
 * emitter its BSDF sample meets, by its multiple-importance weight), or the
 * background a camera ray meets. Direct light is sharp and, from small
 * lights, nearly noiseless; indirect light is smooth and noisy: the
 * denoiser filters each with its own variance. A sample that is not finite
 * is dropped and counted. The sums are exact, so the image does not depend
 * on how samples were split into launches, calls or devices. Compiled
 * with VCT_PT_COLOUR_ONLY, it adds the colour and the count alone: the
 * moments cost about a twentieth of the time on PoCL, and a render that no
 * denoiser reads needs none of them.
 *
 * A pixel's samples are taken ACCEL_GROUP at a time. On CPU devices
 * (VCT_PACKETS) they go through their vertices together in vector lanes
 * (render/pt_lanes.h); elsewhere (pt_group) their camera rays and the rays
 * their first surfaces send on are traced together, then each path goes
 * on by itself (render/pt_path.h). Both give the same image bit for bit.
 *
 * max_depth: surface interactions per path (1 = direct light only). */
/* bsdf.h first: accel/ray_tri.h turns FP_CONTRACT off for all that follows
 * it, and the materials' arithmetic is fused where written so. */
#include "scene/bsdf.h"
#include "scene/camera.h"
#include "light/nee.h"
#include "scene/texture.h"
#include "accel/accel.h"
#include "scene/rng.h"
#include "render/exact_sum.h"
#include "render/pt_path.h"
#include "render/pt_lanes.h"
#include "vct_types.h"

#define PT_SUMS 10u

inline float pt_luminance(float3 c) {
    return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

#ifndef VCT_PACKETS
/* Samples first .. first + n - 1 (n <= ACCEL_GROUP) of pixel (x, y), each
 * path by itself after its first bounce: each one's radiance and its direct
 * part. */
inline void pt_group(const pt_scene *sc, const vct_camera_desc *cam, uint x, uint y, uint seed,
                     uint first, uint n, float3 *radiance, float3 *direct) {
    uint rngs[ACCEL_GROUP];
    float3 dirs[ACCEL_GROUP];
    hit_record firsts[ACCEL_GROUP];
    int found[ACCEL_GROUP];
    pt_camera_rays(&sc->g, cam, x, y, seed, first, n, rngs, dirs, firsts, found);
    pt_path paths[ACCEL_GROUP];
    ray_packet bounce;
    bounce.count = 0u;
    uint lane_of[ACCEL_GROUP];
    for (uint s = 0; s < n; ++s) {
        pt_path *q = &paths[s];
        q->throughput = (float3)(1.0f);
        q->radiance = q->direct = (float3)(0.0f);
        q->org = q->prev_p = cam->position.xyz;
        q->dir = dirs[s];
        q->prev_pdf = 0.0f; /* 0: camera ray or delta bounce, emission counts fully */
        q->rng = rngs[s];
        if (pt_walk(sc, q, 0u, 0u, firsts[s], found[s])) {
            lane_of[bounce.count] = s;
            packet_set(&bounce, bounce.count++, q->org, q->dir, 0.0f, INFINITY);
        }
    }
    hit_record seconds[ACCEL_GROUP];
    int met[ACCEL_GROUP];
    accel_trace_packet(&sc->g, &bounce, 0, seconds, met);
    for (uint k = 0; k < bounce.count; ++k)
        pt_walk(sc, &paths[lane_of[k]], 1u, sc->max_depth, seconds[k], met[k]);
    for (uint s = 0; s < n; ++s) {
        radiance[s] = paths[s].radiance;
        direct[s] = paths[s].direct;
    }
}
#endif

__kernel void pathtrace(ACCEL_ARGS, vct_camera_desc cam,
                        __global const vct_material_desc *materials,
                        __global const uint *tri_material, TEXTURE_ARGS,
                        __global const vct_light_desc *lights, uint light_count,
                        __global const uint *emitter_tris, __global const float *emitter_cdf,
                        uint emitter_count, float emitter_inv_area, uint sample_begin, uint samples,
                        uint max_depth, uint seed, __global exact_sum *accum,
                        __global uint *discarded, float4 ambient) {
    const uint x = get_global_id(0), y = get_global_id(1);
    if (x >= cam.size.x || y >= cam.size.y)
        return;
    const pt_scene sc = {ACCEL_VIEW(),
                         TEXTURE_VIEW(),
                         {{emitter_tris, emitter_cdf, 0, emitter_count, 1u}, emitter_inv_area},
                         materials,
                         tri_material,
                         lights,
                         light_count,
                         max_depth,
                         ambient.xyz,
                         emitter_count > 0 || any(ambient.xyz != 0.0f)};
    const uint pixel = y * cam.size.x + x;
    __global exact_sum *sums = accum + PT_SUMS * pixel;
    exact_sum sum_r = sums[0], sum_g = sums[1], sum_b = sums[2], sum_l2 = sums[4];
    exact_sum direct_r = sums[5], direct_g = sums[6], direct_b = sums[7], direct_l2 = sums[8],
              indirect_l2 = sums[9];
    uint dropped = 0;
    for (uint s0 = 0; s0 < samples; s0 += ACCEL_GROUP) {
        const uint group = min(samples - s0, ACCEL_GROUP);
        float3 radiances[ACCEL_GROUP], directs[ACCEL_GROUP];
#ifdef VCT_PACKETS
        pt_group_lanes(&sc, &cam, x, y, seed, sample_begin + s0, group, radiances, directs);
#else
        pt_group(&sc, &cam, x, y, seed, sample_begin + s0, group, radiances, directs);
#endif
        for (uint s = 0; s < group; ++s) {
            const float3 radiance = radiances[s], direct = directs[s];
            if (all(isfinite(radiance))) {
                sum_r = exact_add(sum_r, exact_from_float(radiance.x));
                sum_g = exact_add(sum_g, exact_from_float(radiance.y));
                sum_b = exact_add(sum_b, exact_from_float(radiance.z));
#ifndef VCT_PT_COLOUR_ONLY
                const float l = pt_luminance(radiance), ld = pt_luminance(direct),
                            li = pt_luminance(radiance - direct);
                sum_l2 = exact_add(sum_l2, exact_from_float(l * l));
                direct_r = exact_add(direct_r, exact_from_float(direct.x));
                direct_g = exact_add(direct_g, exact_from_float(direct.y));
                direct_b = exact_add(direct_b, exact_from_float(direct.z));
                direct_l2 = exact_add(direct_l2, exact_from_float(ld * ld));
                indirect_l2 = exact_add(indirect_l2, exact_from_float(li * li));
#endif
            } else {
                ++dropped;
            }
        }
    }
    sums[0] = sum_r;
    sums[1] = sum_g;
    sums[2] = sum_b;
    sums[3].x += (ulong)(samples - dropped);
    sums[4] = sum_l2;
    sums[5] = direct_r;
    sums[6] = direct_g;
    sums[7] = direct_b;
    sums[8] = direct_l2;
    sums[9] = indirect_l2;
    if (dropped)
        atomic_add(discarded, dropped);
}

/* A pixel's summed red, green and blue. */
inline float3 pt_sum_rgb(__global const exact_sum *sums) {
    return (float3)(exact_to_float(sums[0]), exact_to_float(sums[1]), exact_to_float(sums[2]));
}

/* Pixel i's sums, and in *n the count of its samples kept. */
inline __global const exact_sum *pt_pixel_sums(__global const exact_sum *accum, uint i, float *n) {
    __global const exact_sum *sums = accum + PT_SUMS * i;
    *n = (float)sums[3].x;
    return sums;
}

/* The frame: each pixel's mean sample (black where every sample was dropped). */
__kernel void pathtrace_resolve(__global const exact_sum *accum, uint pixels,
                                __global float4 *frame) {
    const uint i = get_global_id(0);
    if (i >= pixels)
        return;
    float n;
    __global const exact_sum *sums = pt_pixel_sums(accum, i, &n);
    frame[i] = n > 0.0f ? (float4)(pt_sum_rgb(sums) / n, 1.0f) : (float4)(0.0f, 0.0f, 0.0f, 1.0f);
}

/* The variance of a mean of n samples from the sums of their luminance
 * (mean) and of its squares; -1 below two samples, where it is unknown (0
 * would say the pixel is exact). */
inline float pt_mean_variance(float n, float mean, exact_sum squares) {
    return n > 1.0f ? fmax(exact_to_float(squares) / n - mean * mean, 0.0f) / n : -1.0f;
}

/* Each pixel's indirect light: the mean of the samples less their direct
 * parts, from the exact difference of the sums. */
__kernel void pathtrace_resolve_indirect(__global const exact_sum *accum, uint pixels,
                                         __global float4 *indirect) {
    const uint i = get_global_id(0);
    if (i >= pixels)
        return;
    float n;
    __global const exact_sum *sums = pt_pixel_sums(accum, i, &n);
    float3 rest = (float3)(0.0f);
    if (n > 0.0f)
        rest = (float3)(exact_to_float(exact_add(sums[0], exact_negate(sums[5]))),
                        exact_to_float(exact_add(sums[1], exact_negate(sums[6]))),
                        exact_to_float(exact_add(sums[2], exact_negate(sums[7])))) /
               n;
    indirect[i] = (float4)(rest, 1.0f);
}

/* The variance of each pixel's mean luminance, (E[l^2] - E[l]^2) / n: of
 * the whole sample in x, of its direct part in y, of its indirect part in
 * z (each -1 below two samples). */
__kernel void pathtrace_variance(__global const exact_sum *accum, uint pixels,
                                 __global float4 *variance) {
    const uint i = get_global_id(0);
    if (i >= pixels)
        return;
    float n;
    __global const exact_sum *sums = pt_pixel_sums(accum, i, &n);
    const float mean = pt_luminance(pt_sum_rgb(sums)) / n,
                mean_direct = pt_luminance(pt_sum_rgb(sums + 5)) / n;
    variance[i] =
        (float4)(pt_mean_variance(n, mean, sums[4]), pt_mean_variance(n, mean_direct, sums[8]),
                 pt_mean_variance(n, mean - mean_direct, sums[9]), 1.0f);
}
