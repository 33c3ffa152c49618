/* One camera ray of cone tracing's primary pass: followed through
 * dielectrics (the transmitted ray exactly, total internal reflection where
 * there is none) and off perfect mirrors, then emission and direct light at
 * the first other surface, exactly as the ray caster computes them. What it
 * finds is what the G-buffer
 * keeps for the cone passes, and a key that tells surfaces apart: the
 * materials on the way and the lights the point sees. Neighbouring pixels
 * whose keys or surfaces differ hold an edge, and are supersampled
 * (vct_edge_flags, vct_primary_refine in render/vct_render.cl). */
#ifndef VCT_PRIMARY_SAMPLE_H
#define VCT_PRIMARY_SAMPLE_H

#include "accel/accel.h"
#include "light/direct_light.h"
#include "light/emitters.h"
#include "scene/bsdf.h"
#include "scene/camera.h"
#include "scene/rng.h"
#include "scene/texture.h"
#include "render/shading_scene.h"
#include "vct_types.h"

#define VCT_MAX_INTERFACES 8u

#ifdef VCT_SHADOWS
#define SHADOWS 1
#else
#define SHADOWS 0
#endif

/* Lights with a radius are shaded by vct_soft_shadows instead. */
#ifdef VCT_SOFT_SHADOWS
#define SOFT_SHADOWS 1
#else
#define SOFT_SHADOWS 0
#endif

/* What one camera ray found. */
typedef struct primary_sample {
    float3 radiance;        /* emission and direct light, through the throughput on the way */
    float3 sampled;         /* the part of it from emitter samples: noise, not detail */
    float sampled_variance; /* of that part's luminance, from the samples' spread */
    float3 throughput;      /* of the dielectrics and mirrors on the way to the surface */
    int found;              /* a surface other than a dielectric or mirror was reached */
    float4 gpos, gnormal, gview, galbedo; /* the G-buffer's slots 0, 1, 2 and 4 */
    /* The Fresnel reflection of the first dielectric entered: (point,
     * weight.x), (normal, weight.y), (mirror direction, weight.z). */
    float4 rpos, rnormal, rdir;
    uint key;
} primary_sample;

/* The Phong exponent of m's glossy lobe and its mirror direction *r, or -1
 * where direct light has no glossy term. */
inline float direct_lobe(const vct_material_desc *m, float3 wo, float3 n, float3 *r) {
    *r = (float3)(0.0f);
#ifdef VCT_SPECULAR
    if (glossy_probability(m) > 0.0f && !is_mirror(m) && !is_dielectric(m)) {
        *r = reflect_dir(wo, n);
        return phong_exponent(m->emission.w);
    }
#endif
    return -1.0f;
}

/* Radiance the direct terms reflect off m. */
inline float3 direct_shade(const vct_material_desc *m, direct_terms d, float e) {
    float3 out = diffuse_color(m) * VCT_INV_PI * d.irradiance;
    if (e >= 0.0f)
        out += glossy_color(m) * d.lobe;
    return out;
}

/* The camera ray along dir, which meets `first` (where first_found);
 * seed keys the pixel's emitter samples, of which the ray takes those from
 * `part` on, every `parts` (light/emitters.h). */
inline primary_sample primary_trace_hit(const shading_scene *ps, const vct_camera_desc *cam,
                                        float3 dir, hit_record first, int first_found, uint seed,
                                        uint part, uint parts) {
    primary_sample out;
    out.radiance = out.sampled = (float3)(0.0f);
    out.sampled_variance = 0.0f;
    out.throughput = (float3)(1.0f);
    out.found = 0;
    out.gpos = out.gnormal = out.gview = out.galbedo = (float4)(0.0f);
    out.rpos = out.rnormal = out.rdir = (float4)(0.0f);
    out.key = 0x9e3779b9u;
    float3 org = cam->position.xyz;
    int reflected = 0;
    for (uint depth = 0; depth < VCT_MAX_INTERFACES; ++depth) {
        hit_record h = first;
        if (depth == 0 ? !first_found : !accel_trace(&ps->g, org, dir, 0.0f, INFINITY, 0, &h)) {
            out.radiance += out.throughput * ps->ambient;
            out.key = rng_hash(out.key ^ 0xFFFFFFFFu);
            break;
        }
        float3 p, ng, n;
        int front;
        if (!surface_hit(&ps->g, &h, dir, &p, &ng, &n, &front))
            break;
        const uint mat = ps->tri_material[h.tri];
        out.key = rng_hash(out.key ^ mat);
        vct_material_desc m = ps->materials[mat];
        m.albedo.xyz = texture_albedo(&ps->tv, &m, h.tri, h.u, h.v);
        const float3 wo = -dir;
#ifdef VCT_REFRACTION
        if (is_dielectric(&m)) {
            /* The reflected part of the first surface entered goes to
             * vct_glass_reflection; later ones are left out. */
            const float ior = fmax(m.extra.x, 1.0001f);
            const float eta = front ? 1.0f / ior : ior;
            const float cos_i = fmin(dot(n, wo), 1.0f);
            const float F = fresnel_dielectric(cos_i, eta);
            const float eps = surface_epsilon(&ps->g, p);
            if (F >= 1.0f) {
                dir = reflect_dir(wo, n);
                org = p + n * eps;
            } else {
                const float sin2_t = eta * eta * fmax(0.0f, 1.0f - cos_i * cos_i);
                const float cos_t = sqrt(fmax(0.0f, 1.0f - sin2_t));
                dir = normalize(-eta * wo + (eta * cos_i - cos_t) * n);
#ifdef VCT_SPECULAR
                if (front && !reflected) {
                    reflected = 1;
                    const float3 w = out.throughput * F;
                    out.rpos = (float4)(p, w.x);
                    out.rnormal = (float4)(n, w.y);
                    out.rdir = (float4)(reflect_dir(wo, n), w.z);
                }
#endif
                out.throughput *= (1.0f - F) * m.albedo.xyz;
                org = p - n * eps;
            }
            continue;
        }
#endif
#ifdef VCT_EMISSION
        out.radiance += out.throughput * m.emission.xyz;
#endif
#ifdef VCT_SPECULAR
        if (bsdf_delta_only(&m)) {
            /* A perfect mirror: the reflected ray exactly, as through glass;
             * a cone would blur what it shows to the voxels' size. */
            out.throughput *= glossy_color(&m);
            dir = reflect_dir(wo, n);
            org = p + n * surface_epsilon(&ps->g, p);
            continue;
        }
#endif
#ifdef VCT_DIRECT
        float3 r;
        const float e = direct_lobe(&m, wo, n, &r);
        direct_terms d =
            direct_gather(&ps->g, ps->lights, ps->light_count, p, n, SHADOWS, r, e, SOFT_SHADOWS);
#ifdef VCT_EMITTERS
        /* The pixel's rays take its emitter samples' strata in a shuffled
         * order: in their own order, the rays of one part of the pixel (its
         * top half) would all take the same strata (the same of a quad's two
         * triangles), and an edge that one side of them sees alone would be
         * lit by those strata alone. */
        direct_terms de = {(float3)(0.0f), (float3)(0.0f), 0u, 0u, 0u, 0.0f};
        direct_emitters_part(&ps->g, &ps->e, ps->materials, ps->tri_material, p, n, r, e, seed,
                             rng_permute(part, parts, seed), parts, &de);
        out.sampled = out.throughput * direct_shade(&m, de, e);
        out.radiance += out.sampled;
        const float reflect =
            dot(out.throughput * diffuse_color(&m), (float3)(0.2126f, 0.7152f, 0.0722f)) *
            VCT_INV_PI;
        out.sampled_variance = reflect * reflect * de.emitter_variance;
        /* None, some or all of the emitter samples seen: an area light's
         * shadow edge. */
        const uint seen_class =
            de.emitters_seen == 0u ? 0u : (de.emitters_seen == de.emitters_facing ? 2u : 1u);
        out.key = rng_hash(out.key ^ (seen_class << 30));
#endif
        out.key = rng_hash(out.key ^ d.lights_seen);
        out.radiance += out.throughput * direct_shade(&m, d, e);
#endif
        out.found = 1;
        out.gpos = (float4)(p, as_float(mat));
        out.galbedo = (float4)(m.albedo.xyz, 0.0f);
        out.gnormal = (float4)(n, 1.0f);
        out.gview = (float4)(wo, 0.0f);
        break;
    }
    return out;
}

/* primary_trace_hit for the camera ray through (px, py) in the whole
 * image's pixel coordinates, traced alone. */
inline primary_sample primary_trace(const shading_scene *ps, const vct_camera_desc *cam, float px,
                                    float py, uint seed, uint part, uint parts) {
    const float3 dir = camera_ray_dir(cam, px, py);
    hit_record h;
    const int found = accel_trace(&ps->g, cam->position.xyz, dir, 0.0f, INFINITY, 0, &h);
    return primary_trace_hit(ps, cam, dir, h, found, seed, part, parts);
}

#endif
