/* Next-event estimation at a surface point: the punctual lights through
 * shadow rays, and one emissive-triangle sample picked by area, weighted
 * against BSDF sampling by the power heuristic when the caller also finds
 * emitters by BSDF sampling (the path tracer), fully otherwise (photon
 * mapping's visible points, whose emitted light comes from here alone). */
#ifndef VCT_NEE_H
#define VCT_NEE_H

#include "accel/accel.h"
#include "light/direct_light.h"
#include "light/emitters.h"
#include "scene/bsdf.h"
#include "scene/rng.h"
#include "vct_types.h"

/* The emitters, picked by area (light/emitters.h's view, one sample a hit). */
typedef struct emitters {
    emitter_view view;
    float inv_area; /* 1 / total emissive area */
} emitters;

inline float power_heuristic(float a, float b) {
    const float a2 = a * a, b2 = b * b;
    return a2 + b2 > 0.0f ? a2 / (a2 + b2) : 0.0f;
}

/* Radiance from the punctual lights, for any BSDF (delta lobes excluded).
 * A light with a radius is shaded from its centre; its shadow ray goes to a
 * random point of its extent. */
inline float3 nee_punctual(const accel_view *g, __global const vct_light_desc *lights,
                           uint light_count, const vct_material_desc *m, float3 p, float3 n,
                           float3 wo, uint *rng) {
    float3 sum = (float3)(0.0f);
    const float eps = surface_epsilon(g, p);
    for (uint i = 0; i < light_count; ++i) {
        float3 wi, radiant;
        float dist, pdf;
        if (!light_incident(lights, i, p, &wi, &dist, &radiant))
            continue;
        const float3 fc = bsdf_eval(m, n, wo, wi, &pdf);
        if (all(fc == 0.0f) || all(radiant == 0.0f))
            continue;
        float3 towards = wi;
        float reach = dist;
        if (light_is_soft(lights, i)) {
            const float u1 = rng_next(rng), u2 = rng_next(rng);
            towards = light_extent_sample(lights, i, wi, dist, u1, u2, &reach);
        }
        if (light_visible(g, p, n, eps, towards, reach))
            sum += radiant * fc;
    }
    return sum;
}

/* One emissive-triangle sample; mis: weighted against BSDF sampling. */
inline float3 nee_emitters(const accel_view *g, const emitters *e,
                           __global const vct_material_desc *materials,
                           __global const uint *tri_material, const vct_material_desc *m, float3 p,
                           float3 n, float3 wo, int mis, uint *rng) {
    if (e->view.count == 0)
        return (float3)(0.0f);
    const uint tri = e->view.tris[emitter_pick(&e->view, rng_next(rng))];
    float u = rng_next(rng), v = rng_next(rng);
    if (u + v > 1.0f) {
        u = 1.0f - u;
        v = 1.0f - v;
    }
    float3 a, b, c;
    emitter_vertices(g, tri, &a, &b, &c); /* the same point for either winding */
    const float3 q = a + u * (b - a) + v * (c - a);
    const float3 nl = normalize(cross(b - a, c - a));
    const float3 to = q - p;
    const float d2 = dot(to, to);
    if (!(d2 > 0.0f))
        return (float3)(0.0f);
    const float dist = sqrt(d2);
    const float3 wi = to / dist;
    const float cos_l = fabs(dot(nl, wi));
    if (!(cos_l > 0.0f))
        return (float3)(0.0f);
    float pdf_bsdf;
    const float3 fc = bsdf_eval(m, n, wo, wi, &pdf_bsdf);
    if (all(fc == 0.0f))
        return (float3)(0.0f);
    /* The shadow ray runs from the lifted point to q itself, not parallel
     * to p -> q: towards an emitter seen edge-on (a ceiling beside a panel a
     * centimetre under it) a parallel ray meets the emitter's own plane the
     * lift over the sine of the angle short of q, which hid it. */
    const float3 o = p + n * surface_epsilon(g, p);
    const float3 to_q = q - o;
    const float reach = length(to_q);
    hit_record h;
    if (accel_trace(g, o, to_q / reach, 0.0f, reach - 2.0f * surface_epsilon(g, q), 1, &h))
        return (float3)(0.0f);
    const float pdf_light = e->inv_area * d2 / cos_l; /* solid angle */
    const float3 Le = materials[tri_material[tri]].emission.xyz;
    return Le * fc * ((mis ? power_heuristic(pdf_light, pdf_bsdf) : 1.0f) / pdf_light);
}

#endif
