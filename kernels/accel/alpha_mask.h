/* Alpha masks: rays pass a masked triangle where its material's alpha
 * (glTF alphaMode MASK) is below the cutoff. Every traversal asks
 * accel_masked of each hit it would take.
 *
 * The mask data lives after the triangles' vertices in tri_vertices (3
 * float4 per triangle), so that every ray query already has it:
 *   tri_vertices[1].w        as_float(h): the block's first float4, 0: no masks
 *   tri_vertices[3t].w       as_float(r + 1) for triangle t's mask record r, 0: opaque
 *                            (the BVH's leaf vertices carry it in the second vertex's w,
 *                            so that an unmasked hit costs no load)
 *   block h                  uint4 (first record, first material, first texel, 0)
 *   record r (2 float4)      (uv0, uv1), (uv2, as_float(material slot m), 0)
 *   material m (2 float4)    uint4 (first alpha, width, height, wrap), (alpha, cutoff, 0, 0);
 *                            width 0: no texture, the alpha alone
 *   texels                   the textures' alpha, one float each, rows from the top
 * Texture coordinates and filtering are texture.h's: bilinear between texel
 * centres, repeat or clamp per axis. */
#ifndef VCT_ALPHA_MASK_H
#define VCT_ALPHA_MASK_H

#include "vct_types.h"

inline int mask_wrap(int i, int n, int clamp_axis) {
    if (clamp_axis)
        return clamp(i, 0, n - 1);
    const int m = i % n;
    return m < 0 ? m + n : m;
}

/* Bilinear alpha of a texture (first, width, height, wrap) at uv. */
inline float mask_alpha_at(__global const float *alpha, uint4 tex, float2 uv) {
    const int w = (int)tex.y, h = (int)tex.z;
    const float x = uv.x * (float)w - 0.5f, y = uv.y * (float)h - 0.5f;
    const float fx = floor(x), fy = floor(y);
    const float ax = x - fx, ay = y - fy;
    const int x0 = (int)fmod(fx, (float)(w * 1024)), y0 = (int)fmod(fy, (float)(h * 1024));
    const int cs = (tex.w & 1u) != 0u, ct = (tex.w & 2u) != 0u;
    const int xa = mask_wrap(x0, w, cs), xb = mask_wrap(x0 + 1, w, cs);
    const int ya = mask_wrap(y0, h, ct), yb = mask_wrap(y0 + 1, h, ct);
    __global const float *p = alpha + tex.x;
    const float top = mix(p[ya * w + xa], p[ya * w + xb], ax);
    const float bottom = mix(p[yb * w + xa], p[yb * w + xb], ax);
    return mix(top, bottom, ay);
}

/* accel_masked's test of a masked triangle. Not inlined: inside the
 * traversal loops its texture read made every ray 15-20 % slower on PoCL,
 * masked or not. */
__attribute__((noinline)) int accel_mask_test(__global const float4 *tri_vertices, uint slot,
                                              float u, float v) {
    const uint4 head = as_uint4(tri_vertices[as_uint(tri_vertices[1].w)]);
    __global const float4 *record = tri_vertices + head.x + 2u * (slot - 1u);
    const float4 r0 = record[0], r1 = record[1];
    const float2 uv = r0.xy + u * (r0.zw - r0.xy) + v * (r1.xy - r0.xy);
    __global const float4 *material = tri_vertices + head.y + 2u * as_uint(r1.z);
    const uint4 tex = as_uint4(material[0]);
    const float4 m = material[1];
    float alpha = m.x;
    if (tex.y > 0u)
        alpha *= mask_alpha_at((__global const float *)(tri_vertices + head.z), tex, uv);
    return alpha < m.y;
}

/* 1 where a ray passes the triangle whose mask slot (its first vertex's w
 * in tri_vertices) is `slot`, at barycentrics (u, v). */
inline int accel_masked(__global const float4 *tri_vertices, uint slot, float u, float v) {
    return slot != 0u && accel_mask_test(tri_vertices, slot, u, v);
}

#endif
