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
 * Texture coordinates and filtering are texture.h's (texel_taps_at). */
#ifndef VCT_ALPHA_MASK_H
#define VCT_ALPHA_MASK_H

#include "scene/texture.h"
#include "vct_types.h"

/* Bilinear alpha of a texture (first, width, height, wrap) at uv. */
inline float mask_alpha_at(__global const float *alpha, uint4 tex, float2 uv) {
    const texel_taps k = texel_taps_at((int)tex.y, (int)tex.z, tex.w, uv);
    __global const float *p = alpha + tex.x;
    const float top = mix(p[k.top_left], p[k.top_right], k.ax);
    const float bottom = mix(p[k.bottom_left], p[k.bottom_right], k.ax);
    return mix(top, bottom, k.ay);
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
