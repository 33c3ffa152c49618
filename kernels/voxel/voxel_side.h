/* The two sides of a voxel's surface.
 *
 * A wall lit on one face must not light what lies behind it, however thin
 * it is. So a voxel keeps, beside its radiance (its front side's: the
 * brighter one), the difference to its back side and the plane between
 * them: the front side's unit normal n and offset h = n . c, c a point of
 * its surfaces in volume units less 0.5 (centred, for half precision in the
 * bricks):
 *     radiance[v]    = (front side's radiance, opacity)
 *     side[2v]       = (front - back side's radiance, k)
 *     side[2v + 1]   = (n, h), n = 0 where the voxel has no normal
 * k is the difference's luminance (or more, voxel_side_keep): how much
 * light the side a cone is on decides. Bricks filter the difference
 * premultiplied by opacity, like radiance, and the plane by opacity times
 * k, so that where surfaces meet, the plane is the one that matters (a dark
 * floor has no say in which side of a sunlit wall a cone is on):
 * VCT_BRICK_SHADE holds (opacity (front - back), opacity k),
 * VCT_BRICK_PLANE opacity k (n, h).
 * A cone whose origin lies behind a sample's plane sees the back side
 * (cone_trace.h).
 *
 * The first bounce decides which side is which (voxel_side_store); the
 * bounces between it and the last only add light to each side and may make a
 * voxel more one-sided, never less (voxel_side_keep); the last decides again,
 * from the light the cones will see. Deciding with every bounce made the
 * gather depend on its own result: in a hall lit through a slit in a
 * one-voxel roof, planes turned between bounces and the bounces' light
 * oscillated, settling a fifth above the right mean. */
#ifndef VCT_VOXEL_SIDE_H
#define VCT_VOXEL_SIDE_H

#include "vct_types.h"

inline float side_luminance(float3 c) {
    return dot(c, (float3)(0.2126f, 0.7152f, 0.0722f));
}

/* The light of a voxel's side that point o (in volume units less 0.5, as
 * the plane's offset is) lies on, from the voxel's radiance, side
 * difference and plane (side[2v], side[2v + 1]): the front side's on the
 * plane's normal side or where the voxel has no plane, else the back
 * side's. */
inline float3 voxel_side_light(float4 front, float4 difference, float4 plane, float3 o) {
    if (all(plane.xyz == 0.0f) || dot(plane.xyz, o) >= plane.w)
        return front.xyz;
    return front.xyz - difference.xyz;
}

/* The light a voxel's surfaces send out, by the way it leaves: per axis
 * direction (+x, +y, +z, -x, -y, -z), what leaves towards it, weighted by
 * the squared components of each surface side's normal; and the direction
 * most of it leaves along (the lit sides' normals weighted by their
 * luminance). The two sides of the voxel's plane follow from them, for any
 * plane, without keeping each fragment. */
typedef struct side_cube {
    float3 out[6];
    float3 lean;
} side_cube;

inline side_cube side_cube_empty(void) {
    side_cube c;
    for (uint k = 0; k < 6u; ++k)
        c.out[k] = (float3)(0.0f);
    c.lean = (float3)(0.0f);
    return c;
}

/* Light l leaving a surface side of unit normal m. */
inline void side_cube_add(side_cube *c, float3 m, float3 l) {
    const float3 w = m * m;
    c->out[m.x >= 0.0f ? 0 : 3] += w.x * l;
    c->out[m.y >= 0.0f ? 1 : 4] += w.y * l;
    c->out[m.z >= 0.0f ? 2 : 5] += w.z * l;
    c->lean += side_luminance(l) * m;
}

/* What leaves on the side n points to (*toward) and on the other (*away):
 * each axis direction's light by how far it faces n: all of it within 60
 * degrees of n, half where it lies in the plane, none within 60 degrees of
 * -n. */
inline void side_cube_split(const side_cube *c, float3 n, float3 *toward, float3 *away) {
    const float3 axes[6] = {(float3)(1.0f, 0.0f, 0.0f),  (float3)(0.0f, 1.0f, 0.0f),
                            (float3)(0.0f, 0.0f, 1.0f),  (float3)(-1.0f, 0.0f, 0.0f),
                            (float3)(0.0f, -1.0f, 0.0f), (float3)(0.0f, 0.0f, -1.0f)};
    *toward = *away = (float3)(0.0f);
    for (uint k = 0; k < 6u; ++k) {
        const float w = clamp(0.5f + dot(axes[k], n), 0.0f, 1.0f);
        *toward += w * c->out[k];
        *away += (1.0f - w) * c->out[k];
    }
}

/* Stores voxel v: `toward` is what it sends along +n, `away` along -n;
 * centre: a point of its surfaces. */
inline void voxel_side_store(float3 toward, float3 away, float3 n, float3 centre, float opacity,
                             __global float4 *radiance, __global float4 *side, uint v) {
    const int flip = side_luminance(away) > side_luminance(toward);
    const float3 bright = flip ? away : toward, dark = flip ? toward : away;
    const float3 up = flip ? -n : n;
    radiance[v] = (float4)(bright, opacity);
    __global float4 *out = side + VCT_VOXEL_SIDE_FLOAT4S * v;
    out[0] = (float4)(bright - dark, side_luminance(bright - dark));
    out[1] = (float4)(up, dot(up, centre));
}

/* Stores voxel v keeping the plane its sides have: `toward` is what it
 * sends along +n, `away` along -n (n: the plane's normal up to its sign).
 * The side the plane faces may now be the darker one: radiance less shade
 * is still the other side's light, and k grows to the sides' difference. */
inline void voxel_side_keep(float3 toward, float3 away, float3 n, float opacity,
                            __global float4 *radiance, __global float4 *side, uint v) {
    __global float4 *out = side + VCT_VOXEL_SIDE_FLOAT4S * v;
    const int flip = dot(out[1].xyz, n) < 0.0f;
    const float3 front = flip ? away : toward, back = flip ? toward : away;
    radiance[v] = (float4)(front, opacity);
    out[0] = (float4)(front - back, fmax(out[0].w, fabs(side_luminance(front - back))));
}

#endif
