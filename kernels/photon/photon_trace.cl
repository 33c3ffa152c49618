/* Photon tracing (seed 000 §1.2-1.4, with what it lacked): one work-item per
 * photon path. A path picks a light by power, leaves it (point: uniform
 * sphere; spot: uniform in its cone, weighted by the falloff; directional: a
 * disk covering the scene; emissive triangle: an area-uniform point, either
 * side, cosine direction), and bounces by the path tracer's BSDF (Fresnel and
 * total internal reflection included) with Russian roulette by how much of
 * its power the bounce keeps. At every hit on a diffuse or glossy surface it
 * deposits a photon, of the kinds in store_mask, into its own slots
 * path * max_depth + k: no atomics, and the same slots on every run.
 *
 * sources: per light, then one entry for all emitters and one for the
 * environment: x = the cumulative pick probability, y = 1 / its own, z = the
 * light's index (as bits; ~0 for the emitters, ~1 for the environment).
 * bounds: the scene's bounding sphere; ambient: the environment's radiance,
 * which arrives from every direction: its photons come in along a uniform
 * direction through a disk covering the scene. */
#include "accel/accel.h"
#include "light/direct_light.h"
#include "light/emitters.h"
#include "photon/photon.h"
#include "scene/bsdf.h"
#include "scene/rng.h"
#include "scene/texture.h"
#include "scene/turn.h"
#include "vct_types.h"

#define PHOTON_PI 3.14159265f
#define SOURCE_EMITTERS 0xffffffffu
#define SOURCE_ENVIRONMENT 0xfffffffeu

/* A unit vector about axis w: cos_theta given, phi = 2 pi u. */
inline float3 photon_dir_about(float3 w, float cos_theta, float u) {
    float3 t, b;
    basis_of(w, &t, &b);
    const float s = sqrt(fmax(0.0f, 1.0f - cos_theta * cos_theta));
    const float2 cs = turn_cos_sin(u);
    return normalize(s * cs.x * t + s * cs.y * b + cos_theta * w);
}

/* A photon's start: origin, direction and power, for light source `src`. */
/* A photon entering along d through the disk of the bounding sphere facing
 * it: a directional light's, or the environment's for a uniform d. */
inline float3 photon_from_disk(float4 bounds, float3 d, float u1, float u2) {
    float3 t, b;
    basis_of(d, &t, &b);
    const float rad = bounds.w * sqrt(u1);
    const float2 cs = turn_cos_sin(u2);
    return bounds.xyz - d * (2.0f * bounds.w) + rad * (cs.x * t + cs.y * b);
}

inline int photon_emit(const accel_view *g, __global const vct_light_desc *lights, float4 source,
                       const emitter_view *e, __global const vct_material_desc *materials,
                       __global const uint *tri_material, float4 bounds, float4 ambient, uint *rng,
                       float3 *org, float3 *dir, float3 *power) {
    const uint index = as_uint(source.z);
    const float inv_p = source.y;
    const float u1 = rng_next(rng), u2 = rng_next(rng);
    const float disk = PHOTON_PI * bounds.w * bounds.w;
    if (index == SOURCE_ENVIRONMENT) {
        *dir = photon_dir_about((float3)(0.0f, 0.0f, 1.0f), 1.0f - 2.0f * rng_next(rng),
                                rng_next(rng));
        *org = photon_from_disk(bounds, *dir, u1, u2);
        *power = ambient.xyz * (4.0f * PHOTON_PI * disk * inv_p);
        return 1;
    }
    if (index == SOURCE_EMITTERS) {
        const uint i = emitter_pick(e, fmin(rng_next(rng), 0.99999994f));
        const uint tri = e->tris[i];
        float3 a, b, c;
        emitter_vertices(g, tri, &a, &b, &c);
        float u = u1, v = u2;
        if (u + v > 1.0f) {
            u = 1.0f - u;
            v = 1.0f - v;
        }
        const float3 q = a + u * (b - a) + v * (c - a);
        float3 nl = normalize(cross(b - a, c - a));
        if (rng_next(rng) < 0.5f)
            nl = -nl; /* emitters are two-sided */
        const float w = rng_next(rng);
        *dir = photon_dir_about(nl, sqrt(fmax(0.0f, 1.0f - w)), rng_next(rng));
        *org = q + nl * surface_epsilon(g, q);
        *power =
            materials[tri_material[tri]].emission.xyz * (e->scale[i] * 2.0f * PHOTON_PI * inv_p);
        return 1;
    }
    const vct_light_desc L = lights[index];
    const uint kind = (uint)L.position.w;
    if (kind == VCT_LIGHT_KIND_DIRECTIONAL) {
        *dir = L.direction.xyz;
        *org = photon_from_disk(bounds, *dir, u1, u2);
        *power = L.color.xyz * (disk * inv_p);
        return 1;
    }
    *org = L.position.xyz;
    if (kind == VCT_LIGHT_KIND_SPOT) {
        const float cos_outer = L.direction.w, cos_inner = L.color.w;
        const float ct = 1.0f - u1 * (1.0f - cos_outer);
        *dir = photon_dir_about(L.direction.xyz, ct, u2);
        const float x = clamp((ct - cos_outer) / fmax(cos_inner - cos_outer, 1e-6f), 0.0f, 1.0f);
        *power = L.color.xyz * (x * x * 2.0f * PHOTON_PI * (1.0f - cos_outer) * inv_p);
        return x > 0.0f;
    }
    *dir = photon_dir_about((float3)(0.0f, 0.0f, 1.0f), 1.0f - 2.0f * u1, u2);
    *power = L.color.xyz * (4.0f * PHOTON_PI * inv_p);
    return 1;
}

inline float max3(float3 v) {
    return fmax(v.x, fmax(v.y, v.z));
}

__kernel void photon_trace(ACCEL_ARGS, __global const vct_material_desc *materials,
                           __global const uint *tri_material, TEXTURE_ARGS,
                           __global const vct_light_desc *lights, __global const float4 *sources,
                           uint source_count, __global const uint *emitter_tris,
                           __global const float *emitter_cdf, __global const float *emitter_scale,
                           uint emitter_count, float4 bounds, float4 ambient, uint seed, uint pass,
                           uint paths, uint max_depth, uint store_mask, __global float4 *records,
                           __global uint *kinds) {
    const uint path = get_global_id(0);
    if (path >= paths)
        return;
    const accel_view g = ACCEL_VIEW();
    const texture_view tv = TEXTURE_VIEW();
    const emitter_view e = {emitter_tris, emitter_cdf, emitter_scale, emitter_count, 1u};
    uint rng = rng_start(seed ^ 0x70686fu, path, pass);
    const float pick = rng_next(&rng);
    uint src = 0;
    while (src + 1u < source_count && sources[src].x <= pick)
        ++src;
    float3 org, dir, power;
    uint stored = 0;
    if (photon_emit(&g, lights, sources[src], &e, materials, tri_material, bounds, ambient, &rng,
                    &org, &dir, &power)) {
        uint specular = 0, dielectric = 0;
        for (uint bounce = 0; bounce < max_depth; ++bounce) {
            hit_record h;
            if (!accel_trace(&g, org, dir, 0.0f, INFINITY, 0, &h))
                break;
            float3 p, ng, n;
            int front;
            if (!surface_hit(&g, &h, dir, &p, &ng, &n, &front))
                break;
            vct_material_desc m = materials[tri_material[h.tri]];
            m.albedo.xyz = texture_albedo(&tv, &m, h.tri, h.u, h.v);
            const float3 wo = -dir;
            if (!bsdf_delta_only(&m)) {
                const uint kind = specular ? PHOTON_CAUSTIC | (dielectric ? PHOTON_DIELECTRIC : 0u)
                                           : (bounce == 0u ? PHOTON_DIRECT : PHOTON_INDIRECT);
                if (kind & store_mask) {
                    const uint slot = path * max_depth + stored++;
                    records[3u * slot] = (float4)(p, n.x);
                    records[3u * slot + 1u] = (float4)(wo, n.y);
                    records[3u * slot + 2u] = (float4)(power, n.z);
                    kinds[slot] = kind;
                }
            }
            if (bounce + 1u == max_depth)
                break;
            bsdf_sample bs;
            const float u0 = rng_next(&rng), u1 = rng_next(&rng), u2 = rng_next(&rng);
            if (!bsdf_sample_dir(&m, n, wo, front, u0, u1, u2, &bs))
                break;
            const float3 next = power * bs.weight;
            /* Russian roulette: go on with the share of power the bounce keeps. */
            const float keep = fmin(max3(next) / fmax(max3(power), 1e-30f), 1.0f);
            if (!(rng_next(&rng) < keep))
                break;
            power = next / keep;
            specular = bs.delta ? 1u : 0u;
            dielectric = specular && (dielectric || is_dielectric(&m)) ? 1u : 0u;
            const float eps = surface_epsilon(&g, p);
            org = p + (dot(bs.wi, n) > 0.0f ? n : -n) * eps;
            dir = bs.wi;
        }
    }
    for (uint k = stored; k < max_depth; ++k)
        kinds[path * max_depth + k] = 0u;
}
