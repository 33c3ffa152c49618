/* What both BVH traversals (one level, bvh_traverse.h; two, bvh2_traverse.h)
 * do at a node and at a leaf: the slab test's arithmetic, the children met
 * in order onto the stack, four triangles tested at once and their hits
 * taken in order. */
#ifndef VCT_BVH_WALK_H
#define VCT_BVH_WALK_H

#include "accel/alpha_mask.h"
#include "accel/bvh/bvh_node.h"
#include "accel/hit.h"
#include "accel/ray_tri.h"
#include "accel/ray_tri4.h"
#include "vct_types.h"

/* Deep enough for 3 pushes per level of a tree the host checked is no
 * deeper than BVH_MAX_DEPTH levels. */
#define BVH_MAX_DEPTH 40
#define BVH_STACK (3 * BVH_MAX_DEPTH)

/* a * b - c as one fused operation where the device has it in hardware
 * (VCT_FAST_FMA, which the engine sets from CL_FP_FMA), else a product and a
 * sum, which is as conservative (see accel_trace) and never emulated. */
#if defined(VCT_FAST_FMA) || defined(FP_FAST_FMAF)
#define bvh_slab(a, b, c) fma((a), (b), -(c))
#else
#define bvh_slab(a, b, c) mad((a), (b), -(c))
#endif

/* A ray's slab test against a node's four child boxes (rows nx, ny, nz the
 * near planes; inv_far and org_inv_far widened for the far planes): the
 * entry distances in *enter, and which boxes it meets within (tmin, best]. */
__attribute__((always_inline)) inline int4 bvh_boxes(__global const float4 *node, float3 inv,
                                                     float3 inv_far, float3 org_inv,
                                                     float3 org_inv_far, int nx, int ny, int nz,
                                                     float tmin, float best, float4 *enter) {
    const float4 t0x = bvh_slab(node[nx], inv.x, org_inv.x),
                 t1x = bvh_slab(node[nx ^ 1], inv_far.x, org_inv_far.x);
    const float4 t0y = bvh_slab(node[ny], inv.y, org_inv.y),
                 t1y = bvh_slab(node[ny ^ 1], inv_far.y, org_inv_far.y);
    const float4 t0z = bvh_slab(node[nz], inv.z, org_inv.z),
                 t1z = bvh_slab(node[nz ^ 1], inv_far.z, org_inv_far.z);
    *enter = fmax(fmax(t0x, t0y), fmax(t0z, (float4)(tmin)));
    const float4 leave = fmin(fmin(t1x, t1y), fmin(t1z, (float4)(best)));
    return *enter <= leave;
}

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

/* The children a node's slab test met (hit, at distances enter): *ref
 * takes the nearest, the stack the others, farthest first so that they
 * come off nearest first. 0 when none was met. */
__attribute__((always_inline)) inline int bvh_descend(float4 enter, int4 hit, uint4 refs, uint *ref,
                                                      uint *stack_ref, float *stack_t, int *sp) {
    const int count = -(hit.x + hit.y + hit.z + hit.w);
    if (count == 0)
        return 0;
    /* Missed children go last; a sorting network puts the rest nearest
     * first, in registers. */
    const float4 t = select((float4)(INFINITY), enter, hit);
    float t0 = t.x, t1 = t.y, t2 = t.z, t3 = t.w;
    uint r0 = refs.x, r1 = refs.y, r2 = refs.z, r3 = refs.w;
    bvh_order(&t0, &r0, &t1, &r1);
    bvh_order(&t2, &r2, &t3, &r3);
    bvh_order(&t0, &r0, &t2, &r2);
    bvh_order(&t1, &r1, &t3, &r3);
    bvh_order(&t1, &r1, &t2, &r2);
    if (count > 3) {
        stack_ref[*sp] = r3;
        stack_t[(*sp)++] = t3;
    }
    if (count > 2) {
        stack_ref[*sp] = r2;
        stack_t[(*sp)++] = t2;
    }
    if (count > 1) {
        stack_ref[*sp] = r1;
        stack_t[(*sp)++] = t1;
    }
    *ref = r0;
    return 1;
}

/* The watertight test of four triangles (vertices a, b, c of each) at once. */
__attribute__((always_inline)) inline tri4_hits
bvh_leaf4(const ray_shear *shear, float4 a0, float4 b0, float4 c0, float4 a1, float4 b1, float4 c1,
          float4 a2, float4 b2, float4 c2, float4 a3, float4 b3, float4 c3, float tmin,
          float best) {
    return ray_triangle4(shear, (float4)(a0.x, a1.x, a2.x, a3.x), (float4)(a0.y, a1.y, a2.y, a3.y),
                         (float4)(a0.z, a1.z, a2.z, a3.z), (float4)(b0.x, b1.x, b2.x, b3.x),
                         (float4)(b0.y, b1.y, b2.y, b3.y), (float4)(b0.z, b1.z, b2.z, b3.z),
                         (float4)(c0.x, c1.x, c2.x, c3.x), (float4)(c0.y, c1.y, c2.y, c3.y),
                         (float4)(c0.z, c1.z, c2.z, c3.z), tmin, best);
}

/* Four triangles' hits (ids and alpha-mask slots per lane) taken in lane
 * order, as one at a time would take them: each one no farther than the
 * best so far and not masked out becomes the hit. 1 when any_hit found one. */
__attribute__((always_inline)) inline int bvh_take_hits(__global const float4 *tri_vertices,
                                                        const tri4_hits *h, int4 ids, int4 masks,
                                                        int any_hit, float *best, int *found,
                                                        hit_record *hit) {
    for (int k = 0; k < 4; ++k) {
        const float t = lane_get(h->t, k);
        /* of two hits at the same distance the lower triangle index, so
         * that the hit does not depend on the tree's order (a refit tree
         * and a rebuilt one agree) */
        const uint id = (uint)lane_geti(ids, k);
        if (lane_geti(h->hit, k) && (t < *best || (t == *best && (!*found || id < hit->tri))) &&
            !accel_masked(tri_vertices, (uint)lane_geti(masks, k), lane_get(h->u, k),
                          lane_get(h->v, k))) {
            *best = t;
            *found = 1;
            hit->t = t;
            hit->u = lane_get(h->u, k);
            hit->v = lane_get(h->v, k);
            hit->tri = id;
            if (any_hit)
                return 1;
        }
    }
    return 0;
}

#endif
