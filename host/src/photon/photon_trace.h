/* Photon tracing on the device (kernels/photon/photon_trace.cl): one pass of
 * photon paths into fixed slots, max_depth per path. */
#ifndef VCT_PHOTON_TRACE_H
#define VCT_PHOTON_TRACE_H

#include "accel/accel.h"
#include "photon/photon_sources.h"
#include "scene/scene_device.h"

/* Kinds, as in kernels/photon/photon.h. */
#define VCT_PHOTON_DIRECT 1u
#define VCT_PHOTON_INDIRECT 2u
#define VCT_PHOTON_CAUSTIC 4u
#define VCT_PHOTON_DIELECTRIC 8u /* with CAUSTIC: the specular bounces met a dielectric */

#define VCT_PHOTON_BYTES 48u /* 3 float4 */

typedef struct vct_photon_slots {
    cl_mem records; /* 3 float4 per slot */
    cl_mem kinds;   /* uint per slot: its kind, 0 where empty */
    uint32_t paths, depth;
} vct_photon_slots;

/* Bytes of slots for `paths` paths of `depth` bounces. */
uint64_t vct_photon_slot_bytes(uint32_t paths, uint32_t depth);
/* Makes slots for paths x depth photons; a size over the device's limit
 * fails naming what to lower. */
int vct_photon_slots_make(vct_context *ctx, const char *stage, uint32_t paths, uint32_t depth,
                          vct_photon_slots *slots, vct_error *err);
void vct_photon_slots_release(vct_context *ctx, vct_photon_slots *slots);

typedef struct vct_photon_trace_job {
    const vct_scene *scene;
    const vct_accel *accel;
    const vct_scene_buffers *buffers;
    const vct_photon_sources *sources;
    uint32_t seed, pass; /* the pass's photons: seed, pass and path index alone */
    uint32_t store_mask; /* kinds to keep */
} vct_photon_trace_job;

/* Enqueues one pass of slots->paths photon paths. */
int vct_photon_trace(vct_context *ctx, const char *stage, const vct_photon_trace_job *job,
                     vct_photon_slots *slots, vct_error *err);

#endif
