/* The one acceleration interface of every ray query: ACCEL_ARGS (the first
 * five arguments of a kernel that traces rays, set by the host's
 * vct_accel_set_args), ACCEL_VIEW() (the view made of them) and accel_trace
 * (closest or any hit). -DVCT_ACCEL_BVH selects the 4-wide BVH,
 * -DVCT_ACCEL_BVH2 its two-level form (a BVH per mesh under one over the
 * instances), otherwise the uniform triangle grid; both keep the triangles' vertices in the scene's
 * order (tri_vertices) and the scene's extent and tolerance in desc. */
#ifndef VCT_ACCEL_H
#define VCT_ACCEL_H

/* Shared headers first: the host's include expansion takes each file once,
 * wherever it first appears, even inside a branch that is not compiled. */
#include "accel/alpha_mask.h"
#include "accel/bvh/bvh_node.h"
#include "accel/bvh/bvh_walk.h"
#include "accel/hit.h"
#include "accel/ray_tri.h"
#include "accel/ray_packet.h"
#include "accel/ray_tri4.h"
#include "scene/tri_normal.h"
#include "vct_types.h"

#if defined(VCT_ACCEL_BVH2)
#include "accel/bvh/bvh2_traverse.h"
#elif defined(VCT_ACCEL_BVH)
#include "accel/bvh/bvh_traverse.h"
#else
#include "accel/grid_traverse.h"
#endif

/* accel_trace_packet: the 4-wide BVH's own on CPU devices, else each ray
 * alone (ray_packet.h). */
#include "accel/bvh/bvh_packet.h"
#if !(defined(VCT_PACKETS) && defined(VCT_ACCEL_BVH))
inline void accel_trace_packet(const accel_view *g, ray_packet *r, int any_hit, hit_record *hits,
                               int *found) {
    for (uint k = 0; k < r->count; ++k)
        found[k] = accel_trace(g, packet_org(r, k), packet_dir(r, k), r->tmin[k], r->tmax[k],
                               any_hit, &hits[k]);
}
#endif

/* How many alike rays a method gathers before tracing them together: a
 * packet's worth (one ray where packets are not traced at once). */
#define ACCEL_GROUP PACKET_RAYS

/* Closest hits of n (at most PACKET_RAYS) rays from org along dirs[k]. */
inline void accel_trace_from(const accel_view *g, float3 org, const float3 *dirs, uint n,
                             hit_record *hits, int *found) {
    ray_packet packet;
    packet.count = n;
    for (uint k = 0; k < n; ++k)
        packet_set(&packet, k, org, dirs[k], 0.0f, INFINITY);
    accel_trace_packet(g, &packet, 0, hits, found);
}

/* Where a hit lies: position from barycentrics, unit geometric normal ng and
 * the normal n turned towards the incoming ray; front: the ray arrived on
 * ng's side. 0 for a zero-area triangle (which traversal never reports). */
inline int surface_hit(const accel_view *g, const hit_record *h, float3 dir, float3 *p, float3 *ng,
                       float3 *n, int *front) {
    const float3 a = g->tri_vertices[3 * h->tri].xyz, b = g->tri_vertices[3 * h->tri + 1].xyz,
                 c = g->tri_vertices[3 * h->tri + 2].xyz;
    const float3 cr = tri_normal(a, b, c);
    const float len = length(cr);
    if (!(len > 0.0f))
        return 0;
    *ng = cr / len;
    *front = dot(*ng, dir) < 0.0f;
    *n = *front ? *ng : -*ng;
    *p = a + h->u * (b - a) + h->v * (c - a);
    return 1;
}

#endif
