/* Whitted ray tracing: camera rays; at every hit, emission and direct light
 * from every light with hard shadows (the ray caster's shading, emissive
 * triangles included), an optional ambient term, and the Phong highlight of
 * glossy surfaces; ideal mirror reflection for mirror and metal materials;
 * for dielectrics, Fresnel-weighted reflection and refraction, with total
 * internal reflection. The ray tree is walked depth first with a small
 * explicit stack (no recursion), cut at max_depth surface interactions and
 * where the throughput falls below min_throughput. Shadow rays treat glass
 * as opaque (the classic rule). Diffuse and glossy surfaces end a branch. */
#include "accel/accel.h"
#include "light/direct_light.h"
#include "light/emitters.h"
#include "scene/bsdf.h"
#include "scene/camera.h"
#include "scene/texture.h"
#include "render/shading_scene.h"
#include "vct_types.h"

/* One refraction branch per level at most, so the stack never holds more
 * than the depth limit allows (VCT_WHITTED_MAX_DEPTH, checked by the host). */
#define WHITTED_STACK 16

/* Local radiance of a non-dielectric hit: what the ray caster computes for a
 * diffuse surface, plus the glossy highlight and the ambient term; plain:
 * exactly the ray caster's (every surface Lambertian with its albedo). */
inline float3 whitted_local(const accel_view *g, const vct_material_desc *m, float3 albedo,
                            float3 p, float3 n, float3 wo, __global const vct_light_desc *lights,
                            uint light_count, const emitter_view *e,
                            __global const vct_material_desc *materials,
                            __global const uint *tri_material, uint pixel, float3 ambient,
                            int plain, uint *seen) {
    const float pg = glossy_probability(m);
    const int highlight = !plain && pg > 0.0f && !is_mirror(m);
    const float3 r = reflect_dir(wo, n);
    const float exponent = highlight ? phong_exponent(m->emission.w) : -1.0f;
    direct_terms d = direct_gather(g, lights, light_count, p, n, 1, r, exponent, 0);
    direct_emitters(g, e, materials, tri_material, p, n, r, exponent, pixel, &d);
    /* For the corner key: the lights seen, and none, part or all of the
     * emitter samples (an area light's shadow edge splits squares). */
    const uint emitters =
        d.emitters_seen == 0u ? 0u : (d.emitters_seen == d.emitters_facing ? 2u : 1u);
    *seen = d.lights_seen ^ (emitters << 30);
    const float3 matte = !plain && m->albedo.w > 0.5f ? (float3)(0.0f) : albedo;
    float3 shade = m->emission.xyz + matte * VCT_INV_PI * d.irradiance;
    if (highlight)
        shade += glossy_color(m) * d.lobe;
    if (any(ambient > 0.0f))
        shade += matte * ambient;
    return shade;
}

/* What a ray tree reads. */
typedef struct whitted_scene {
    shading_scene s;
    uint max_depth;
    float min_throughput;
    uint plain; /* the ray caster: one hit, Lambertian shading, no ambient */
} whitted_scene;

#define WHITTED_SCENE() ((whitted_scene){SHADING_SCENE(), max_depth, min_throughput, plain})

inline uint key_mix(uint key, uint v) {
    return (key ^ v) * 16777619u; /* FNV-1a, a word at a time */
}

/* The radiance of pixel (x, y)'s ray tree; *key receives what
 * the tree met: the material at each hit, in order, each miss, and the
 * lights each shaded hit sees (seed 001's corner key), from the shading's
 * own shadow rays. */
inline float3 whitted_tree(const whitted_scene *w, const vct_camera_desc *cam, uint x, uint y,
                           uint *key) {
    const uint pixel = camera_pixel_id(cam, x, y);
    /* Pending branches: origin (w: depth), direction, throughput. */
    float4 stack_org[WHITTED_STACK], stack_dir[WHITTED_STACK], stack_w[WHITTED_STACK];
    int sp = 0;
    float3 org = cam->position.xyz;
    float3 dir = camera_ray_dir(cam, (float)x + 0.5f, (float)camera_row(cam, y) + 0.5f);
    float3 throughput = (float3)(1.0f);
    uint depth = 0;
    float3 radiance = (float3)(0.0f);
    uint k = 2166136261u;
    for (;;) {
        hit_record h;
        int next = 0; /* 1: this branch continues with org, dir, throughput */
        if (!accel_trace(&w->s.g, org, dir, 0.0f, INFINITY, 0, &h)) {
            radiance += throughput * w->s.ambient; /* the environment */
            k = key_mix(k, 0xFFFFFFFFu);
        } else {
            float3 p, ng, n;
            int front;
            if (surface_hit(&w->s.g, &h, dir, &p, &ng, &n, &front)) {
                const uint mat = w->s.tri_material[h.tri];
                const vct_material_desc m = w->s.materials[mat];
                const float3 wo = -dir;
                const float eps = surface_epsilon(&w->s.g, p);
                const int deeper = depth + 1 < w->max_depth;
                k = key_mix(k, mat);
                if (is_dielectric(&m) && !w->plain) {
                    radiance += throughput * m.emission.xyz;
                    const float ior = fmax(m.extra.x, 1.0001f);
                    const float eta = front ? 1.0f / ior : ior;
                    const float cos_i = fmin(dot(n, wo), 1.0f);
                    const float F = fresnel_dielectric(cos_i, eta);
                    const float3 tw = throughput * (1.0f - F) * m.albedo.xyz;
                    if (deeper && F < 1.0f && fmax(tw.x, fmax(tw.y, tw.z)) >= w->min_throughput &&
                        sp < WHITTED_STACK) {
                        const float sin2_t = eta * eta * fmax(0.0f, 1.0f - cos_i * cos_i);
                        const float cos_t = sqrt(fmax(0.0f, 1.0f - sin2_t));
                        const float3 t = normalize(-eta * wo + (eta * cos_i - cos_t) * n);
                        stack_org[sp] = (float4)(p - n * eps, (float)(depth + 1));
                        stack_dir[sp] = (float4)(t, 0.0f);
                        stack_w[sp++] = (float4)(tw, 0.0f);
                    }
                    throughput *= F;
                    org = p + n * eps;
                    dir = reflect_dir(wo, n);
                    next = deeper;
                } else {
                    const float3 albedo = texture_albedo(&w->s.tv, &m, h.tri, h.u, h.v);
                    uint seen;
                    radiance += throughput * whitted_local(&w->s.g, &m, albedo, p, n, wo,
                                                           w->s.lights, w->s.light_count, &w->s.e,
                                                           w->s.materials, w->s.tri_material, pixel,
                                                           w->s.ambient, (int)w->plain, &seen);
                    k = key_mix(k, seen);
                    if (is_mirror(&m)) {
                        throughput *= glossy_color(&m);
                        org = p + n * eps;
                        dir = reflect_dir(wo, n);
                        next = deeper;
                    }
                }
            }
        }
        if (next && fmax(throughput.x, fmax(throughput.y, throughput.z)) >= w->min_throughput) {
            ++depth;
            continue;
        }
        if (sp == 0)
            break;
        --sp;
        org = stack_org[sp].xyz;
        depth = (uint)stack_org[sp].w;
        dir = stack_dir[sp].xyz;
        throughput = stack_w[sp].xyz;
        k = key_mix(k, 0xFFFFFFFEu); /* a branch taken up again */
    }
    *key = k;
    return radiance;
}

#define WHITTED_ARGS                                                                               \
    ACCEL_ARGS, vct_camera_desc cam, __global const vct_material_desc *materials,                  \
        __global const uint *tri_material, TEXTURE_ARGS, __global const vct_light_desc *lights,    \
        uint light_count, EMITTER_ARGS, float4 ambient, uint max_depth, float min_throughput,      \
        uint plain

/* Every pixel. */
__kernel void whitted(WHITTED_ARGS, __global float4 *image) {
    const uint x = get_global_id(0), y = get_global_id(1);
    if (x >= cam.size.x || y >= cam.size.y)
        return;
    const whitted_scene w = WHITTED_SCENE();
    uint key;
    image[y * cam.size.x + x] = (float4)(whitted_tree(&w, &cam, x, y, &key), 1.0f);
}

/* The listed pixels (indices y * width + x), with their keys; traced marks
 * them (adaptive subsampling, render/subsample.cl). */
__kernel void whitted_points(WHITTED_ARGS, __global const uint *points, uint n, __global uint *keys,
                             __global uint *traced, __global float4 *image) {
    const uint i = get_global_id(0);
    if (i >= n)
        return;
    const uint pixel = points[i], x = pixel % cam.size.x, y = pixel / cam.size.x;
    const whitted_scene w = WHITTED_SCENE();
    uint key;
    image[pixel] = (float4)(whitted_tree(&w, &cam, x, y, &key), 1.0f);
    keys[pixel] = key;
    traced[pixel] = 1u;
}
