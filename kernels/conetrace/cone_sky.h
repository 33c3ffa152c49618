/* What a cone leaves open. A cone that leaves the volume takes the ambient
 * light for what it still sees there, but wide cones at coarse levels step
 * over one-voxel walls: inside a closed room they found the sky through its
 * walls. So a ray along the cone's axis, through the acceleration
 * structure, decides: where it meets geometry, the sky is closed that way.
 *
 * Isotropic bricks (no VCT_ANISOTROPIC) average a wall with the empty space
 * beside it, so at every coarse level a cone passes walls in part and lost
 * what it left open: a closed box of albedo 0.5 kept 0.22 of each bounce's
 * light. There the open rest takes the light where rays across the cone
 * meet the scene, at the cone's footprint there, seen from the cone's side
 * (the box keeps 0.504). One ray on the axis switches the whole rest on or
 * off between neighbouring pixels, whose cones' axes meet a wall or leave
 * through an opening: polygons of light on the walls. A cone sends
 * CONE_REST_RAYS (the Cornell box 0.146 with one, 0.100 with nine, as with
 * sixteen) over its cell (the directions it stands for, wider than the cone
 * where the aperture is capped: host/src/voxel/cones.c). Directional bricks keep a wall's opacity
 * along its normal; with the same rest the box gained light (0.543), so they keep the sky check
 * alone. */
#ifndef VCT_CONE_SKY_H
#define VCT_CONE_SKY_H

#include "accel/accel.h"
#include "scene/bsdf.h" /* basis_of */
#include "conetrace/cone_trace.h"

#define CONE_REST_RAYS 9u
/* The rest's rays read the light where they meet the scene over a third of
 * the cone's diameter there: each of the nine stands for a ninth of the
 * cone's solid angle, a cone a third as wide. A wider cell takes in what
 * lies around the hit in depth (a wall's corner, the far side of a slab, a
 * block beside a floor) that the ray never sees, and darkened every bounce
 * (the Cornell box's first bounce at the camera 0.94 of the path tracer's
 * at 0.7 of the diameter, 0.97 at a third, 0.99 at the finest level).
 * Finer cells see more of a texture's or a hot spot's detail through nine
 * rays: blotches. Over the scene suite at 128^2 (mean NRMSE, against
 * 4096-spp references): 0.7 0.0802, a third 0.0794 (Cornell box 0.061 ->
 * 0.053, its mean 0.972 -> 0.982; panel room 0.128 -> 0.122; lamp room
 * 0.063 -> 0.067, textured room 0.056 -> 0.062), the finest 0.0799. */
#define CONE_REST_FOOTPRINT (1.0f / 3.0f)
/* Below this a sample's colour over its opacity is half-float noise. */
#define CONE_REST_MIN_OPACITY 1e-3f

/* Ray k of the rest's nine, across a disc of radius 1 (the cell's
 * aperture): the axis, four at 0.565, four at 0.879 between them, the
 * centroids of nine parts of equal area (a centre of radius 1/3, rings to
 * sqrt(5) / 3 and to 1). */
inline float2 cone_rest_offset(uint k) {
    const float a = 0.565f, b = 0.879f * 0.70710678f;
    switch (k) {
    case 1:
        return (float2)(a, 0.0f);
    case 2:
        return (float2)(0.0f, a);
    case 3:
        return (float2)(-a, 0.0f);
    case 4:
        return (float2)(0.0f, -a);
    case 5:
        return (float2)(b, b);
    case 6:
        return (float2)(-b, b);
    case 7:
        return (float2)(-b, -b);
    case 8:
        return (float2)(b, -b);
    default:
        return (float2)(0.0f);
    }
}

/* The unit direction of ray k across the cell of the cone along unit d
 * (t1, t2: basis_of(d)), spread: tan of the cell's half-angle. */
inline float3 cone_rest_dir(float3 d, float3 t1, float3 t2, float spread, uint k) {
    const float2 off = cone_rest_offset(k);
    return normalize(d + spread * (off.x * t1 + off.y * t2));
}

/* The voxels' light where a ray from `from` along unit d met the scene at
 * distance t: the sample there at `footprint` times the diameter a cone of
 * aperture tan_half has at that distance (1: the level cone_trace would
 * read), seen from `seen_from` (the side of its plane that point lies on,
 * voxel_side.h), un-premultiplied where the half floats still hold it (0
 * elsewhere).
 * A coarse sample takes in surfaces far from the hit: in a closed room,
 * walls on both sides of its cell, whose one-sided planes then disagree, so
 * that it cannot tell the side the ray comes from and shows the brighter
 * one, the outside's (1.8 % of the sky light outside came in, README). So
 * the sample is read one whole level finer until its planes agree
 * (side_coherence 1) or the finest level, as cone_trace's march cannot
 * (it has no hit to look at). */
inline float3 cone_hit_light(CONE_POOLS, __global const uint *child, const vct_cone_desc *c,
                             float3 from, float3 d, float t, float tan_half, float footprint,
                             float3 seen_from) {
    const uint levels = c->res.y;
    const float voxel = c->volume.w / (float)c->res.x, min_diameter = 2.0f * voxel;
    const float level = cone_level(
        (float)(levels - 1u), fmax(footprint * 2.0f * t * tan_half, min_diameter), min_diameter);
    const float3 at = clamp((from + t * d - c->volume.xyz) * c->ambient.w, 0.0f, 0.99999f);
    /* a surface the ray met: no lift, none of it the cone's own */
    const float4 o = (float4)((seen_from - c->volume.xyz) * c->ambient.w - 0.5f, -1.0f);
    cone_path path = cone_path_root();
    float coherence = 1.0f;
    float4 s =
        cone_sample(CONE_POOLS_PASS, c->res.zw, child, levels, at, level, d, o, &path, &coherence);
    for (float finer = floor(level) + 1.0f; coherence < 1.0f && finer <= (float)(levels - 1u);
         finer += 1.0f) {
        coherence = 1.0f;
        s = cone_sample(CONE_POOLS_PASS, c->res.zw, child, levels, at, finer, d, o, &path,
                        &coherence);
    }
    return s.w > CONE_REST_MIN_OPACITY ? s.xyz / s.w : (float3)(0.0f);
}

/* r's radiance, its ambient share dropped where the ray from origin along d
 * meets geometry; with isotropic bricks, that share split by what
 * CONE_REST_RAYS rays across the cone's cell (tan_half the cone's aperture,
 * spread the cell's) meet: the ambient light for the share of them that
 * leave the scene (at most that share), the mean light where the others
 * meet it for the remainder. */
inline float3 cone_open_checked(const accel_view *g, CONE_POOLS, __global const uint *child,
                                const vct_cone_desc *c, float3 origin, float3 d, float tan_half,
                                float spread, cone_result r) {
#ifdef VCT_ANISOTROPIC
    if (!r.left || all(c->ambient.xyz == 0.0f) || r.alpha >= 1.0f)
        return r.radiance;
    hit_record h;
    if (accel_trace(g, origin, d, 0.0f, INFINITY, 1, &h))
        return r.radiance - (1.0f - r.alpha) * c->ambient.xyz;
    return r.radiance;
#else
    if (!r.left || r.alpha >= 1.0f)
        return r.radiance;
    float3 t1, t2;
    basis_of(d, &t1, &t2);
    float3 met = (float3)(0.0f);
    uint open = 0u;
    for (uint k = 0; k < CONE_REST_RAYS; ++k) {
        const float3 dk = cone_rest_dir(d, t1, t2, spread, k);
        hit_record h;
        if (!accel_trace(g, origin, dk, 0.0f, INFINITY, 0, &h)) {
            ++open;
            continue;
        }
        met += cone_hit_light(CONE_POOLS_PASS, child, c, origin, dk, h.t, tan_half,
                              CONE_REST_FOOTPRINT, origin);
    }
    /* The rays' open share is the cone's view of the sky through the real
     * geometry; the cone's own opacity already took in the occluders the
     * rays passed, so the open share is not scaled by it a second time
     * (a 0.8 m roof slit seen by wide cones: its sky light squared). What
     * the rest leaves beyond the open share is what the other rays met. */
    const float rest = 1.0f - r.alpha;
    const float sky = fmin((float)open / (float)CONE_REST_RAYS, rest);
    const float3 beyond =
        open < CONE_REST_RAYS ? met / (float)(CONE_REST_RAYS - open) : (float3)(0.0f);
    return r.radiance + (sky - rest) * c->ambient.xyz + (rest - sky) * beyond;
#endif
}

#endif
