/* Voxel cone tracing: the voxel hierarchy the plan needs, and the image
 * (kernels/render/vct_render.cl), one stage per effect. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accel/accel.h"
#include "light/emitters.h"
#include "frame/frame.h"
#include "conetrace/gather_picks.h"
#include "conetrace/vct_caustics.h"
#include "conetrace/vct_indirect_filter.h"
#include "conetrace/vct_relight.h"
#include "voxel/bounce_rest.h"
#include "voxel/cones.h"
#include "scene/scene_device.h"
#include "vct_types.h"
#include "voxel/voxels.h"

#define PRIMARY_STAGE "vct primary"
#define DIFFUSE_STAGE "vct diffuse cones"
#define SPECULAR_STAGE "vct specular cone"
#define SOFT_STAGE "vct soft shadows"
#define GLASS_STAGE "vct glass reflection"
#define CAUSTICS_STAGE "vct caustics"
#define BOUNCE_STAGE "light bounce"

vct_vct_options vct_vct_options_default(int width, int height) {
    vct_vct_options o;
    memset(&o, 0, sizeof o);
    o.width = width;
    o.height = height;
    o.diffuse_cones = 9;
    o.sparse_diffuse = 1;
    o.cones = vct_cone_settings_default();
    o.edge_samples = VCT_EDGE_SAMPLES_DEFAULT;
    o.indirect_passes = VCT_INDIRECT_PASSES_DEFAULT;
    return o;
}

void vct_aovs_release(vct_aovs *a) {
    vct_image_release(&a->direct);
    vct_image_release(&a->indirect);
    vct_image_release(&a->specular);
    vct_image_release(&a->ao);
    vct_image_release(&a->position);
    vct_image_release(&a->normal);
    vct_image_release(&a->albedo);
    vct_image_release(&a->normal_depth);
    vct_image_release(&a->indirect_variance);
}

/* The diffuse passes' cone argument: count vct_cone_dir, zeroed. Their
 * gather spreads GATHER_RAYS_PER_CONE rays a cone over the hemisphere
 * itself (kernels/render/diffuse_rays.h), so any count from 1 to 16 is
 * taken; the argument keeps the signature every cone pass shares. */
static cl_mem cone_buffer(vct_context *ctx, uint32_t count, const char *stage, vct_error *err) {
    if (count < 1 || count > 16) {
        vct_fail(err, VCT_ERR_INPUT, "%u diffuse cones: 1 to 16 (9 gather rays each)", count);
        return NULL;
    }
    vct_cone_dir cones[16];
    memset(cones, 0, sizeof cones);
    return vct_buffer_create(ctx, stage, "diffuse cones", sizeof cones[0] * count, CL_MEM_READ_ONLY,
                             cones, err);
}

static int keep_direct(vct_context *ctx, vct_voxels *v, vct_error *err) {
    const uint64_t n = v->info.voxels;
    /* made once: what the bounces add to */
    int rc = vct_buffer_copy_into(ctx, BOUNCE_STAGE, "direct voxel radiance", v->radiance,
                                  &v->direct_radiance, 16 * n, err);
    return rc ? rc
              : vct_buffer_copy_into(ctx, BOUNCE_STAGE, "direct voxel sides", v->side,
                                     &v->direct_side, 16 * VCT_VOXEL_SIDE_FLOAT4S * n, err);
}

/* The arguments inject_bounce and inject_bounce_fill share: the
 * acceleration structure, the cone pools of the light gathered, the cones
 * and the voxels; *next: the first argument after them. */
static int bounce_shared_args(cl_kernel k, const vct_accel *g, const vct_voxels *light,
                              const vct_cone_desc *desc, vct_voxels *v, cl_uint keep_sides,
                              int *next, vct_error *err) {
    const cl_uint voxels = v->info.voxels;
    *next = 5; /* after ACCEL_ARGS */
    int rc = vct_accel_set_args(k, g, BOUNCE_STAGE, err);
    if (rc == VCT_OK)
        rc = vct_cone_set_args(k, light, desc, BOUNCE_STAGE, next, err);
    if (rc == VCT_OK)
        rc = vct_set_args(err, BOUNCE_STAGE, k, *next, 8, VCT_ARG_OF(v->keys), VCT_ARG_OF(voxels),
                          VCT_ARG_OF(v->albedo), VCT_ARG(direct, v->direct_radiance),
                          VCT_ARG_OF(v->direct_side), VCT_ARG(voxel_radiance, v->radiance),
                          VCT_ARG_OF(v->side), VCT_ARG_OF(keep_sides));
    *next += 8;
    return rc;
}

/* What a bounce leaves of the radiance bricks: every level made again; the
 * leaf level alone, which is all the next bounce's rays read, the coarser
 * levels waiting for a later refresh (v->radiance_stale); or nothing, for
 * the rest of the series that follows, which filters them once. */
typedef enum { REFRESH_NONE, REFRESH_LEAVES, REFRESH_ALL } bounce_refresh;

/* One bounce into v's voxels, gathered by rays from `light`'s bricks:
 * v's own, or (carry) the voxels before, whose light a moved scene carries
 * over; then a carried voxel keeps its light before until its turn to
 * gather comes (carry->every). keep_sides 1: each voxel's sides keep their
 * plane (voxel_side.h). */
static int inject_bounce(vct_context *ctx, const vct_scene *s, const vct_accel *g, vct_voxels *v,
                         const vct_voxel_carry *carry, const vct_cone_settings *cs,
                         bounce_refresh refresh, int keep_sides, vct_error *err) {
    const vct_voxels *light = carry ? carry->before : v;
    if (!v->radiance || !v->has_bricks)
        return vct_fail(err, VCT_ERR_INPUT,
                        "%s: inject light into built bricks first (vct_bricks_build, "
                        "vct_voxels_inject_light)",
                        BOUNCE_STAGE);
    int rc = vct_cone_settings_check(cs, err);
    const uint32_t n = v->info.voxels;
    if (rc || n == 0)
        return rc;
    vct_stage_begin(ctx, BOUNCE_STAGE);
    if (v->bounces == 0) /* keep the direct light that every bounce adds to */
        rc = keep_direct(ctx, v, err);
    cl_program p;
    char options[256];
    vct_cone_options(light, cs, options, sizeof options);
    /* the accel's options too: rays test the sky */
    snprintf(options + strlen(options), sizeof options - strlen(options), " %s",
             vct_accel_program_options(g));
    if (rc == VCT_OK)
        rc = vct_program_get(ctx, "conetrace/inject_bounce.cl", options, &p, err);
    cl_kernel k = rc == VCT_OK ? vct_kernel_create(ctx, p, "inject_bounce", err) : NULL;
    vct_cone_desc desc;
    vct_cone_desc_make(light, cs, s->ambient, &desc);
    int next = 0;
    rc = k ? bounce_shared_args(k, g, light, &desc, v, (cl_uint)keep_sides, &next, err)
           : (int)err->status;
    /* without carried light carry_every is 0 and the buffers never read */
    cl_mem carried_from = carry ? carry->carried_from : v->radiance;
    const cl_uint carry_every = carry ? carry->every : 0u, carry_phase = carry ? carry->phase : 0u;
    if (rc == VCT_OK)
        rc = vct_set_args(err, BOUNCE_STAGE, k, next, 5, VCT_ARG_OF(carried_from),
                          VCT_ARG(before_radiance, light->radiance),
                          VCT_ARG(before_side, light->side), VCT_ARG_OF(carry_every),
                          VCT_ARG_OF(carry_phase));
    /* carried light gathers a share of the voxels its own way */
    const cl_uint sparse = !carry && !v->dense_bounces;
    cl_mem received =
        rc == VCT_OK ? vct_buffer_create(ctx, BOUNCE_STAGE, "received light",
                                         sparse ? 32ull * n : 16u, CL_MEM_READ_WRITE, NULL, err)
                     : NULL;
    if (rc == VCT_OK && !received)
        rc = (int)err->status;
    if (rc == VCT_OK)
        rc = vct_set_args(err, BOUNCE_STAGE, k, next + 5, 2, VCT_ARG_OF(sparse),
                          VCT_ARG_OF(received));
    if (rc == VCT_OK)
        rc = vct_bounce_rest_keep(ctx, v, err);
    if (rc == VCT_OK)
        rc = vct_launch(ctx, k, n, 64, err);
    cl_kernel fill =
        rc == VCT_OK && sparse ? vct_kernel_create(ctx, p, "inject_bounce_fill", err) : NULL;
    if (rc == VCT_OK && sparse && !fill)
        rc = (int)err->status;
    if (fill) {
        int at = 0;
        rc = bounce_shared_args(fill, g, light, &desc, v, (cl_uint)keep_sides, &at, err);
        if (rc == VCT_OK)
            rc = vct_set_args(err, BOUNCE_STAGE, fill, at, 2, VCT_ARG_OF(received),
                              VCT_ARG(neighbours, v->neighbours));
        if (rc == VCT_OK)
            rc = vct_launch(ctx, fill, n, 64, err);
        clReleaseKernel(fill);
    }
    vct_buffer_release(ctx, received);
    if (rc == VCT_OK)
        rc = vct_bounce_rest_measure(ctx, v, err);
    if (rc == VCT_OK)
        rc = vct_finish(ctx, BOUNCE_STAGE, err);
    if (rc == VCT_OK)
        ++v->bounces;
    if (k)
        clReleaseKernel(k);
    vct_stage_end(ctx);
    if (rc != VCT_OK)
        return rc;
    v->radiance_stale = refresh != REFRESH_ALL;
    if (refresh == REFRESH_LEAVES)
        return vct_bricks_refresh_leaves(ctx, v, err);
    return refresh == REFRESH_ALL ? vct_bricks_refresh_radiance(ctx, v, err) : VCT_OK;
}

vct_status vct_voxels_inject_bounce(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                                    vct_voxels *v, const vct_cone_settings *cs, vct_error *err) {
    return inject_bounce(ctx, s, g, v, NULL, cs, REFRESH_ALL, v->bounces >= 1, err);
}

/* The bounces after direct light: the last bounce's radiance is filtered
 * once, after the rest of the series is added. The first and the last
 * decide each voxel's sides, those between keep them (voxel_side.h). */
static int light_bounces(vct_context *ctx, const vct_scene *s, const vct_accel *g, vct_voxels *v,
                         const vct_cone_settings *cs, uint32_t bounces, vct_error *err) {
    int rc = VCT_OK;
    for (uint32_t b = 1; rc == VCT_OK && b < bounces; ++b) {
        const bounce_refresh refresh = b + 1 < bounces  ? REFRESH_LEAVES
                                       : v->bounce_rest ? REFRESH_NONE
                                                        : REFRESH_ALL;
        rc = inject_bounce(ctx, s, g, v, NULL, cs, refresh, b > 1 && b + 1 < bounces, err);
    }
    return rc == VCT_OK ? vct_voxels_bounce_rest(ctx, v, err) : (vct_status)rc;
}

static int check_bounces(uint32_t bounces, vct_error *err) {
    if (bounces < 1 || bounces > 4)
        return vct_fail(err, VCT_ERR_INPUT, "%u bounces: give 1 (direct light in the voxels) to 4",
                        bounces);
    return VCT_OK;
}

/* 1 when b's voxels can take a's light: the same volume frame, and light
 * in a's voxels. */
static int same_frame(const vct_voxels *a, const vct_voxels *b) {
    return a->radiance && a->side && vct_voxels_same_frame(a, b);
}

/* 1 when cones for b's voxels can march through a's bricks. */
static int same_bricks(const vct_voxels *a, const vct_voxels *b) {
    return a->has_bricks && a->radiance_ready && !a->radiance_stale && b->has_bricks &&
           a->brick_info.anisotropic == b->brick_info.anisotropic &&
           a->brick_info.image == b->brick_info.image;
}

/* New voxels, lit: every bounce, or (carry) direct light kept from the
 * voxels before where nothing that moved reaches and one bounce gathered
 * from their light. *carried: which was done. */
static vct_status prepare(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                          const vct_plan *plan, const vct_voxel_options *vo,
                          const vct_brick_options *bo, uint32_t bounces,
                          const vct_cone_settings *cs, vct_voxel_carry *carry, vct_voxels **out,
                          int *carried, vct_error *err) {
    *out = NULL;
    *carried = 0;
    if (!vct_plan_needs_voxels(plan))
        return VCT_OK;
    if (check_bounces(bounces, err) != VCT_OK)
        return err->status;
    /* only what moved voxelized again, where that is known */
    vct_voxels *v =
        carry && carry->moved_hi > carry->moved_lo
            ? vct_voxelize_moved(ctx, s, vo, carry->before, carry->moved_lo, carry->moved_hi, err)
            : vct_voxelize(ctx, s, vo, err);
    if (v)
        v->emitters_by_cones = plan->emitters_by_cones;
    int rc = v ? vct_octree_build(ctx, v, err) : err->status;
    if (carry && v && !same_frame(carry->before, v))
        carry = NULL; /* the scene's bounds moved the voxels: nothing to carry */
    /* Light first, into the voxels: the bricks then build and filter every
     * channel in one pass (1.2x faster than re-filtering radiance after). */
    const int lit = vct_plan_needs_voxel_light(plan);
    if (rc == VCT_OK && lit)
        rc = carry ? vct_voxels_inject_light_carried(ctx, s, g, v, carry, err)
                   : (int)vct_voxels_inject_light(ctx, s, g, v, err);
    vct_brick_options bricks = {VCT_BRICKS_AUTO, 0, 0};
    if (bo)
        bricks = *bo;
    bricks.radiance_later = 0;
    if (rc == VCT_OK)
        rc = vct_bricks_build(ctx, v, &bricks, err);
    if (rc == VCT_OK && lit && carry && same_bricks(carry->before, v)) {
        /* the light carried holds the higher bounces: no rest of the series */
        const int rest = v->bounce_rest;
        v->bounce_rest = 0;
        rc = inject_bounce(ctx, s, g, v, carry, cs, REFRESH_ALL, 0, err);
        v->bounce_rest = rest;
        *carried = 1;
    } else if (rc == VCT_OK && lit) {
        rc = light_bounces(ctx, s, g, v, cs, bounces, err);
    }
    if (carry) {
        vct_buffer_release(ctx, carry->carried_from);
        carry->carried_from = NULL;
    }
    if (rc != VCT_OK) {
        vct_voxels_release(v);
        return rc;
    }
    *out = v;
    return VCT_OK;
}

vct_status vct_vct_prepare(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                           const vct_plan *plan, const vct_voxel_options *vo,
                           const vct_brick_options *bo, uint32_t bounces,
                           const vct_cone_settings *cs, vct_voxels **out, vct_error *err) {
    int carried;
    return prepare(ctx, s, g, plan, vo, bo, bounces, cs, NULL, out, &carried, err);
}

vct_status vct_vct_prepare_carry(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                                 const vct_plan *plan, const vct_voxel_options *vo,
                                 const vct_brick_options *bo, uint32_t bounces,
                                 const vct_cone_settings *cs, vct_voxel_carry *carry,
                                 vct_voxels **out, int *carried, vct_error *err) {
    return prepare(ctx, s, g, plan, vo, bo, bounces, cs, carry, out, carried, err);
}

int vct_vct_relight(vct_context *ctx, const vct_scene *s, const vct_accel *g, vct_voxels *v,
                    uint32_t bounces, const vct_cone_settings *cs, vct_error *err) {
    if (check_bounces(bounces, err) != VCT_OK)
        return err->status;
    const int rc = vct_voxels_inject_light(ctx, s, g, v, err);
    return rc == VCT_OK ? light_bounces(ctx, s, g, v, cs, bounces, err) : rc;
}

int vct_vct_relight_carry(vct_context *ctx, const vct_scene *s, const vct_accel *g, vct_voxels *v,
                          const vct_cone_settings *cs, int inject_direct, vct_error *err) {
    /* the light already holds the higher bounces: no rest of the series */
    const int rest = v->bounce_rest;
    v->bounce_rest = 0;
    int rc = VCT_OK;
    if (inject_direct) /* else the direct light kept from the injection before */
        rc = vct_voxels_inject_light_kept(ctx, s, g, v, err);
    /* each render's bounce is the last so far: it decides the sides */
    if (rc == VCT_OK)
        rc = inject_bounce(ctx, s, g, v, NULL, cs, REFRESH_ALL, 0, err);
    v->bounce_rest = rest;
    return rc;
}

/* -D options: the planned effects, which also choose the kernels the
 * program holds (a kernel no pass runs is not compiled), then the cones'
 * (pool kind, levels). */
static void program_options(const vct_plan *plan, int emitters, int sparse, const vct_voxels *v,
                            const vct_cone_settings *cones, char *out, size_t size) {
    static const char *defines[VCT_EFFECTS] = {
        "-DVCT_DIRECT",   "-DVCT_SHADOWS",      "-DVCT_INDIRECT",
        "-DVCT_SPECULAR", "-DVCT_REFRACTION",   "-DVCT_EMISSION",
        "-DVCT_AO",       "-DVCT_SOFT_SHADOWS", "-DVCT_CAUSTICS"};
    size_t len = 0;
    out[0] = '\0';
    for (int e = 0; e < VCT_EFFECTS; ++e)
        if (plan->on[e] && defines[e])
            len += (size_t)snprintf(out + len, size - len, "%s%s", len ? " " : "", defines[e]);
    if (emitters && plan->on[VCT_EFFECT_DIRECT] && len < size)
        len += (size_t)snprintf(out + len, size - len, " -DVCT_EMITTERS");
    if (sparse && len < size)
        len += (size_t)snprintf(out + len, size - len, " -DVCT_SPARSE_DIFFUSE");
    if (v && len < size)
        vct_cone_options(v, cones, out + len, size - len);
}

typedef struct frame {
    vct_context *ctx;
    const vct_voxels *v;
    const vct_accel *accel; /* the diffuse cones' sky rays */
    cl_program program;
    cl_mem gbuf, image, aov;
    cl_mem reflection;       /* glass reflections, when refraction and specular are planned */
    vct_scene_buffers scene; /* materials and lights, uploaded once per frame */
    vct_emitters emitters;   /* emissive triangles, sampled as lights */
    vct_gather_picks picks;  /* the diffuse gather's (kernels/render/gather_picks.h) */
    vct_cone_desc desc;
    cl_uint size[2];
} frame;

/* Over every pixel, or with `every` 2 over every other pixel per axis. */
static int launch_frame_kernel(frame *f, cl_kernel k, cl_uint every, vct_error *err) {
    const size_t global[2] = {(f->size[0] + every - 1) / every, (f->size[1] + every - 1) / every};
    const size_t local[2] = {8, 8};
    return vct_launch_2d(f->ctx, k, global, local, err);
}

/* The diffuse gather's arguments from `first` on (GATHER_ARGS in
 * kernels/render/vct_render.cl): the scene's shading inputs, one emitter
 * sample per ray, and the voxels' light with its direct part (the light
 * itself before any bounce: none bounced). */
static int gather_args(frame *f, cl_kernel k, const char *stage, int first, vct_error *err) {
    const vct_scene_buffers sb = f->scene;
    const vct_voxels *v = f->v;
    const int bounced = v->bounces > 0 && v->direct_radiance;
    const cl_mem direct = bounced ? v->direct_radiance : v->radiance;
    const cl_mem direct_side = bounced ? v->direct_side : v->side;
    int rc = vct_set_args(err, stage, k, first, 1, VCT_ARG_OF(sb.tri_material));
    if (rc == VCT_OK)
        rc = vct_scene_texture_args(k, first + 1, &sb, stage, err);
    if (rc == VCT_OK)
        rc = vct_set_args(err, stage, k, first + 4, 2, VCT_ARG_OF(sb.lights),
                          VCT_ARG_OF(sb.light_count));
    if (rc == VCT_OK)
        rc = vct_emitters_set_args(k, first + 6, &f->emitters, 1, stage, err);
    if (rc == VCT_OK)
        rc = vct_set_args(err, stage, k, first + 11, 4, VCT_ARG(voxel_total, v->radiance),
                          VCT_ARG(voxel_total_side, v->side), VCT_ARG(voxel_direct, direct),
                          VCT_ARG(voxel_direct_side, direct_side));
    /* without picks any buffer will do: none is read */
    const cl_mem cdf = f->picks.cdf ? f->picks.cdf : v->keys;
    if (rc == VCT_OK)
        rc = vct_set_args(err, stage, k, first + 15, 4, VCT_ARG(pick_cdf, cdf),
                          VCT_ARG(voxel_keys, v->keys), VCT_ARG(pick_count, f->picks.count),
                          VCT_ARG(pick_total, f->picks.total));
    return rc;
}

/* vct_primary's arguments, which vct_primary_refine shares. */
static int primary_args(frame *f, cl_kernel k, const vct_scene *s, const vct_accel *g,
                        const vct_camera_desc *cam, vct_error *err) {
    const vct_scene_buffers sb = f->scene;
    int rc = vct_accel_set_args(k, g, PRIMARY_STAGE, err);
    const cl_float4 ambient = {{s->ambient[0], s->ambient[1], s->ambient[2], 0.0f}};
    if (rc == VCT_OK)
        rc = vct_set_args(err, PRIMARY_STAGE, k, 5, 3, VCT_ARG_OF(*cam), VCT_ARG_OF(sb.materials),
                          VCT_ARG_OF(sb.tri_material));
    if (rc == VCT_OK)
        rc = vct_scene_texture_args(k, 8, &sb, PRIMARY_STAGE, err);
    if (rc == VCT_OK)
        rc = vct_set_args(err, PRIMARY_STAGE, k, 11, 2, VCT_ARG_OF(sb.lights),
                          VCT_ARG_OF(sb.light_count));
    if (rc == VCT_OK)
        rc = vct_emitters_set_args(k, 13, &f->emitters, VCT_EMITTER_SAMPLES, PRIMARY_STAGE, err);
    if (rc == VCT_OK)
        rc = vct_set_args(err, PRIMARY_STAGE, k, 18, 5, VCT_ARG_OF(ambient), VCT_ARG_OF(f->gbuf),
                          VCT_ARG_OF(f->image), VCT_ARG_OF(f->aov), VCT_ARG_OF(f->reflection));
    return rc;
}

/* vct_primary (with its keys) or vct_primary_refine (with the flags and
 * the rays per axis) over every pixel. */
static int primary_launch(frame *f, const char *name, const vct_scene *s, const vct_accel *g,
                          const vct_camera_desc *cam, cl_mem buffer, cl_uint n, vct_error *err) {
    cl_kernel k = vct_kernel_create(f->ctx, f->program, name, err);
    int rc = k ? primary_args(f, k, s, g, cam, err) : (int)err->status;
    if (rc == VCT_OK)
        rc = vct_set_args(err, PRIMARY_STAGE, k, 23, 1, sizeof buffer, (const void *)&buffer,
                          strcmp(name, "vct_primary") == 0 ? "keys" : "flags");
    if (rc == VCT_OK && n)
        rc = vct_set_args(err, PRIMARY_STAGE, k, 24, 1, VCT_ARG_OF(n));
    if (rc == VCT_OK)
        rc = launch_frame_kernel(f, k, 1, err);
    if (k)
        clReleaseKernel(k);
    return rc;
}

/* Camera rays through the pixels' centres; then, unless edge_samples is 1,
 * the pixels on an edge again with n x n rays each. */
static int primary(frame *f, const vct_scene *s, const vct_accel *g, const vct_camera_desc *cam,
                   cl_uint edge_samples, vct_error *err) {
    const size_t pixels = (size_t)f->size[0] * f->size[1];
    cl_mem keys = vct_buffer_create(f->ctx, PRIMARY_STAGE, "edge keys", 4 * pixels,
                                    CL_MEM_READ_WRITE, NULL, err);
    int rc = keys ? primary_launch(f, "vct_primary", s, g, cam, keys, 0, err) : (int)err->status;
    cl_mem flags = NULL;
    if (rc == VCT_OK && edge_samples > 1) {
        flags = vct_buffer_create(f->ctx, PRIMARY_STAGE, "edge flags", pixels, CL_MEM_READ_WRITE,
                                  NULL, err);
        rc = flags ? vct_run_kernel(f->ctx, f->program, "vct_edge_flags", PRIMARY_STAGE, pixels,
                                    err, 5, VCT_ARG_OF(f->gbuf), VCT_ARG_OF(keys),
                                    VCT_ARG(materials, f->scene.materials), VCT_ARG_OF(f->size),
                                    VCT_ARG_OF(flags))
                   : (int)err->status;
        if (rc == VCT_OK)
            rc = primary_launch(f, "vct_primary_refine", s, g, cam, flags, edge_samples, err);
    }
    if (rc == VCT_OK)
        rc = vct_finish(f->ctx, PRIMARY_STAGE, err);
    vct_buffer_release(f->ctx, flags);
    vct_buffer_release(f->ctx, keys);
    return rc;
}

/* One cone kernel over the G-buffer: ACCEL_ARGS when `rays` (the diffuse
 * gather traces them), CONE_POOLS, child, desc, then, if given, a
 * buffer and a count (cones, lights, or glass reflections and float4 per
 * pixel), then gbuf, materials, size, image, aov, the sparse diffuse
 * cells if given (which the kernel runs over, one per 2x2 pixels, when
 * `over_cells`), and for the diffuse kernels the gather's (gather_args). */
static int cone_pass_with(frame *f, const char *stage, const char *name, int rays, cl_mem list,
                          cl_uint list_count, cl_mem sparse, int over_cells, vct_error *err) {
    cl_kernel k = vct_kernel_create(f->ctx, f->program, name, err);
    int next = rays ? 5 : 0;
    int rc = k ? VCT_OK : (int)err->status;
    if (rc == VCT_OK && rays)
        rc = vct_accel_set_args(k, f->accel, stage, err);
    if (rc == VCT_OK)
        rc = vct_cone_set_args(k, f->v, &f->desc, stage, &next, err);
    if (rc == VCT_OK && list) {
        /* the list's parameters, by pass */
        const int diffuse = strstr(name, "diffuse") != NULL,
                  soft = strcmp(name, "vct_soft_shadows") == 0;
        rc = vct_set_args(err, stage, k, next, 2, sizeof list, (const void *)&list,
                          diffuse ? "cones"
                          : soft  ? "lights"
                                  : "reflection",
                          sizeof list_count, (const void *)&list_count,
                          diffuse ? "cone_count"
                          : soft  ? "light_count"
                                  : "per_pixel");
        next += 2;
    }
    if (rc == VCT_OK)
        rc = vct_set_args(err, stage, k, next, 5, VCT_ARG_OF(f->gbuf),
                          VCT_ARG_OF(f->scene.materials), VCT_ARG_OF(f->size), VCT_ARG_OF(f->image),
                          VCT_ARG_OF(f->aov));
    if (rc == VCT_OK && sparse)
        rc = vct_set_args(err, stage, k, next + 5, 1, VCT_ARG_OF(sparse));
    if (rc == VCT_OK && strstr(name, "diffuse"))
        rc = gather_args(f, k, stage, next + 5 + (sparse ? 1 : 0), err);
    if (rc == VCT_OK)
        rc = launch_frame_kernel(f, k, over_cells ? 2 : 1, err);
    if (rc == VCT_OK)
        rc = vct_finish(f->ctx, stage, err);
    if (k)
        clReleaseKernel(k);
    return rc;
}

static int cone_pass(frame *f, const char *stage, const char *name, cl_mem list, cl_uint list_count,
                     vct_error *err) {
    return cone_pass_with(f, stage, name, 0, list, list_count, NULL, 0, err);
}

/* Indirect diffuse light (or AO): every pixel's cones, or with sparse
 * diffuse, those of every other pixel per axis and the rest filled in. */
static int diffuse_pass(frame *f, cl_mem cones, cl_uint count, int sparse, int indirect,
                        vct_error *err) {
    int rc = indirect
                 ? vct_gather_picks_build(f->ctx, f->program, f->v, DIFFUSE_STAGE, &f->picks, err)
                 : VCT_OK;
    if (rc == VCT_OK && !sparse)
        rc = cone_pass_with(f, DIFFUSE_STAGE, "vct_diffuse_cones", 1, cones, count, NULL, 0, err);
    if (rc != VCT_OK || !sparse)
        return rc;
    const size_t cells = (size_t)((f->size[0] + 1) / 2) * ((f->size[1] + 1) / 2);
    cl_mem buffer = vct_buffer_create(f->ctx, DIFFUSE_STAGE, "sparse diffuse cells", 32 * cells,
                                      CL_MEM_READ_WRITE, NULL, err);
    rc = buffer ? cone_pass_with(f, DIFFUSE_STAGE, "vct_diffuse_sparse", 1, cones, count, buffer, 1,
                                 err)
                : (int)err->status;
    if (rc == VCT_OK)
        rc = cone_pass_with(f, DIFFUSE_STAGE, "vct_diffuse_fill", 1, cones, count, buffer, 0, err);
    vct_buffer_release(f->ctx, buffer);
    return rc;
}

/* The AOV buffer (AOV_SLOTS float4 per pixel, kernels/render/vct_render.cl) split
 * into images: a slot's float4 as it is, or one of its components as grey. */
#define AOV_SLOTS 8
static int read_aovs(frame *f, vct_aovs *a, vct_image *direct_variance, vct_error *err) {
    const struct {
        vct_image *image;
        int slot, component; /* component -1: the whole float4 */
    } outs[] = {{&a->direct, 0, -1},    {&a->indirect, 1, -1},     {&a->specular, 2, -1},
                {&a->ao, 3, 0},         {&a->position, 4, -1},     {&a->normal, 5, -1},
                {&a->albedo, 6, -1},    {&a->normal_depth, 7, -1}, {&a->indirect_variance, 3, 1},
                {direct_variance, 3, 2}};
    const size_t pixels = (size_t)f->size[0] * f->size[1], bytes = 16 * AOV_SLOTS * pixels;
    float *raw = malloc(bytes);
    int rc = raw ? vct_buffer_read(f->ctx, "vct AOVs", f->aov, 0, bytes, raw, err)
                 : vct_fail(err, VCT_ERR_MEMORY, "vct AOVs: out of host memory");
    for (size_t i = 0; i < sizeof outs / sizeof outs[0] && rc == VCT_OK; ++i) {
        vct_image *im = outs[i].image;
        if (!im)
            continue;
        im->width = (int)f->size[0];
        im->height = (int)f->size[1];
        im->rgba = malloc(16 * pixels);
        if (!im->rgba) {
            rc = vct_fail(err, VCT_ERR_MEMORY, "vct AOVs: out of host memory");
            break;
        }
        for (size_t p = 0; p < pixels; ++p) {
            const float *src = &raw[4 * (AOV_SLOTS * p + (size_t)outs[i].slot)];
            float *dst = &im->rgba[4 * p];
            if (outs[i].component < 0)
                memcpy(dst, src, 16);
            else
                dst[0] = dst[1] = dst[2] = src[outs[i].component], dst[3] = 1.0f;
        }
    }
    free(raw);
    return rc;
}

vct_status vct_render_vct(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                          const vct_voxels *v, const vct_plan *plan, const vct_vct_options *opt,
                          vct_image *image, vct_aovs *aovs, vct_error *err) {
    memset(image, 0, sizeof *image);
    if (aovs)
        memset(aovs, 0, sizeof *aovs);
    const int cones_on = vct_plan_needs_voxels(plan);
    if (cones_on && (!v || !v->has_bricks))
        return vct_fail(err, VCT_ERR_INPUT,
                        "vct: the plan traces cones: build the voxels first (vct_vct_prepare)");
    int rc = vct_cone_settings_check(&opt->cones, err);
    if (rc == VCT_OK && opt->edge_samples > VCT_EDGE_SAMPLES_MAX)
        rc = vct_fail(err, VCT_ERR_INPUT,
                      "vct: %u rays per axis at edges is more than %u: give 1 to %u (1: pixel "
                      "centres only)",
                      opt->edge_samples, VCT_EDGE_SAMPLES_MAX, VCT_EDGE_SAMPLES_MAX);
    if (rc == VCT_OK && opt->indirect_passes > VCT_INDIRECT_PASSES_MAX)
        rc = vct_fail(err, VCT_ERR_INPUT,
                      "vct: %u filter passes over the indirect light: give 0 (none) to %u",
                      opt->indirect_passes, VCT_INDIRECT_PASSES_MAX);
    vct_camera_desc cam;
    if (rc == VCT_OK)
        rc = vct_frame_camera(ctx, &s->camera, opt->width, opt->height, &cam, err);
    if (rc)
        return rc;
    frame f;
    memset(&f, 0, sizeof f);
    f.ctx = ctx;
    f.v = cones_on ? v : NULL;
    f.accel = g;
    f.size[0] = (cl_uint)opt->width;
    f.size[1] = (cl_uint)opt->height;
    if (f.v)
        vct_cone_desc_make(f.v, &opt->cones, s->ambient, &f.desc);
    char own[256], options[320];
    /* emissive triangles sampled as lights (VCT_EMITTERS) */
    const int emitters = vct_scene_emissive_triangles(s) > 0 && !plan->emitters_by_cones &&
                         plan->on[VCT_EFFECT_DIRECT];
    program_options(plan, emitters, opt->sparse_diffuse, f.v, &opt->cones, own, sizeof own);
    vct_accel_options_join(g, own, options, sizeof options);
    const size_t pixels = (size_t)opt->width * opt->height;

    vct_stage_begin(ctx, PRIMARY_STAGE);
    rc = vct_program_get(ctx, "render/vct_render.cl", options, &f.program, err);
    /* GBUF_SLOTS (8) float4 per pixel (kernels/render/vct_render.cl) */
    f.gbuf = rc == VCT_OK ? vct_buffer_create(ctx, PRIMARY_STAGE, "G-buffer", 128 * pixels,
                                              CL_MEM_READ_WRITE, NULL, err)
                          : NULL;
    f.image = f.gbuf ? vct_frame_get(ctx, PRIMARY_STAGE, opt->width, opt->height, err) : NULL;
    rc = f.image ? VCT_OK : (int)err->status;
    const int filter = opt->indirect_passes > 0 && plan->on[VCT_EFFECT_INDIRECT];
    if (rc == VCT_OK && (aovs || filter)) {
        f.aov = vct_buffer_create(ctx, PRIMARY_STAGE, "AOVs", 16 * AOV_SLOTS * pixels,
                                  CL_MEM_READ_WRITE, NULL, err);
        rc = f.aov ? vct_buffer_fill_u32(ctx, PRIMARY_STAGE, f.aov, 0, 4 * AOV_SLOTS * pixels, err)
                   : (int)err->status;
    }
    const int glass = plan->on[VCT_EFFECT_REFRACTION] && plan->on[VCT_EFFECT_SPECULAR];
    if (rc == VCT_OK && glass) {
        f.reflection = vct_buffer_create(ctx, PRIMARY_STAGE, "glass reflections", 48 * pixels,
                                         CL_MEM_READ_WRITE, NULL, err);
        rc = f.reflection ? VCT_OK : (int)err->status;
    }
    if (rc == VCT_OK)
        rc = vct_scene_buffers_make(ctx, s, PRIMARY_STAGE, &f.scene, err);
    if (rc == VCT_OK)
        rc = vct_emitters_build(ctx, s, VCT_EMITTERS_BY_POWER, PRIMARY_STAGE, &f.emitters, err);
    if (rc == VCT_OK)
        rc = primary(&f, s, g, &cam,
                     opt->edge_samples ? opt->edge_samples : VCT_EDGE_SAMPLES_DEFAULT, err);
    vct_stage_end(ctx);

    if (rc == VCT_OK && plan->on[VCT_EFFECT_CAUSTICS]) {
        vct_stage_begin(ctx, CAUSTICS_STAGE);
        rc = vct_caustics_add(ctx, s, g, &f.scene, f.program, f.gbuf, f.image, f.aov, f.size, err);
        vct_stage_end(ctx);
    }
    if (rc == VCT_OK && plan->on[VCT_EFFECT_SOFT_SHADOWS]) {
        vct_stage_begin(ctx, SOFT_STAGE);
        rc =
            cone_pass(&f, SOFT_STAGE, "vct_soft_shadows", f.scene.lights, f.scene.light_count, err);
        vct_stage_end(ctx);
    }
    if (rc == VCT_OK && (plan->on[VCT_EFFECT_INDIRECT] || plan->on[VCT_EFFECT_AO])) {
        vct_stage_begin(ctx, DIFFUSE_STAGE);
        cl_mem cones = cone_buffer(ctx, opt->diffuse_cones, DIFFUSE_STAGE, err);
        const cl_uint count = opt->diffuse_cones;
        rc = cones ? diffuse_pass(&f, cones, count, opt->sparse_diffuse,
                                  plan->on[VCT_EFFECT_INDIRECT], err)
                   : (int)err->status;
        vct_buffer_release(ctx, cones);
        vct_stage_end(ctx);
    }
    if (rc == VCT_OK && plan->on[VCT_EFFECT_SPECULAR]) {
        vct_stage_begin(ctx, SPECULAR_STAGE);
        rc = cone_pass(&f, SPECULAR_STAGE, "vct_specular_cone", NULL, 0, err);
        vct_stage_end(ctx);
    }
    if (rc == VCT_OK && glass) {
        vct_stage_begin(ctx, GLASS_STAGE);
        rc = cone_pass(&f, GLASS_STAGE, "vct_glass_reflection", f.reflection, 3, err);
        vct_stage_end(ctx);
    }
    /* the filter reads the indirect AOV and leaves it as the image holds it */
    vct_aovs for_filter = {0};
    vct_image direct_variance = {0};
    if (rc == VCT_OK && (aovs || filter))
        rc = read_aovs(&f, aovs ? aovs : &for_filter, filter && emitters ? &direct_variance : NULL,
                       err);
    vct_aovs *kept = aovs ? aovs : &for_filter;
    /* and the emitter samples' noise in the direct light, where there are any */
    if (rc == VCT_OK && filter)
        rc = vct_indirect_filter(ctx, &kept->albedo, &kept->normal_depth, &kept->indirect_variance,
                                 opt->indirect_passes, &kept->indirect, &direct_variance,
                                 emitters ? &kept->direct : NULL, err);
    vct_image_release(&direct_variance);
    vct_aovs_release(&for_filter);
    if (rc == VCT_OK)
        rc = vct_frame_deliver(ctx, "vct image", image, err);
    vct_scene_buffers_release(ctx, &f.scene);
    vct_emitters_release(ctx, &f.emitters);
    vct_buffer_release(ctx, f.picks.cdf);
    vct_buffer_release(ctx, f.aov);
    vct_buffer_release(ctx, f.gbuf);
    vct_buffer_release(ctx, f.reflection);
    if (rc != VCT_OK) {
        vct_image_release(image);
        if (aovs)
            vct_aovs_release(aovs);
    }
    return rc;
}
