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

/* The four texels (row-major indices) a bilinear sample of a w x h texture
 * at uv reads, and the fractions between them: texel centres at
 * (i + 1/2) / size, wrapping by repeat or clamp per axis (wrap bits 1: s,
 * 2: t). */
typedef struct texel_taps {
    int top_left, top_right, bottom_left, bottom_right;
    float ax, ay;
} texel_taps;

inline texel_taps texel_taps_at(int w, int h, uint wrap, float2 uv) {
    const float x = uv.x * (float)w - 0.5f, y = uv.y * (float)h - 0.5f;
    const float fx = floor(x), fy = floor(y);
    /* large uv: keep the integer part in range before converting */
    const int x0 = (int)fmod(fx, (float)(w * 1024)), y0 = (int)fmod(fy, (float)(h * 1024));
    const int cs = (wrap & 1u) != 0u, ct = (wrap & 2u) != 0u;
    const int xa = texel_wrap(x0, w, cs), xb = texel_wrap(x0 + 1, w, cs);
    const int ya = texel_wrap(y0, h, ct), yb = texel_wrap(y0 + 1, h, ct);
    texel_taps t;
    t.top_left = ya * w + xa;
    t.top_right = ya * w + xb;
    t.bottom_left = yb * w + xa;
    t.bottom_right = yb * w + xb;
    t.ax = x - fx;
    t.ay = y - fy;
    return t;
}

/* Texture t (0-based) at uv, bilinear between the four texels around it. */
inline float4 texture_bilinear(const texture_view *tv, uint t, float2 uv, uint wrap) {
    const uint4 e = tv->table[t];
    const texel_taps k = texel_taps_at((int)e.y, (int)e.z, wrap, uv);
    __global const float4 *p = tv->texels + e.x;
    const float4 top = mix(p[k.top_left], p[k.top_right], k.ax);
    const float4 bottom = mix(p[k.bottom_left], p[k.bottom_right], k.ax);
    return mix(top, bottom, k.ay);
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
