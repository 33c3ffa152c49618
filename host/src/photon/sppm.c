/* Photon mapping, progressive (SPPM) or with the seed's fixed radii: the
 * passes (kernels/render/sppm.cl) over the photon stage's tracing and grids.
 * The per-pixel statistics are kept with the scene's running sums
 * (vct_accumulation_of) so that a resumed call (the viewer's frames) goes
 * on from them. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "accel/tri_vertices.h"
#include "light/emitters.h"
#include "photon/photon_grid.h"
#include "photon/sppm.h"
#include "frame/frame.h"
#include "frame/progress.h"
#include "runtime/runtime.h"
#include "scene/scene_device.h"
#include "scene/scene_resident.h"

#define STAGE "photon mapping"

enum { GLOBAL, CAUSTIC, MAPS };

/* What persists between passes and resumed calls. */
typedef struct sppm_state {
    int width, height;
    vct_pm_options settings; /* those the statistics were made with */
    cl_mem vp, direct_sum, fg_sum, radius_max;
    cl_mem stats[MAPS], radius[MAPS];
    uint32_t passes;
    uint64_t emitted, stored[MAPS];
} sppm_state;

/* One call's working set. */
typedef struct sppm_run {
    const vct_scene *scene;
    const vct_accel *accel;
    const vct_pm_options *opt;
    vct_accumulation *acc; /* where st is kept */
    sppm_state *st;
    vct_scene_buffers sb;
    vct_emitters nee; /* by area, for the visible points' direct light */
    vct_photon_sources sources;
    vct_photon_slots slots;
    vct_photon_grid grid[MAPS];
    vct_camera_desc cam;
    cl_program program;
    cl_kernel visible, gather, final_gather;
    int map_on[MAPS];
    uint32_t store_mask;
    float r0[MAPS];
    vct_scene_frame frame;
} sppm_run;

vct_pm_options vct_pm_options_default(int width, int height) {
    vct_pm_options o;
    memset(&o, 0, sizeof o);
    o.width = width;
    o.height = height;
    o.passes = 64;
    o.photons_per_pass = 131072;
    o.max_depth = 16;
    o.alpha = 2.0f / 3.0f;
    o.gather_rays = 8;
    o.kernel = VCT_PM_KERNEL_EPANECHNIKOV;
    o.normal_cos = 0.0f;
    return o;
}

static void state_free(vct_context *ctx, sppm_state *st) {
    if (!st)
        return;
    cl_mem mems[] = {st->vp,       st->direct_sum, st->fg_sum,    st->radius_max,
                     st->stats[0], st->stats[1],   st->radius[0], st->radius[1]};
    for (size_t i = 0; i < sizeof mems / sizeof *mems; ++i)
        vct_buffer_release(ctx, mems[i]);
    free(st);
}

void vct_pm_state_release(vct_context *ctx, vct_accumulation *acc) {
    state_free(ctx, acc->pm_state);
    acc->pm_state = NULL;
}

static void context_state_release(vct_context *ctx) {
    vct_pm_state_release(ctx, &ctx->accumulation);
}

/* Settings that change what the statistics mean. */
static int same_settings(const vct_pm_options *a, const vct_pm_options *b) {
    return a->width == b->width && a->height == b->height &&
           a->photons_per_pass == b->photons_per_pass && a->max_depth == b->max_depth &&
           a->radius == b->radius && a->caustic_radius == b->caustic_radius &&
           a->fixed_radius == b->fixed_radius && a->alpha == b->alpha &&
           a->final_gather == b->final_gather && a->gather_rays == b->gather_rays &&
           a->direct_photons == b->direct_photons && a->kernel == b->kernel &&
           a->normal_cos == b->normal_cos && a->seed == b->seed;
}

/* A buffer of bytes / 4 words, each set to `fill` (a uint or a float's bits). */
static cl_mem pixel_buffer(vct_context *ctx, const char *what, size_t bytes, uint32_t fill, int *rc,
                           vct_error *err) {
    if (*rc != VCT_OK)
        return NULL;
    cl_mem m = vct_buffer_create(ctx, STAGE, what, bytes, CL_MEM_READ_WRITE, NULL, err);
    if (!m)
        *rc = err->status;
    else
        *rc = vct_buffer_fill_u32(ctx, STAGE, m, fill, bytes / 4, err);
    return m;
}

/* The statistics: kept when resuming with the same settings, else new. */
static int state_get(vct_context *ctx, sppm_run *r, vct_error *err) {
    const vct_pm_options *o = r->opt;
    sppm_state *old = r->acc->pm_state;
    if (o->resume && old && same_settings(&old->settings, o)) {
        r->st = old;
        return VCT_OK;
    }
    vct_pm_state_release(ctx, r->acc);
    if (r->acc == &ctx->accumulation)
        vct_context_on_release(ctx, context_state_release);
    sppm_state *st = calloc(1, sizeof *st);
    if (!st)
        return vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory", STAGE);
    st->settings = *o;
    const size_t px = (size_t)o->width * o->height;
    int rc = VCT_OK;
    st->vp = pixel_buffer(ctx, "visible points", 80 * px, 0, &rc, err);
    st->direct_sum = pixel_buffer(ctx, "direct light sums", 16 * px, 0, &rc, err);
    st->fg_sum = pixel_buffer(ctx, "final gathering sums", 16 * px, 0, &rc, err);
    st->radius_max = pixel_buffer(ctx, "largest radii", 8, 0, &rc, err);
    for (int m = 0; m < MAPS; ++m) {
        uint32_t r0_bits;
        memcpy(&r0_bits, &r->r0[m], 4);
        st->stats[m] = pixel_buffer(ctx, "photon statistics", 16 * px, 0, &rc, err);
        st->radius[m] = pixel_buffer(ctx, "gather radii", 4 * px, r0_bits, &rc, err);
    }
    if (rc != VCT_OK) {
        state_free(ctx, st);
        return rc;
    }
    r->acc->pm_state = r->st = st;
    return VCT_OK;
}

/* Mirrors and glass: what makes caustics. */
static int scene_has_specular(const vct_scene *s) {
    for (uint32_t i = 0; i < s->material_count; ++i) {
        vct_material_desc d;
        vct_material_desc_make(&s->materials[i], &d);
        const float glossy = d.albedo.s[3] > 0.5f
                                 ? d.albedo.s[0] + d.albedo.s[1] + d.albedo.s[2]
                                 : d.specular.s[0] + d.specular.s[1] + d.specular.s[2];
        if (d.specular.s[3] > 0.0f || (glossy > 0.0f && d.emission.s[3] < VCT_MIRROR_ROUGHNESS))
            return 1;
    }
    return 0;
}

static int options_check(const vct_scene *s, const vct_pm_options *o, const vct_scene_frame *f,
                         vct_error *err) {
    const int sky = s->ambient[0] > 0.0f || s->ambient[1] > 0.0f || s->ambient[2] > 0.0f;
    if (s->light_count == 0 && vct_scene_emissive_triangles(s) == 0 && !sky)
        return vct_fail(err, VCT_ERR_INPUT,
                        "%s: the scene has no lights, nothing emits and it has no sky: add a "
                        "light (--point-light, --dir-light, --ambient) or an emissive material",
                        STAGE);
    if (o->passes == 0 && !(o->time_limit_s > 0.0))
        return vct_fail(err, VCT_ERR_INPUT, "%s: give a pass count (--spp) or a time (--time)",
                        STAGE);
    if (o->max_depth == 0)
        return vct_fail(err, VCT_ERR_INPUT, "%s: the depth must be at least 1", STAGE);
    if (o->photons_per_pass == 0)
        return vct_fail(err, VCT_ERR_INPUT, "%s: give at least 1 photon per pass (--photons)",
                        STAGE);
    const float radii[2] = {o->radius, o->caustic_radius};
    for (int m = 0; m < 2; ++m) {
        const char *flag = m ? "--pm-caustic-radius" : "--pm-radius";
        if (!(radii[m] >= 0.0f) || !isfinite(radii[m]))
            return vct_fail(err, VCT_ERR_INPUT, "%s: %s %g must be a positive distance", STAGE,
                            flag, radii[m]);
        if (radii[m] > 0.0f && radii[m] < 1e-6f * f->extent)
            return vct_fail(err, VCT_ERR_INPUT,
                            "%s: %s %g is below what positions in a scene %g across can tell "
                            "apart: give at least %g",
                            STAGE, flag, radii[m], f->extent, 1e-6f * f->extent);
        if (radii[m] > f->extent)
            return vct_fail(err, VCT_ERR_INPUT,
                            "%s: %s %g is larger than the scene (%g across): give a radius "
                            "below a tenth of that",
                            STAGE, flag, radii[m], f->extent);
    }
    if (!o->fixed_radius && !(o->alpha > 0.0f && o->alpha <= 1.0f))
        return vct_fail(err, VCT_ERR_INPUT, "%s: alpha %g must be in (0, 1]", STAGE, o->alpha);
    if (o->final_gather && o->gather_rays == 0)
        return vct_fail(err, VCT_ERR_INPUT, "%s: final gathering needs at least 1 ray", STAGE);
    if (o->final_gather && o->direct_photons)
        return vct_fail(err, VCT_ERR_INPUT,
                        "%s: final gathering takes direct light from shadow rays: drop one of "
                        "final gathering and direct light from photons",
                        STAGE);
    return VCT_OK;
}

static int kernels_make(vct_context *ctx, sppm_run *r, vct_error *err) {
    int rc = vct_program_get(ctx, "render/sppm.cl", vct_accel_program_options(r->accel),
                             &r->program, err);
    if (rc == VCT_OK && !(r->visible = vct_kernel_create(ctx, r->program, "sppm_visible", err)))
        rc = err->status;
    if (rc == VCT_OK && !(r->gather = vct_kernel_create(ctx, r->program, "sppm_gather", err)))
        rc = err->status;
    if (rc == VCT_OK &&
        !(r->final_gather = vct_kernel_create(ctx, r->program, "sppm_final_gather", err)))
        rc = err->status;
    return rc;
}

static int visible_pass(vct_context *ctx, sppm_run *r, cl_uint pass, vct_error *err) {
    sppm_state *st = r->st;
    cl_kernel k = r->visible;
    const vct_scene *s = r->scene;
    const cl_float4 ambient = {{s->ambient[0], s->ambient[1], s->ambient[2], 0.0f}};
    const cl_uint seed = r->opt->seed, depth = r->opt->max_depth;
    const cl_uint direct_mode = r->opt->direct_photons ? 0u : 1u;
    int rc = vct_accel_set_args(k, r->accel, STAGE, err);
    if (rc == VCT_OK)
        rc = vct_set_args(err, STAGE, k, 5, 3, VCT_ARG_OF(r->cam), VCT_ARG_OF(r->sb.materials),
                          VCT_ARG_OF(r->sb.tri_material));
    if (rc == VCT_OK)
        rc = vct_scene_texture_args(k, 8, &r->sb, STAGE, err);
    if (rc == VCT_OK)
        rc = vct_set_args(
            err, STAGE, k, 11, 18, VCT_ARG_OF(r->sb.lights), VCT_ARG_OF(r->sb.light_count),
            VCT_ARG(emitter_tris, r->nee.tris), VCT_ARG(emitter_cdf, r->nee.cdf),
            VCT_ARG(emitter_count, r->nee.count), VCT_ARG(emitter_inv_area, r->nee.inv_area),
            VCT_ARG_OF(seed), VCT_ARG_OF(pass), VCT_ARG(max_depth, depth), VCT_ARG_OF(ambient),
            VCT_ARG_OF(direct_mode), VCT_ARG_OF(st->vp), VCT_ARG_OF(st->direct_sum),
            VCT_ARG(stats_global, st->stats[GLOBAL]), VCT_ARG(radius_global, st->radius[GLOBAL]),
            VCT_ARG(stats_caustic, st->stats[CAUSTIC]),
            VCT_ARG(radius_caustic, st->radius[CAUSTIC]), VCT_ARG_OF(st->radius_max));
    if (rc == VCT_OK)
        rc = vct_buffer_fill_u32(ctx, STAGE, st->radius_max, 0, 2, err);
    const size_t global[2] = {(size_t)r->cam.size.s[0], (size_t)r->cam.size.s[1]},
                 local[2] = {8, 8};
    if (rc == VCT_OK)
        rc = vct_launch_2d(ctx, k, global, local, err);
    return rc;
}

/* The grids' cells: the largest radius a pixel that found photons has
 * (the initial one until some have), or final gathering's this pass. */
static int photon_pass(vct_context *ctx, sppm_run *r, cl_uint pass, float fg_radius,
                       vct_pm_result *res, vct_error *err) {
    sppm_state *st = r->st;
    cl_uint bits[MAPS] = {0, 0};
    int rc = vct_buffer_read(ctx, STAGE, st->radius_max, 0, sizeof bits, bits, err);
    /* A band takes the whole image's largest radii, so that its grids are
     * the whole image's (the order photons are summed in follows the cells). */
    if (rc == VCT_OK && ctx->band_sync && ctx->band_sync(ctx->band_sync_user, pass, bits) != 0)
        rc = vct_fail(err, VCT_ERR_OPENCL, "%s: the other bands of the image stopped", STAGE);
    double t0 = vct_now_ms();
    const vct_photon_trace_job job = {r->scene,     r->accel, &r->sb,       &r->sources,
                                      r->opt->seed, pass,     r->store_mask};
    if (rc == VCT_OK)
        rc = vct_photon_trace(ctx, STAGE, &job, &r->slots, err);
    if (rc == VCT_OK)
        rc = vct_finish(ctx, STAGE, err);
    const double t1 = vct_now_ms();
    res->trace_ms += t1 - t0;
    const uint32_t masks[MAPS] = {VCT_PHOTON_INDIRECT | (r->store_mask & VCT_PHOTON_DIRECT),
                                  VCT_PHOTON_CAUSTIC};
    for (int m = 0; m < MAPS && rc == VCT_OK; ++m) {
        if (!r->map_on[m])
            continue;
        float cell;
        memcpy(&cell, &bits[m], 4);
        if (!(cell > 0.0f))
            cell = r->r0[m];
        if (m == GLOBAL && r->opt->final_gather)
            cell = fg_radius;
        /* Cells stay countable in ints however far the radii shrink. */
        cell = fmaxf(cell, 1e-6f * r->frame.extent);
        rc = vct_photon_grid_build(ctx, STAGE, &r->slots, masks[m], cell, r->frame.lo, r->frame.hi,
                                   &r->grid[m], err);
        st->stored[m] += r->grid[m].count;
    }
    if (rc == VCT_OK)
        rc = vct_finish(ctx, STAGE, err);
    res->grid_ms += vct_now_ms() - t1;
    return rc;
}

static int gather_pass(vct_context *ctx, sppm_run *r, cl_uint pass, float fg_radius,
                       vct_error *err) {
    sppm_state *st = r->st;
    const cl_uint pixels = (cl_uint)(r->cam.size.s[0] * r->cam.size.s[1]);
    const cl_float alpha = r->opt->fixed_radius ? 1.0f : r->opt->alpha;
    const cl_uint flags = r->opt->kernel == VCT_PM_KERNEL_EPANECHNIKOV ? 1u : 0u;
    const cl_float normal_cos = r->opt->normal_cos;
    int rc = VCT_OK;
    for (int m = 0; m < MAPS && rc == VCT_OK; ++m) {
        if (!r->map_on[m] || (m == GLOBAL && r->opt->final_gather))
            continue;
        cl_kernel k = r->gather;
        rc = vct_set_args(err, STAGE, k, 0, 3, VCT_ARG_OF(st->vp), VCT_ARG_OF(pixels),
                          VCT_ARG_OF(r->sb.materials));
        if (rc == VCT_OK)
            rc = vct_photon_grid_args(k, 3, "map", &r->grid[m], STAGE, err);
        if (rc == VCT_OK)
            rc = vct_set_args(err, STAGE, k, 7, 5, VCT_ARG_OF(alpha), VCT_ARG_OF(flags),
                              VCT_ARG_OF(normal_cos), VCT_ARG(stats, st->stats[m]),
                              VCT_ARG(radius, st->radius[m]));
        if (rc == VCT_OK)
            rc = vct_launch(ctx, k, pixels, 64, err);
    }
    if (rc != VCT_OK || !r->opt->final_gather || !r->map_on[GLOBAL])
        return rc;
    cl_kernel k = r->final_gather;
    const cl_uint caustics = (cl_uint)r->map_on[CAUSTIC], rays = r->opt->gather_rays;
    const cl_uint seed = r->opt->seed;
    const cl_float inv_emitted = 1.0f / (float)r->slots.paths;
    rc = vct_accel_set_args(k, r->accel, STAGE, err);
    if (rc == VCT_OK)
        rc = vct_set_args(err, STAGE, k, 5, 2, VCT_ARG_OF(r->sb.materials),
                          VCT_ARG_OF(r->sb.tri_material));
    if (rc == VCT_OK)
        rc = vct_scene_texture_args(k, 7, &r->sb, STAGE, err);
    const cl_uint first_pixel = r->cam.size.s[2] * r->cam.size.s[0]; /* a band's first */
    if (rc == VCT_OK)
        rc = vct_set_args(err, STAGE, k, 10, 3, VCT_ARG_OF(st->vp), VCT_ARG_OF(pixels),
                          VCT_ARG_OF(first_pixel));
    if (rc == VCT_OK)
        rc = vct_photon_grid_args(k, 13, "glob", &r->grid[GLOBAL], STAGE, err);
    /* Without a caustic map its arguments are the global map's, never read. */
    if (rc == VCT_OK)
        rc = vct_photon_grid_args(k, 17, "caus", &r->grid[caustics ? CAUSTIC : GLOBAL], STAGE, err);
    if (rc == VCT_OK)
        rc = vct_set_args(err, STAGE, k, 21, 9, VCT_ARG_OF(caustics), VCT_ARG(radius, fg_radius),
                          VCT_ARG_OF(inv_emitted), VCT_ARG_OF(rays), VCT_ARG_OF(seed),
                          VCT_ARG_OF(pass), VCT_ARG_OF(flags), VCT_ARG_OF(normal_cos),
                          VCT_ARG_OF(st->fg_sum));
    if (rc == VCT_OK)
        rc = vct_launch(ctx, k, pixels, 64, err);
    return rc;
}

static int resolve(vct_context *ctx, sppm_run *r, vct_image *image, vct_error *err) {
    sppm_state *st = r->st;
    const int w = r->cam.size.s[0], h = r->cam.size.s[1];
    cl_mem frame = vct_frame_get(ctx, STAGE, w, h, err);
    if (!frame)
        return err->status;
    const cl_uint pixels = (cl_uint)(w * h);
    const cl_float inv_passes = st->passes ? 1.0f / (float)st->passes : 0.0f;
    const cl_float inv_emitted = st->emitted ? (float)(1.0 / (double)st->emitted) : 0.0f;
    const cl_uint components = r->opt->components ? r->opt->components : VCT_PM_ALL;
    int rc = vct_run_kernel(
        ctx, r->program, "sppm_resolve", STAGE, pixels, err, 11, VCT_ARG_OF(st->direct_sum),
        VCT_ARG_OF(st->fg_sum), VCT_ARG(stats_global, st->stats[GLOBAL]),
        VCT_ARG(radius_global, st->radius[GLOBAL]), VCT_ARG(stats_caustic, st->stats[CAUSTIC]),
        VCT_ARG(radius_caustic, st->radius[CAUSTIC]), VCT_ARG_OF(inv_passes),
        VCT_ARG_OF(inv_emitted), VCT_ARG_OF(components), VCT_ARG_OF(pixels), VCT_ARG_OF(frame));
    if (rc == VCT_OK)
        rc = vct_frame_deliver(ctx, STAGE, image, err);
    return rc;
}

/* What the scene calls for: the maps, what photons keep, the radii. */
static int plan_maps(sppm_run *r, vct_error *err) {
    const vct_pm_options *o = r->opt;
    vct_plan plan;
    vct_plan_make(r->scene, NULL, &plan);
    r->map_on[GLOBAL] = plan.on[VCT_EFFECT_INDIRECT] || o->direct_photons;
    r->map_on[CAUSTIC] = scene_has_specular(r->scene);
    r->store_mask = 0;
    if (r->map_on[GLOBAL])
        r->store_mask |=
            VCT_PHOTON_INDIRECT | (o->direct_photons || o->final_gather ? VCT_PHOTON_DIRECT : 0u);
    if (r->map_on[CAUSTIC])
        r->store_mask |= VCT_PHOTON_CAUSTIC;
    vct_scene_frame_of(r->scene, &r->frame);
    r->r0[GLOBAL] = o->radius > 0.0f ? o->radius : 0.015f * r->frame.extent;
    /* Progressive radii shrink fastest where photons are densest, caustics
     * first, so both maps start alike; fixed radii follow the seed, whose
     * caustic radius was about half the global one. */
    const float caustic_share = o->fixed_radius ? 0.5f : 1.0f;
    r->r0[CAUSTIC] = o->caustic_radius > 0.0f ? o->caustic_radius : caustic_share * r->r0[GLOBAL];
    (void)err;
    return VCT_OK;
}

static void run_release(vct_context *ctx, sppm_run *r) {
    cl_kernel ks[] = {r->visible, r->gather, r->final_gather};
    for (int i = 0; i < 3; ++i)
        if (ks[i])
            clReleaseKernel(ks[i]);
    for (int m = 0; m < MAPS; ++m)
        vct_photon_grid_release(ctx, &r->grid[m]);
    vct_photon_slots_release(ctx, &r->slots);
    vct_photon_sources_release(ctx, &r->sources);
    vct_emitters_release(ctx, &r->nee);
    vct_scene_buffers_release(ctx, &r->sb);
}

vct_status vct_render_pm(vct_context *ctx, const vct_scene *s, const vct_accel *accel,
                         const vct_pm_options *opt, vct_image *image, vct_pm_result *result,
                         vct_error *err) {
    vct_pm_result unused;
    if (!result)
        result = &unused;
    memset(image, 0, sizeof *image);
    memset(result, 0, sizeof *result);
    sppm_run r;
    memset(&r, 0, sizeof r);
    r.scene = s;
    r.accel = accel;
    r.opt = opt;
    r.acc = vct_accumulation_of(ctx, s);
    int rc = plan_maps(&r, err);
    if (rc == VCT_OK)
        rc = options_check(s, opt, &r.frame, err);
    if (rc == VCT_OK)
        rc = vct_frame_camera(ctx, &s->camera, opt->width, opt->height, &r.cam, err);
    if (rc != VCT_OK)
        return rc;
    vct_stage_begin(ctx, STAGE);
    rc = vct_scene_buffers_make(ctx, s, STAGE, &r.sb, err);
    if (rc == VCT_OK)
        rc = vct_emitters_build(ctx, s, VCT_EMITTERS_BY_AREA, STAGE, &r.nee, err);
    if (rc == VCT_OK && r.store_mask)
        rc = vct_photon_sources_make(ctx, s, STAGE, &r.sources, err);
    if (rc == VCT_OK && r.store_mask)
        rc =
            vct_photon_slots_make(ctx, STAGE, opt->photons_per_pass, opt->max_depth, &r.slots, err);
    if (rc == VCT_OK)
        rc = kernels_make(ctx, &r, err);
    if (rc == VCT_OK)
        rc = state_get(ctx, &r, err);
    const int show = opt->progress && isatty(2);
    const double t0 = vct_now_ms();
    uint32_t done = 0;
    while (rc == VCT_OK) {
        const double elapsed = (vct_now_ms() - t0) * 1e-3;
        if (opt->passes ? done >= opt->passes : elapsed >= opt->time_limit_s)
            break;
        sppm_state *st = r.st;
        const cl_uint pass = st->passes;
        /* Final gathering's radius shrinks for all pixels alike (Knaus and
         * Zwicker 2011): r_i^2 = r_1^2 prod (k + alpha) / (k + 1). */
        double r2 = (double)r.r0[GLOBAL] * r.r0[GLOBAL];
        const double alpha = opt->fixed_radius ? 1.0 : opt->alpha;
        for (uint32_t k = 1; k <= pass; ++k)
            r2 *= (k + alpha) / (k + 1.0);
        const float fg_radius = (float)sqrt(r2);
        rc = visible_pass(ctx, &r, pass, err);
        if (rc == VCT_OK && r.store_mask) {
            rc = photon_pass(ctx, &r, pass, fg_radius, result, err);
            const double tg = vct_now_ms();
            if (rc == VCT_OK)
                rc = gather_pass(ctx, &r, pass, fg_radius, err);
            if (rc == VCT_OK)
                rc = vct_finish(ctx, STAGE, err);
            result->gather_ms += vct_now_ms() - tg;
            st->emitted += r.slots.paths;
        }
        ++st->passes;
        ++done;
        if (show)
            vct_progress_line(done, opt->passes, (vct_now_ms() - t0) * 1e-3, opt->time_limit_s,
                              "passes");
    }
    if (show)
        fputc('\n', stderr);
    if (rc == VCT_OK)
        rc = resolve(ctx, &r, image, err);
    result->seconds = (vct_now_ms() - t0) * 1e-3;
    if (r.st) {
        result->passes = r.st->passes;
        result->photons_emitted = r.st->emitted;
        result->photons_stored[0] = r.st->stored[GLOBAL];
        result->photons_stored[1] = r.st->stored[CAUSTIC];
    }
    result->global_map = r.map_on[GLOBAL] && r.store_mask;
    result->caustic_map = r.map_on[CAUSTIC] && r.store_mask;
    for (int m = 0; m < MAPS; ++m) {
        result->hashed[m] = r.grid[m].dims.s[3] != 0;
        result->grid_bytes[m] = vct_photon_grid_bytes(&r.grid[m]);
        result->cell[m] = r.grid[m].origin.s[3];
    }
    if (rc != VCT_OK) {
        vct_image_release(image);
        vct_pm_state_release(ctx, r.acc); /* the statistics are no longer whole */
    }
    run_release(ctx, &r);
    vct_stage_end(ctx);
    return rc;
}
