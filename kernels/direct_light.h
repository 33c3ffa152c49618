/* Direct illumination from punctual lights at a surface point, with hard
 * shadows from any-hit rays through the grid. Lambert: albedo / pi. */
#ifndef VCT_DIRECT_LIGHT_H
#define VCT_DIRECT_LIGHT_H

#include "grid_traverse.h"
#include "vct_types.h"

#define VCT_INV_PI 0.318309886f

/* Offset that lifts a point off its surface: relative to the scene extent and
 * to the point's own magnitude (float spacing grows with it). */
inline float surface_epsilon(const grid_view *g, float3 p) {
    const float3 ap = fabs(p);
    return g->desc.origin.w * 1e-5f + fmax(ap.x, fmax(ap.y, ap.z)) * 2e-6f;
}

/* Light i as seen from p: direction wi towards it, distance (INFINITY for a
 * directional light) and incident radiant quantity before the cosine:
 * I / d^2 (times the spot falloff) or E. Returns 0 if it cannot light p. */
inline int light_incident(__global const vct_light_desc *lights, uint i, float3 p, float3 *wi,
                          float *dist, float3 *radiant) {
    const vct_light_desc L = lights[i];
    const uint kind = (uint)L.position.w;
    if (kind == VCT_LIGHT_KIND_DIRECTIONAL) {
        *wi = -L.direction.xyz;
        *dist = INFINITY;
        *radiant = L.color.xyz;
        return 1;
    }
    const float3 to = L.position.xyz - p;
    const float d2 = dot(to, to);
    if (!(d2 > 0.0f))
        return 0;
    *dist = sqrt(d2);
    *wi = to / *dist;
    *radiant = L.color.xyz / d2;
    if (kind == VCT_LIGHT_KIND_SPOT) {
        const float cd = dot(-*wi, L.direction.xyz);
        const float cos_outer = L.direction.w, cos_inner = L.color.w;
        const float x = clamp((cd - cos_outer) / fmax(cos_inner - cos_outer, 1e-6f), 0.0f, 1.0f);
        *radiant *= x * x;
    }
    return 1;
}

/* 1 if nothing blocks the segment from p (lifted off its surface along n by
 * eps) towards wi over dist; shading itself uses p. */
inline int light_visible(const grid_view *g, float3 p, float3 n, float eps, float3 wi, float dist) {
    hit_record h;
    return !grid_trace(g, p + n * eps, wi, 0.0f, dist * (1.0f - 1e-6f) - 2.0f * eps, 1, &h);
}

/* What every light sends to p (normal n): the irradiance sum of radiant *
 * cos(theta), with hard shadows when `shadows`, and, for a Phong exponent
 * e >= 0 about the mirror direction r, the lobe-weighted sum
 * radiant * cos(theta) * cos(alpha)^e * (e + 2) / (2 pi). */
typedef struct direct_terms {
    float3 irradiance, lobe;
} direct_terms;

inline direct_terms direct_gather(const grid_view *g, __global const vct_light_desc *lights,
                                  uint light_count, float3 p, float3 n, int shadows, float3 r,
                                  float e) {
    direct_terms sum = {(float3)(0.0f), (float3)(0.0f)};
    const float eps = surface_epsilon(g, p);
    for (uint i = 0; i < light_count; ++i) {
        float3 wi, radiant;
        float dist;
        if (!light_incident(lights, i, p, &wi, &dist, &radiant))
            continue;
        const float cos_theta = dot(n, wi);
        if (!(cos_theta > 0.0f) || all(radiant == 0.0f))
            continue;
        if (shadows && !light_visible(g, p, n, eps, wi, dist))
            continue;
        sum.irradiance += radiant * cos_theta;
        if (e >= 0.0f)
            sum.lobe += radiant * cos_theta * pow(fmax(dot(r, wi), 0.0f), e) * (e + 2.0f) *
                        (0.5f * VCT_INV_PI);
    }
    return sum;
}

/* Radiance reflected towards the viewer by a Lambertian point p with normal n
 * (facing the viewer) from every light. */
inline float3 direct_lambert(const grid_view *g, __global const vct_light_desc *lights,
                             uint light_count, float3 p, float3 n, float3 albedo) {
    return albedo * VCT_INV_PI *
           direct_gather(g, lights, light_count, p, n, 1, (float3)(0.0f), -1.0f).irradiance;
}

#endif
