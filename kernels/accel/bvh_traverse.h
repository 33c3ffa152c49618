/* Ray traversal of the 4-wide BVH: one ray meets a node's four child boxes in
 * float4 slab tests (SSE/AVX lanes on CPU devices), enters the nearest child
 * it hits and pushes the others, farthest first, with their entry distance,
 * on a short private stack; closest-hit rays drop stacked nodes that lie
 * beyond the best hit so far. Box tests are conservative: boxes are padded by
 * the scene's tolerance when built and exit distances are widened by a few
 * float ulps (Ize 2013), so the watertight triangle test decides every hit. */
#ifndef VCT_BVH_TRAVERSE_H
#define VCT_BVH_TRAVERSE_H

#include "accel/bvh_node.h"
#include "accel/hit.h"
#include "accel/ray_tri.h"
#include "vct_types.h"

/* Deep enough for 3 pushes per level of a tree the host checked is no
 * deeper than BVH_MAX_DEPTH levels. */
#define BVH_MAX_DEPTH 40
#define BVH_STACK (3 * BVH_MAX_DEPTH)

typedef struct accel_view {
    vct_accel_desc desc;                  /* res.x: node count */
    __global const float4 *nodes;         /* BVH_NODE_FLOAT4S per node */
    __global const float4 *leaf_vertices; /* 3 per sorted triangle; w of the first: its index */
    __global const uint *tri_ids;         /* sorted position -> triangle */
    __global const float4 *tri_vertices;  /* 3 per triangle, in the scene's order */
} accel_view;

#define ACCEL_ARGS                                                                                 \
    vct_accel_desc accel, __global const float4 *bvh_nodes,                                        \
        __global const float4 *bvh_leaf_vertices, __global const uint *tri_ids,                    \
        __global const float4 *tri_vertices
#define ACCEL_VIEW() ((accel_view){accel, bvh_nodes, bvh_leaf_vertices, tri_ids, tri_vertices})

/* Swaps (a, ra) and (b, rb) when b is nearer. */
inline void bvh_order(float *a, uint *ra, float *b, uint *rb) {
    if (*b < *a) {
        const float t = *a;
        const uint r = *ra;
        *a = *b;
        *ra = *rb;
        *b = t;
        *rb = r;
    }
}

/* Closest hit in (tmin, tmax]; any_hit: stop at the first one (shadow rays). */
__attribute__((always_inline)) inline int accel_trace(const accel_view *g, float3 org, float3 dir,
                                                      float tmin, float tmax, int any_hit,
                                                      hit_record *hit) {
    if (g->desc.res.x == 0u)
        return 0;
    const ray_shear shear = ray_shear_make(org, dir);
    const float3 inv = 1.0f / dir; /* +-inf on zero components */
    /* Which of a node's lo/hi rows is the near plane on each axis; the sign
     * bit, not a comparison, so that -0 picks the side whose infinities make
     * an empty box miss. */
    const int nx = signbit(dir.x) ? 1 : 0, ny = signbit(dir.y) ? 3 : 2, nz = signbit(dir.z) ? 5 : 4;
    const float widen = 1.0f + 4.0f * FLT_EPSILON;
    uint stack_ref[BVH_STACK];
    float stack_t[BVH_STACK];
    int sp = 0;
    uint ref = 0u;
    float best = tmax;
    int found = 0;
    for (;;) {
        if (!(ref & BVH_LEAF)) {
            __global const float4 *node = g->nodes + BVH_NODE_FLOAT4S * ref;
            /* fmin/fmax drop the NaN of 0 * inf, so axis-parallel rays work. */
            const float4 t0x = (node[nx] - org.x) * inv.x, t1x = (node[nx ^ 1] - org.x) * inv.x;
            const float4 t0y = (node[ny] - org.y) * inv.y, t1y = (node[ny ^ 1] - org.y) * inv.y;
            const float4 t0z = (node[nz] - org.z) * inv.z, t1z = (node[nz ^ 1] - org.z) * inv.z;
            const float4 enter = fmax(fmax(t0x, t0y), fmax(t0z, (float4)(tmin)));
            const float4 leave = fmin(fmin(fmin(t1x, t1y), t1z) * widen, (float4)(best));
            const int4 hit = enter <= leave;
            const int count = -(hit.x + hit.y + hit.z + hit.w);
            if (count > 0) {
                /* Missed children go last; a sorting network puts the rest
                 * nearest first, in registers. */
                const float4 t = select((float4)(INFINITY), enter, hit);
                const uint4 refs = as_uint4(node[BVH_NODE_REFS]);
                float t0 = t.x, t1 = t.y, t2 = t.z, t3 = t.w;
                uint r0 = refs.x, r1 = refs.y, r2 = refs.z, r3 = refs.w;
                bvh_order(&t0, &r0, &t1, &r1);
                bvh_order(&t2, &r2, &t3, &r3);
                bvh_order(&t0, &r0, &t2, &r2);
                bvh_order(&t1, &r1, &t3, &r3);
                bvh_order(&t1, &r1, &t2, &r2);
                /* The others onto the stack farthest first, so that they
                 * come off nearest first. */
                if (count > 3) {
                    stack_ref[sp] = r3;
                    stack_t[sp++] = t3;
                }
                if (count > 2) {
                    stack_ref[sp] = r2;
                    stack_t[sp++] = t2;
                }
                if (count > 1) {
                    stack_ref[sp] = r1;
                    stack_t[sp++] = t1;
                }
                ref = r0;
                continue;
            }
        } else {
            const uint first = ref & BVH_LEAF_FIRST_MASK;
            const uint end = first + ((ref >> BVH_LEAF_COUNT_SHIFT) & 15u) + 1u;
            for (uint i = first; i < end; ++i) {
                const float4 a = g->leaf_vertices[3 * i];
                float t, u, v;
                if (ray_triangle(&shear, a.xyz, g->leaf_vertices[3 * i + 1].xyz,
                                 g->leaf_vertices[3 * i + 2].xyz, tmin, best, &t, &u, &v)) {
                    best = t;
                    found = 1;
                    hit->t = t;
                    hit->u = u;
                    hit->v = v;
                    hit->tri = as_uint(a.w);
                    if (any_hit)
                        return 1;
                }
            }
        }
        /* Next: the nearest stacked node that can still hold a closer hit. */
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
