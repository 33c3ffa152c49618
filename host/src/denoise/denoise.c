/* The denoiser's host side: uploads the image and its guides, runs
 * kernels/denoise/atrous.cl (demodulate, clamp fireflies, the à-trous
 * passes, remodulate) with kernels/denoise/edge_fit.cl's fit of the edge
 * pixels between the clamp and the passes, and reads the result back. */
#include <stdlib.h>
#include <string.h>

#include "denoise/denoise_parts.h"
#include "runtime/runtime.h"
#include "vct/denoise.h"

#define STAGE "denoise"

/* Each pass allows this share of the luminance difference the one before
 * allowed: its taps lie twice as far apart, where what differs is more
 * often the lighting than noise. */
#define SIGMA_LUMINANCE_DECAY 0.8f

vct_denoise_options vct_denoise_options_default(void) {
    vct_denoise_options o;
    o.iterations = 5;
    o.sigma_luminance = 4.0f;
    o.sigma_normal = 128.0f;
    o.sigma_depth = 1.0f;
    o.firefly_sigma = 6.0f;
    return o;
}

int vct_denoise_check(const vct_image *color, const vct_denoise_guides *g,
                      const vct_denoise_options *o, vct_error *err) {
    if (!color || !color->rgba || color->width < 1 || color->height < 1)
        return vct_fail(err, VCT_ERR_INPUT, "%s: no image to filter", STAGE);
    if (!g || !g->albedo || !g->normal_depth)
        return vct_fail(err, VCT_ERR_INPUT,
                        "%s: the albedo and normal-depth guides are needed (vct_render_guides)",
                        STAGE);
    const vct_image *guides[4] = {g->albedo, g->normal_depth, g->variance, g->indirect};
    static const char *names[4] = {"albedo", "normal and depth", "variance", "indirect light"};
    for (int i = 0; i < 4; ++i)
        if (guides[i] && (!guides[i]->rgba || guides[i]->width != color->width ||
                          guides[i]->height != color->height))
            return vct_fail(err, VCT_ERR_INPUT, "%s: the %s guide is %dx%d, the image %dx%d", STAGE,
                            names[i], guides[i]->width, guides[i]->height, color->width,
                            color->height);
    if (o->iterations < 1 || o->iterations > 10)
        return vct_fail(err, VCT_ERR_INPUT, "%s: %u passes: give 1 to 10", STAGE, o->iterations);
    if (!(o->sigma_luminance > 0.0f) || !(o->sigma_normal >= 0.0f) || !(o->sigma_depth > 0.0f) ||
        !(o->firefly_sigma >= 0.0f))
        return vct_fail(err, VCT_ERR_INPUT,
                        "%s: the sigmas must be positive (luminance %g, normal %g, depth %g, "
                        "fireflies %g)",
                        STAGE, o->sigma_luminance, o->sigma_normal, o->sigma_depth,
                        o->firefly_sigma);
    return VCT_OK;
}

/* The variance's first components, one float per pixel. */
static float *variance_floats(const vct_image *v, size_t pixels) {
    float *out = malloc(4 * pixels);
    for (size_t i = 0; out && i < pixels; ++i)
        out[i] = v->rgba[4 * i];
    return out;
}

/* A variance guide to use: none where a pixel's is negative (unknown, as
 * the path tracer's below two samples), so the image's own is estimated. */
static const vct_image *known_variance(const vct_image *v) {
    if (!v)
        return NULL;
    const size_t pixels = (size_t)v->width * v->height;
    for (size_t i = 0; i < pixels; ++i)
        if (!(v->rgba[4 * i] >= 0.0f))
            return NULL;
    return v;
}

typedef struct denoise_run {
    vct_context *ctx;
    cl_program program, edge_program;
    cl_mem color, albedo, normal_depth, variance, signal[2], guide, slope, fit;
    cl_uint size[2];
} denoise_run;

/* The passes, ping-ponging between the two signal buffers; the last one
 * written is returned in *last. */
static int atrous_passes(denoise_run *r, const vct_denoise_options *o, int first, int *last,
                         vct_error *err) {
    cl_float4 sigma = {{o->sigma_luminance, o->sigma_normal, o->sigma_depth, 0.0f}};
    /* Where the program has it (CPU devices), the pass that takes 16
     * pixels of a row per work-item in vector lanes: the same image. */
    cl_int lanes_rc = CL_SUCCESS;
    cl_kernel k = clCreateKernel(r->program, "denoise_atrous16", &lanes_rc);
    const size_t span = lanes_rc == CL_SUCCESS ? 16 : 1;
    if (lanes_rc != CL_SUCCESS)
        k = vct_kernel_create(r->ctx, r->program, "denoise_atrous", err);
    int rc = k ? VCT_OK : (int)err->status;
    const size_t global[2] = {(r->size[0] + span - 1) / span, r->size[1]}, local[2] = {8, 8};
    int from = first;
    for (uint32_t i = 0; rc == VCT_OK && i < o->iterations;
         ++i, from ^= 1, sigma.s[0] *= SIGMA_LUMINANCE_DECAY) {
        const cl_int step = 1 << i;
        rc = vct_set_args(err, STAGE, k, 0, 7, VCT_ARG(in, r->signal[from]), VCT_ARG_OF(r->guide),
                          VCT_ARG_OF(r->slope), VCT_ARG_OF(r->size), VCT_ARG_OF(step),
                          VCT_ARG_OF(sigma), VCT_ARG(out, r->signal[from ^ 1]));
        if (rc == VCT_OK)
            rc = vct_launch_2d(r->ctx, k, global, local, err);
    }
    if (k)
        clReleaseKernel(k);
    *last = from;
    return rc;
}

/* Launches k (its arguments set while rc is VCT_OK) over every pixel in
 * 8 x 8 groups, and releases it. */
static int over_pixels(denoise_run *r, cl_kernel k, int rc, vct_error *err) {
    const size_t global[2] = {r->size[0], r->size[1]}, local[2] = {8, 8};
    if (rc == VCT_OK)
        rc = vct_launch_2d(r->ctx, k, global, local, err);
    if (k)
        clReleaseKernel(k);
    return rc;
}

/* A kernel over every pixel with arguments (in, size, out[, out2, albedo]). */
static int pixel_pass(denoise_run *r, const char *name, cl_mem in, cl_mem out, cl_mem out2,
                      vct_error *err) {
    cl_kernel k = vct_kernel_create(r->ctx, r->program, name, err);
    /* the estimate reads the colour into the variance, the guides the
     * normals and depths into the guide */
    const int guides = strcmp(name, "denoise_guides") == 0;
    int rc = k ? vct_set_args(err, STAGE, k, 0, 3, sizeof in, (const void *)&in,
                              guides ? "normal_depth" : "color", VCT_ARG_OF(r->size), sizeof out,
                              (const void *)&out, guides ? "guide" : "variance")
               : (int)err->status;
    if (rc == VCT_OK && out2)
        rc = vct_set_args(err, STAGE, k, 3, 2, VCT_ARG(slope, out2), VCT_ARG_OF(r->albedo));
    return over_pixels(r, k, rc, err);
}

/* The edge pixels' fit from the clamped signal (signal[1]) into fit. */
static int fit_edges(denoise_run *r, vct_error *err) {
    cl_kernel k = vct_kernel_create(r->ctx, r->edge_program, "denoise_edge_fit", err);
    int rc =
        k ? vct_set_args(err, STAGE, k, 0, 5, VCT_ARG(signal, r->signal[1]), VCT_ARG_OF(r->albedo),
                         VCT_ARG_OF(r->normal_depth), VCT_ARG_OF(r->size), VCT_ARG_OF(r->fit))
          : (int)err->status;
    return over_pixels(r, k, rc, err);
}

/* signal[0] into signal[1], its fireflies clamped. */
static int clamp_fireflies(denoise_run *r, float sigmas, vct_error *err) {
    cl_kernel k = vct_kernel_create(r->ctx, r->program, "denoise_clamp", err);
    const cl_float bound = sigmas;
    int rc = k ? vct_set_args(err, STAGE, k, 0, 4, VCT_ARG(in, r->signal[0]), VCT_ARG_OF(r->size),
                              VCT_ARG(k, bound), VCT_ARG(out, r->signal[1]))
               : (int)err->status;
    return over_pixels(r, k, rc, err);
}

/* The image and guides to the device; `known`: the variance guide to use
 * (known_variance), or NULL for one estimated from the image. */
static int upload(denoise_run *r, const vct_image *color, const vct_denoise_guides *g,
                  const vct_image *known, size_t pixels, vct_error *err) {
    const size_t bytes = 16 * pixels;
    r->color =
        vct_buffer_create(r->ctx, STAGE, "image", bytes, CL_MEM_READ_WRITE, color->rgba, err);
    r->albedo = r->color ? vct_buffer_create(r->ctx, STAGE, "albedo", bytes, CL_MEM_READ_ONLY,
                                             g->albedo->rgba, err)
                         : NULL;
    r->normal_depth = r->albedo ? vct_buffer_create(r->ctx, STAGE, "normal and depth", bytes,
                                                    CL_MEM_READ_ONLY, g->normal_depth->rgba, err)
                                : NULL;
    float *v = known ? variance_floats(known, pixels) : NULL;
    if (known && !v)
        return vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory", STAGE);
    r->variance = r->normal_depth ? vct_buffer_create(r->ctx, STAGE, "variance", 4 * pixels,
                                                      CL_MEM_READ_WRITE, v, err)
                                  : NULL;
    free(v);
    for (int i = 0; i < 2; ++i)
        r->signal[i] = r->variance ? vct_buffer_create(r->ctx, STAGE, "signal", bytes,
                                                       CL_MEM_READ_WRITE, NULL, err)
                                   : NULL;
    r->guide = r->signal[1]
                   ? vct_buffer_create(r->ctx, STAGE, "guide", bytes, CL_MEM_READ_WRITE, NULL, err)
                   : NULL;
    r->slope = r->guide ? vct_buffer_create(r->ctx, STAGE, "depth slope", 8 * pixels,
                                            CL_MEM_READ_WRITE, NULL, err)
                        : NULL;
    r->fit = r->slope
                 ? vct_buffer_create(r->ctx, STAGE, "edge fit", bytes, CL_MEM_READ_WRITE, NULL, err)
                 : NULL;
    return r->fit ? VCT_OK : (int)err->status;
}

int vct_denoise_whole(vct_context *ctx, const vct_image *color, const vct_denoise_guides *g,
                      const vct_denoise_options *o, vct_image *out, vct_error *err) {
    memset(out, 0, sizeof *out);
    int rc = VCT_OK;
    const size_t pixels = (size_t)color->width * color->height;
    denoise_run r;
    memset(&r, 0, sizeof r);
    r.ctx = ctx;
    r.size[0] = (cl_uint)color->width;
    r.size[1] = (cl_uint)color->height;
    const cl_uint n = (cl_uint)pixels;
    vct_stage_begin(ctx, STAGE);
    rc = vct_program_get(ctx, "denoise/atrous.cl", NULL, &r.program, err);
    if (rc == VCT_OK)
        rc = vct_program_get(ctx, "denoise/edge_fit.cl", NULL, &r.edge_program, err);
    const vct_image *known = known_variance(g->variance);
    if (rc == VCT_OK)
        rc = upload(&r, color, g, known, pixels, err);
    if (rc == VCT_OK && !known)
        rc = pixel_pass(&r, "denoise_estimate_variance", r.color, r.variance, NULL, err);
    if (rc == VCT_OK)
        rc = pixel_pass(&r, "denoise_guides", r.normal_depth, r.guide, r.slope, err);
    if (rc == VCT_OK)
        rc = vct_run_kernel(ctx, r.program, "denoise_demodulate", STAGE, pixels, err, 5,
                            VCT_ARG_OF(r.color), VCT_ARG_OF(r.albedo), VCT_ARG_OF(r.variance),
                            VCT_ARG(pixels, n), VCT_ARG(signal, r.signal[0]));
    int last = 0;
    if (rc == VCT_OK)
        rc = clamp_fireflies(&r, o->firefly_sigma, err);
    if (rc == VCT_OK)
        rc = fit_edges(&r, err);
    if (rc == VCT_OK)
        rc = atrous_passes(&r, o, 1, &last, err);
    if (rc == VCT_OK)
        rc = vct_run_kernel(ctx, r.program, "denoise_remodulate", STAGE, pixels, err, 5,
                            VCT_ARG(signal, r.signal[last]), VCT_ARG_OF(r.albedo),
                            VCT_ARG_OF(r.fit), VCT_ARG(pixels, n), VCT_ARG_OF(r.color));
    if (rc == VCT_OK) {
        out->rgba = malloc(16 * pixels);
        rc = out->rgba ? vct_buffer_read(ctx, STAGE, r.color, 0, 16 * pixels, out->rgba, err)
                       : vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory", STAGE);
        out->width = color->width;
        out->height = color->height;
    }
    cl_mem all[] = {r.color,     r.albedo, r.normal_depth, r.variance, r.signal[0],
                    r.signal[1], r.guide,  r.slope,        r.fit};
    for (size_t i = 0; i < sizeof all / sizeof all[0]; ++i)
        vct_buffer_release(ctx, all[i]);
    vct_stage_end(ctx);
    if (rc != VCT_OK)
        vct_image_release(out);
    return rc;
}
