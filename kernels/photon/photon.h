/* Photons and the photon grid (seed 000's scheme): what a stored photon
 * holds, which map it belongs to, the grid's cell keys and the radius
 * search that every estimate makes.
 *
 * A photon is 3 float4: (position, n.x), (direction it came from, n.y),
 * (power, n.z), n the surface normal on the side it arrived from. Its power
 * is not divided by the photon count: estimates divide by the photons
 * emitted.
 *
 * The grid: cells of edge `cell` from `origin`. Dense (mask 0): key = the
 * cell's linear index over dims. Hashed (mask = table size - 1, a power of
 * two): key = a hash of the cell's coordinates; a search then keeps only
 * the photons of the cell it visits, since a bucket may hold several cells. */
#ifndef VCT_PHOTON_H
#define VCT_PHOTON_H

#include "scene/bsdf.h"
#include "scene/rng.h"
#include "vct_types.h"

/* Map kinds, as bits so that a grid takes any set of them. */
#define PHOTON_DIRECT 1u   /* first hit from a light (read by final gathering, the seed's mode) */
#define PHOTON_INDIRECT 2u /* after a diffuse or glossy bounce: the global map */
#define PHOTON_CAUSTIC 4u  /* a specular bounce since the last diffuse one: the caustic map */
/* Also set on a caustic photon whose specular bounces met a dielectric
 * (cone tracing's caustics: light through glass, which its voxels cannot
 * carry; mirrors' light they carry already). */
#define PHOTON_DIELECTRIC 8u

/* Estimate flags. */
#define PHOTON_EPANECHNIKOV 1u /* 2 (1 - d^2 / r^2) instead of the box's 1 */
#define PHOTON_RAW 2u          /* power alone: no BSDF, no normal filter (tests) */

#define PHOTON_GRID_ARGS(m)                                                                        \
    __global const float4 *m##_photons, __global const uint2 *m##_ranges, float4 m##_origin,       \
        uint4 m##_dims
#define PHOTON_GRID_VIEW(m) ((photon_grid){m##_photons, m##_ranges, m##_origin, m##_dims})

typedef struct photon_grid {
    __global const float4 *photons; /* sorted by key, 3 float4 each */
    __global const uint2 *ranges;   /* per key: [first, end) */
    float4 origin;                  /* w: cell edge */
    uint4 dims;                     /* w: hash mask, 0 for a dense grid */
} photon_grid;

inline int3 photon_cell_of(float4 origin, float3 p) {
    return convert_int3_rtn((p - origin.xyz) / origin.w);
}

/* The key of cell c; 0xffffffff when a dense grid has no such cell. */
inline uint photon_cell_key(float4 origin, uint4 dims, int3 c) {
    if (dims.w != 0u) {
        const uint h = ((uint)c.x * 73856093u) ^ ((uint)c.y * 19349663u) ^ ((uint)c.z * 83492791u);
        return rng_hash(h) & dims.w;
    }
    if (any(c < 0) || c.x >= (int)dims.x || c.y >= (int)dims.y || c.z >= (int)dims.z)
        return 0xffffffffu;
    return ((uint)c.z * dims.y + (uint)c.y) * dims.x + (uint)c.x;
}

/* The sum over the photons within r of p of weight * power * f(wo, wi)
 * (f of the material at p, normal n facing wo), photons whose normal's
 * cosine with n is below normal_cos rejected; *found counts them. The
 * cells visited reach r whatever the cell size. */
inline float3 photon_estimate(const photon_grid *g, float3 p, float3 n, float3 wo, float r,
                              const vct_material_desc *m, uint flags, float normal_cos,
                              uint *found) {
    float3 sum = (float3)(0.0f);
    *found = 0u;
    if (!(r > 0.0f))
        return sum;
    const float r2 = r * r, inv_r2 = 1.0f / r2;
    const int reach = max(1, (int)ceil(r / g->origin.w));
    const int3 c0 = photon_cell_of(g->origin, p);
    for (int dz = -reach; dz <= reach; ++dz)
        for (int dy = -reach; dy <= reach; ++dy)
            for (int dx = -reach; dx <= reach; ++dx) {
                const int3 c = c0 + (int3)(dx, dy, dz);
                const uint key = photon_cell_key(g->origin, g->dims, c);
                if (key == 0xffffffffu)
                    continue;
                const uint2 range = g->ranges[key];
                for (uint j = range.x; j < range.y; ++j) {
                    const float4 a = g->photons[3u * j], b = g->photons[3u * j + 1u];
                    const float3 d = a.xyz - p;
                    const float d2 = dot(d, d);
                    if (d2 > r2)
                        continue;
                    if (g->dims.w != 0u && any(photon_cell_of(g->origin, a.xyz) != c))
                        continue; /* another cell of the same bucket */
                    const float4 e = g->photons[3u * j + 2u];
                    float3 f = (float3)(1.0f);
                    if (!(flags & PHOTON_RAW)) {
                        if (dot((float3)(a.w, b.w, e.w), n) < normal_cos)
                            continue;
                        const float cos_i = dot(n, b.xyz);
                        if (!(cos_i > 0.0f))
                            continue;
                        float pdf;
                        f = bsdf_eval(m, n, wo, b.xyz, &pdf) / cos_i;
                    }
                    const float w =
                        (flags & PHOTON_EPANECHNIKOV) ? 2.0f * (1.0f - d2 * inv_r2) : 1.0f;
                    sum += e.xyz * f * w;
                    ++*found;
                }
            }
    return sum;
}

#endif
