/* The gather's second way to aim its rays: at voxels picked by their
 * direct light.
 *
 * A small bright patch (the ceiling a hand above a point light, the floor
 * under a lamp shade's opening) sends much of the light a wall gathers, and
 * few of the rays spread by the cosine meet it: the light arrived as single
 * bright pixels that the indirect filter turned into blotches (a living
 * room lit by a point light 0.2 below its ceiling: 0.097 NRMSE unfiltered
 * with 81 rays, 0.086 with 144 at every pixel; 0.062 with 81 and 18
 * picks). So each gather point also picks leaf voxels in proportion to
 * their direct light (the running sum `cdf` of gather_pick_weights in
 * vct_render.cl, where a scene has such a patch) and aims a ray at each,
 * uniformly within the cone of the sphere around the voxel's cube; the ray
 * counts where its first hit lies in the voxel it was aimed at. The two
 * ways are weighed by the power heuristic (multiple importance sampling,
 * exponent 2), so that the gather still estimates the cosine-weighted mean
 * of the light around it, for m rays by the cosine, k picks and p the
 * picks' density in a direction (pick_density): a ray by the cosine adds
 * its light times c^2 / (c^2 + q^2), a pick c q / (c^2 + q^2), over m, with
 * c = m cos / pi and q = k p (gather_mis, diffuse_rays.h). The balance
 * heuristic let the picks' noise in where they match the light poorly
 * (every voxel at least 1/64 as bright as the brightest picked, the
 * Cornell box unfiltered: 0.0376 NRMSE, 0.0334 by the power heuristic,
 * 0.0316 without picks). A voxel within two of its sphere's radius of the
 * point is never picked; the cosine's rays alone see it. */
#ifndef VCT_GATHER_PICKS_H
#define VCT_GATHER_PICKS_H

#include "scene/bsdf.h" /* basis_of */
#include "scene/rng.h"
#include "scene/turn.h"
#include "voxel/octree.h"
#include "vct_types.h"

/* The voxels' running sum of pick weights, inclusive, per leaf voxel
 * (`count` of them, summing to `total`; 0: no picks) and their keys. */
typedef struct gather_picks {
    __global const uint *cdf;
    __global const uint *keys;
    uint count, total;
} gather_picks;

/* The leaf voxel holding the hit t along unit d from `from`: the point a
 * quarter voxel back (less where t is shorter), which lies on the ray and
 * in the voxel the hit's light is read from (gather_surface_voxel); OCT_NULL
 * where none holds it. */
inline uint pick_voxel_of(__global const uint *child, const vct_cone_desc *c, float3 from, float3 d,
                          float t) {
    const float voxel = c->volume.w / (float)c->res.x;
    const float3 q = from + d * (t - fmin(0.25f * voxel, 0.5f * t));
    const float3 at = (q - c->volume.xyz) * c->ambient.w;
    if (any(at < 0.0f) || any(at >= 1.0f))
        return OCT_NULL;
    return octree_leaf_voxel(child, convert_uint3_rtz(at * (float)c->res.x), c->res.y);
}

/* The solid angle of the sphere around the cube of the voxel of Morton
 * key `key`, seen from p, with its axis and the cosine of its half angle;
 * 0 where p lies within two of its radius. */
inline float pick_cone(const vct_cone_desc *c, uint key, float3 p, float3 *axis, float *cos_max) {
    const float voxel = c->volume.w / (float)c->res.x;
    const float3 centre = c->volume.xyz + (convert_float3(morton_decode(key)) + 0.5f) * voxel;
    const float3 to = centre - p;
    const float d2 = dot(to, to), r2 = 0.75f * voxel * voxel;
    if (!(d2 > 4.0f * r2))
        return 0.0f;
    *axis = to * rsqrt(d2);
    const float sin2 = r2 / d2;
    *cos_max = sqrt(1.0f - sin2);
    /* 2 pi (1 - cos), without the cancellation */
    return 6.28318530718f * sin2 / (1.0f + *cos_max);
}

/* The picks' density (per steradian, per pick) in a direction whose first
 * hit lies in leaf voxel v, seen from p. */
inline float pick_density(const gather_picks *gp, const vct_cone_desc *c, uint v, float3 p) {
    if (gp->count == 0u || v == OCT_NULL)
        return 0.0f;
    const uint weight = gp->cdf[v] - (v > 0u ? gp->cdf[v - 1u] : 0u);
    if (weight == 0u)
        return 0.0f;
    float3 axis;
    float cos_max;
    const float omega = pick_cone(c, gp->keys[v], p, &axis, &cos_max);
    return omega > 0.0f ? (float)weight / ((float)gp->total * omega) : 0.0f;
}

/* The first voxel in [lo, hi) whose running sum exceeds target (hi - 1 if
 * none does). */
inline uint pick_search(__global const uint *cdf, uint lo, uint hi, uint target) {
    --hi;
    while (lo < hi) {
        const uint mid = (lo + hi) / 2u;
        if (cdf[mid] > target)
            hi = mid;
        else
            lo = mid + 1u;
    }
    return lo;
}

/* The first voxel in [lo, hi) whose key is at least `key` (hi if none). */
inline uint pick_key_search(__global const uint *keys, uint lo, uint hi, uint key) {
    while (lo < hi) {
        const uint mid = (lo + hi) / 2u;
        if (keys[mid] >= key)
            hi = mid;
        else
            lo = mid + 1u;
    }
    return lo;
}

/* A block of PICK_BLOCK_BITS low Morton bits: 8^3 voxels, which lie
 * together in the sorted voxels. */
#define PICK_BLOCK_BITS 9u

/* Pick i of k from stream `seed`, each voxel by its weight's share of the
 * total: first a block (stratified over the running sum: the block of the
 * voxel whose sum first exceeds the pick's share of the total), then a
 * voxel in it by its share of the block's weight. A voxel whose light
 * changes (a moving object's, a wall's wound the other way) moves the
 * running sum beyond it, and with one search every pick beyond it would
 * land on another voxel, the whole image's noise changing; by blocks only
 * the picks near a block's border move. */
inline uint pick_find(const gather_picks *gp, uint i, uint k, uint seed) {
    const uint s1 = rng_hash(seed), s2 = rng_hash(s1 ^ 0x2c1b3c6du);
    const ulong at = (((ulong)i << 32) + (ulong)s1) / (ulong)k; /* < 2^32 */
    const uint v = pick_search(gp->cdf, 0u, gp->count, (uint)((at * (ulong)gp->total) >> 32));
    const uint block = gp->keys[v] >> PICK_BLOCK_BITS;
    const uint lo = pick_key_search(gp->keys, 0u, v, block << PICK_BLOCK_BITS),
               hi = pick_key_search(gp->keys, v + 1u, gp->count, (block + 1u) << PICK_BLOCK_BITS);
    const uint before = lo > 0u ? gp->cdf[lo - 1u] : 0u, weight = gp->cdf[hi - 1u] - before;
    return pick_search(gp->cdf, lo, hi, before + (uint)(((ulong)s2 * (ulong)weight) >> 32));
}

/* The direction of pick i of k from p, uniform in its voxel's cone, in *v
 * the voxel; 0 where the voxel lies too near p. */
inline float3 pick_dir(const gather_picks *gp, const vct_cone_desc *c, float3 p, uint i, uint k,
                       uint seed, uint *v) {
    *v = pick_find(gp, i, k, seed);
    float3 axis, t, b;
    float cos_max;
    const float omega = pick_cone(c, gp->keys[*v], p, &axis, &cos_max);
    if (!(omega > 0.0f))
        return (float3)(0.0f);
    const uint s1 = rng_hash(seed ^ 0x68e31da4u), s2 = rng_hash(s1);
    /* 1 - cos theta, uniform in [0, 1 - cos_max): from the solid angle, as
     * 1 - cos_max itself cancels to 0 for a voxel far away */
    const float below = (float)(s1 >> 8) * (1.0f / 16777216.0f) * (omega * (1.0f / 6.28318530718f));
    const float cos_theta = 1.0f - below;
    const float sin_theta = sqrt(fmax(below * (2.0f - below), 0.0f));
    const float2 cs = turn_cos_sin((float)(s2 >> 8) * (1.0f / 16777216.0f));
    basis_of(axis, &t, &b);
    return normalize(cos_theta * axis + sin_theta * (cs.x * t + cs.y * b));
}

#endif
