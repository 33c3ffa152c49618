/* Materials for the path tracer: Lambert, a normalised Phong lobe (glossy, or
 * an ideal mirror at roughness ~0), and a smooth dielectric with Fresnel
 * reflection and total internal reflection. Directions point away from the
 * surface; n faces the incoming ray's side. */
#ifndef VCT_BSDF_H
#define VCT_BSDF_H

#include "scene/turn.h"
#include "vct_types.h"

#define BSDF_PI 3.14159265f

typedef struct bsdf_sample {
    float3 wi;
    float3 weight; /* f cos / pdf */
    float pdf;     /* solid angle; 0 for a delta lobe */
    int delta;
} bsdf_sample;

inline void basis_of(float3 n, float3 *t, float3 *b) {
    const float s = n.z >= 0.0f ? 1.0f : -1.0f; /* Duff et al. 2017 */
    const float a = -1.0f / (s + n.z);
    const float c = n.x * n.y * a;
    *t = (float3)(1.0f + s * n.x * n.x * a, s * c, -s * n.x);
    *b = (float3)(c, s + n.y * n.y * a, -n.y);
}

/* glTF's roughness is perceptual: the microfacet width is alpha = roughness^2
 * (glTF 2.0, appendix B). The Phong exponent of the same width is
 * 2 / alpha^2 - 2 (Walter et al. 2007, Beckmann). */
inline float phong_exponent(float roughness) {
    const float r = fmax(roughness, 1e-3f);
    const float alpha = r * r;
    return fmax(2.0f / (alpha * alpha) - 2.0f, 0.0f);
}

inline float3 reflect_dir(float3 wo, float3 n) {
    return 2.0f * dot(wo, n) * n - wo;
}

/* Glossy weight: specular colour (or albedo for metals). */
inline float3 glossy_color(const vct_material_desc *m) {
    return m->albedo.w > 0.5f ? m->albedo.xyz : m->specular.xyz;
}

inline float3 diffuse_color(const vct_material_desc *m) {
    return m->albedo.w > 0.5f ? (float3)(0.0f) : m->albedo.xyz;
}

/* Probability of choosing the glossy lobe over the diffuse one. */
inline float glossy_probability(const vct_material_desc *m) {
    const float g = dot(glossy_color(m), (float3)(1.0f)), d = dot(diffuse_color(m), (float3)(1.0f));
    return g + d > 0.0f ? g / (g + d) : 0.0f;
}

inline int is_dielectric(const vct_material_desc *m) {
    return m->specular.w > 0.0f;
}

/* A glossy lobe of probability pg that is an ideal mirror. */
inline int mirror_lobe(const vct_material_desc *m, float pg) {
    return pg > 0.0f && m->emission.w < VCT_MIRROR_ROUGHNESS;
}

inline int is_mirror(const vct_material_desc *m) {
    return mirror_lobe(m, glossy_probability(m));
}

/* Only delta lobes (glass, a pure mirror): nothing for next-event
 * estimation or a density estimate to see. */
inline int bsdf_delta_only(const vct_material_desc *m) {
    return is_dielectric(m) || (is_mirror(m) && glossy_probability(m) >= 1.0f);
}

/* x^y for x in [0, 1] and y > 0 as exp2(y log2 x): pow's special cases
 * cost the path tracer on the heavy scene about 3 % of its time on PoCL. */
inline float pow_unit(float x, float y) {
    return x > 0.0f ? exp2(y * log2(x)) : 0.0f;
}

/* f(wo, wi) cos(wi) and the pdf of sampling wi, for the non-delta lobes. */
inline float3 bsdf_eval(const vct_material_desc *m, float3 n, float3 wo, float3 wi, float *pdf) {
    const float cos_i = dot(n, wi);
    *pdf = 0.0f;
    if (cos_i <= 0.0f || is_dielectric(m))
        return (float3)(0.0f);
    const float pg = glossy_probability(m);
    float3 f = diffuse_color(m) * (cos_i / BSDF_PI);
    float pdf_d = cos_i / BSDF_PI, pdf_g = 0.0f;
    if (pg > 0.0f && !mirror_lobe(m, pg)) {
        const float e = phong_exponent(m->emission.w);
        const float ca = fmax(dot(reflect_dir(wo, n), wi), 0.0f);
        const float lobe = pow_unit(ca, e) * (e + 1.0f) / (2.0f * BSDF_PI);
        pdf_g = lobe;
        f += glossy_color(m) * (lobe * (e + 2.0f) / (e + 1.0f)) * cos_i;
    }
    *pdf = (1.0f - pg) * pdf_d + pg * pdf_g;
    return f;
}

inline float fresnel_dielectric(float cos_i, float eta) {
    const float sin2_t = eta * eta * fmax(0.0f, 1.0f - cos_i * cos_i);
    if (sin2_t >= 1.0f)
        return 1.0f; /* total internal reflection */
    const float cos_t = sqrt(1.0f - sin2_t);
    const float rs = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    const float rp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return 0.5f * (rs * rs + rp * rp);
}

/* Cosine-weighted direction (u1, u2) about unit n in the frame (t, b):
 * the unit disc's point at radius sqrt(u1) and turn u2 lifted onto the
 * hemisphere (Malley's method). Unit already in an orthonormal frame. */
inline float3 cosine_dir(float3 n, float3 t, float3 b, float u1, float u2) {
    const float r = sqrt(u1), cos_i = sqrt(fmax(0.0f, 1.0f - u1));
    const float2 cs = turn_cos_sin(u2);
    return r * cs.x * t + r * cs.y * b + cos_i * n;
}

#ifdef VCT_PACKETS
/* The Lambert branch of bsdf_sample_dir in vector lanes (where rays go in
 * packets): basis_of, cosine_dir and the pdf with the same operations in
 * the same order, so each lane's direction (wx, wy, wz) and returned pdf are
 * the scalar branch's bit for bit. */
inline float16 bsdf_lambert16(float16 nx, float16 ny, float16 nz, float16 u1, float16 u2,
                              float16 *wx, float16 *wy, float16 *wz) {
    const float16 s = select((float16)(-1.0f), (float16)(1.0f), nz >= 0.0f);
    const float16 a = -1.0f / (s + nz);
    const float16 c = nx * ny * a;
    const float16 tx = 1.0f + s * nx * nx * a, ty = s * c, tz = -s * nx;
    const float16 bx = c, by = s + ny * ny * a, bz = -ny;
    const float16 r = sqrt(u1), cos_i = sqrt(fmax(0.0f, 1.0f - u1));
    float16 cs_x, cs_y;
    turn_cos_sin16(u2, &cs_x, &cs_y);
    *wx = r * cs_x * tx + r * cs_y * bx + cos_i * nx;
    *wy = r * cs_x * ty + r * cs_y * by + cos_i * ny;
    *wz = r * cs_x * tz + r * cs_y * bz + cos_i * nz;
    return cos_i / BSDF_PI;
}
#endif

/* front: the ray arrived on the side the geometric normal points to. */
inline int bsdf_sample_dir(const vct_material_desc *m, float3 n, float3 wo, int front, float u0,
                           float u1, float u2, bsdf_sample *s) {
    s->delta = 0;
    if (is_dielectric(m)) {
        const float ior = fmax(m->extra.x, 1.0001f);
        const float eta = front ? 1.0f / ior : ior; /* n_incident / n_transmitted */
        const float cos_i = fmin(dot(n, wo), 1.0f);
        const float F = fresnel_dielectric(cos_i, eta);
        s->delta = 1;
        s->pdf = 0.0f;
        if (u0 < F) {
            s->wi = reflect_dir(wo, n);
            s->weight = (float3)(1.0f);
        } else {
            const float sin2_t = eta * eta * fmax(0.0f, 1.0f - cos_i * cos_i);
            const float cos_t = sqrt(fmax(0.0f, 1.0f - sin2_t));
            s->wi = normalize(-eta * wo + (eta * cos_i - cos_t) * n);
            s->weight = m->albedo.xyz; /* transmitted tint */
        }
        return 1;
    }
    const float pg = glossy_probability(m);
    const int mirror = mirror_lobe(m, pg);
    if (mirror) {
        /* A mirror may still have a diffuse part: choose the lobe. */
        if (u0 < pg) {
            s->wi = reflect_dir(wo, n);
            s->weight = glossy_color(m) / pg;
            s->pdf = 0.0f;
            s->delta = 1;
            return dot(s->wi, n) > 0.0f;
        }
        u0 = (u0 - pg) / (1.0f - pg);
    }
    float3 t, b;
    if (pg > 0.0f && !mirror && u0 < pg) {
        const float e = phong_exponent(m->emission.w);
        const float3 r = reflect_dir(wo, n);
        basis_of(r, &t, &b);
        const float ct = pow_unit(u1, 1.0f / (e + 1.0f)), st = sqrt(fmax(0.0f, 1.0f - ct * ct));
        const float2 cs = turn_cos_sin(u2);
        s->wi = normalize(st * cs.x * t + st * cs.y * b + ct * r);
    } else {
        basis_of(n, &t, &b);
        const float cos_i = sqrt(fmax(0.0f, 1.0f - u1));
        /* unit already: no normalize, which cost the path tracer about 3 %
         * on PoCL */
        s->wi = cosine_dir(n, t, b, u1, u2);
        if (!(pg > 0.0f)) { /* Lambert alone: f cos / pdf is the albedo */
            s->pdf = cos_i / BSDF_PI;
            s->weight = diffuse_color(m);
            return s->pdf > 0.0f;
        }
    }
    float pdf;
    const float3 fc = bsdf_eval(m, n, wo, s->wi, &pdf);
    if (!(pdf > 0.0f))
        return 0;
    s->pdf = pdf;
    s->weight = fc / pdf;
    return 1;
}

#endif
