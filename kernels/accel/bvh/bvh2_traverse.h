/* Ray traversal of the two-level BVH: a 4-wide BVH over the instances (world
 * space) whose leaves are instances, each naming its mesh's own 4-wide BVH
 * (the mesh's space). A ray meets the top level as bvh_traverse.h meets a
 * whole scene; at an instance it is carried into the mesh's space by the
 * instance's inverse transform and meets the mesh's boxes, widened by a pad
 * that covers the rounding of that transform; the triangles themselves are
 * tested in world space, from the scene's own vertices (tri_vertices), with
 * the world ray: the same test on the same numbers as the one-level BVH, so
 * a ray reports the same hit. Instances of one mesh share its nodes. */
#ifndef VCT_BVH2_TRAVERSE_H
#define VCT_BVH2_TRAVERSE_H

#include "accel/bvh/bvh_walk.h"

/* An instance: its inverse transform's three rows (mesh = rows . (p, 1)),
 * then (its mesh's root node, the mesh's first sorted triangle, the
 * instance's first triangle in the scene, 0) as uint4, then (pad per unit
 * of distance, the instance's reach, 0, 0): the mesh-space pad is
 * pad * (largest |origin coordinate| + reach). */
#define BVH2_INSTANCE_FLOAT4S 5

typedef struct accel_view {
    vct_accel_desc desc;              /* res.x: top-level nodes (0: nothing to hit) */
    __global const float4 *nodes;     /* BVH_NODE_FLOAT4S each: the top level's, then the meshes' */
    __global const float4 *instances; /* BVH2_INSTANCE_FLOAT4S each, in the top level's order */
    __global const uint *tri_ids;     /* every mesh's sorted triangles, as indices in the mesh */
    __global const float4 *tri_vertices; /* 3 per triangle, world space, in the scene's order */
} accel_view;

#define ACCEL_ARGS                                                                                 \
    vct_accel_desc accel, __global const float4 *bvh_nodes,                                        \
        __global const float4 *bvh_leaf_vertices, __global const uint *tri_ids,                    \
        __global const float4 *tri_vertices
#define ACCEL_VIEW() ((accel_view){accel, bvh_nodes, bvh_leaf_vertices, tri_ids, tri_vertices})

/* The ray against one instance's mesh: hits closer than *best update it. */
__attribute__((noinline)) int bvh2_instance(const accel_view *g, __global const float4 *inst,
                                            const ray_shear *shear, float3 org, float3 dir,
                                            float tmin, int any_hit, float *best, int *found,
                                            hit_record *hit) {
    const float4 r0 = inst[0], r1 = inst[1], r2 = inst[2];
    const uint4 at = as_uint4(inst[3]);
    const float4 padding = inst[4];
    const float3 o =
        (float3)(dot(r0.xyz, org) + r0.w, dot(r1.xyz, org) + r1.w, dot(r2.xyz, org) + r2.w);
    const float3 d = (float3)(dot(r0.xyz, dir), dot(r1.xyz, dir), dot(r2.xyz, dir));
    const float3 ao = fabs(org);
    const float pad = padding.x * (fmax(ao.x, fmax(ao.y, ao.z)) + padding.y);
    const float3 inv = select(1.0f / d, copysign((float3)(1e30f), d), fabs(d) < 1e-30f);
    const float3 inv_far = inv * (1.0f + 4.0f * FLT_EPSILON);
    /* near planes moved towards the ray's origin by the pad, far planes away */
    const float3 near_pad =
        (float3)(signbit(d.x) ? pad : -pad, signbit(d.y) ? pad : -pad, signbit(d.z) ? pad : -pad);
    const int nx = signbit(d.x) ? 1 : 0, ny = signbit(d.y) ? 3 : 2, nz = signbit(d.z) ? 5 : 4;
    uint stack_ref[BVH_STACK];
    float stack_t[BVH_STACK];
    int sp = 0;
    uint ref = 0u;
    for (;;) {
        if (!(ref & BVH_LEAF)) {
            __global const float4 *node = g->nodes + BVH_NODE_FLOAT4S * (at.x + ref);
            const float4 t0x = (node[nx] + near_pad.x - o.x) * inv.x,
                         t1x = (node[nx ^ 1] - near_pad.x - o.x) * inv_far.x;
            const float4 t0y = (node[ny] + near_pad.y - o.y) * inv.y,
                         t1y = (node[ny ^ 1] - near_pad.y - o.y) * inv_far.y;
            const float4 t0z = (node[nz] + near_pad.z - o.z) * inv.z,
                         t1z = (node[nz ^ 1] - near_pad.z - o.z) * inv_far.z;
            const float4 enter = fmax(fmax(t0x, t0y), fmax(t0z, (float4)(tmin)));
            const float4 leave = fmin(fmin(t1x, t1y), fmin(t1z, (float4)(*best)));
            if (bvh_descend(enter, enter <= leave, as_uint4(node[BVH_NODE_REFS]), &ref, stack_ref,
                            stack_t, &sp))
                continue;
        } else {
            /* The leaf's triangles four at a time from the scene's vertices,
             * lanes past its end repeating its first triangle. */
            const uint first = ref & BVH_LEAF_FIRST_MASK;
            const uint count = ((ref >> BVH_LEAF_COUNT_SHIFT) & 15u) + 1u;
            for (uint base = first; base < first + count; base += 4u) {
                uint ids[4];
                for (uint k = 0; k < 4u; ++k)
                    ids[k] = at.z + g->tri_ids[at.y + (base + k < first + count ? base + k : base)];
                __global const float4 *v0 = g->tri_vertices + 3 * ids[0],
                                      *v1 = g->tri_vertices + 3 * ids[1],
                                      *v2 = g->tri_vertices + 3 * ids[2],
                                      *v3 = g->tri_vertices + 3 * ids[3];
                const tri4_hits h =
                    bvh_leaf4(shear, v0[0], v0[1], v0[2], v1[0], v1[1], v1[2], v2[0], v2[1], v2[2],
                              v3[0], v3[1], v3[2], tmin, *best);
                if (!any(h.hit))
                    continue;
                const int4 masks = as_int4((float4)(v0[0].w, v1[0].w, v2[0].w, v3[0].w));
                if (bvh_take_hits(g->tri_vertices, &h,
                                  (int4)((int)ids[0], (int)ids[1], (int)ids[2], (int)ids[3]), masks,
                                  any_hit, best, found, hit))
                    return 1;
            }
        }
        for (;;) {
            if (sp == 0)
                return 0;
            --sp;
            if (stack_t[sp] <= *best) {
                ref = stack_ref[sp];
                break;
            }
        }
    }
}

/* Closest hit in (tmin, tmax]; any_hit: stop at the first one. */
__attribute__((noinline)) int accel_trace(const accel_view *g, float3 org, float3 dir, float tmin,
                                          float tmax, int any_hit, hit_record *hit) {
    if (g->desc.res.x == 0u)
        return 0;
    const ray_shear shear = ray_shear_make(org, dir);
    const float3 inv = select(1.0f / dir, copysign((float3)(1e30f), dir), fabs(dir) < 1e-30f);
    const float3 inv_far = inv * (1.0f + 4.0f * FLT_EPSILON), org_inv = org * inv,
                 org_inv_far = org * inv_far;
    const int nx = signbit(dir.x) ? 1 : 0, ny = signbit(dir.y) ? 3 : 2, nz = signbit(dir.z) ? 5 : 4;
    uint stack_ref[BVH_STACK];
    float stack_t[BVH_STACK];
    int sp = 0;
    uint ref = 0u;
    float best = tmax;
    int found = 0;
    for (;;) {
        if (!(ref & BVH_LEAF)) {
            __global const float4 *node = g->nodes + BVH_NODE_FLOAT4S * ref;
            float4 enter;
            const int4 hit =
                bvh_boxes(node, inv, inv_far, org_inv, org_inv_far, nx, ny, nz, tmin, best, &enter);
            if (bvh_descend(enter, hit, as_uint4(node[BVH_NODE_REFS]), &ref, stack_ref, stack_t,
                            &sp))
                continue;
        } else {
            const uint first = ref & BVH_LEAF_FIRST_MASK;
            const uint count = ((ref >> BVH_LEAF_COUNT_SHIFT) & 15u) + 1u;
            for (uint i = first; i < first + count; ++i)
                if (bvh2_instance(g, g->instances + BVH2_INSTANCE_FLOAT4S * i, &shear, org, dir,
                                  tmin, any_hit, &best, &found, hit))
                    return 1;
        }
        for (;;) {
            if (sp == 0)
                return found;
            --sp;
            if (stack_t[sp] <= best) {
                ref = stack_ref[sp];
                break;
            }
        }
    }
}

#endif
