/* Caustics for cone tracing: a pilot pass of photon paths from the lights
 * sets each pixel's gather radius, then passes of other paths are gathered
 * at every pixel's surface, each pass's photons that passed a dielectric in
 * a grid of their own. The same seed every frame: the same image. */
#include <stdarg.h>
#include <string.h>

#include "accel/tri_vertices.h"
#include "photon/photon_grid.h"
#include "photon/photon_sources.h"
#include "photon/photon_trace.h"
#include "conetrace/vct_caustics.h"
#include "runtime/runtime.h"

#define STAGE "vct caustics"
#define CAUSTIC_SEED 0x63617573u

typedef struct caustic_run {
    vct_context *ctx;
    const vct_scene *s;
    const vct_accel *g;
    const vct_scene_buffers *sb;
    vct_photon_sources sources;
    vct_photon_slots slots;
    vct_photon_grid grid;
    vct_scene_frame frame;
    float radius;
} caustic_run;

/* Traces pass `pass` and puts its photons in the grid; 0 photons: *empty. */
static int photon_pass(caustic_run *r, cl_uint pass, int *empty, vct_error *err) {
    const vct_photon_trace_job job = {
        r->s, r->g, r->sb, &r->sources, CAUSTIC_SEED, pass, VCT_PHOTON_DIELECTRIC};
    int rc = vct_photon_trace(r->ctx, STAGE, &job, &r->slots, err);
    /* Cells as wide as the widest search (kernels/render/vct_render.cl): a
     * search visits 3 x 3 x 3 of them at most. */
    if (rc == VCT_OK)
        rc = vct_photon_grid_build(r->ctx, STAGE, &r->slots, VCT_PHOTON_DIELECTRIC,
                                   4.0f * r->radius, r->frame.lo, r->frame.hi, &r->grid, err);
    *empty = r->grid.count == 0;
    return rc;
}

/* Runs `name` over the pixels: the grid's arguments, then `count` more. */
static int pixel_pass(caustic_run *r, cl_program program, const char *name, const cl_uint size[2],
                      vct_error *err, int count, ...) {
    cl_kernel k = vct_kernel_create(r->ctx, program, name, err);
    int rc = k ? vct_photon_grid_args(k, 0, "c", &r->grid, STAGE, err) : (int)err->status;
    va_list ap;
    va_start(ap, count);
    for (int i = 0; rc == VCT_OK && i < count; ++i) {
        const size_t bytes = va_arg(ap, size_t);
        const void *value = va_arg(ap, const void *);
        const char *bound = va_arg(ap, const char *);
        rc = vct_set_args(err, STAGE, k, 4 + i, 1, bytes, value, bound);
    }
    va_end(ap);
    const size_t global[2] = {size[0], size[1]}, local[2] = {8, 8};
    if (rc == VCT_OK)
        rc = vct_launch_2d(r->ctx, k, global, local, err);
    if (k)
        clReleaseKernel(k);
    return rc;
}

int vct_caustics_add(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                     const vct_scene_buffers *sb, cl_program program, cl_mem gbuf, cl_mem image,
                     cl_mem aov, const cl_uint size[2], vct_error *err) {
    caustic_run r;
    memset(&r, 0, sizeof r);
    r.ctx = ctx, r.s = s, r.g = g, r.sb = sb;
    vct_scene_frame_of(s, &r.frame);
    r.radius = VCT_CAUSTIC_RADIUS * r.frame.extent;
    const cl_uint2 dims = {{size[0], size[1]}};
    const cl_float radius = r.radius;
    const cl_float inv_emitted = 1.0f / (float)(VCT_CAUSTIC_PATHS * VCT_CAUSTIC_PASSES);
    int rc = vct_photon_sources_make(ctx, s, STAGE, &r.sources, err);
    if (rc == VCT_OK)
        rc = vct_photon_slots_make(ctx, STAGE, VCT_CAUSTIC_PATHS, VCT_CAUSTIC_DEPTH, &r.slots, err);
    cl_mem radii = rc == VCT_OK
                       ? vct_buffer_create(ctx, STAGE, "caustic radii", 4ull * size[0] * size[1],
                                           CL_MEM_READ_WRITE, NULL, err)
                       : NULL;
    if (rc == VCT_OK && !radii)
        rc = err->status;
    /* The pilot: its own paths (the pass after the estimate's). */
    int empty = 1;
    if (rc == VCT_OK)
        rc = photon_pass(&r, VCT_CAUSTIC_PASSES, &empty, err);
    if (rc == VCT_OK && !empty)
        rc = pixel_pass(&r, program, "vct_caustic_radius", size, err, 5, VCT_ARG_OF(radius),
                        VCT_ARG_OF(gbuf), VCT_ARG_OF(sb->materials), VCT_ARG(size, dims),
                        VCT_ARG_OF(radii));
    /* No photon passed a dielectric: nothing to gather. */
    for (cl_uint pass = 0; rc == VCT_OK && !empty && pass < VCT_CAUSTIC_PASSES; ++pass) {
        int none;
        rc = photon_pass(&r, pass, &none, err);
        if (rc == VCT_OK && !none)
            rc = pixel_pass(&r, program, "vct_caustics", size, err, 7, VCT_ARG_OF(radii),
                            VCT_ARG_OF(inv_emitted), VCT_ARG_OF(gbuf), VCT_ARG_OF(sb->materials),
                            VCT_ARG(size, dims), VCT_ARG_OF(image), VCT_ARG_OF(aov));
    }
    if (rc == VCT_OK)
        rc = vct_finish(ctx, STAGE, err);
    vct_buffer_release(ctx, radii);
    vct_photon_grid_release(ctx, &r.grid);
    vct_photon_slots_release(ctx, &r.slots);
    vct_photon_sources_release(ctx, &r.sources);
    return rc;
}
