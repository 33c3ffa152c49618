/* A fragment's albedo: the mean of its material's (textured) albedo over
 * the part of its triangle inside the voxel, not one texel. A square of
 * FRAGMENT_ALBEDO_SIDE^2 stratified points about the voxel's centre, in the
 * triangle's plane, is projected onto the plane; the points that land inside
 * both the triangle and the voxel are read. A fragment that none lands on
 * (a sliver through a corner) reads the point nearest the centre. With an
 * alpha mask (accel/alpha_mask.h), only the points the mask keeps count for
 * the albedo, and how many of them it keeps is the fragment's coverage. */
#ifndef VCT_FRAGMENT_ALBEDO_H
#define VCT_FRAGMENT_ALBEDO_H

#include "accel/tri_nearest.h"
#include "scene/bsdf.h"
#include "scene/texture.h"
#include "scene/tri_normal.h"
#include "vct_types.h"

/* 4: the textured room's voxelization and light injection both read these
 * points, and 8 x 8 of them took 214 + 230 ms of its 820 ms at 128^3 on two
 * CPU cores; 4 x 4 took 61 + 69 ms for the same NRMSE (0.0556). Voxels are
 * seen only through cones, whose samples average many of them. */
#define FRAGMENT_ALBEDO_SIDE 4

/* Whether m's mask keeps its surface where the texture reads `texel`. */
inline int fragment_kept(const vct_material_desc *m, float4 texel) {
    return !(texel.w < m->extra.w);
}

/* The sum of m's albedo over the samples of triangle tri that land inside
 * it and the voxel and that its mask keeps, their count in *inside, and the
 * share of the samples inside the mask keeps in *coverage; where none lands
 * inside, the albedo at the triangle's point nearest the centre, with
 * *inside 0 and *coverage whether the mask keeps that point. */
inline float3 fragment_albedo_sum(const texture_view *tv, const vct_material_desc *m, uint tri,
                                  float3 a, float3 b, float3 c, float3 centre, float voxel,
                                  uint *inside, float *coverage) {
    *inside = 0u;
    const float3 cr = tri_normal(a, b, c);
    const float len = length(cr);
    const uint texture = (uint)m->extra.y;
    if (texture == 0u || !(len > 0.0f)) {
        *coverage = fragment_kept(m, (float4)(1.0f)) ? 1.0f : 0.0f;
        return m->albedo.xyz;
    }
    /* the plane's frame from its normal turned one fixed way, so that the
     * samples do not depend on the winding */
    const float3 n = axis_canonical(cr / len);
    float3 t1, t2;
    basis_of(n, &t1, &t2);
    const float3 on_plane = centre - n * dot(centre - a, n);
    const float half_voxel = 0.5f * voxel * (1.0f + 1e-5f);
    float3 sum = (float3)(0.0f);
    uint landed = 0u;
    for (int j = 0; j < FRAGMENT_ALBEDO_SIDE; ++j)
        for (int i = 0; i < FRAGMENT_ALBEDO_SIDE; ++i) {
            const float s = ((float)i + 0.5f) / FRAGMENT_ALBEDO_SIDE - 0.5f;
            const float t = ((float)j + 0.5f) / FRAGMENT_ALBEDO_SIDE - 0.5f;
            const float3 q = on_plane + voxel * (s * t1 + t * t2);
            const float2 uv = triangle_barycentrics(q, a, b, c);
            if (uv.x < 0.0f || uv.y < 0.0f || uv.x + uv.y > 1.0f ||
                any(fabs(q - centre) > half_voxel))
                continue;
            ++landed;
            const float4 texel = texture_bilinear(tv, texture - 1u, texture_uv(tv, tri, uv.x, uv.y),
                                                  (uint)m->extra.z);
            if (!fragment_kept(m, texel))
                continue;
            sum += m->albedo.xyz * texel.xyz;
            ++*inside;
        }
    if (landed > 0u) {
        *coverage = (float)*inside / (float)landed;
        if (*inside > 0u)
            return sum;
    }
    const float2 uv = triangle_barycentrics(triangle_nearest(centre, a, b, c), a, b, c);
    const float4 texel =
        texture_bilinear(tv, texture - 1u, texture_uv(tv, tri, uv.x, uv.y), (uint)m->extra.z);
    if (landed == 0u)
        *coverage = fragment_kept(m, texel) ? 1.0f : 0.0f;
    return m->albedo.xyz * texel.xyz;
}

/* The fragment's own mean (light injection shades each fragment alone). */
inline float3 fragment_albedo(const texture_view *tv, const vct_material_desc *m, uint tri,
                              float3 a, float3 b, float3 c, float3 centre, float voxel) {
    uint inside;
    float coverage;
    const float3 sum = fragment_albedo_sum(tv, m, tri, a, b, c, centre, voxel, &inside, &coverage);
    return inside > 0u ? sum / (float)inside : sum;
}

#endif
