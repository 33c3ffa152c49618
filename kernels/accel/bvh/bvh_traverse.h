/* Ray traversal of the 4-wide BVH: one ray meets a node's four child boxes in
 * float4 slab tests (SSE/AVX lanes on CPU devices), enters the nearest child
 * it hits and pushes the others, farthest first, with their entry distance,
 * on a short private stack; closest-hit rays drop stacked nodes that lie
 * beyond the best hit so far. Box tests are conservative: boxes are padded by
 * the scene's tolerance when built and exit distances are widened by a few
 * float ulps (Ize 2013), so the watertight triangle test decides every hit.
 * The slab distances are node * inv - org * inv, one fma each where fma is
 * fast, and the far planes' widening is folded into their inverse: that
 * shortens the chain from a node's load to the next node's address, and on 2
 * PoCL cores the path tracer runs about 4 % faster than with
 * (node - org) * inv. */
#ifndef VCT_BVH_TRAVERSE_H
#define VCT_BVH_TRAVERSE_H

#include "accel/bvh/bvh_walk.h"

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

/* Closest hit in (tmin, tmax]; any_hit: stop at the first one (shadow rays).
 * Not inlined: a method calls it from several places, and one copy of the
 * loop keeps the kernels small (the path tracer runs 10-25 % faster on PoCL). */
__attribute__((noinline)) int accel_trace(const accel_view *g, float3 org, float3 dir, float tmin,
                                          float tmax, int any_hit, hit_record *hit) {
    if (g->desc.res.x == 0u)
        return 0;
    const ray_shear shear = ray_shear_make(org, dir);
    /* Slab distances as node * inv - org * inv (bvh_slab). Each rounding costs at
     * most half an ulp of a coordinate of the scene or of the origin, below
     * the boxes' padding (4 ulps of the scene's largest coordinate) for
     * origins inside the scene, as (node - org) costs for origins outside
     * it. A zero component (or one whose inverse would overflow) gets a huge
     * finite inverse, not an infinity whose inf - inf would be NaN: its slab
     * still spans -+huge or misses. */
    const float3 inv = select(1.0f / dir, copysign((float3)(1e30f), dir), fabs(dir) < 1e-30f);
    const float widen = 1.0f + 4.0f * FLT_EPSILON;
    const float3 inv_far = inv * widen, org_inv = org * inv, org_inv_far = org * inv_far;
    /* Which of a node's lo/hi rows is the near plane on each axis; the sign
     * bit, not a comparison, so that -0 picks the side whose infinities make
     * an empty box miss. */
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
            /* The leaf's triangles four at a time, lanes past its end
             * repeating its first triangle. */
            const uint first = ref & BVH_LEAF_FIRST_MASK;
            const uint count = ((ref >> BVH_LEAF_COUNT_SHIFT) & 15u) + 1u;
            for (uint base = first; base < first + count; base += 4u) {
                __global const float4 *lv = g->leaf_vertices + 3 * base;
                const uint left = min(4u, first + count - base);
                const float4 a0 = lv[0], b0 = lv[1], c0 = lv[2];
                const float4 a1 = left > 1u ? lv[3] : a0, b1 = left > 1u ? lv[4] : b0,
                             c1 = left > 1u ? lv[5] : c0;
                const float4 a2 = left > 2u ? lv[6] : a0, b2 = left > 2u ? lv[7] : b0,
                             c2 = left > 2u ? lv[8] : c0;
                const float4 a3 = left > 3u ? lv[9] : a0, b3 = left > 3u ? lv[10] : b0,
                             c3 = left > 3u ? lv[11] : c0;
                const tri4_hits h =
                    bvh_leaf4(&shear, a0, b0, c0, a1, b1, c1, a2, b2, c2, a3, b3, c3, tmin, best);
                if (!any(h.hit))
                    continue;
                if (bvh_take_hits(g->tri_vertices, &h, as_int4((float4)(a0.w, a1.w, a2.w, a3.w)),
                                  as_int4((float4)(b0.w, b1.w, b2.w, b3.w)), any_hit, &best, &found,
                                  hit))
                    return 1;
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
