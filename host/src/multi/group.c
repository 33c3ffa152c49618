/* Device groups: their contexts, the structures each device builds, the
 * threads that drive them, and devices dropped when they fail. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "device_scene/device_scene_prepare.h"
#include "multi/device_list.h"
#include "multi/group.h"

vct_group *vct_group_create(const char *list, vct_error *err) {
    int indices[VCT_GROUP_MAX];
    const int n = vct_device_list_parse(list, indices, VCT_GROUP_MAX, err);
    if (n < 0)
        return NULL;
    vct_group *g = calloc(1, sizeof *g);
    if (!g) {
        vct_fail(err, VCT_ERR_MEMORY, "devices: out of host memory");
        return NULL;
    }
    for (int i = 0; i < n; ++i) {
        char selector[16];
        snprintf(selector, sizeof selector, "%d", indices[i]);
        g->ctx[i] = vct_context_create(selector, err);
        if (!g->ctx[i]) {
            vct_group_release(g);
            return NULL;
        }
        g->count = i + 1;
        vct_group_device *d = &g->devices[i];
        d->info = *vct_context_device(g->ctx[i]);
        d->active = 1;
        d->share = 1.0 / n;
    }
    return g;
}

static void structures_free(vct_group *g, int i) {
    vct_device_scene_release(g->ds[i]);
    g->ds[i] = NULL;
    g->voxels[i] = NULL;
    g->accel[i] = NULL;
}

void vct_group_release(vct_group *g) {
    if (!g)
        return;
    for (int i = 0; i < g->count; ++i) {
        structures_free(g, i);
        vct_context_release(g->ctx[i]);
    }
    free(g);
}

int vct_group_size(const vct_group *g) {
    return g->count;
}

vct_context *vct_group_context(vct_group *g, int i) {
    return i >= 0 && i < g->count ? g->ctx[i] : NULL;
}

void vct_group_set_log(vct_group *g, vct_log_fn log, void *user) {
    g->log = log;
    g->log_user = user;
    for (int i = 0; i < g->count; ++i)
        if (g->ctx[i])
            vct_context_set_log(g->ctx[i], log, user);
}

int vct_group_devices(const vct_group *g, const vct_group_device **devices) {
    *devices = g->devices;
    return g->count;
}

int vct_group_alone(const vct_group *g) {
    return g->solo.state == VCT_SOLO && g->devices[g->solo.device].active ? g->solo.device : -1;
}

int vct_group_faults(const vct_group *g) {
    return g->faults;
}

/* ---- structures ------------------------------------------------------------------ */

typedef struct prepare_job {
    const vct_scene *scene;
    const vct_group_build *build;
    vct_error errors[VCT_GROUP_MAX];
    int rc[VCT_GROUP_MAX];
    int builder;                /* the device whose voxels the others copy; -1: each builds */
    int changed[VCT_GROUP_MAX]; /* the device's commit found the scene changed */
} prepare_job;

static int voxels_wanted(const vct_group_build *b) {
    return b->plan && vct_plan_needs_voxels(b->plan);
}

/* The acceleration structure, and the voxels unless another device builds
 * them for this one. */
static void prepare_one(vct_group *g, int i, void *arg) {
    prepare_job *p = arg;
    vct_context *ctx = g->ctx[i];
    vct_error *err = &p->errors[i];
    const double t0 = vct_now_ms();
    const vct_group_build *b = p->build;
    vct_group_device *d = &g->devices[i];
    if (!g->ds[i])
        g->ds[i] = vct_device_scene_create(ctx, p->scene, err);
    int rc = g->ds[i] ? VCT_OK : (int)err->status;
    /* the structures as a render of this job would build them */
    const int voxels = voxels_wanted(b) && (p->builder < 0 || p->builder == i);
    vct_render_job job = vct_render_job_default(voxels ? VCT_METHOD_VCT : VCT_METHOD_RAYCAST, 1, 1);
    job.plan = b->plan;
    job.accel_options = b->accel;
    job.voxel_options = b->voxel;
    job.brick_options = b->bricks;
    job.bounces = b->bounces;
    job.vct.cones = b->cones;
    vct_device_scene_stats before, after;
    if (rc == VCT_OK) {
        vct_device_scene_stats_get(g->ds[i], &before);
        rc = vct_device_scene_prepare(g->ds[i], &job, err);
        vct_device_scene_stats_get(g->ds[i], &after);
        p->changed[i] = after.changes != before.changes;
    }
    if (rc == VCT_OK) {
        g->accel[i] = vct_device_scene_accel(g->ds[i]);
        g->voxels[i] = voxels ? vct_device_scene_voxels(g->ds[i]) : NULL;
        if (after.voxel_builds != before.voxel_builds ||
            after.light_builds != before.light_builds) {
            d->voxels_ms = vct_now_ms() - t0;
            d->voxels_copied = 0;
        }
    }
    p->rc[i] = rc;
    d->build_ms += vct_now_ms() - t0;
    d->build_mib = ctx->bytes_live / 1048576.0;
    if (rc != VCT_OK)
        structures_free(g, i);
}

/* Devices that failed to build are left out with a message. */
static void drop_failed_builds(vct_group *g, prepare_job *p, int *first_failure) {
    for (int i = 0; i < g->count; ++i)
        if (g->devices[i].active && p->rc[i] != VCT_OK) {
            if (*first_failure < 0)
                *first_failure = i;
            /* a device that cannot hold the structures is left out, not the frame */
            vct_group_drop(g, i, &p->errors[i]);
        }
}

/* The builder's voxels copied to every other device, one after the other
 * (the builder's context serves one caller at a time). */
static void copy_voxels(vct_group *g, prepare_job *p) {
    const vct_voxels *from = g->voxels[p->builder];
    for (int i = 0; i < g->count; ++i) {
        if (i == p->builder || !g->devices[i].active)
            continue;
        const double t0 = vct_now_ms();
        vct_voxels *copy = vct_voxels_copy(g->ctx[i], from, &p->errors[i]);
        if (copy)
            vct_device_scene_adopt_voxels(g->ds[i], copy, g->ds[p->builder]);
        g->voxels[i] = copy;
        p->rc[i] = copy ? VCT_OK : (int)p->errors[i].status;
        vct_group_device *d = &g->devices[i];
        d->voxels_ms = vct_now_ms() - t0;
        d->voxels_copied = 1;
        d->build_ms += d->voxels_ms;
        d->build_mib = g->ctx[i]->bytes_live / 1048576.0;
    }
}

vct_status vct_group_prepare(vct_group *g, const vct_scene *scene, const vct_group_build *build,
                             vct_error *err) {
    prepare_job p;
    memset(&p, 0, sizeof p);
    p.scene = scene;
    p.build = build;
    p.builder = -1;
    const int new_scene = scene != g->scene;
    for (int i = 0; i < g->count; ++i) {
        /* a device scene serves its scene alone; the same scene again keeps
         * what is still valid (a moved light: the voxels relit) */
        if (new_scene)
            structures_free(g, i);
        g->voxels[i] = NULL;
        g->devices[i].build_ms = g->devices[i].voxels_ms = 0.0;
        if (build->copy_voxels && p.builder < 0 && g->devices[i].active)
            p.builder = i;
    }
    g->scene = scene;
    int rc = vct_group_each(g, prepare_one, &p, err);
    if (rc != VCT_OK)
        return rc;
    /* the devices' running sums started over: so does the group's count */
    int changed = new_scene;
    for (int i = 0; i < g->count; ++i)
        changed |= p.changed[i];
    if (changed) {
        g->pt_done = 0;
        g->pm_height = 0;
    }
    int first_failure = -1;
    drop_failed_builds(g, &p, &first_failure);
    if (p.builder >= 0 && voxels_wanted(build)) {
        if (g->devices[p.builder].active) {
            copy_voxels(g, &p);
        } else { /* the builder could not: every device builds its own */
            p.builder = -1;
            rc = vct_group_each(g, prepare_one, &p, err);
        }
        drop_failed_builds(g, &p, &first_failure);
    }
    if (vct_group_active_count(g) == 0) {
        *err = p.errors[first_failure >= 0 ? first_failure : 0];
        return err->status ? (int)err->status : VCT_ERR_INPUT;
    }
    for (int i = 0; i < g->count; ++i)
        g->devices[i].share = g->devices[i].active ? 1.0 / vct_group_active_count(g) : 0.0;
    return VCT_OK;
}

/* ---- rendering ------------------------------------------------------------------- */

vct_status vct_group_render(vct_group *g, const vct_render_job *job, vct_image *image,
                            vct_render_result *result, vct_error *err) {
    memset(image, 0, sizeof *image);
    if (job->aovs)
        return vct_fail(err, VCT_ERR_INPUT,
                        "devices: AOVs come from one device: render them without a group");
    if (job->band.height && job->method == VCT_METHOD_PATHTRACE)
        return vct_fail(err, VCT_ERR_INPUT,
                        "devices: the path tracer is split by samples, not bands "
                        "(vct_group_render_samples)");
    if (job->band.height && job->method == VCT_METHOD_PM && !job->band.pass_sync &&
        job->band.height != job->height)
        return vct_fail(err, VCT_ERR_INPUT,
                        "devices: a band of photon mapping needs band.pass_sync (vct/partial.h)");
    int align, above, below;
    vct_band_shape(job, &align, &above, &below);
    if (job->band.height && job->band.first % align)
        return vct_fail(err, VCT_ERR_INPUT,
                        "devices: a band starts on a multiple of %d rows here, not at row %d "
                        "(vct_band_shape)",
                        align, job->band.first);
    if (job->band.height && (job->band.first < 0 || job->height < 1 ||
                             job->band.first + job->height > job->band.height))
        return vct_fail(err, VCT_ERR_INPUT,
                        "devices: rows %d to %d are not a band of an image %d rows tall",
                        job->band.first, job->band.first + job->height - 1, job->band.height);
    int active = 0;
    for (int i = 0; i < g->count; ++i)
        active += g->devices[i].active && g->accel[i];
    if (active == 0)
        return vct_fail(err, VCT_ERR_INPUT,
                        "devices: no device holds the scene's structures: call "
                        "vct_group_prepare first");
    if (job->method == VCT_METHOD_PATHTRACE)
        return vct_group_render_chunks(g, job, image, result, err);
    if (job->method == VCT_METHOD_PM && job->pm.passes == 0)
        return vct_fail(err, VCT_ERR_INPUT,
                        "devices: photon mapping on several devices takes a pass count (--spp), "
                        "not a time: its bands agree on their grids pass by pass");
    return vct_group_render_rows(g, job, image, result, err);
}

vct_status vct_group_resolve_samples(vct_group *g, const vct_render_job *job,
                                     const vct_sample_sums *sums, vct_image *image,
                                     vct_error *err) {
    memset(image, 0, sizeof *image);
    for (int i = 0; i < g->count; ++i)
        if (g->devices[i].active && g->ds[i])
            return vct_device_scene_resolve_samples(g->ds[i], job, sums, image, err);
    return vct_fail(err, VCT_ERR_INPUT,
                    "devices: no device holds the scene: call vct_group_prepare first");
}
