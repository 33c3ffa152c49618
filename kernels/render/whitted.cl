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
#include "vct_types.h"

/* One refraction branch per level at most, so the stack never holds more
 * than the depth limit allows (VCT_WHITTED_MAX_DEPTH, checked by the host). */
#define WHITTED_STACK 16

/* Local radiance of a non-dielectric hit: what the ray caster computes for a
 * diffuse surface, plus the glossy highlight and the ambient term. */
inline float3 whitted_local(const accel_view *g, const vct_material_desc *m, float3 albedo,
                            float3 p, float3 n, float3 wo, __global const vct_light_desc *lights,
                            uint light_count, const emitter_view *e,
                            __global const vct_material_desc *materials,
                            __global const uint *tri_material, uint pixel, float3 ambient) {
    const float pg = glossy_probability(m);
    const int highlight = pg > 0.0f && !is_mirror(m);
    const float3 r = reflect_dir(wo, n);
    const float exponent = highlight ? phong_exponent(m->emission.w) : -1.0f;
    direct_terms d = direct_gather(g, lights, light_count, p, n, 1, r, exponent, 0);
    direct_emitters(g, e, materials, tri_material, p, n, r, exponent, pixel, &d);
    const float3 matte = m->albedo.w > 0.5f ? (float3)(0.0f) : albedo;
    float3 shade = m->emission.xyz + matte * VCT_INV_PI * d.irradiance;
    if (highlight)
        shade += glossy_color(m) * d.lobe;
    if (any(ambient > 0.0f))
        shade += matte * ambient;
    return shade;
}

__kernel void whitted(ACCEL_ARGS, vct_camera_desc cam, __global const vct_material_desc *materials,
                      __global const uint *tri_material, TEXTURE_ARGS,
                      __global const vct_light_desc *lights, uint light_count, EMITTER_ARGS,
                      float4 ambient, uint max_depth, float min_throughput,
                      __global float4 *image) {
    const uint x = get_global_id(0), y = get_global_id(1);
    if (x >= cam.size.x || y >= cam.size.y)
        return;
    const accel_view g = ACCEL_VIEW();
    const texture_view tv = TEXTURE_VIEW();
    const emitter_view e = EMITTER_VIEW();
    const uint pixel = y * cam.size.x + x;
    /* Pending branches: origin (w: depth), direction, throughput. */
    float4 stack_org[WHITTED_STACK], stack_dir[WHITTED_STACK], stack_w[WHITTED_STACK];
    int sp = 0;
    float3 org = cam.position.xyz;
    float3 dir = camera_ray_dir(&cam, (float)x + 0.5f, (float)y + 0.5f);
    float3 throughput = (float3)(1.0f);
    uint depth = 0;
    float3 radiance = (float3)(0.0f);
    for (;;) {
        hit_record h;
        int next = 0; /* 1: this branch continues with org, dir, throughput */
        if (!accel_trace(&g, org, dir, 0.0f, INFINITY, 0, &h)) {
            radiance += throughput * ambient.xyz; /* the environment */
        } else {
            float3 p, ng, n;
            int front;
            if (surface_hit(&g, &h, dir, &p, &ng, &n, &front)) {
                const vct_material_desc m = materials[tri_material[h.tri]];
                const float3 wo = -dir;
                const float eps = surface_epsilon(&g, p);
                const int deeper = depth + 1 < max_depth;
                if (is_dielectric(&m)) {
                    radiance += throughput * m.emission.xyz;
                    const float ior = fmax(m.extra.x, 1.0001f);
                    const float eta = front ? 1.0f / ior : ior;
                    const float cos_i = fmin(dot(n, wo), 1.0f);
                    const float F = fresnel_dielectric(cos_i, eta);
                    const float3 tw = throughput * (1.0f - F) * m.albedo.xyz;
                    if (deeper && F < 1.0f && fmax(tw.x, fmax(tw.y, tw.z)) >= min_throughput &&
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
                    const float3 albedo = texture_albedo(&tv, &m, h.tri, h.u, h.v);
                    radiance +=
                        throughput * whitted_local(&g, &m, albedo, p, n, wo, lights, light_count,
                                                   &e, materials, tri_material, pixel, ambient.xyz);
                    if (is_mirror(&m)) {
                        throughput *= glossy_color(&m);
                        org = p + n * eps;
                        dir = reflect_dir(wo, n);
                        next = deeper;
                    }
                }
            }
        }
        if (next && fmax(throughput.x, fmax(throughput.y, throughput.z)) >= min_throughput) {
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
    }
    image[pixel] = (float4)(radiance, 1.0f);
}
