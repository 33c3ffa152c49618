/* The path tracer in parts (vct/partial.h): ranges of samples rendered into
 * exact sums on the host, and sums turned into the image. */
#include <stdlib.h>
#include <string.h>

#include "device_scene/device_scene_prepare.h"
#include "pathtrace/pathtrace.h"
#include "runtime/runtime.h"
#include "vct/partial.h"

#define STAGE "path trace (parts)"

size_t vct_sample_sums_bytes(int width, int height) {
    return VCT_SAMPLE_SUM_BYTES * (size_t)width * (size_t)height;
}

void vct_sample_sums_release(vct_sample_sums *sums) {
    if (!sums)
        return;
    free(sums->data);
    memset(sums, 0, sizeof *sums);
}

/* The job's path-tracer options at its size, starting over, with nothing
 * printed. */
static int parts_options(const vct_render_job *job, vct_pathtrace_options *opt, vct_error *err) {
    if (job->method != VCT_METHOD_PATHTRACE)
        return vct_fail(err, VCT_ERR_INPUT, "%s: the job's method must be the path tracer", STAGE);
    if (job->width < 1 || job->height < 1)
        return vct_fail(err, VCT_ERR_INPUT, "%s: the job's image is %dx%d", STAGE, job->width,
                        job->height);
    *opt = job->pathtrace;
    opt->width = job->width;
    opt->height = job->height;
    opt->resume = 0;
    opt->progress = 0;
    return VCT_OK;
}

vct_status vct_device_scene_render_samples(vct_device_scene *ds, const vct_render_job *job,
                                           uint32_t first, uint32_t count, vct_sample_sums *sums,
                                           vct_error *err) {
    memset(sums, 0, sizeof *sums);
    vct_pathtrace_options opt;
    int rc = parts_options(job, &opt, err);
    opt.variance = opt.indirect = NULL;
    if (rc == VCT_OK)
        rc = vct_device_scene_prepare(ds, job, err);
    if (rc != VCT_OK)
        return rc;
    const size_t bytes = vct_sample_sums_bytes(opt.width, opt.height);
    sums->data = malloc(bytes);
    if (!sums->data)
        return vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory for %zu bytes of sums", STAGE,
                        bytes);
    sums->width = opt.width;
    sums->height = opt.height;
    sums->samples = count;
    vct_pt_session pt;
    rc = vct_pt_begin(vct_device_scene_context(ds), vct_device_scene_scene(ds),
                      vct_device_scene_accel(ds), &opt, &pt, err);
    if (rc == VCT_OK)
        rc = vct_pt_run(&pt, first, count, 1, err);
    if (rc == VCT_OK)
        rc = vct_pt_sums_read(&pt, sums->data, &sums->discarded, err);
    rc = vct_pt_end(&pt, rc, NULL, NULL, NULL, err);
    if (rc != VCT_OK)
        vct_sample_sums_release(sums);
    return rc;
}

vct_status vct_sample_sums_add(vct_sample_sums *into, const vct_sample_sums *add, vct_error *err) {
    if (into->width != add->width || into->height != add->height || !into->data || !add->data)
        return vct_fail(err, VCT_ERR_INPUT, "%s: sums of %dx%d and %dx%d do not add", STAGE,
                        into->width, into->height, add->width, add->height);
    vct_sample_sums_add_words(into->data, add->data,
                              vct_sample_sums_bytes(into->width, into->height) / 16);
    into->samples += add->samples;
    into->discarded += add->discarded;
    return VCT_OK;
}

vct_status vct_device_scene_resolve_samples(vct_device_scene *ds, const vct_render_job *job,
                                            const vct_sample_sums *sums, vct_image *image,
                                            vct_error *err) {
    memset(image, 0, sizeof *image);
    vct_pathtrace_options opt;
    int rc = parts_options(job, &opt, err);
    if (rc == VCT_OK && (sums->width != opt.width || sums->height != opt.height || !sums->data))
        rc = vct_fail(err, VCT_ERR_INPUT, "%s: sums of %dx%d for an image of %dx%d", STAGE,
                      sums->width, sums->height, opt.width, opt.height);
    if (rc == VCT_OK)
        rc = vct_device_scene_prepare(ds, job, err);
    if (rc != VCT_OK)
        return rc;
    vct_context *ctx = vct_device_scene_context(ds);
    vct_pt_session pt;
    rc = vct_pt_begin(ctx, vct_device_scene_scene(ds), vct_device_scene_accel(ds), &opt, &pt, err);
    cl_mem summed =
        rc == VCT_OK ? vct_buffer_create(ctx, STAGE, "summed samples",
                                         vct_sample_sums_bytes(opt.width, opt.height),
                                         CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sums->data, err)
                     : NULL;
    if (rc == VCT_OK && !summed)
        rc = err->status;
    rc = vct_pt_end(&pt, rc, summed, image, NULL, err);
    vct_buffer_release(ctx, summed);
    return rc;
}
