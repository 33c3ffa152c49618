/* Ray casting: primary visibility through the acceleration structure, direct light
 * from every punctual light with hard shadows and from emissive triangles
 * (light/emitters.h, emitter_samples shadow rays per pixel), emission,
 * Lambert shading. */
#include "scene/camera.h"
#include "light/direct_light.h"
#include "light/emitters.h"
#include "scene/texture.h"
#include "accel/accel.h"
#include "vct_types.h"

__kernel void render_direct(ACCEL_ARGS, vct_camera_desc cam,
                            __global const vct_material_desc *materials,
                            __global const uint *tri_material, TEXTURE_ARGS,
                            __global const vct_light_desc *lights, uint light_count, EMITTER_ARGS,
                            __global float4 *image) {
    const uint x = get_global_id(0), y = get_global_id(1);
    if (x >= cam.size.x || y >= cam.size.y)
        return;
    const accel_view g = ACCEL_VIEW();
    const float3 dir = camera_ray_dir(&cam, (float)x + 0.5f, (float)camera_row(&cam, y) + 0.5f);
    float3 radiance = (float3)(0.0f);
    hit_record h;
    if (accel_trace(&g, cam.position.xyz, dir, 0.0f, INFINITY, 0, &h)) {
        float3 p, ng, n;
        int front;
        surface_hit(&g, &h, dir, &p, &ng, &n, &front);
        const vct_material_desc m = materials[tri_material[h.tri]];
        const texture_view tv = TEXTURE_VIEW();
        const float3 albedo = texture_albedo(&tv, &m, h.tri, h.u, h.v);
        direct_terms d = direct_gather(&g, lights, light_count, p, n, 1, (float3)(0.0f), -1.0f, 0);
        const emitter_view e = EMITTER_VIEW();
        direct_emitters(&g, &e, materials, tri_material, p, n, (float3)(0.0f), -1.0f,
                        camera_pixel_id(&cam, x, y), &d);
        radiance = m.emission.xyz + albedo * VCT_INV_PI * d.irradiance;
    }
    image[y * cam.size.x + x] = (float4)(radiance, 1.0f);
}

/* Closest (or any) hits for arbitrary rays: t < 0 on a miss. */
__kernel void trace_rays(ACCEL_ARGS, __global const vct_ray_desc *rays, uint n, uint any_hit,
                         __global vct_hit_desc *hits) {
    const uint i = get_global_id(0);
    if (i >= n)
        return;
    const accel_view g = ACCEL_VIEW();
    const vct_ray_desc r = rays[i];
    hit_record h;
    if (accel_trace(&g, r.origin.xyz, r.direction.xyz, r.origin.w, r.direction.w, any_hit, &h))
        hits[i] = (float4)(h.t, as_float(h.tri), h.u, h.v);
    else
        hits[i] = (float4)(-1.0f, as_float(0xffffffffu), 0.0f, 0.0f);
}

/* The same, TRACE_PACKET_SPAN consecutive rays to a work-item, traced in
 * packets (accel/ray_packet.h: one packet of 16 on CPU devices, else one
 * ray at a time); an any-hit ray reports t 0 where blocked. */
#define TRACE_PACKET_SPAN 16u
__kernel void trace_ray_packets(ACCEL_ARGS, __global const vct_ray_desc *rays, uint n, uint any_hit,
                                __global vct_hit_desc *hits) {
    const uint span = get_global_id(0) * TRACE_PACKET_SPAN;
    const accel_view g = ACCEL_VIEW();
    for (uint first = span; first < min(n, span + TRACE_PACKET_SPAN); first += PACKET_RAYS) {
        ray_packet p;
        p.count = min(n - first, PACKET_RAYS);
        for (uint k = 0; k < p.count; ++k) {
            const vct_ray_desc r = rays[first + k];
            packet_set(&p, k, r.origin.xyz, r.direction.xyz, r.origin.w, r.direction.w);
        }
        hit_record h[PACKET_RAYS];
        int found[PACKET_RAYS];
        accel_trace_packet(&g, &p, any_hit, h, found);
        for (uint k = 0; k < p.count; ++k)
            hits[first + k] = !found[k] ? (float4)(-1.0f, as_float(0xffffffffu), 0.0f, 0.0f)
                              : any_hit ? (float4)(0.0f, as_float(0xffffffffu), 0.0f, 0.0f)
                                        : (float4)(h[k].t, as_float(h[k].tri), h[k].u, h[k].v);
    }
}
