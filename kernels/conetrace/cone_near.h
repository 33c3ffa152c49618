/* What lies nearer than a cone's march starts. cone_origin lifts a cone
 * the cone offset (march.y, 4 voxels by default) off its surface along the
 * normal, so that it does not see its own voxels, and the march starts a
 * voxel further: a surface in
 * that slab (a slat in front of a wall, the wall beside a floor's edge) was
 * stepped over, and the cone saw what lies behind it. Rays from the
 * surface point through the slab across the cone's cell decide: the share
 * of them that meets geometry takes the voxels' light there, seen from the
 * ray's side, at the cone's footprint there, instead of the cone's march.
 * A voxel without a normal (fragments facing every way) sends none. */
#ifndef VCT_CONE_NEAR_H
#define VCT_CONE_NEAR_H

#include "accel/accel.h"
#include "light/direct_light.h" /* surface_epsilon */
#include "conetrace/cone_sky.h"
#include "conetrace/cone_trace.h"

/* Where the march of a camera cone along d from surface point p (unit
 * normal n) starts: lifted the offset along n (cone_origin), then moved
 * CONE_ORIGIN_TOWARDS_AXIS of the way, at that height, towards the cone's
 * axis, whose point there is where the near ray's reach ends. Lifted along
 * n alone, an oblique cone started beside the stretch of axis its near ray
 * had traced and marched from inside what lies there (a wall's cones beside
 * a window's slats started among the slats: 2x the light there); on the
 * axis, cones started past the surfaces near their start that lit them
 * (lamp room 0.096 -> 0.109, Cornell box 0.088 -> 0.091). Half way: blinds
 * 0.159 -> 0.138, the suite's mean 0.0955 -> 0.0937 (README). */
#define CONE_ORIGIN_TOWARDS_AXIS 0.5f
/* The least normal component of a cone's axis the shift assumes (the
 * presets' cones have 0.5 or more). */
#define CONE_ORIGIN_MIN_UP 0.25f
/* How far (voxels) along its side's normal a ray from a surface tells the
 * side it sees a hit voxel's plane from: a voxel's plane point lies inside
 * a slab one voxel thick (a roof lit on top), where a ray meets the near
 * face of a voxel whose plane it sits on. */
#define NEAR_SIDE_LIFT 0.1f

inline float3 cone_camera_origin(const vct_cone_desc *c, float3 p, float3 n, float3 d) {
    const float3 on_axis = p + d * (cone_lift(c) / fmax(dot(d, n), CONE_ORIGIN_MIN_UP));
    return mix(cone_origin(c, p, n), on_axis, CONE_ORIGIN_TOWARDS_AXIS);
}

/* 1, the light in *light and the distance in *dist where the ray from
 * surface point p (unit normal n) along d meets geometry before the cone's
 * march begins. The side of the voxels' plane the ray sees is told from a
 * point off the hit surface on the ray's side, a cone's diameter out: the
 * ray's origin, beside a surface that meets the one hit at an angle or off
 * a curved one, can lie on the other side of the hit voxels' plane (window
 * room 0.101 -> 0.096, dense hall 0.095 -> 0.087). Where the hit has no
 * surface frame, from NEAR_SIDE_LIFT voxels off the origin along n. */
inline int cone_near_light(const accel_view *g, CONE_POOLS, __global const uint *child,
                           const vct_cone_desc *c, float3 p, float3 n, float3 d, float tan_half,
                           float3 *light, float *dist) {
    const float voxel = c->volume.w / (float)c->res.x;
    const float lift = cone_lift(c), up = dot(d, n);
    if (!(up > 0.0f))
        return 0;
    /* through the slab below the lifted origin, and the march's first step */
    const float reach = lift / up + voxel;
    const float3 from = p + n * surface_epsilon(g, p);
    hit_record h;
    if (!accel_trace(g, from, d, 0.0f, reach, 0, &h))
        return 0;
    float3 seen_from = from + n * NEAR_SIDE_LIFT * voxel;
    float3 hit_p, hit_ng, hit_n;
    int front;
    if (surface_hit(g, &h, d, &hit_p, &hit_ng, &hit_n, &front))
        seen_from = hit_p + hit_n * fmax(2.0f * h.t * tan_half, 2.0f * voxel);
    *light = cone_hit_light(CONE_POOLS_PASS, child, c, from, d, h.t, tan_half, 1.0f, seen_from);
    *dist = h.t;
    return 1;
}

/* Near rays a camera cone sends: along its axis and the inner ring of its
 * open rest's rays (cone_sky.h), across its cell. One ray along the axis
 * decided for the whole cell: a wall strip above a window's sunlit slats,
 * whose cones' cells take them in only in part, got 0.71 of the path
 * tracer's indirect light, and the blinds scene 0.121 NRMSE at 128^2; with
 * five 0.115 (the long hall 0.151 -> 0.147, the suite's mean 0.0759 ->
 * 0.0753, the atrium 0.0625 -> 0.0643 the most worse), for 5 to 10 % more
 * device time. */
#define CONE_NEAR_RAYS 5u

/* The share of CONE_NEAR_RAYS rays across the cell of the cone along d
 * (aperture tan_half, its cell's spread) that meet geometry before the
 * march begins, the mean light where they do in *light and the nearest
 * distance in *dist (INFINITY where none does). */
inline float cone_near_cell(const accel_view *g, CONE_POOLS, __global const uint *child,
                            const vct_cone_desc *c, float3 p, float3 n, float3 d, float tan_half,
                            float spread, float3 *light, float *dist) {
    float3 t1, t2;
    basis_of(d, &t1, &t2);
    *light = (float3)(0.0f);
    *dist = INFINITY;
    uint hits = 0u;
    for (uint k = 0; k < CONE_NEAR_RAYS; ++k) {
        float3 l;
        float t;
        if (cone_near_light(g, CONE_POOLS_PASS, child, c, p, n, cone_rest_dir(d, t1, t2, spread, k),
                            tan_half, &l, &t)) {
            *light += l;
            *dist = fmin(*dist, t);
            ++hits;
        }
    }
    if (hits)
        *light /= (float)hits;
    return (float)hits / (float)CONE_NEAR_RAYS;
}

#endif
