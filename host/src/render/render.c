/* One way to every method: a job (method, inputs, that method's options)
 * in, the frame out. Callers such as the command line, the viewer and a
 * multi-device splitter need no case per method. */
#include <string.h>

#include "accel/accel.h"
#include "runtime/runtime.h"
#include "vct/partial.h"
#include "voxel/voxels.h"

static const char *const method_names[VCT_METHODS] = {"vct",    "raycast", "pt",
                                                      "voxels", "whitted", "pm"};

const char *vct_method_name(vct_method method) {
    return method >= 0 && method < VCT_METHODS ? method_names[method] : "?";
}

int vct_method_from_name(const char *name) {
    for (int m = 0; name && m < VCT_METHODS; ++m)
        if (strcmp(name, method_names[m]) == 0)
            return m;
    return -1;
}

vct_render_options vct_render_options_default(int width, int height) {
    vct_render_options o;
    memset(&o, 0, sizeof o);
    o.width = width;
    o.height = height;
    o.subsample_contrast = VCT_SUBSAMPLE_CONTRAST_DEFAULT;
    return o;
}

vct_pathtrace_options vct_pathtrace_options_default(int width, int height) {
    vct_pathtrace_options o;
    memset(&o, 0, sizeof o);
    o.width = width;
    o.height = height;
    o.spp = 64;
    o.max_depth = 16;
    o.samples_per_pass = 16;
    return o;
}

vct_whitted_options vct_whitted_options_default(int width, int height) {
    vct_whitted_options o;
    memset(&o, 0, sizeof o);
    o.width = width;
    o.height = height;
    o.max_depth = 8;
    o.min_throughput = 1e-3f;
    o.subsample_contrast = VCT_SUBSAMPLE_CONTRAST_DEFAULT;
    return o;
}

vct_voxel_view_options vct_voxel_view_options_default(int width, int height) {
    const vct_voxel_view_options o = {width, height, VCT_VOXEL_VIEW_LEAVES};
    return o;
}

vct_render_job vct_render_job_default(vct_method method, int width, int height) {
    vct_render_job job;
    memset(&job, 0, sizeof job);
    job.method = method;
    job.width = width;
    job.height = height;
    job.raycast = vct_render_options_default(width, height);
    job.whitted = vct_whitted_options_default(width, height);
    job.pathtrace = vct_pathtrace_options_default(width, height);
    job.pm = vct_pm_options_default(width, height);
    job.vct = vct_vct_options_default(width, height);
    job.voxel_view = vct_voxel_view_options_default(width, height);
    job.accel_options = vct_accel_options_default();
    job.voxel_options = vct_voxel_options_default();
    job.brick_options = vct_brick_options_default();
    job.bounces = VCT_DEFAULT_BOUNCES;
    return job;
}

/* The job with every method's options at the job's image size. */
static vct_render_job sized(const vct_render_job *job) {
    vct_render_job own = *job;
    own.raycast.width = own.whitted.width = own.pathtrace.width = own.pm.width = own.vct.width =
        own.voxel_view.width = job->width;
    own.raycast.height = own.whitted.height = own.pathtrace.height = own.pm.height =
        own.vct.height = own.voxel_view.height = job->height;
    return own;
}

/* What the job's method reads, present. */
static int job_check(const vct_context *ctx, const vct_render_job *job, vct_error *err) {
    const char *name = vct_method_name(job->method);
    if (job->method < 0 || job->method >= VCT_METHODS)
        return vct_fail(err, VCT_ERR_INPUT, "render: unknown method %d", (int)job->method);
    if (!job->scene)
        return vct_fail(err, VCT_ERR_INPUT, "render (%s): the job has no scene", name);
    if (job->method != VCT_METHOD_VOXELS && !job->accel)
        return vct_fail(
            err, VCT_ERR_INPUT,
            "render (%s): the job has no acceleration structure: build one with vct_accel_build",
            name);
    if (job->method == VCT_METHOD_VOXELS && !job->voxels)
        return vct_fail(err, VCT_ERR_INPUT,
                        "render (voxels): the job has no voxels: build them with vct_voxelize "
                        "and vct_octree_build");
    if (job->band.height && job->method == VCT_METHOD_PATHTRACE)
        return vct_fail(err, VCT_ERR_INPUT,
                        "render (pt): the path tracer is split by samples, not bands "
                        "(vct_device_scene_render_samples)");
    if (job->band.height && job->band.height != job->height && job->method == VCT_METHOD_PM &&
        !job->band.pass_sync)
        return vct_fail(err, VCT_ERR_INPUT,
                        "render (pm): a band of photon mapping needs band.pass_sync, so that "
                        "every band gathers with the whole image's radii (vct/partial.h)");
    if (job->band.height) {
        int align, above, below;
        vct_band_shape(job, &align, &above, &below);
        if (job->band.first % align)
            return vct_fail(err, VCT_ERR_INPUT,
                            "render (%s): a band starts on a multiple of %d rows here, not at "
                            "row %d (vct_band_shape)",
                            name, align, job->band.first);
    }
    if ((job->accel && job->accel->ctx != ctx) || (job->voxels && job->voxels->ctx != ctx))
        return vct_fail(err, VCT_ERR_INPUT,
                        "render (%s): the job's %s was built on another context: build it on "
                        "this one (or copy voxels with vct_voxels_copy)",
                        name,
                        job->accel && job->accel->ctx != ctx ? "acceleration structure" : "voxels");
    return VCT_OK;
}

static int render_vct_job(vct_context *ctx, const vct_render_job *job, vct_image *image,
                          vct_error *err) {
    vct_plan own;
    const vct_plan *plan = job->plan;
    if (!plan) {
        vct_plan_make(job->scene, NULL, &own);
        plan = &own;
    }
    return vct_render_vct(ctx, job->scene, job->accel, job->voxels, plan, &job->vct, image,
                          job->aovs, err);
}

vct_status vct_render(vct_context *ctx, const vct_render_job *given, vct_image *image,
                      vct_render_result *result, vct_error *err) {
    const double start = vct_now_ms();
    const vct_render_job own = sized(given), *job = &own;
    memset(image, 0, sizeof *image);
    int rc = job_check(ctx, job, err);
    vct_pathtrace_result pt = {0};
    vct_whitted_result wr = {0, 0, NULL, 0};
    vct_pm_result pm = {0};
    if (rc == VCT_OK && job->band.height) {
        ctx->band_first = job->band.first;
        ctx->band_height = job->band.height;
        ctx->band_sync = job->band.pass_sync;
        ctx->band_sync_user = job->band.pass_sync_user;
    }
    if (rc == VCT_OK) {
        switch (job->method) {
        case VCT_METHOD_RAYCAST:
            rc = vct_render_raycast(ctx, job->scene, job->accel, &job->raycast, image, err);
            break;
        case VCT_METHOD_WHITTED:
            rc = vct_render_whitted(ctx, job->scene, job->accel, &job->whitted, image, &wr, err);
            break;
        case VCT_METHOD_PATHTRACE:
            rc =
                vct_render_pathtrace(ctx, job->scene, job->accel, &job->pathtrace, image, &pt, err);
            break;
        case VCT_METHOD_PM:
            rc = vct_render_pm(ctx, job->scene, job->accel, &job->pm, image, &pm, err);
            break;
        case VCT_METHOD_VOXELS: {
            vct_voxel_info info;
            vct_voxels_info_get(job->voxels, &info);
            const uint32_t level = job->voxel_view.level == VCT_VOXEL_VIEW_LEAVES
                                       ? info.levels
                                       : job->voxel_view.level;
            rc = vct_render_voxels_level(ctx, job->scene, job->voxels, level, job->voxel_view.width,
                                         job->voxel_view.height, image, err);
            break;
        }
        default:
            rc = render_vct_job(ctx, job, image, err);
            break;
        }
    }
    ctx->band_first = ctx->band_height = 0;
    ctx->band_sync = NULL;
    ctx->band_sync_user = NULL;
    if (result) {
        memset(result, 0, sizeof *result);
        result->method = job->method;
        result->width = image->width;
        result->height = image->height;
        result->seconds = (vct_now_ms() - start) * 1e-3;
        result->spp = job->method == VCT_METHOD_PM ? pm.passes : pt.spp;
        result->photons = pm.photons_emitted;
        result->pm = pm;
        result->discarded = pt.discarded;
        result->traced = wr.traced_pixels;
        result->camera_rays = wr.camera_rays;
    }
    return rc;
}
