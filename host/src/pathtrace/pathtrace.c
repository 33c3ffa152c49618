/* Progressive path tracing: passes of a few samples per pixel accumulate on
 * the device until the requested sample count or time is reached. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "scene/scene_resident.h"
#include "runtime/runtime.h"
#include "accel/accel.h"
#include "frame/frame.h"
#include "pathtrace/pathtrace.h"
#include "vct/partial.h"
#include "frame/progress.h"

#define STAGE "path trace"
/* The kernel variant whose sums hold the colour alone (colour_only). */
#define PT_COLOUR_ONLY_OPTION "-DVCT_PT_COLOUR_ONLY"

void vct_pt_sums_release(vct_context *ctx, vct_accumulation *acc) {
    vct_buffer_release(ctx, acc->pt_sums);
    vct_buffer_release(ctx, acc->pt_discarded);
    acc->pt_sums = acc->pt_discarded = NULL;
    acc->pt_size[0] = acc->pt_size[1] = 0;
    acc->pt_done = 0;
}

static void context_sums_release(vct_context *ctx) {
    vct_pt_sums_release(ctx, &ctx->accumulation);
}

/* The running sums: kept when resuming at the same size, else zeroed. */
static int accumulation_get(vct_context *ctx, vct_accumulation *acc,
                            const vct_pathtrace_options *opt, vct_error *err) {
    if (opt->resume && acc->pt_sums && acc->pt_size[0] == opt->width &&
        acc->pt_size[1] == opt->height && acc->pt_colour_only == (opt->colour_only != 0))
        return VCT_OK;
    vct_pt_sums_release(ctx, acc);
    if (acc == &ctx->accumulation)
        vct_context_on_release(ctx, context_sums_release);
    const size_t pixels = (size_t)opt->width * opt->height;
    acc->pt_sums = vct_buffer_create(ctx, STAGE, "accumulation", VCT_PT_ACCUM_BYTES * pixels,
                                     CL_MEM_READ_WRITE, NULL, err);
    acc->pt_discarded = acc->pt_sums ? vct_buffer_create(ctx, STAGE, "discarded count", 4,
                                                         CL_MEM_READ_WRITE, NULL, err)
                                     : NULL;
    int rc = acc->pt_discarded ? VCT_OK : (int)err->status;
    if (rc == VCT_OK)
        rc = vct_buffer_fill_u32(ctx, STAGE, acc->pt_sums, 0, VCT_PT_ACCUM_BYTES / 4 * pixels, err);
    if (rc == VCT_OK)
        rc = vct_buffer_fill_u32(ctx, STAGE, acc->pt_discarded, 0, 1, err);
    if (rc != VCT_OK)
        vct_pt_sums_release(ctx, acc);
    else {
        acc->pt_size[0] = opt->width;
        acc->pt_size[1] = opt->height;
        acc->pt_colour_only = opt->colour_only != 0;
    }
    return rc;
}

int vct_pt_begin(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                 const vct_pathtrace_options *opt, vct_pt_session *pt, vct_error *err) {
    memset(pt, 0, sizeof *pt);
    pt->ctx = ctx;
    pt->opt = opt;
    pt->acc = vct_accumulation_of(ctx, s);
    if (opt->max_depth == 0)
        return vct_fail(err, VCT_ERR_INPUT, "%s: the path depth must be at least 1", STAGE);
    if (opt->colour_only && (opt->variance || opt->indirect))
        return vct_fail(err, VCT_ERR_INPUT,
                        "%s: the variance and the indirect light need the sums' moments: "
                        "set colour_only to 0 to have them",
                        STAGE);
    vct_camera_desc cam;
    int rc = vct_frame_camera(ctx, &s->camera, opt->width, opt->height, &cam, err);
    if (rc)
        return rc;
    vct_stage_begin(ctx, STAGE);
    char options[256];
    rc = vct_program_get(
        ctx, "render/pathtrace.cl",
        opt->colour_only ? vct_accel_options_join(g, PT_COLOUR_ONLY_OPTION, options, sizeof options)
                         : vct_accel_program_options(g),
        &pt->program, err);
    if (rc == VCT_OK)
        rc = vct_scene_buffers_make(ctx, s, STAGE, &pt->sb, err);
    if (rc == VCT_OK)
        rc = vct_emitters_build(ctx, s, VCT_EMITTERS_BY_AREA, STAGE, &pt->eb, err);
    if (rc == VCT_OK)
        rc = accumulation_get(ctx, pt->acc, opt, err);
    cl_kernel k = rc == VCT_OK ? vct_kernel_create(ctx, pt->program, "pathtrace", err) : NULL;
    pt->kernel = k;
    if (rc == VCT_OK && !k)
        rc = err->status;
    if (rc == VCT_OK)
        rc = vct_accel_set_args(k, g, STAGE, err);
    cl_uint max_depth = opt->max_depth, seed = opt->seed;
    const cl_float4 ambient = {{s->ambient[0], s->ambient[1], s->ambient[2], 0.0f}};
    const vct_scene_buffers *sb = &pt->sb;
    const vct_emitters *eb = &pt->eb;
    if (rc == VCT_OK)
        rc = vct_set_args(err, STAGE, k, 5, 3, VCT_ARG_OF(cam), VCT_ARG_OF(sb->materials),
                          VCT_ARG_OF(sb->tri_material));
    if (rc == VCT_OK)
        rc = vct_scene_texture_args(k, 8, sb, STAGE, err);
    if (rc == VCT_OK)
        rc = vct_set_args(err, STAGE, k, 11, 6, VCT_ARG_OF(sb->lights), VCT_ARG_OF(sb->light_count),
                          VCT_ARG(emitter_tris, eb->tris), VCT_ARG(emitter_cdf, eb->cdf),
                          VCT_ARG(emitter_count, eb->count),
                          VCT_ARG(emitter_inv_area, eb->inv_area));
    if (rc == VCT_OK)
        rc = vct_set_args(err, STAGE, k, 19, 5, VCT_ARG_OF(max_depth), VCT_ARG_OF(seed),
                          VCT_ARG(accum, pt->acc->pt_sums),
                          VCT_ARG(discarded, pt->acc->pt_discarded), VCT_ARG_OF(ambient));
    return rc;
}

int vct_pt_sums_read(vct_pt_session *pt, void *sums, uint32_t *discarded, vct_error *err) {
    const size_t bytes = VCT_PT_ACCUM_BYTES * (size_t)pt->opt->width * pt->opt->height;
    cl_uint dropped = 0;
    int rc = vct_buffer_read(pt->ctx, STAGE, pt->acc->pt_sums, 0, bytes, sums, err);
    if (rc == VCT_OK)
        rc = vct_buffer_read(pt->ctx, STAGE, pt->acc->pt_discarded, 0, 4, &dropped, err);
    *discarded = dropped;
    return rc;
}

void vct_sample_sums_add_words(uint64_t *into, const uint64_t *add, size_t pairs) {
    /* 128-bit two's-complement addition, as kernels/render/exact_sum.h adds */
    for (size_t k = 0; k < pairs; ++k) {
        const uint64_t lo = into[2 * k + 1] + add[2 * k + 1];
        into[2 * k] += add[2 * k] + (lo < add[2 * k + 1] ? 1u : 0u);
        into[2 * k + 1] = lo;
    }
}

int vct_pt_run(vct_pt_session *pt, uint32_t first, uint32_t count, int wait, vct_error *err) {
    const vct_pathtrace_options *opt = pt->opt;
    const size_t global[2] = {(size_t)opt->width, (size_t)opt->height}, local[2] = {8, 8};
    const cl_uint per_pass = opt->samples_per_pass ? opt->samples_per_pass : 1;
    int rc = VCT_OK;
    for (cl_uint done = 0; rc == VCT_OK && done < count;) {
        cl_uint n = count - done < per_pass ? count - done : per_pass;
        cl_uint sample = first + done;
        rc = vct_set_args(err, STAGE, pt->kernel, 17, 2, VCT_ARG(sample_begin, sample),
                          VCT_ARG(samples, n));
        if (rc == VCT_OK)
            rc = vct_launch_2d(pt->ctx, pt->kernel, global, local, err);
        done += n;
    }
    if (rc == VCT_OK && wait)
        rc = vct_finish(pt->ctx, STAGE, err);
    return rc;
}

/* A float4 per pixel from `sums` by `kernel` (accum, pixels, then its
 * parameter `param`), into a host image; `what` names it in errors. */
static int pixels_from_sums(vct_context *ctx, cl_program program, const char *kernel,
                            const char *param, const char *what, cl_mem sums,
                            const vct_pathtrace_options *opt, vct_image *image, vct_error *err) {
    const size_t pixels = (size_t)opt->width * opt->height;
    const cl_uint pixel_count = (cl_uint)pixels;
    memset(image, 0, sizeof *image);
    image->rgba = malloc(16 * pixels);
    if (!image->rgba)
        return vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory for the %s", STAGE, what);
    image->width = opt->width;
    image->height = opt->height;
    cl_mem out = vct_buffer_create(ctx, STAGE, what, 16 * pixels, CL_MEM_WRITE_ONLY, NULL, err);
    int rc =
        out ? vct_run_kernel(ctx, program, kernel, STAGE, pixels, err, 3, VCT_ARG(accum, sums),
                             VCT_ARG(pixels, pixel_count), sizeof out, (const void *)&out, param)
            : (int)err->status;
    if (rc == VCT_OK)
        rc = vct_buffer_read(ctx, STAGE, out, 0, 16 * pixels, image->rgba, err);
    vct_buffer_release(ctx, out);
    if (rc != VCT_OK)
        vct_image_release(image);
    return rc;
}

int vct_pt_end(vct_pt_session *pt, int rc, cl_mem sums, vct_image *image,
               vct_pathtrace_result *result, vct_error *err) {
    vct_context *ctx = pt->ctx;
    const vct_pathtrace_options *opt = pt->opt;
    const size_t pixels = (size_t)opt->width * opt->height;
    if (!sums)
        sums = pt->acc->pt_sums;
    cl_mem frame =
        rc == VCT_OK && image ? vct_frame_get(ctx, STAGE, opt->width, opt->height, err) : NULL;
    if (rc == VCT_OK && image && !frame)
        rc = err->status;
    const cl_uint pixel_count = (cl_uint)pixels;
    if (rc == VCT_OK && image)
        rc = vct_run_kernel(ctx, pt->program, "pathtrace_resolve", STAGE, pixels, err, 3,
                            VCT_ARG(accum, sums), VCT_ARG(pixels, pixel_count), VCT_ARG_OF(frame));
    if (rc == VCT_OK && image && opt->variance) /* the call that delivers the frame */
        rc = pixels_from_sums(ctx, pt->program, "pathtrace_variance", "variance", "variance", sums,
                              opt, opt->variance, err);
    if (rc == VCT_OK && image && opt->indirect)
        rc = pixels_from_sums(ctx, pt->program, "pathtrace_resolve_indirect", "indirect",
                              "indirect light", sums, opt, opt->indirect, err);
    cl_uint dropped = 0;
    if (rc == VCT_OK && result)
        rc = vct_buffer_read(ctx, STAGE, pt->acc->pt_discarded, 0, 4, &dropped, err);
    if (result)
        result->discarded = dropped;
    if (rc == VCT_OK && image)
        rc = vct_frame_deliver(ctx, STAGE, image, err);
    if (rc != VCT_OK) {
        if (image)
            vct_image_release(image);
        vct_pt_sums_release(ctx, pt->acc); /* the running sums are no longer whole */
    }
    if (pt->kernel)
        clReleaseKernel(pt->kernel);
    vct_emitters_release(ctx, &pt->eb);
    vct_scene_buffers_release(ctx, &pt->sb);
    vct_stage_end(ctx);
    return rc;
}

vct_status vct_render_pathtrace(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                                const vct_pathtrace_options *opt, vct_image *image,
                                vct_pathtrace_result *result, vct_error *err) {
    vct_pathtrace_result unused;
    if (!result)
        result = &unused;
    memset(image, 0, sizeof *image);
    memset(result, 0, sizeof *result);
    if (opt->spp == 0 && !(opt->time_limit_s > 0.0))
        return vct_fail(err, VCT_ERR_INPUT, "%s: give a sample count (--spp) or a time (--time)",
                        STAGE);
    vct_pt_session pt;
    int rc = vct_pt_begin(ctx, s, g, opt, &pt, err);
    const int show = opt->progress && isatty(2);
    const cl_uint per_pass = opt->samples_per_pass ? opt->samples_per_pass : 1;
    const double t0 = vct_now_ms();
    cl_uint done = 0, sample = pt.acc->pt_done;
    while (rc == VCT_OK) {
        const double elapsed = (vct_now_ms() - t0) * 1e-3;
        if (opt->spp ? done >= opt->spp : elapsed >= opt->time_limit_s)
            break;
        cl_uint n = opt->spp ? per_pass : 1u;
        if (opt->spp && done + n > opt->spp)
            n = opt->spp - done;
        /* Waiting per pass only serves the clock and the progress bar; a fixed
         * sample count is queued whole and awaited by the final read. */
        rc = vct_pt_run(&pt, sample, n, show || !opt->spp, err);
        done += n;
        sample += n;
        if (show)
            vct_progress_line(done, opt->spp, (vct_now_ms() - t0) * 1e-3, opt->time_limit_s, "spp");
    }
    if (show)
        fputc('\n', stderr);
    pt.acc->pt_done = sample;
    result->spp = sample;
    result->seconds = (vct_now_ms() - t0) * 1e-3;
    return vct_pt_end(&pt, rc, NULL, image, result, err);
}
