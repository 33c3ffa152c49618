/* vct: one frame on several OpenCL devices at once.
 *
 * A group is one context per device (any platforms together), each with its
 * own queue, program cache and copy of the scene's structures, built there.
 * Path tracing is split by samples: each device takes the next chunk of the
 * sample sequence whenever it finishes one, into exact sums that add up to
 * the one-device sums bit for bit. The other methods split the image into
 * row bands shared by each device's measured time per row: rebalanced after
 * every render (damped, with a dead band), and a device too slow to pay for
 * its part gets none. A device that fails is dropped, said once, and its
 * work is done again by the others: the frame completes, unchanged. */
#ifndef VCT_API_MULTI_H
#define VCT_API_MULTI_H

#include "vct/export.h"

#include "vct/accel.h"
#include "vct/render.h"
#include "vct/partial.h"
#include "vct/voxels.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct vct_group vct_group;

/* list: comma-separated device selectors (an index in `vct devices`, or a
 * name as vct_context_create takes), or "all", "gpu" (every GPU), "cpu"
 * (every CPU); NULL or "": $VCT_DEVICE, else vct_context_create's choice.
 * A device that does not exist, or one named twice, is refused with the list
 * of devices there are. */
VCT_API vct_group *vct_group_create(const char *list, vct_error *err);
VCT_API void vct_group_release(vct_group *group);
VCT_API int vct_group_size(const vct_group *group);
VCT_API vct_context *vct_group_context(vct_group *group, int device);

/* What every device builds for the renders. */
typedef struct vct_group_build {
    vct_accel_options accel;
    /* Cone tracing's voxels, when the plan reads them (NULL: none). */
    const vct_plan *plan;
    vct_voxel_options voxel;
    vct_brick_options bricks;
    uint32_t bounces;
    vct_cone_settings cones;
    /* 1: the first device builds the voxels and the others receive a copy
     * (vct_voxels_copy); 0: every device builds its own. */
    int copy_voxels;
} vct_group_build;

/* Builds `scene`'s structures on every device, at once; a device that cannot
 * hold them is left out with a message, unless none can. Each device holds
 * a device scene of `scene` (vct/device_scene.h): its scene data stay on
 * the device between renders, and preparing the same scene again after a
 * change rebuilds only what the change needs (a moved light: the voxels'
 * light). The scene must outlive the group or the next prepare. */
VCT_API vct_status vct_group_prepare(vct_group *group, const vct_scene *scene,
                                     const vct_group_build *build, vct_error *err);

/* Renders `job` over the group's devices, with each device's own structures
 * (the job's accel and voxels are not read; its aovs must be NULL). The
 * image is the one a single device of the same kind gives. With a band
 * (vct/partial.h) the group renders rows [band.first, band.first + height)
 * of an image band.height tall, itself rendering the rows around them that
 * its bands need; photon mapping's devices agree on their radii among
 * themselves, then through band.pass_sync with the other bands.
 * Resuming (pathtrace.resume, pm.resume) continues each device's own sums
 * or statistics; a device dropped then loses what it held from earlier
 * calls (the path tracer averages the samples that remain; photon mapping
 * starts over). Photon mapping takes a pass count, not a time. */
VCT_API vct_status vct_group_render(vct_group *group, const vct_render_job *job, vct_image *image,
                                    vct_render_result *result, vct_error *err);

/* The path tracer's samples [first, first + count) over the group's
 * devices, summed exactly into *sums (allocated here), as
 * vct_device_scene_render_samples does on one device (vct/partial.h); the
 * devices' running sums start over. */
VCT_API vct_status vct_group_render_samples(vct_group *group, const vct_render_job *job,
                                            uint32_t first, uint32_t count, vct_sample_sums *sums,
                                            vct_error *err);
/* The image of `sums`, resolved on the group's first active device. */
VCT_API vct_status vct_group_resolve_samples(vct_group *group, const vct_render_job *job,
                                             const vct_sample_sums *sums, vct_image *image,
                                             vct_error *err);

typedef struct vct_group_device {
    vct_device_info info;
    int active;         /* 0 once dropped */
    char dropped[2048]; /* why it was dropped */
    double build_ms;    /* its structures: build time and device memory */
    double build_mib;
    double voxels_ms; /* of which its voxels: built, or copied from another device */
    int voxels_copied;
    double share;     /* row methods: its share of the next render's rows */
    double speed;     /* rows (or samples) per second it last measured, 0 unknown */
    double last_ms;   /* its part of the last render: wall time */
    double last_work; /* and rows or samples */
} vct_group_device;

/* vct_context_set_log on every device's context: the callback may then be
 * called from the devices' threads at once. */
VCT_API void vct_group_set_log(vct_group *group, vct_log_fn log, void *user);
/* The devices, in the order the list named them. */
VCT_API int vct_group_devices(const vct_group *group, const vct_group_device **devices);
/* Devices not dropped. */
VCT_API int vct_group_active_count(const vct_group *group);
/* The device rendering the row methods alone, having measured faster than
 * the devices together (-1: they render together). */
VCT_API int vct_group_alone(const vct_group *group);
/* Failures seen so far (each reported once, on stderr, when it happened). */
VCT_API int vct_group_faults(const vct_group *group);

#ifdef __cplusplus
}
#endif
#endif
