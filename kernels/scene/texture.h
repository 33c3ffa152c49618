/* Base-colour textures at a hit: the triangle's texture coordinates at its
 * barycentrics, a bilinear sample of the material's texture (wrapping by
 * repeat or clamp per axis), times the material's albedo factor. Layout in
 * kernels/README.md (Textures). */
#ifndef VCT_TEXTURE_H
#define VCT_TEXTURE_H

#include "vct_types.h"

#define TEXTURE_ARGS                                                                               \
    __global const float4 *texels, __global const uint4 *texture_table,                            \
        __global const float4 *tri_uvs
#define TEXTURE_VIEW() ((texture_view){texels, texture_table, tri_uvs})

typedef struct texture_view {
    __global const float4 *texels;
    __global const uint4 *table;    /* first texel, width, height */
    __global const float4 *tri_uvs; /* per triangle: (uv0, uv1), (uv2, 0, 0) */
} texture_view;

/* Texel index along one axis of size n for integer coordinate i. */
inline int texel_wrap(int i, int n, int clamp_axis) {
    if (clamp_axis)
        return clamp(i, 0, n - 1);
    const int m = i % n;
    return m < 0 ? m + n : m;
}

/* Texture t (0-based) at uv: texel centres at (i + 1/2) / size, bilinear
 * between the four around uv. */
inline float4 texture_bilinear(const texture_view *tv, uint t, float2 uv, uint wrap) {
    const uint4 e = tv->table[t];
    const int w = (int)e.y, h = (int)e.z;
    const float x = uv.x * (float)w - 0.5f, y = uv.y * (float)h - 0.5f;
    const float fx = floor(x), fy = floor(y);
    const float ax = x - fx, ay = y - fy;
    /* large uv: keep the integer part in range before converting */
    const int x0 = (int)fmod(fx, (float)(w * 1024)), y0 = (int)fmod(fy, (float)(h * 1024));
    const int cs = (wrap & 1u) != 0u, ct = (wrap & 2u) != 0u;
    const int xa = texel_wrap(x0, w, cs), xb = texel_wrap(x0 + 1, w, cs);
    const int ya = texel_wrap(y0, h, ct), yb = texel_wrap(y0 + 1, h, ct);
    __global const float4 *p = tv->texels + e.x;
    const float4 top = mix(p[ya * w + xa], p[ya * w + xb], ax);
    const float4 bottom = mix(p[yb * w + xa], p[yb * w + xb], ax);
    return mix(top, bottom, ay);
}

/* The texture coordinates of triangle tri at barycentrics (u, v). */
inline float2 texture_uv(const texture_view *tv, uint tri, float u, float v) {
    const float4 a = tv->tri_uvs[2u * tri], b = tv->tri_uvs[2u * tri + 1u];
    return a.xy + u * (a.zw - a.xy) + v * (b.xy - a.xy);
}

/* m's albedo at a hit on triangle tri (barycentrics u, v): the factor times
 * the texture where m has one. */
inline float3 texture_albedo(const texture_view *tv, const vct_material_desc *m, uint tri, float u,
                             float v) {
    const uint t = (uint)m->extra.y;
    if (t == 0u)
        return m->albedo.xyz;
    return m->albedo.xyz *
           texture_bilinear(tv, t - 1u, texture_uv(tv, tri, u, v), (uint)m->extra.z).xyz;
}

#endif
