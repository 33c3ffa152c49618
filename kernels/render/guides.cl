/* The denoiser's guides: what the camera sees first at each pixel, as the
 * mean of n x n stratified rays across it (so the guides' edges are
 * antialiased as the image's are):
 *   albedo        the first hit's albedo, textures included; 1 where a ray
 *                 leaves the scene (the sky is not divided by anything);
 *                 w: the share of the rays whose first hit emits nothing
 *                 (below 1: an emitter is seen, whose light is not noise)
 *   normal_depth  xyz: the mean of the hits' normals facing the viewer (not
 *                 normalised: shorter at edges); w: the mean distance of the
 *                 rays that hit, 0 where none did */
#include "scene/camera.h"
#include "scene/texture.h"
#include "accel/accel.h"
#include "vct_types.h"

__kernel void render_guides(ACCEL_ARGS, vct_camera_desc cam,
                            __global const vct_material_desc *materials,
                            __global const uint *tri_material, TEXTURE_ARGS, uint n,
                            __global float4 *albedo, __global float4 *normal_depth) {
    const uint x = get_global_id(0), y = get_global_id(1);
    if (x >= cam.size.x || y >= cam.size.y)
        return;
    const accel_view g = ACCEL_VIEW();
    const texture_view tv = TEXTURE_VIEW();
    float3 a = (float3)(0.0f), normal = (float3)(0.0f);
    float depth = 0.0f;
    uint hits = 0, glowing = 0;
    for (uint j = 0; j < n; ++j)
        for (uint i = 0; i < n; ++i) {
            const float3 dir =
                camera_ray_dir(&cam, (float)x + ((float)i + 0.5f) / (float)n,
                               (float)camera_row(&cam, y) + ((float)j + 0.5f) / (float)n);
            hit_record h;
            float3 p, ng, nf;
            int front;
            if (accel_trace(&g, cam.position.xyz, dir, 0.0f, INFINITY, 0, &h) &&
                surface_hit(&g, &h, dir, &p, &ng, &nf, &front)) {
                const vct_material_desc m = materials[tri_material[h.tri]];
                a += texture_albedo(&tv, &m, h.tri, h.u, h.v);
                glowing += any(m.emission.xyz > 0.0f);
                normal += nf;
                depth += h.t;
                ++hits;
            } else {
                a += (float3)(1.0f);
            }
        }
    const float inv = 1.0f / (float)(n * n);
    const uint pixel = y * cam.size.x + x;
    albedo[pixel] = (float4)(a * inv, (float)(n * n - glowing) * inv);
    normal_depth[pixel] = (float4)(normal * inv, hits ? depth / (float)hits : 0.0f);
}
