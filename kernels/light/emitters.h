/* Emissive triangles as lights for the methods that take direct light in
 * one pass (ray casting, cone tracing's primary hit, light injection): at a
 * shading point, `samples` samples stratified over the emitters' CDF (picked
 * by power), each a point uniform on its triangle, seen through a shadow
 * ray. A sample's weight is Le cos_l / d^2 times the emitter's area over its
 * pick probability (emitter_scale); emitters are two-sided. The sample
 * stream is keyed by the caller's seed (pixel or voxel), so an image is the
 * same bit for bit on every run. */
#ifndef VCT_EMITTERS_H
#define VCT_EMITTERS_H

#include "accel/accel.h"
#include "light/direct_light.h"
#include "scene/rng.h"
#include "vct_types.h"

#define EMITTER_ARGS                                                                               \
    __global const uint *emitter_tris, __global const float *emitter_cdf,                          \
        __global const float *emitter_scale, uint emitter_count, uint emitter_samples
#define EMITTER_VIEW()                                                                             \
    ((emitter_view){emitter_tris, emitter_cdf, emitter_scale, emitter_count, emitter_samples})

typedef struct emitter_view {
    __global const uint *tris;
    __global const float *cdf;
    __global const float *scale;
    uint count, samples;
} emitter_view;

/* Triangle t's vertices in lexicographic order of position: a sample at
 * given barycentrics lands on the same point whichever way t is wound. */
inline void emitter_vertices(const accel_view *g, uint t, float3 *a, float3 *b, float3 *c) {
    float3 v[3] = {g->tri_vertices[3u * t].xyz, g->tri_vertices[3u * t + 1u].xyz,
                   g->tri_vertices[3u * t + 2u].xyz};
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2 - i; ++j) {
            const float3 p = v[j], q = v[j + 1];
            const int after = p.x != q.x ? p.x > q.x : p.y != q.y ? p.y > q.y : p.z > q.z;
            if (after) {
                v[j] = q;
                v[j + 1] = p;
            }
        }
    *a = v[0];
    *b = v[1];
    *c = v[2];
}

/* The emitter whose CDF interval holds u. */
inline uint emitter_pick(const emitter_view *e, float u) {
    uint lo = 0, hi = e->count - 1;
    while (lo < hi) {
        const uint mid = (lo + hi) / 2;
        if (e->cdf[mid] <= u)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

/* Sample s of stream `seed`: an emitter point *q, the emitter's triangle in
 * *tri, and the sample's weight before the receiver's cosine and 1 /
 * samples: Le cos_l / d^2 * scale, seen from p (0 when edge-on). */
inline float3 emitter_sample(const emitter_view *e, const accel_view *g,
                             __global const vct_material_desc *materials,
                             __global const uint *tri_material, float3 p, uint seed, uint s,
                             float3 *q, uint *tri) {
    /* The pick stratified over the CDF; the point from the R2 sequence
     * (Roberts 2018: additive recurrence on the plastic number), shifted per
     * stream, which covers the triangle more evenly than independent points. */
    uint rng = rng_start(seed, 0u, 0x5a17e3u);
    const float shift_u = rng_next(&rng), shift_v = rng_next(&rng);
    uint jitter = rng_start(seed, s + 1u, 0x5a17e3u);
    const float u0 = ((float)s + rng_next(&jitter)) / (float)e->samples;
    const uint i = emitter_pick(e, fmin(u0, 0.99999994f));
    float u = shift_u + 0.75487767f * (float)s, v = shift_v + 0.56984029f * (float)s;
    u -= floor(u);
    v -= floor(v);
    if (u + v > 1.0f) {
        u = 1.0f - u;
        v = 1.0f - v;
    }
    *tri = e->tris[i];
    float3 a, b, c;
    emitter_vertices(g, *tri, &a, &b, &c);
    *q = a + u * (b - a) + v * (c - a);
    const float3 to = *q - p;
    const float d2 = dot(to, to);
    const float3 nl = normalize(cross(b - a, c - a));
    const float cos_l = fabs(dot(nl, to)) * rsqrt(d2);
    if (!(d2 > 0.0f) || !(cos_l > 0.0f))
        return (float3)(0.0f);
    return materials[tri_material[*tri]].emission.xyz * (cos_l / d2 * e->scale[i]);
}

/* 1 if nothing blocks the segment from o to emitter point q (ending short of
 * q by its surface epsilon, so that the emitter itself does not block it). */
inline int emitter_visible(const accel_view *g, float3 o, float3 q) {
    const float3 to = q - o;
    const float dist = length(to);
    hit_record h;
    return !accel_trace(g, o, to / dist, 0.0f, dist - 2.0f * surface_epsilon(g, q), 1, &h);
}

/* Adds the emitters' light at p (normal n facing the viewer) to `sum`, as
 * direct_gather adds a punctual light's: the irradiance, and the Phong lobe
 * of exponent e about r when e >= 0. Only samples first, first + stride, ...
 * of the stream: the rays of one pixel share its stream that way, each
 * taking its part (the pixel's mean is then the whole stratified sum). */
inline void direct_emitters_part(const accel_view *g, const emitter_view *e,
                                 __global const vct_material_desc *materials,
                                 __global const uint *tri_material, float3 p, float3 n, float3 r,
                                 float exponent, uint seed, uint first, uint stride,
                                 direct_terms *sum) {
    if (e->count == 0u)
        return;
    first %= e->samples;
    const float3 o = p + n * surface_epsilon(g, p);
    const float inv = 1.0f / (float)((e->samples - first + stride - 1u) / stride);
    for (uint s = first; s < e->samples; s += stride) {
        float3 q;
        uint tri;
        const float3 radiant = emitter_sample(e, g, materials, tri_material, p, seed, s, &q, &tri);
        const float3 wi = normalize(q - p);
        const float cos_theta = dot(n, wi);
        if (!(cos_theta > 0.0f) || all(radiant == 0.0f))
            continue;
        ++sum->emitters_facing;
        if (!emitter_visible(g, o, q))
            continue;
        ++sum->emitters_seen;
        direct_add(sum, radiant * inv, cos_theta, wi, r, exponent, 1.0f);
    }
}

/* All of the stream's samples. */
inline void direct_emitters(const accel_view *g, const emitter_view *e,
                            __global const vct_material_desc *materials,
                            __global const uint *tri_material, float3 p, float3 n, float3 r,
                            float exponent, uint seed, direct_terms *sum) {
    direct_emitters_part(g, e, materials, tri_material, p, n, r, exponent, seed, 0u, 1u, sum);
}

#endif
