/* The device group's state, shared by its files: one context per device
 * with its structures, and what the scheduler has measured. */
#ifndef VCT_MULTI_GROUP_H
#define VCT_MULTI_GROUP_H

#include "multi/balance.h"
#include "runtime/runtime.h"

#define VCT_GROUP_MAX 16

struct vct_group {
    int count;
    vct_group_device devices[VCT_GROUP_MAX];
    vct_context *ctx[VCT_GROUP_MAX];
    /* Each device's device scene of the prepared scene, which owns its
     * structures; accel and voxels are the ones the renders read. */
    vct_device_scene *ds[VCT_GROUP_MAX];
    const vct_scene *scene;
    const vct_accel *accel[VCT_GROUP_MAX];
    const vct_voxels *voxels[VCT_GROUP_MAX];
    int faults;
    uint32_t pt_done;  /* samples of the path tracer's running sums (resume) */
    vct_solo solo;     /* row methods: the devices together, or the fastest alone */
    uint64_t solo_job; /* what solo's frame times were measured on */
    /* Photon mapping: the bands of the last render, kept while it resumes. */
    int pm_first[VCT_GROUP_MAX], pm_rows[VCT_GROUP_MAX], pm_height;
    vct_log_fn log; /* vct_group_set_log's, for what the group itself says */
    void *log_user;
};

/* Runs work(group, device, arg) for every active device at once, one host
 * thread each, and waits for all of them. */
typedef void (*vct_group_work)(vct_group *g, int device, void *arg);
int vct_group_each(vct_group *g, vct_group_work work, void *arg, vct_error *err);

/* Drops a device that failed with `why`: said once through the log. */
void vct_group_drop(vct_group *g, int device, const vct_error *why);

/* Row methods and the path tracer, over the active devices. */
int vct_group_render_rows(vct_group *g, const vct_render_job *job, vct_image *image,
                          vct_render_result *result, vct_error *err);
int vct_group_render_chunks(vct_group *g, const vct_render_job *job, vct_image *image,
                            vct_render_result *result, vct_error *err);

#endif
