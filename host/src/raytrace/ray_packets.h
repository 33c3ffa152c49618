/* Rays traced in packets (kernels/accel/ray_packet.h): what methods that
 * trace bundles of alike rays use, open to tests. */
#ifndef VCT_RAYTRACE_RAY_PACKETS_H
#define VCT_RAYTRACE_RAY_PACKETS_H

#include "vct/accel.h"

/* Rays per work-item of trace_ray_packets (TRACE_PACKET_SPAN in
 * kernels/render/raycast.cl): a packet on CPU devices. */
#define VCT_PACKET_RAYS 16u

/* vct_trace_rays with every VCT_PACKET_RAYS consecutive rays traced as one
 * packet (one by one where the device traces no packets). Closest hits are vct_trace_rays' bit for
 * bit; an any-hit ray reports t 0 where it is blocked (not by what), -1 where it is not. */
vct_status vct_trace_ray_packets(vct_context *ctx, const vct_accel *accel, const float *rays,
                                 uint32_t n, int any_hit, vct_hit *hits, vct_error *err);

#endif
