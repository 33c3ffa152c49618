/* Stochastic progressive photon mapping (Hachisuka and Jensen 2009) on the
 * photon grid. Each pass: sppm_visible follows every pixel's camera ray
 * through mirrors and glass to its first diffuse or glossy hit (the visible
 * point), adding the emission it meets and, at the visible point, direct
 * light by shadow rays; photons are traced and gridded; sppm_gather adds
 * each map's photons within the pixel's radius to its statistics (N, tau,
 * r) and shrinks the radius by alpha; sppm_final_gather optionally reads
 * the global map at the hits of a few rays from the visible point instead.
 * sppm_resolve makes the frame.
 *
 * Light paths are split without overlap: light -> visible point by shadow
 * rays (or by the direct photons, in the seed's mode); with a specular bounce
 * since the last diffuse one by the caustic map; the rest by the global map
 * (or by final gathering). */
#include "accel/accel.h"
#include "light/nee.h"
#include "photon/photon.h"
#include "scene/bsdf.h"
#include "scene/camera.h"
#include "scene/rng.h"
#include "scene/texture.h"
#include "vct_types.h"

#define SPPM_PI 3.14159265f

/* A visible point: pos (xyz, w 1 where there is one), normal n facing the
 * viewer, wo, the camera path's throughput beta and the material (albedo
 * textured, w its index). */
typedef struct visible_point {
    float3 p, n, wo, beta;
    vct_material_desc m;
} visible_point;

inline int visible_point_get(__global const float4 *vp, uint pixel,
                             __global const vct_material_desc *materials, visible_point *v) {
    const float4 pos = vp[5u * pixel];
    if (!(pos.w > 0.0f))
        return 0;
    const float4 mat = vp[5u * pixel + 4u];
    v->p = pos.xyz;
    v->n = vp[5u * pixel + 1u].xyz;
    v->wo = vp[5u * pixel + 2u].xyz;
    v->beta = vp[5u * pixel + 3u].xyz;
    v->m = materials[as_uint(mat.w)];
    v->m.albedo.xyz = mat.xyz;
    return 1;
}

/* One BSDF-sampled ray: the emitter it reaches, weighted against the emitter
 * sample by the power heuristic as in the path tracer (the two together keep
 * the variance low near a large emitter, where the BSDF finds it, and far
 * from a small one, where the emitter sample does), or the environment
 * where it escapes, which only this ray finds. */
inline float3 direct_by_bsdf(const accel_view *g, const emitters *e,
                             __global const vct_material_desc *materials,
                             __global const uint *tri_material, const vct_material_desc *m,
                             float3 p, float3 n, float3 wo, int front, float3 ambient, uint *rng) {
    if (e->view.count == 0 && all(ambient == 0.0f))
        return (float3)(0.0f);
    bsdf_sample bs;
    const float u0 = rng_next(rng), u1 = rng_next(rng), u2 = rng_next(rng);
    if (!bsdf_sample_dir(m, n, wo, front, u0, u1, u2, &bs) || bs.delta)
        return (float3)(0.0f);
    hit_record h;
    const float3 o = p + (dot(bs.wi, n) > 0.0f ? n : -n) * surface_epsilon(g, p);
    if (!accel_trace(g, o, bs.wi, 0.0f, INFINITY, 0, &h))
        return bs.weight * ambient;
    const float3 Le = materials[tri_material[h.tri]].emission.xyz;
    float3 q, ng, nq;
    int fr;
    if (e->view.count == 0 || all(Le == 0.0f) || !surface_hit(g, &h, bs.wi, &q, &ng, &nq, &fr))
        return (float3)(0.0f);
    const float3 d = q - p;
    const float pdf_light = e->inv_area * dot(d, d) / fabs(dot(ng, bs.wi));
    return bs.weight * Le * power_heuristic(bs.pdf, pdf_light);
}

/* direct_mode 1: direct light by shadow rays; 0: left to the photons.
 * vp: 5 float4 per pixel. radius_max: per map, the largest radius of a
 * pixel that has found photons (float bits), for the grids' cells. */
__kernel void
sppm_visible(ACCEL_ARGS, vct_camera_desc cam, __global const vct_material_desc *materials,
             __global const uint *tri_material, TEXTURE_ARGS, __global const vct_light_desc *lights,
             uint light_count, __global const uint *emitter_tris, __global const float *emitter_cdf,
             uint emitter_count, float emitter_inv_area, uint seed, uint pass, uint max_depth,
             float4 ambient, uint direct_mode, __global float4 *vp, __global float4 *direct_sum,
             __global const float4 *stats_global, __global const float *radius_global,
             __global const float4 *stats_caustic, __global const float *radius_caustic,
             __global uint *radius_max) {
    const uint x = get_global_id(0), y = get_global_id(1);
    if (x >= cam.size.x || y >= cam.size.y)
        return;
    const accel_view g = ACCEL_VIEW();
    const texture_view tv = TEXTURE_VIEW();
    const emitters em = {{emitter_tris, emitter_cdf, 0, emitter_count, 1u}, emitter_inv_area};
    const uint pixel = y * cam.size.x + x;
    uint rng = rng_start(seed, camera_pixel_id(&cam, x, y), pass);
    const float jx = rng_next(&rng), jy = rng_next(&rng);
    float3 org = cam.position.xyz,
           dir = camera_ray_dir(&cam, (float)x + jx, (float)camera_row(&cam, y) + jy);
    float3 beta = (float3)(1.0f), radiance = (float3)(0.0f);
    float4 vp_pos = (float4)(0.0f), vp_n = vp_pos, vp_wo = vp_pos, vp_beta = vp_pos,
           vp_mat = vp_pos;
    for (uint depth = 0; depth < max_depth; ++depth) {
        hit_record h;
        if (!accel_trace(&g, org, dir, 0.0f, INFINITY, 0, &h)) {
            radiance += beta * ambient.xyz;
            break;
        }
        float3 p, ng, n;
        int front;
        if (!surface_hit(&g, &h, dir, &p, &ng, &n, &front))
            break;
        const uint mi = tri_material[h.tri];
        vct_material_desc m = materials[mi];
        m.albedo.xyz = texture_albedo(&tv, &m, h.tri, h.u, h.v);
        radiance += beta * m.emission.xyz;
        const float3 wo = -dir;
        if (!bsdf_delta_only(&m)) {
            if (direct_mode) {
                radiance += beta * nee_punctual(&g, lights, light_count, &m, p, n, wo, &rng);
                radiance +=
                    beta * nee_emitters(&g, &em, materials, tri_material, &m, p, n, wo, 1, &rng);
                radiance += beta * direct_by_bsdf(&g, &em, materials, tri_material, &m, p, n, wo,
                                                  front, ambient.xyz, &rng);
            }
            vp_pos = (float4)(p, 1.0f);
            vp_n = (float4)(n, 0.0f);
            vp_wo = (float4)(wo, 0.0f);
            vp_beta = (float4)(beta, 0.0f);
            vp_mat = (float4)(m.albedo.xyz, as_float(mi));
            break;
        }
        bsdf_sample bs;
        const float u0 = rng_next(&rng), u1 = rng_next(&rng), u2 = rng_next(&rng);
        if (!bsdf_sample_dir(&m, n, wo, front, u0, u1, u2, &bs))
            break;
        beta *= bs.weight;
        org = p + (dot(bs.wi, n) > 0.0f ? n : -n) * surface_epsilon(&g, p);
        dir = bs.wi;
    }
    vp[5u * pixel] = vp_pos;
    vp[5u * pixel + 1u] = vp_n;
    vp[5u * pixel + 2u] = vp_wo;
    vp[5u * pixel + 3u] = vp_beta;
    vp[5u * pixel + 4u] = vp_mat;
    if (all(isfinite(radiance)))
        direct_sum[pixel] += (float4)(radiance, 0.0f);
    if (vp_pos.w > 0.0f) {
        /* Radii are positive: their float bits order as the floats do. */
        if (stats_global[pixel].w > 0.0f)
            atomic_max(&radius_max[0], as_uint(radius_global[pixel]));
        if (stats_caustic[pixel].w > 0.0f)
            atomic_max(&radius_max[1], as_uint(radius_caustic[pixel]));
    }
}

/* One map's photons at every visible point: the progressive update
 * N' = N + alpha M, r' = r sqrt(N' / (N + M)), tau' = (tau + beta Phi) r'^2 / r^2
 * (alpha 1: a fixed radius, the sums simply accumulate). */
__kernel void sppm_gather(__global const float4 *vp, uint pixels,
                          __global const vct_material_desc *materials, PHOTON_GRID_ARGS(map),
                          float alpha, uint flags, float normal_cos, __global float4 *stats,
                          __global float *radius) {
    const uint i = get_global_id(0);
    if (i >= pixels)
        return;
    visible_point v;
    if (!visible_point_get(vp, i, materials, &v))
        return;
    const photon_grid g = PHOTON_GRID_VIEW(map);
    const float4 s = stats[i];
    float r = radius[i];
    /* A pixel that has found no photon yet has nothing to keep consistent
     * with its radius: it follows the grid down to two cells, so that its
     * search never spans many more cells than the others'. */
    if (s.w == 0.0f && r > 2.0f * g.origin.w) {
        r = 2.0f * g.origin.w;
        radius[i] = r;
    }
    uint found;
    const float3 phi = photon_estimate(&g, v.p, v.n, v.wo, r, &v.m, flags, normal_cos, &found);
    if (found == 0u)
        return;
    const float n_new = s.w + alpha * (float)found;
    const float r_new = r * sqrt(n_new / (s.w + (float)found));
    const float shrink = (r_new * r_new) / (r * r);
    stats[i] = (float4)((s.xyz + v.beta * phi) * shrink, n_new);
    radius[i] = r_new;
}

/* Final gathering: `rays` BSDF-sampled rays from each visible point; where
 * one meets a diffuse or glossy surface, the light it reflects there is read
 * from this pass's photons (global and, if any, caustic) within `radius`.
 * Rays that reach an emitter or a mirror add nothing: that light is the
 * shadow rays' and the caustic map's. fg_sum gains the pass's estimate. */
__kernel void sppm_final_gather(ACCEL_ARGS, __global const vct_material_desc *materials,
                                __global const uint *tri_material, TEXTURE_ARGS,
                                __global const float4 *vp, uint pixels, uint first_pixel,
                                PHOTON_GRID_ARGS(glob), PHOTON_GRID_ARGS(caus), uint caustics,
                                float radius, float inv_emitted, uint rays, uint seed, uint pass,
                                uint flags, float normal_cos, __global float4 *fg_sum) {
    const uint i = get_global_id(0);
    if (i >= pixels)
        return;
    visible_point v;
    if (!visible_point_get(vp, i, materials, &v))
        return;
    const accel_view g = ACCEL_VIEW();
    const texture_view tv = TEXTURE_VIEW();
    const photon_grid gg = PHOTON_GRID_VIEW(glob), gc = PHOTON_GRID_VIEW(caus);
    const float norm = inv_emitted / (SPPM_PI * radius * radius);
    uint rng = rng_start(seed ^ 0x6667u, first_pixel + i, pass); /* the whole image's pixel */
    float3 sum = (float3)(0.0f);
    for (uint k = 0; k < rays; ++k) {
        bsdf_sample bs;
        const float u0 = rng_next(&rng), u1 = rng_next(&rng), u2 = rng_next(&rng);
        if (!bsdf_sample_dir(&v.m, v.n, v.wo, 1, u0, u1, u2, &bs) || bs.delta)
            continue;
        hit_record h;
        const float3 o = v.p + v.n * surface_epsilon(&g, v.p);
        if (!accel_trace(&g, o, bs.wi, 0.0f, INFINITY, 0, &h))
            continue;
        float3 p, ng, n;
        int front;
        if (!surface_hit(&g, &h, bs.wi, &p, &ng, &n, &front))
            continue;
        vct_material_desc m = materials[tri_material[h.tri]];
        m.albedo.xyz = texture_albedo(&tv, &m, h.tri, h.u, h.v);
        if (bsdf_delta_only(&m))
            continue;
        uint found;
        float3 l = photon_estimate(&gg, p, n, -bs.wi, radius, &m, flags, normal_cos, &found);
        if (caustics)
            l += photon_estimate(&gc, p, n, -bs.wi, radius, &m, flags, normal_cos, &found);
        sum += bs.weight * l * norm;
    }
    if (all(isfinite(sum)))
        fg_sum[i] += (float4)(v.beta * sum / (float)rays, 0.0f);
}

/* components: 1 emission and direct light, 2 the global map (or final
 * gathering), 4 the caustic map. inv_emitted: 1 / photons emitted in all. */
__kernel void sppm_resolve(__global const float4 *direct_sum, __global const float4 *fg_sum,
                           __global const float4 *stats_global, __global const float *radius_global,
                           __global const float4 *stats_caustic,
                           __global const float *radius_caustic, float inv_passes,
                           float inv_emitted, uint components, uint pixels,
                           __global float4 *frame) {
    const uint i = get_global_id(0);
    if (i >= pixels)
        return;
    float3 c = (float3)(0.0f);
    if (components & 1u)
        c += direct_sum[i].xyz * inv_passes;
    if (components & 2u) {
        const float r = radius_global[i];
        c += fg_sum[i].xyz * inv_passes + stats_global[i].xyz * (inv_emitted / (SPPM_PI * r * r));
    }
    if (components & 4u) {
        const float r = radius_caustic[i];
        c += stats_caustic[i].xyz * (inv_emitted / (SPPM_PI * r * r));
    }
    frame[i] = (float4)(c, 1.0f);
}
