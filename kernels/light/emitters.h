/* Emissive triangles as lights for the methods that take direct light in
 * one pass (ray casting, cone tracing's primary hit, light injection): at a
 * shading point, `samples` samples stratified over the emitters' CDF (picked
 * by power), each a point uniform on its triangle, seen through a shadow
 * ray. A sample's weight is Le cos_l / d^2 times the emitter's area over its
 * pick probability (emitter_scale); emitters are two-sided. The sample
 * stream is keyed by the caller's seed (pixel or voxel), so an image is the
 * same bit for bit on every run.
 *
 * Near an emitter (a lamp panel a centimetre under a ceiling) that weight's
 * 1 / d^2 is heavy-tailed: a few samples almost always miss the close part
 * that holds most of the light, and the mean of a pixel's samples falls far
 * short. So direct_emitters_part takes the unoccluded light of a near
 * triangle from Lambert's formula, exactly, and only its visibility from the
 * shadow rays: the ratio of the seen samples' weight to all samples' weight
 * (Heitz et al. 2018, "Combining analytic direct illumination and
 * stochastic shadows"). Far triangles keep the point weight, whose mean the
 * ratio then leaves as it was. */
#ifndef VCT_EMITTERS_H
#define VCT_EMITTERS_H

#include "accel/accel.h"
#include "light/direct_light.h"
#include "scene/angle.h"
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

/* The emitter whose CDF interval holds u: the first whose CDF exceeds u
 * (the last if none does). A search whose steps depend on the count alone,
 * each a conditional move: a binary search's branches on the CDF went
 * wrong half the time, a third of the path tracer's emitter sampling. */
inline uint emitter_pick(const emitter_view *e, float u) {
    uint base = 0u, n = e->count;
    while (n > 1u) {
        const uint step = n / 2u;
        base = e->cdf[base + step] <= u ? base + step : base;
        n -= step;
    }
    return min(base + (e->cdf[base] <= u ? 1u : 0u), e->count - 1u);
}

/* Which emitter sample s of stream `seed` picks (stratified over the CDF). */
inline uint emitter_index(const emitter_view *e, uint seed, uint s) {
    uint jitter = rng_start(seed, s + 1u, 0x5a17e3u);
    const float u0 = ((float)s + rng_next(&jitter)) / (float)e->samples;
    return emitter_pick(e, fmin(u0, 0.99999994f));
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
    const uint i = emitter_index(e, seed, s);
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

/* A triangle is near where it spans more than this share of its distance:
 * there Lambert's formula replaces the point weight. Farther, its sum of
 * nearly cancelling edge terms loses float digits that the point weight,
 * almost constant over the triangle there, does not need. */
#define EMITTER_NEAR_SPAN 0.1f
/* Vertices within this share of their distance of p's plane lie in it. */
#define EMITTER_IN_PLANE 1e-4f

/* Lambert's formula: the irradiance at p (unit normal n) from triangle
 * (a, b, c) of unit radiance, unoccluded and two-sided: half the magnitude
 * of the sum, over the edges of its part above p's horizon, of each edge's
 * angle at p times the cosine between n and the plane through p and it. */
inline float emitter_irradiance(float3 p, float3 n, float3 a, float3 b, float3 c) {
    const float3 v[3] = {a - p, b - p, c - p};
    /* A triangle in p's own plane (an emitter inlaid in a floor, or the
     * emitter p lies on) sends nothing: the sum would count its angles. */
    const float reach = fmax(fmax(length(v[0]), length(v[1])), length(v[2]));
    const float rise = fmax(fmax(dot(n, v[0]), dot(n, v[1])), dot(n, v[2]));
    if (!(rise > EMITTER_IN_PLANE * reach))
        return 0.0f;
    float3 poly[4];
    uint count = 0u;
    for (uint k = 0u; k < 3u; ++k) {
        const float3 from = v[k], to = v[k == 2u ? 0u : k + 1u];
        const float h_from = dot(n, from), h_to = dot(n, to);
        if (h_from >= 0.0f)
            poly[count++] = from;
        if ((h_from >= 0.0f) != (h_to >= 0.0f))
            poly[count++] = from + (h_from / (h_from - h_to)) * (to - from);
    }
    float sum = 0.0f;
    for (uint k = 0u; k < count; ++k) {
        const float3 from = poly[k], to = poly[k + 1u == count ? 0u : k + 1u];
        if (!(dot(from, from) > 0.0f) || !(dot(to, to) > 0.0f))
            return 0.0f; /* p on a corner: a point of no area */
        const float3 u = normalize(from), w = normalize(to), cr = cross(u, w);
        const float s = length(cr);
        if (s > 0.0f)
            sum += angle_of(s, dot(u, w)) * (dot(n, cr) / s);
    }
    return 0.5f * fabs(sum);
}

/* Whether triangle (a, b, c) is near p. */
inline int emitter_is_near(float3 p, float3 a, float3 b, float3 c) {
    const float span = fmax(fmax(distance(a, b), distance(b, c)), distance(c, a));
    const float3 to = (a + b + c) * (1.0f / 3.0f) - p;
    return span * span >= EMITTER_NEAR_SPAN * EMITTER_NEAR_SPAN * dot(to, to);
}

/* Emitter triangle tri's unoccluded irradiance at p if it is near p (-1 if
 * not), and its area. */
inline float3 emitter_near_light(const accel_view *g, __global const vct_material_desc *materials,
                                 __global const uint *tri_material, uint tri, float3 p, float3 n,
                                 float *area) {
    float3 a, b, c;
    emitter_vertices(g, tri, &a, &b, &c);
    *area = 0.5f * length(cross(b - a, c - a));
    if (!emitter_is_near(p, a, b, c))
        return (float3)(-1.0f);
    if (!(*area > 0.0f))
        return (float3)(0.0f); /* a sliver of no area sends nothing */
    return materials[tri_material[tri]].emission.xyz * emitter_irradiance(p, n, a, b, c);
}

/* Scenes of at most this many emitter triangles (a quad lamp or a few) sum
 * every near triangle's light at each point instead of taking it from the
 * samples' picks: the picks' noise is then gone where it was worst. */
#define EMITTER_EXACT_MAX 16u

/* The unoccluded light of every near emitter triangle at p. */
inline float3 emitters_near_sum(const emitter_view *e, const accel_view *g,
                                __global const vct_material_desc *materials,
                                __global const uint *tri_material, float3 p, float3 n) {
    float3 total = (float3)(0.0f);
    for (uint i = 0u; i < e->count; ++i) {
        float area;
        const float3 near = emitter_near_light(g, materials, tri_material, e->tris[i], p, n, &area);
        if (near.x >= 0.0f)
            total += near;
    }
    return total;
}

/* Adds the emitters' light at p (normal n facing the viewer) to `sum`, as
 * direct_gather adds a punctual light's: the irradiance, and the Phong lobe
 * of exponent e about r when e >= 0. Only samples first, first + stride, ...
 * of the stream: the rays of one pixel share its stream that way, each
 * taking its part (the pixel's mean is then the whole stratified sum).
 * The irradiance is the samples' unoccluded light (near triangles' exact)
 * times the share of their point weight that the shadow rays see; the lobe
 * takes the point weights of the seen samples. sum->emitter_variance gains
 * the variance of the irradiance's luminance by that share's spread. */
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
    const int exact = e->count <= EMITTER_EXACT_MAX;
    const float3 common =
        exact ? emitters_near_sum(e, g, materials, tri_material, p, n) / inv : (float3)(0.0f);
    /* per half of the samples (every other one): their part of the
     * unoccluded light, their point weight and the weight seen */
    float3 part[2] = {(float3)(0.0f), (float3)(0.0f)};
    float weight[2] = {0.0f, 0.0f}, weight_seen[2] = {0.0f, 0.0f};
    uint which = 1u;
    for (uint s = first; s < e->samples; s += stride) {
        which ^= 1u;
        float3 q;
        uint tri;
        const float3 radiant = emitter_sample(e, g, materials, tri_material, p, seed, s, &q, &tri);
        const float3 wi = normalize(q - p);
        const float cos_theta = dot(n, wi);
        const int facing = cos_theta > 0.0f && any(radiant != 0.0f);
        int is_near;
        if (exact) { /* its light is in the sum already */
            float3 a, b, c;
            emitter_vertices(g, tri, &a, &b, &c);
            is_near = emitter_is_near(p, a, b, c);
        } else {
            float area;
            const float3 near = emitter_near_light(g, materials, tri_material, tri, p, n, &area);
            is_near = near.x >= 0.0f;
            if (is_near && area > 0.0f) /* over the pick's probability */
                part[which] += near * (e->scale[emitter_index(e, seed, s)] / area);
        }
        if (!facing)
            continue;
        const float3 point = radiant * cos_theta;
        const float w = point.x + point.y + point.z;
        if (!is_near)
            part[which] += point;
        weight[which] += w;
        ++sum->emitters_facing;
        if (!emitter_visible(g, o, q))
            continue;
        ++sum->emitters_seen;
        weight_seen[which] += w;
        direct_add_lobe(sum, radiant * inv, cos_theta, wi, r, exponent);
    }
    const float all = weight[0] + weight[1];
    if (all > 0.0f)
        sum->irradiance +=
            (common + part[0] + part[1]) * (inv * ((weight_seen[0] + weight_seen[1]) / all));
    /* the variance of that by the halves' difference (each half an estimate
     * of its own, stratified as the whole is): the mean of two estimates
     * a and b varies by (a - b)^2 / 4 */
    if (weight[0] > 0.0f && weight[1] > 0.0f) {
        const float3 w = (float3)(0.2126f, 0.7152f, 0.0722f);
        const float a = dot(common + 2.0f * part[0], w) * weight_seen[0] / weight[0],
                    b = dot(common + 2.0f * part[1], w) * weight_seen[1] / weight[1];
        sum->emitter_variance += 0.25f * (a - b) * (a - b) * inv * inv;
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
