/* A packet of rays through the 4-wide BVH at once, one float16 lane per ray
 * (VCT_PACKETS, set for CPU devices): a node's four boxes are met by all
 * the packet's rays, four vector tests, and a leaf's triangles one at a
 * time by all of them; the packet enters a child any of its rays meets,
 * nearest first, and keeps each ray's entry distance on the stack so that
 * a ray skips what lies beyond its best hit. Every ray meets each box and
 * triangle with bvh_traverse.h's operations on its own numbers (the same
 * near planes, slab distances, shear and watertight test), so the closest
 * hit, taken by the same rule (nearest, then the lower triangle index), is
 * the one accel_trace finds. An any-hit ray reports whether it is blocked,
 * not by what. */
#ifndef VCT_BVH_PACKET_H
#define VCT_BVH_PACKET_H

#if defined(VCT_PACKETS) && defined(VCT_ACCEL_BVH)

#include "accel/alpha_mask.h"
#include "accel/bvh/bvh_node.h"
#include "accel/bvh/bvh_walk.h"
#include "accel/hit.h"
#include "accel/ray_packet.h"
#include "accel/ray_tri.h"

inline float packet_min(float16 v) {
    const float8 a = fmin(v.lo, v.hi);
    const float4 b = fmin(a.lo, a.hi);
    const float2 c = fmin(b.lo, b.hi);
    return fmin(c.x, c.y);
}

/* The rays' shears (ray_shear_make per lane) as lanes. */
typedef struct packet_shear {
    float16 ox, oy, oz, c0x, c0y, c0z, c1x, c1y, c1z, c2x, c2y, c2z, sz;
} packet_shear;

/* 1 in the lanes where k is axis, else 0. */
inline float16 packet_unit(int16 k, int axis) {
    return select((float16)(0.0f), (float16)(1.0f), k == axis);
}

/* ray_shear_make in every lane, with its operations: the axis the
 * direction is longest along (kz), the other two in turn (kx, ky; swapped
 * where the direction points down kz, to keep the winding), and the
 * matrix's entries as e_kx - sx e_kz, e_ky - sy e_kz and e_kz. */
inline packet_shear packet_shear_make(float16 ox, float16 oy, float16 oz, float16 dx, float16 dy,
                                      float16 dz) {
    const float16 ax = fabs(dx), ay = fabs(dy), az = fabs(dz);
    const int16 kz = select(select((int16)(2), (int16)(1), ay > az),
                            select((int16)(2), (int16)(0), ax > az), ax > ay);
    int16 kx = select(kz + 1, (int16)(0), kz == 2);
    int16 ky = select(kx + 1, (int16)(0), kx == 2);
    const float16 d_z = select(select(dz, dy, kz == 1), dx, kz == 0);
    const int16 flip = d_z < 0.0f;
    const int16 swap = kx;
    kx = select(kx, ky, flip);
    ky = select(ky, swap, flip);
    const float16 d_x = select(select(dz, dy, kx == 1), dx, kx == 0),
                  d_y = select(select(dz, dy, ky == 1), dx, ky == 0);
    const float16 sx = d_x / d_z, sy = d_y / d_z;
    packet_shear p;
    p.ox = ox;
    p.oy = oy;
    p.oz = oz;
    p.c0x = packet_unit(kx, 0) - sx * packet_unit(kz, 0);
    p.c0y = packet_unit(ky, 0) - sy * packet_unit(kz, 0);
    p.c0z = packet_unit(kz, 0);
    p.c1x = packet_unit(kx, 1) - sx * packet_unit(kz, 1);
    p.c1y = packet_unit(ky, 1) - sy * packet_unit(kz, 1);
    p.c1z = packet_unit(kz, 1);
    p.c2x = packet_unit(kx, 2) - sx * packet_unit(kz, 2);
    p.c2y = packet_unit(ky, 2) - sy * packet_unit(kz, 2);
    p.c2z = packet_unit(kz, 2);
    p.sz = 1.0f / d_z;
    return p;
}

/* Vertex v in every ray's sheared frame (ray_sheared4's operations). */
inline void packet_sheared(const packet_shear *s, float4 v, float16 *x, float16 *y, float16 *z) {
    const float16 px = v.x - s->ox, py = v.y - s->oy, pz = v.z - s->oz;
    *x = (px * s->c0x + py * s->c1x) + pz * s->c2x;
    *y = (px * s->c0y + py * s->c1y) + pz * s->c2y;
    *z = (px * s->c0z + py * s->c1z) + pz * s->c2z;
}

/* The watertight test of one triangle by every lane in `lanes` (ray_tri4.h's
 * operations per lane): t, u, v, and the lanes that hit in (tmin, best]. */
__attribute__((always_inline)) inline int16 packet_triangle(const packet_shear *s, float4 a,
                                                            float4 b, float4 c, float16 tmin,
                                                            float16 best, int16 lanes, float16 *t,
                                                            float16 *u, float16 *v) {
    float16 Ax, Ay, Az, Bx, By, Bz, Cx, Cy, Cz;
    packet_sheared(s, a, &Ax, &Ay, &Az);
    packet_sheared(s, b, &Bx, &By, &Bz);
    packet_sheared(s, c, &Cx, &Cy, &Cz);
    float16 U = Cx * By - Cy * Bx;
    float16 V = Ax * Cy - Ay * Cx;
    float16 W = Bx * Ay - By * Ax;
#ifdef cl_khr_fp64
    const int16 zero = (U == 0.0f || V == 0.0f || W == 0.0f) && lanes;
    if (any(zero)) {
        float au[PACKET_RAYS], av[PACKET_RAYS], aw[PACKET_RAYS];
        int az[PACKET_RAYS];
        float ax_[PACKET_RAYS], ay_[PACKET_RAYS], bx_[PACKET_RAYS], by_[PACKET_RAYS],
            cx_[PACKET_RAYS], cy_[PACKET_RAYS];
        vstore16(U, 0, au);
        vstore16(V, 0, av);
        vstore16(W, 0, aw);
        vstore16(zero, 0, az);
        vstore16(Ax, 0, ax_);
        vstore16(Ay, 0, ay_);
        vstore16(Bx, 0, bx_);
        vstore16(By, 0, by_);
        vstore16(Cx, 0, cx_);
        vstore16(Cy, 0, cy_);
        for (uint k = 0; k < PACKET_RAYS; ++k)
            if (az[k]) {
                const double ax = ax_[k], ay = ay_[k], bx = bx_[k], by = by_[k], cx = cx_[k],
                             cy = cy_[k];
                au[k] = (float)(cx * by - cy * bx);
                av[k] = (float)(ax * cy - ay * cx);
                aw[k] = (float)(bx * ay - by * ax);
            }
        U = vload16(0, au);
        V = vload16(0, av);
        W = vload16(0, aw);
    }
#endif
    const int16 outside = (U < 0.0f || V < 0.0f || W < 0.0f) && (U > 0.0f || V > 0.0f || W > 0.0f);
    const float16 det = U + V + W;
    const float16 T = U * (s->sz * Az) + V * (s->sz * Bz) + W * (s->sz * Cz);
    const float16 inv = 1.0f / det;
    *t = T * inv;
    *u = V * inv;
    *v = W * inv;
    return lanes && !outside && det != 0.0f && *t > tmin && *t <= best;
}

/* The lanes of `take` whose hit (at u, v) the triangle's alpha mask `slot`
 * lets through are cleared. */
inline int16 packet_unmasked(__global const float4 *tri_vertices, uint slot, int16 take, float16 u,
                             float16 v) {
    if (slot == 0u || !any(take))
        return take;
    int keep[PACKET_RAYS];
    float au[PACKET_RAYS], av[PACKET_RAYS];
    vstore16(take, 0, keep);
    vstore16(u, 0, au);
    vstore16(v, 0, av);
    for (uint k = 0; k < PACKET_RAYS; ++k)
        if (keep[k] && accel_mask_test(tri_vertices, slot, au[k], av[k]))
            keep[k] = 0;
    return vload16(0, keep);
}

/* Child c's entry distance per lane, NaN in the lanes (of `lanes`) that
 * miss its box. */
#define PACKET_CHILD(c)                                                                            \
    {                                                                                              \
        const float16 lo_x = (float16)(lane_get(r0, c)), hi_x = (float16)(lane_get(r1, c));        \
        const float16 lo_y = (float16)(lane_get(r2, c)), hi_y = (float16)(lane_get(r3, c));        \
        const float16 lo_z = (float16)(lane_get(r4, c)), hi_z = (float16)(lane_get(r5, c));        \
        const float16 t0x = bvh_slab(select(lo_x, hi_x, neg_x), inv_x, org_inv_x),                 \
                      t1x = bvh_slab(select(hi_x, lo_x, neg_x), inv_far_x, org_inv_far_x);         \
        const float16 t0y = bvh_slab(select(lo_y, hi_y, neg_y), inv_y, org_inv_y),                 \
                      t1y = bvh_slab(select(hi_y, lo_y, neg_y), inv_far_y, org_inv_far_y);         \
        const float16 t0z = bvh_slab(select(lo_z, hi_z, neg_z), inv_z, org_inv_z),                 \
                      t1z = bvh_slab(select(hi_z, lo_z, neg_z), inv_far_z, org_inv_far_z);         \
        const float16 enter = fmax(fmax(t0x, t0y), fmax(t0z, tmin));                               \
        const float16 leave = fmin(fmin(t1x, t1y), fmin(t1z, best));                               \
        entry[c] = select((float16)(NAN), enter, enter <= leave && lanes);                         \
        key[c] = packet_min(entry[c]);                                                             \
    }

/* One lane's slab set-up (accel_trace's): inverse with huge finite values
 * for near-zero components, widened for the far planes. */
#define PACKET_AXIS(a)                                                                             \
    const float16 d_##a = vload16(0, r->d##a), o_##a = vload16(0, r->o##a);                        \
    const float16 inv_##a =                                                                        \
        select(1.0f / d_##a, copysign((float16)(1e30f), d_##a), fabs(d_##a) < 1e-30f);             \
    const float16 inv_far_##a = inv_##a * widen, org_inv_##a = o_##a * inv_##a,                    \
                  org_inv_far_##a = o_##a * inv_far_##a;                                           \
    const int16 neg_##a = signbit(d_##a);

/* Fewer rays than this are traced one by one: a packet's lanes cost the
 * same, however few of them are in use (the path tracer at 2 samples a
 * launch: 5 % slower in packets, at 4 as fast). */
#define PACKET_MIN_RAYS 4u

/* Hits of the packet's rays: found[k] and hits[k] for ray k < count (an
 * any-hit ray's record is not to be read). The lanes past the count are
 * filled with copies of ray 0 that meet nothing. */
__attribute__((noinline)) void accel_trace_packet(const accel_view *g, ray_packet *r, int any_hit,
                                                  hit_record *hits, int *found) {
    if (r->count < PACKET_MIN_RAYS) {
        for (uint k = 0; k < r->count; ++k)
            found[k] = accel_trace(g, packet_org(r, k), packet_dir(r, k), r->tmin[k], r->tmax[k],
                                   any_hit, &hits[k]);
        return;
    }
    for (uint k = 0; k < r->count; ++k)
        found[k] = 0;
    if (g->desc.res.x == 0u)
        return;
    for (uint k = r->count; k < PACKET_RAYS; ++k) /* finite numbers in the unused lanes */
        packet_set(r, k, packet_org(r, 0u), packet_dir(r, 0u), 0.0f, -1.0f);
    const float widen = 1.0f + 4.0f * FLT_EPSILON;
    PACKET_AXIS(x)
    PACKET_AXIS(y)
    PACKET_AXIS(z)
    const packet_shear shear = packet_shear_make(o_x, o_y, o_z, d_x, d_y, d_z);
    const float16 tmin = vload16(0, r->tmin);
    float16 best = vload16(0, r->tmax), hit_t = best, hit_u = 0.0f, hit_v = 0.0f;
    uint16 hit_tri = 0u;
    int16 hit_found = 0;
    uint stack_ref[BVH_STACK];
    float16 stack_t[BVH_STACK];
    int sp = 0;
    uint ref = 0u;
    const int16 lane_ids = (int16)(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
    float16 cur = select((float16)(NAN), tmin, lane_ids < (int)r->count);
    for (;;) {
        const int16 lanes = cur <= best;
        if (!(ref & BVH_LEAF)) {
            __global const float4 *node = g->nodes + BVH_NODE_FLOAT4S * ref;
            const float4 r0 = node[0], r1 = node[1], r2 = node[2], r3 = node[3], r4 = node[4],
                         r5 = node[5];
            const uint4 refs = as_uint4(node[BVH_NODE_REFS]);
            float16 entry[4];
            float key[4];
            PACKET_CHILD(0)
            PACKET_CHILD(1)
            PACKET_CHILD(2)
            PACKET_CHILD(3)
            /* nearest first (a NaN key, a child no lane meets, last) */
            float k0 = isnan(key[0]) ? INFINITY : key[0], k1 = isnan(key[1]) ? INFINITY : key[1],
                  k2 = isnan(key[2]) ? INFINITY : key[2], k3 = isnan(key[3]) ? INFINITY : key[3];
            uint c0 = 0u, c1 = 1u, c2 = 2u, c3 = 3u;
            const int count = !isnan(key[0]) + !isnan(key[1]) + !isnan(key[2]) + !isnan(key[3]);
            if (count > 0) {
                bvh_order(&k0, &c0, &k1, &c1);
                bvh_order(&k2, &c2, &k3, &c3);
                bvh_order(&k0, &c0, &k2, &c2);
                bvh_order(&k1, &c1, &k3, &c3);
                bvh_order(&k1, &c1, &k2, &c2);
                /* the farther ones on the stack, farthest first */
                const uint order[4] = {c0, c1, c2, c3};
                for (int i = count - 1; i > 0; --i) {
                    stack_ref[sp] = lane_geti(as_int4(refs), (int)order[i]);
                    stack_t[sp++] = entry[order[i]];
                }
                ref = lane_geti(as_int4(refs), (int)c0);
                cur = entry[c0];
                continue;
            }
        } else {
            const uint first = ref & BVH_LEAF_FIRST_MASK;
            const uint count = ((ref >> BVH_LEAF_COUNT_SHIFT) & 15u) + 1u;
            for (uint i = first; i < first + count; ++i) {
                __global const float4 *lv = g->leaf_vertices + 3 * i;
                const float4 a = lv[0], b = lv[1], c = lv[2];
                float16 t, u, v;
                const int16 hit = packet_triangle(&shear, a, b, c, tmin, best, lanes, &t, &u, &v);
                if (!any(hit))
                    continue;
                const uint id = as_uint(a.w);
                int16 take =
                    hit && (t < best || (t == best && (!hit_found || (uint16)(id) < hit_tri)));
                take = packet_unmasked(g->tri_vertices, as_uint(b.w), take, u, v);
                hit_found = hit_found || take;
                hit_t = select(hit_t, t, take);
                hit_u = select(hit_u, u, take);
                hit_v = select(hit_v, v, take);
                hit_tri = select(hit_tri, (uint16)(id), take);
                /* a blocked any-hit ray leaves the packet */
                best = select(best, any_hit ? (float16)(-INFINITY) : t, take);
            }
        }
        /* Next: the nearest stacked node some lane may still find a closer hit in. */
        for (;;) {
            if (sp == 0) {
                int f[PACKET_RAYS];
                uint tri[PACKET_RAYS];
                float ft[PACKET_RAYS], fu[PACKET_RAYS], fv[PACKET_RAYS];
                vstore16(hit_found, 0, f);
                vstore16(hit_tri, 0, tri);
                vstore16(hit_t, 0, ft);
                vstore16(hit_u, 0, fu);
                vstore16(hit_v, 0, fv);
                for (uint k = 0; k < r->count; ++k) {
                    found[k] = f[k] != 0;
                    if (found[k] && !any_hit)
                        hits[k] = (hit_record){ft[k], fu[k], fv[k], tri[k]};
                }
                return;
            }
            --sp;
            if (any(stack_t[sp] <= best)) {
                ref = stack_ref[sp];
                cur = stack_t[sp];
                break;
            }
        }
    }
}

#endif
#endif
