/* One more diffuse bounce into the voxels: rays from each voxel gather the
 * radiance of the bounces so far where they meet the scene, and the voxel's
 * radiance becomes its direct radiance plus albedo times that (Lambert:
 * albedo / pi times the irradiance, pi times the cosine-weighted mean
 * radiance). Starting again from the direct part each time counts every path
 * once: k calls give the light of paths up to k + 1 bounces.
 *
 * Rays, not cones: BOUNCE_RAYS_SIDE^2 cosine-distributed rays per side,
 * stratified and turned per voxel, through the acceleration structure; each
 * reads the light at its hit from the finest bricks. Cones read what they
 * meet at coarse levels, where a sample mixes a surface with the space and
 * the surfaces around it, seen from one averaged plane, and each bounce lost
 * light: over the scene suite at 128^2 the rays take the mean NRMSE from
 * 0.085 to 0.080 (the panel room 0.169 -> 0.148, its mean 0.866 -> 0.886)
 * and the Cornell box's device time from 485 to 287 ms. Reading at a
 * footprint (a quarter to the whole of a cone's) was worse. The bricks, not
 * the voxel the ray meets: a slab thinner than a voxel is one voxel, and a
 * ray from inside the slab (a plane's back side) sees that voxel's dark
 * side, the slab's inside, where the brick's blend with the voxels beside
 * it shows the underside's light. Read from the voxels, the atrium's third
 * and fourth bounces added 0.92 and 0.82 of what they add from the bricks
 * (suite mean NRMSE 0.0753 -> 0.0775), though the Cornell box's device time
 * fell from 362 to 249 ms. The grain of nine rays is averaged away by the
 * sparse fill, the bricks' filter and the camera's cones, which read these
 * voxels at their own coarse levels; sixteen or thirty-six rays changed no
 * suite scene's error by 0.002.
 *
 * Surfaces are two-sided and each side of a voxel keeps its own light
 * (voxel_side.h): the rays gather on both sides of its plane, each side adds
 * what it receives to its own direct light, and the brighter of the two
 * becomes the voxel's radiance. Behind a closed room's wall it stays dark,
 * whichever way the wall is wound. A voxel whose fragments face every way
 * (no normal) gathers on both sides of z, from its centre lifted the cone
 * offset, and sends the brighter both ways.
 *
 * Sparse (the default): a quarter of the voxels gather, and the others take
 * what their gathering neighbours on the same surface received
 * (inject_bounce_fill). A bounce's light varies slowly along a surface. */
#include "conetrace/cone_frame.h"
#include "conetrace/cone_hit.h" /* cone_hit_light */
#include "conetrace/cone_trace.h"
#include "light/direct_light.h" /* surface_epsilon */
#include "scene/bsdf.h"         /* cosine_dir */
#include "voxel/octree.h"
#include "voxel/voxel_carry.h"
#include "voxel/voxel_side.h"
#include "vct_types.h"

/* How far (voxels) along its side's normal a ray from a surface tells the
 * side it sees a hit voxel's plane from: a voxel's plane point lies inside
 * a slab one voxel thick (a roof lit on top), where a ray meets the near
 * face of a voxel whose plane it sits on. */
#define NEAR_SIDE_LIFT 0.1f

/* rays per side: the square of this, one per cell of a grid over the
 * cosine-weighted hemisphere */
#define BOUNCE_RAYS_SIDE 3u

/* Ray i of the stratified grid, cell (i % side, i / side) at `jitter`
 * within it, about unit n with tangents t, b: cosine-weighted. */
inline float3 bounce_ray_dir(float3 n, float3 t, float3 b, uint i, float2 jitter) {
    const float u = ((float)(i % BOUNCE_RAYS_SIDE) + jitter.x) / (float)BOUNCE_RAYS_SIDE;
    const float v = ((float)(i / BOUNCE_RAYS_SIDE) + jitter.y) / (float)BOUNCE_RAYS_SIDE;
    return normalize(cosine_dir(n, t, b, u, v));
}

/* The cosine-weighted radiance arriving at `from` (voxel `key`, on the
 * side unit n faces) where the rays meet the scene: the finest bricks' light
 * there, seen from the ray's side; the ambient light where they meet
 * nothing. */
inline float3 gather_side(const accel_view *acc, CONE_POOLS, __global const uint *child,
                          const vct_cone_desc *cd, uint key, float3 from, float3 n) {
    float3 t, b;
    cone_frame(n, key, &t, &b);
    const float voxel = cd->volume.w / (float)cd->res.x;
    const float3 seen_from = from + n * NEAR_SIDE_LIFT * voxel;
    /* the grid's offset: its own for each voxel and side */
    const uint h = rng_hash(key ^ (dot(n, (float3)(1.0f, 2.0f, 4.0f)) > 0.0f ? 0x9e3779b9u : 0u));
    const float2 jitter =
        (float2)((float)(h >> 8), (float)(rng_hash(h) >> 8)) * (1.0f / 16777216.0f);
    float3 gathered = (float3)(0.0f);
    for (uint i = 0; i < BOUNCE_RAYS_SIDE * BOUNCE_RAYS_SIDE; ++i) {
        const float3 d = bounce_ray_dir(n, t, b, i, jitter);
        hit_record hit;
        if (!accel_trace(acc, from, d, 0.0f, INFINITY, 0, &hit)) {
            gathered += cd->ambient.xyz;
            continue;
        }
        /* aperture 0: the finest bricks, two voxels across */
        gathered +=
            cone_hit_light(CONE_POOLS_PASS, child, cd, from, d, hit.t, 0.0f, 1.0f, seen_from);
    }
    return gathered / (float)(BOUNCE_RAYS_SIDE * BOUNCE_RAYS_SIDE);
}

/* 1 for the voxels that do not gather in a sparse bounce: all but those
 * whose x + y + z is a multiple of 4, a quarter of any axis-aligned plane's
 * voxels. Along each axis one of them lies at most two voxels away from
 * every other voxel. */
inline uint bounce_skips(uint key) {
    const uint3 c = morton_decode(key);
    return ((c.x + c.y + c.z) & 3u) != 0u;
}

/* A face within a voxel of a voxel's plane and parallel to it (within about
 * 25 degrees) lies between the plane and the side of the voxel that faces
 * the way it does. */
#define SIDE_FACE_PARALLEL 0.9f

/* Where the rays of the side unit n faces leave from, for the voxel's plane
 * point `surface`: just off it, or where a parallel face lies within a
 * voxel along n, just past that face. The plane of a closed object thinner
 * than a voxel (a slat, a table top, a slab) runs between its faces, the
 * mean of its fragments' points, so rays from just off it start inside the
 * object and meet its inner faces: its sides gathered their own light,
 * dark, and the blinds' slats, which reflect most of the floor's light that
 * reaches them back into the room, were black to it. */
inline float3 side_origin(const accel_view *acc, float3 surface, float3 n, float voxel) {
    const float eps = surface_epsilon(acc, surface);
    const float3 from = surface + n * eps;
    hit_record hit;
    float3 p, ng, facing;
    int front;
    if (accel_trace(acc, from, n, 0.0f, voxel, 0, &hit) &&
        surface_hit(acc, &hit, n, &p, &ng, &facing, &front) &&
        fabs(dot(ng, n)) > SIDE_FACE_PARALLEL)
        return p + n * surface_epsilon(acc, p);
    return from;
}

/* What voxel v's two sides receive. With a normal the rays leave from the
 * point of the voxel's plane nearest its centre, just off it on each side;
 * without, from its centre lifted the cone offset along +-z. */
inline void gather_voxel(const accel_view *acc, CONE_POOLS, __global const uint *child,
                         const vct_cone_desc *cd, uint key, float4 plane, float3 *front,
                         float3 *back) {
    const float voxel = cd->volume.w / (float)cd->res.x;
    const float3 centre = cd->volume.xyz + (convert_float3(morton_decode(key)) + 0.5f) * voxel;
    if (!any(plane.xyz != 0.0f)) {
        const float3 z = (float3)(0.0f, 0.0f, 1.0f);
        *front = gather_side(acc, CONE_POOLS_PASS, child, cd, key, cone_origin(cd, centre, z), z);
        *back = gather_side(acc, CONE_POOLS_PASS, child, cd, key, cone_origin(cd, centre, -z), -z);
        return;
    }
    const float3 n = plane.xyz;
    const float3 c_unit = (centre - cd->volume.xyz) * cd->ambient.w - 0.5f;
    const float3 surface =
        cd->volume.xyz + (c_unit - (dot(n, c_unit) - plane.w) * n + 0.5f) * cd->volume.w;
    *front =
        gather_side(acc, CONE_POOLS_PASS, child, cd, key, side_origin(acc, surface, n, voxel), n);
    *back =
        gather_side(acc, CONE_POOLS_PASS, child, cd, key, side_origin(acc, surface, -n, voxel), -n);
}

/* Voxel v's radiance and sides from what its sides receive; keep_sides 1:
 * on the plane its sides have (voxel_side.h). */
inline void bounce_store(uint v, float3 front, float3 back, __global const float4 *albedo,
                         __global const float4 *direct, __global const float4 *direct_side,
                         __global float4 *voxel_radiance, __global float4 *side, uint keep_sides) {
    __global const float4 *sides = direct_side + VCT_VOXEL_SIDE_FLOAT4S * v;
    const float4 bright = direct[v], shade = sides[0], plane = sides[1];
    const int has_normal = any(plane.xyz != 0.0f);
    const float3 rho = albedo[v].xyz;
    /* without a normal both sides send what the brighter side receives */
    const float3 more = side_luminance(front) >= side_luminance(back) ? front : back;
    const float3 toward = has_normal ? front : more, away = has_normal ? back : more;
    const float3 lit_toward = bright.xyz + rho * toward,
                 lit_away = bright.xyz - shade.xyz + rho * away;
    if (keep_sides)
        voxel_side_keep(lit_toward, lit_away, plane.xyz, bright.w, voxel_radiance, side, v);
    else
        voxel_side_store(lit_toward, lit_away, plane.xyz, plane.w * plane.xyz, bright.w,
                         voxel_radiance, side, v);
}

/* sparse 1: only the voxels whose x + y + z is a multiple of 4 gather (and
 * keep what they received in `received`, two float4 each);
 * inject_bounce_fill gives the others theirs. */
__kernel void inject_bounce(ACCEL_ARGS, CONE_POOLS, __global const uint *child, vct_cone_desc cd,
                            __global const uint *keys, uint voxels, __global const float4 *albedo,
                            __global const float4 *direct, __global const float4 *direct_side,
                            __global float4 *voxel_radiance, __global float4 *side, uint keep_sides,
                            __global const uint *carried_from,
                            __global const float4 *before_radiance,
                            __global const float4 *before_side, uint carry_every, uint carry_phase,
                            uint sparse, __global float4 *received) {
    const accel_view acc = ACCEL_VIEW();
    const uint v = get_global_id(0);
    if (v >= voxels || (sparse && bounce_skips(keys[v])))
        return;
    /* carried light gathered over carry_every renders: a voxel whose direct
     * light was carried and whose turn it is not keeps all its light before */
    if (carry_every > 0u && carried_from[v] != VCT_NO_VOXEL &&
        (keys[v] * 2654435761u) % carry_every != carry_phase) {
        const uint from = carried_from[v];
        voxel_radiance[v] = before_radiance[from];
        for (uint k = 0; k < VCT_VOXEL_SIDE_FLOAT4S; ++k)
            side[VCT_VOXEL_SIDE_FLOAT4S * v + k] = before_side[VCT_VOXEL_SIDE_FLOAT4S * from + k];
        return;
    }
    float3 front, back;
    gather_voxel(&acc, CONE_POOLS_PASS, child, &cd, keys[v],
                 direct_side[VCT_VOXEL_SIDE_FLOAT4S * v + 1], &front, &back);
    if (sparse) {
        received[2u * v] = (float4)(front, 0.0f);
        received[2u * v + 1u] = (float4)(back, 0.0f);
    }
    bounce_store(v, front, back, albedo, direct, direct_side, voxel_radiance, side, keep_sides);
}

/* A neighbour's surface is this voxel's where their planes face the same
 * way (or exactly the other way: then its sides swap) and lie within a
 * tenth of a voxel of each other. */
#define FILL_FACING 0.95f
#define FILL_OFFSET 0.1f

/* The voxel k (0 .. 11: one step +x +y +z -x -y -z, then two) away from
 * the one at leaf node `leaf`, at cell q: through the octree's neighbour
 * links (octree.h), two loads a step; by the sorted keys where a two-step
 * link passes a node that does not exist. VCT_NO_VOXEL where there is none. */
inline uint fill_neighbour(__global const uint *child, __global const uint *neighbours,
                           __global const uint *keys, uint voxels, uint leaf, uint k, uint3 q) {
    const uint dir = k % 6u;
    uint node = neighbours[6u * leaf + dir];
    if (k >= 6u) {
        if (node == OCT_NULL) /* no node one step away: the second may still be there */
            return carry_find(keys, voxels, morton_encode(q));
        node = neighbours[6u * node + dir];
    }
    /* no node: no geometry in its parent's cell */
    const uint u = node == OCT_NULL ? OCT_NULL : child[node];
    return u == OCT_NULL ? VCT_NO_VOXEL : u;
}

/* sparse gathers, second pass: each voxel that did not gather takes the
 * mean of what the gathering voxels one and two steps away along the axes,
 * on its own surface, received (inject_bounce), and gathers itself where
 * it has none. */
__kernel void inject_bounce_fill(ACCEL_ARGS, CONE_POOLS, __global const uint *child,
                                 vct_cone_desc cd, __global const uint *keys, uint voxels,
                                 __global const float4 *albedo, __global const float4 *direct,
                                 __global const float4 *direct_side,
                                 __global float4 *voxel_radiance, __global float4 *side,
                                 uint keep_sides, __global const float4 *received,
                                 __global const uint *neighbours) {
    const accel_view acc = ACCEL_VIEW();
    const uint v = get_global_id(0);
    if (v >= voxels || !bounce_skips(keys[v]))
        return;
    const float4 plane = direct_side[VCT_VOXEL_SIDE_FLOAT4S * v + 1];
    const int has_normal = any(plane.xyz != 0.0f);
    const uint3 c = morton_decode(keys[v]);
    uint depth;
    /* its own leaf: the descent reaches the voxel's depth, res.y */
    const uint leaf = octree_descend(child, c, cd.res.y, &depth);
    const float offset = FILL_OFFSET / (float)cd.res.x;
    float3 front = (float3)(0.0f), back = (float3)(0.0f);
    uint found = 0u;
    for (uint k = 0; k < 12u; ++k) { /* +x +y +z -x -y -z, then two steps */
        const int axis = (int)(k % 3u), step = (k % 6u < 3u ? 1 : -1) * (k < 6u ? 1 : 2);
        int3 q = convert_int3(c);
        q.x += axis == 0 ? step : 0;
        q.y += axis == 1 ? step : 0;
        q.z += axis == 2 ? step : 0;
        if (any(q < 0) || any(q >= (int)cd.res.x))
            continue;
        const uint u = fill_neighbour(child, neighbours, keys, voxels, leaf, k, convert_uint3(q));
        if (u == VCT_NO_VOXEL || bounce_skips(keys[u]))
            continue;
        const float4 pu = direct_side[VCT_VOXEL_SIDE_FLOAT4S * u + 1];
        const int u_normal = any(pu.xyz != 0.0f);
        if (u_normal != has_normal)
            continue;
        const float facing = has_normal ? dot(pu.xyz, plane.xyz) : 1.0f;
        const int same = facing > FILL_FACING, flipped = facing < -FILL_FACING;
        if (has_normal && !((same && fabs(pu.w - plane.w) < offset) ||
                            (flipped && fabs(pu.w + plane.w) < offset)))
            continue;
        const float3 f = received[2u * u].xyz, b = received[2u * u + 1u].xyz;
        front += flipped ? b : f;
        back += flipped ? f : b;
        ++found;
    }
    if (found) {
        front /= (float)found;
        back /= (float)found;
    } else {
        gather_voxel(&acc, CONE_POOLS_PASS, child, &cd, keys[v], plane, &front, &back);
    }
    bounce_store(v, front, back, albedo, direct, direct_side, voxel_radiance, side, keep_sides);
}
