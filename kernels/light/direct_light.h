/* Direct illumination from punctual lights at a surface point, with hard
 * shadows from any-hit rays through the acceleration structure. Lambert: albedo / pi. */
#ifndef VCT_DIRECT_LIGHT_H
#define VCT_DIRECT_LIGHT_H

#include "accel/accel.h"
#include "vct_types.h"

#define VCT_INV_PI 0.318309886f

/* Offset that lifts a point off its surface: relative to the scene extent and
 * to the point's own magnitude (float spacing grows with it). */
inline float surface_epsilon(const accel_view *g, float3 p) {
    const float3 ap = fabs(p);
    return g->desc.origin.w * 1e-5f + fmax(ap.x, fmax(ap.y, ap.z)) * 2e-6f;
}

#ifdef VCT_PACKETS
/* surface_epsilon in vector lanes, with its operations (the first product
 * a vector one, so that the sum fuses with it as the scalar form's does). */
inline float16 surface_epsilon16(const accel_view *g, float16 px, float16 py, float16 pz) {
    return (float16)(g->desc.origin.w) * 1e-5f + fmax(fabs(px), fmax(fabs(py), fabs(pz))) * 2e-6f;
}
#endif

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

#ifdef VCT_PACKETS
/* light_incident for points in vector lanes, with its operations; -1 in
 * the lanes it can light. */
inline int16 light_incident16(__global const vct_light_desc *lights, uint i, float16 px, float16 py,
                              float16 pz, float16 *wx, float16 *wy, float16 *wz, float16 *dist,
                              float16 *rr, float16 *rg, float16 *rb) {
    const vct_light_desc L = lights[i];
    const uint kind = (uint)L.position.w;
    if (kind == VCT_LIGHT_KIND_DIRECTIONAL) {
        *wx = (float16)(-L.direction.x);
        *wy = (float16)(-L.direction.y);
        *wz = (float16)(-L.direction.z);
        *dist = (float16)(INFINITY);
        *rr = (float16)(L.color.x);
        *rg = (float16)(L.color.y);
        *rb = (float16)(L.color.z);
        return (int16)(-1);
    }
    const float16 tx = L.position.x - px, ty = L.position.y - py, tz = L.position.z - pz;
    /* dots as the library adds them: a statement a step, nothing fused */
    const float16 txx = tx * tx, tyy = ty * ty, tzz = tz * tz;
    const float16 txy = txx + tyy;
    const float16 d2 = txy + tzz;
    *dist = sqrt(d2);
    *wx = tx / *dist;
    *wy = ty / *dist;
    *wz = tz / *dist;
    *rr = L.color.x / d2;
    *rg = L.color.y / d2;
    *rb = L.color.z / d2;
    if (kind == VCT_LIGHT_KIND_SPOT) {
        const float16 cdx = -*wx * L.direction.x, cdy = -*wy * L.direction.y,
                      cdz = -*wz * L.direction.z;
        const float16 cdxy = cdx + cdy;
        const float16 cd = cdxy + cdz;
        const float cos_outer = L.direction.w, cos_inner = L.color.w;
        const float16 x = clamp((cd - cos_outer) / fmax(cos_inner - cos_outer, 1e-6f), 0.0f, 1.0f);
        *rr *= x * x;
        *rg *= x * x;
        *rb *= x * x;
    }
    return d2 > 0.0f;
}
#endif

/* How far a shadow ray from a point lifted by eps may go towards a light
 * dist away: short of the light by its own lift and a relative margin. */
inline float light_reach(float dist, float eps) {
    return dist * (1.0f - 1e-6f) - 2.0f * eps;
}

/* 1 if nothing blocks the segment from p (lifted off its surface along n by
 * eps) towards wi over dist; shading itself uses p. */
inline int light_visible(const accel_view *g, float3 p, float3 n, float eps, float3 wi,
                         float dist) {
    hit_record h;
    return !accel_trace(g, p + n * eps, wi, 0.0f, light_reach(dist, eps), 1, &h);
}

/* What lights send to p (normal n): the irradiance sum of radiant *
 * cos(theta), with hard shadows when `shadows`, and, for a Phong exponent
 * e >= 0 about the mirror direction r, the lobe-weighted sum
 * radiant * cos(theta) * cos(alpha)^e * (e + 2) / (2 pi). */
typedef struct direct_terms {
    float3 irradiance, lobe;
    /* What the shadow rays found: the lights (the first 32) that reach the
     * point, and how many emitter samples face it and how many it sees. */
    uint lights_seen, emitters_facing, emitters_seen;
    /* the variance of the emitter samples' irradiance (its luminance) */
    float emitter_variance;
} direct_terms;

/* The Phong lobe's part of a light's sample (normalised: (e + 2) / 2pi). */
inline void direct_add_lobe(direct_terms *sum, float3 radiant, float cos_theta, float3 wi, float3 r,
                            float e) {
    if (e >= 0.0f)
        sum->lobe +=
            radiant * cos_theta * pow(fmax(dot(r, wi), 0.0f), e) * (e + 2.0f) * (0.5f * VCT_INV_PI);
}

inline void direct_add(direct_terms *sum, float3 radiant, float cos_theta, float3 wi, float3 r,
                       float e, float visible) {
    sum->irradiance += radiant * (cos_theta * visible);
    direct_add_lobe(sum, radiant * visible, cos_theta, wi, r, e);
}

/* light_incident for a surface with normal n: also the cosine, and 0 where
 * the light sends nothing or arrives from behind. */
inline int light_reaches(__global const vct_light_desc *lights, uint i, float3 p, float3 n,
                         float3 *wi, float *dist, float3 *radiant, float *cos_theta) {
    if (!light_incident(lights, i, p, wi, dist, radiant))
        return 0;
    *cos_theta = dot(n, *wi);
    return *cos_theta > 0.0f && any(*radiant != 0.0f);
}

inline int light_is_soft(__global const vct_light_desc *lights, uint i) {
    return lights[i].shape.x > 0.0f;
}

/* Every light but, when skip_soft, those with a radius (their shadows are
 * traced elsewhere); lights with a radius are otherwise shaded as points. */
inline direct_terms direct_gather(const accel_view *g, __global const vct_light_desc *lights,
                                  uint light_count, float3 p, float3 n, int shadows, float3 r,
                                  float e, int skip_soft) {
    direct_terms sum = {(float3)(0.0f), (float3)(0.0f), 0u, 0u, 0u, 0.0f};
    const float eps = surface_epsilon(g, p);
    for (uint i = 0; i < light_count; ++i) {
        if (skip_soft && light_is_soft(lights, i))
            continue;
        float3 wi, radiant;
        float dist, cos_theta;
        if (!light_reaches(lights, i, p, n, &wi, &dist, &radiant, &cos_theta))
            continue;
        if (shadows && !light_visible(g, p, n, eps, wi, dist))
            continue;
        if (i < 32u)
            sum.lights_seen |= 1u << i;
        direct_add(&sum, radiant, cos_theta, wi, r, e, 1.0f);
    }
    return sum;
}

/* A point of light i's extent as seen from p towards its centre wi (dist
 * away), for uniform u1, u2: on the disk of its radius facing p, or, for a
 * directional light, a direction within its angular radius. Returns the
 * unit direction towards it and sets *to_dist. */
inline float3 light_extent_sample(__global const vct_light_desc *lights, uint i, float3 wi,
                                  float dist, float u1, float u2, float *to_dist) {
    const float size = lights[i].shape.x;
    const float3 t = normalize(fabs(wi.x) > 0.9f ? cross(wi, (float3)(0.0f, 1.0f, 0.0f))
                                                 : cross(wi, (float3)(1.0f, 0.0f, 0.0f)));
    const float3 b = cross(wi, t);
    const float phi = 6.28318531f * u2;
    if (isinf(dist)) {
        /* Uniform in solid angle over the cone of half-angle atan(size). */
        const float cos_max = 1.0f / sqrt(1.0f + size * size);
        const float c = 1.0f - u1 * (1.0f - cos_max), s = sqrt(fmax(0.0f, 1.0f - c * c));
        *to_dist = INFINITY;
        return normalize(c * wi + s * (cos(phi) * t + sin(phi) * b));
    }
    const float rad = size * sqrt(u1);
    const float3 to = wi * dist + rad * (cos(phi) * t + sin(phi) * b);
    *to_dist = length(to);
    return to / *to_dist;
}

/* Radiance reflected towards the viewer by a Lambertian point p with normal n
 * (facing the viewer) from every light. */
inline float3 direct_lambert(const accel_view *g, __global const vct_light_desc *lights,
                             uint light_count, float3 p, float3 n, float3 albedo) {
    return albedo * VCT_INV_PI *
           direct_gather(g, lights, light_count, p, n, 1, (float3)(0.0f), -1.0f, 0).irradiance;
}

#endif
