/* A packet of up to PACKET_RAYS rays traced together (accel_trace_packet,
 * accel.h): rays that start near one another and run alike, such as a
 * pixel's camera rays, visit the same nodes and triangles (rays that part
 * early, such as shadow rays to points spread over a lamp, gain nothing). On CPU devices (VCT_PACKETS) the 4-wide BVH
 * meets all of them at once, one vector lane per ray (bvh/bvh_packet.h);
 * elsewhere, and on the other structures, each ray is traced alone. Either
 * way each ray gets exactly the hit accel_trace gives it. */
#ifndef VCT_RAY_PACKET_H
#define VCT_RAY_PACKET_H

#include "accel/hit.h"

/* Where packets are not traced at once, a packet is one ray: no arrays of
 * 16 in private memory (GPU registers) that would hold one ray's numbers. */
#ifdef VCT_PACKETS
#define PACKET_RAYS 16u
#else
#define PACKET_RAYS 1u
#endif

/* Rays 0 .. count - 1 by component, as separate arrays so that a packet
 * loads each as one vector. */
typedef struct ray_packet {
    float ox[PACKET_RAYS], oy[PACKET_RAYS], oz[PACKET_RAYS];
    float dx[PACKET_RAYS], dy[PACKET_RAYS], dz[PACKET_RAYS];
    float tmin[PACKET_RAYS], tmax[PACKET_RAYS];
    uint count;
} ray_packet;

/* Ray k of the packet: from org along dir, hits in (tmin, tmax]. */
inline void packet_set(ray_packet *r, uint k, float3 org, float3 dir, float tmin, float tmax) {
    r->ox[k] = org.x;
    r->oy[k] = org.y;
    r->oz[k] = org.z;
    r->dx[k] = dir.x;
    r->dy[k] = dir.y;
    r->dz[k] = dir.z;
    r->tmin[k] = tmin;
    r->tmax[k] = tmax;
}

inline float3 packet_org(const ray_packet *r, uint k) {
    return (float3)(r->ox[k], r->oy[k], r->oz[k]);
}

inline float3 packet_dir(const ray_packet *r, uint k) {
    return (float3)(r->dx[k], r->dy[k], r->dz[k]);
}

#endif
