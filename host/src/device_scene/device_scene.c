/* A scene committed to a context: the resident scene data, the emitter
 * tables, the acceleration structure and the voxels, each built at first
 * need and kept until a commit finds a change it depends on. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "accel/accel.h"
#include "accel/bvh.h"
#include "device_scene/device_scene_prepare.h"
#include "device_scene/moved_region.h"
#include "device_scene/scene_digest.h"
#include "light/emitters.h"
#include "conetrace/vct_relight.h"
#include "pathtrace/pathtrace.h"
#include "photon/sppm.h"
#include "runtime/runtime.h"
#include "scene/scene_resident.h"

/* What the voxels were built with: geometry (voxelization, octree, bricks)
 * and light (injection and bounces). Zeroed before it is filled, so that
 * whole structs compare. */
typedef struct voxel_key {
    vct_voxel_options voxel;
    vct_brick_options bricks;
    int emitters_by_cones;
} voxel_key;

typedef struct light_key {
    int lit;
    uint32_t bounces;
    vct_cone_settings cones;
} light_key;

struct vct_device_scene {
    vct_context *ctx;
    const vct_scene *scene;
    vct_resident resident; /* on ctx's list while the device scene lives */
    vct_scene_digest digest;
    vct_accel *accel;
    vct_accel_options accel_key;
    double accel_built_area; /* one level: its nodes' area sum as built (0: not measured) */
    vct_voxels *voxels;      /* NULL: none built, or the last plan needed none */
    /* The voxels a change of geometry or materials left, kept until the next
     * render that needs voxels: a job that carries light gathers from them. */
    vct_voxels *voxels_before;
    vct_moved_region moved; /* what moved since the voxels were built */
    uint32_t carry_renders; /* geometry carried so far: whose turn it is to gather */
    voxel_key voxel_key;
    light_key light_key;
    int light_stale;         /* the lights changed since the voxels' light was made */
    uint32_t light_settling; /* carried light: bounces still to gather (light_carry) */
    double light_ratio;      /* the bounce ratio the last full light build measured (0: none) */
    vct_device_scene_stats stats; /* scene_bytes: the acceleration structures' uploads */
};

vct_device_scene *vct_device_scene_create(vct_context *ctx, const vct_scene *scene,
                                          vct_error *err) {
    if (!ctx || !scene) {
        vct_fail(err, VCT_ERR_INPUT, "device scene: give a context and a scene");
        return NULL;
    }
    if (vct_resident_find(ctx, scene)) {
        vct_fail(err, VCT_ERR_INPUT,
                 "device scene: this scene is already committed to this context: commit that "
                 "device scene again instead (vct_device_scene_commit)");
        return NULL;
    }
    vct_device_scene *ds = calloc(1, sizeof *ds);
    if (!ds) {
        vct_fail(err, VCT_ERR_MEMORY, "device scene: out of host memory");
        return NULL;
    }
    ds->ctx = ctx;
    ds->scene = scene;
    ds->resident.scene = scene;
    ds->resident.next = ctx->resident;
    ctx->resident = &ds->resident;
    vct_scene_digest_make(scene, &ds->digest);
    vct_moved_region_init(&ds->moved, scene);
    ds->stats.commits = 1;
    return ds;
}

/* The progressive methods start over: their sums describe the scene before. */
static void drop_accumulation(vct_device_scene *ds) {
    vct_pt_sums_release(ds->ctx, &ds->resident.accumulation);
    vct_pm_state_release(ds->ctx, &ds->resident.accumulation);
}

static void drop_voxels(vct_device_scene *ds) {
    vct_voxels_release(ds->voxels);
    ds->voxels = NULL;
    ds->light_stale = 0;
    ds->light_settling = 0;
}

/* The voxels out of date, kept aside for their light (voxels_before). */
static void set_voxels_aside(vct_device_scene *ds) {
    vct_voxels_release(ds->voxels_before);
    ds->voxels_before = ds->voxels;
    ds->voxels = NULL;
    ds->light_stale = 0;
    ds->light_settling = 0;
}

static void drop_voxels_before(vct_device_scene *ds) {
    vct_voxels_release(ds->voxels_before);
    ds->voxels_before = NULL;
}

/* One level, its vertices moved: the BVH's boxes refit to them (the same
 * hits as a rebuild: ties go to the lower triangle index), unless that grew
 * the surface area its nodes sum to (the SAH cost before it is divided by
 * the root's) past VCT_REFIT_DEGRADED times the built tree's; then it is
 * built again at the next render. */
#define VCT_REFIT_DEGRADED 1.5

static int refit_one_level(vct_device_scene *ds, vct_error *err) {
    vct_context *ctx = ds->ctx;
    uint32_t leaves = 0;
    double sah = 0.0, area = 0.0;
    int rc = VCT_OK;
    if (!(ds->accel_built_area > 0.0))
        rc = vct_bvh_cost(ctx, ds->accel->bvh, &sah, &ds->accel_built_area, &leaves, err);
    const uint64_t before = ctx->transfers.uploaded;
    if (rc == VCT_OK)
        rc = vct_accel_refit(ctx, ds->accel, ds->scene, err);
    ds->stats.scene_bytes += ctx->transfers.uploaded - before;
    if (rc == VCT_OK)
        rc = vct_bvh_cost(ctx, ds->accel->bvh, &sah, &area, &leaves, err);
    if (rc != VCT_OK || area > VCT_REFIT_DEGRADED * ds->accel_built_area) {
        vct_accel_release(ds->accel);
        ds->accel = NULL;
        return rc;
    }
    ++ds->stats.accel_moves;
    return VCT_OK;
}

vct_status vct_device_scene_commit(vct_device_scene *ds, vct_error *err) {
    vct_scene_digest now;
    vct_scene_digest_make(ds->scene, &now);
    const unsigned changed = vct_scene_digest_changes(&ds->digest, &now);
    ++ds->stats.commits;
    if (!changed)
        return VCT_OK;
    ++ds->stats.changes;
    drop_accumulation(ds);
    vct_moved_region_note(&ds->moved, ds->scene, changed);
    const int masks_changed = now.masks != ds->digest.masks;
    ds->digest = now;
    vct_context *ctx = ds->ctx;
    const unsigned shape =
        VCT_CHANGED_GEOMETRY | VCT_CHANGED_POSITIONS | VCT_CHANGED_MATERIALS | VCT_CHANGED_TEXTURES;
    if (changed & (VCT_CHANGED_GEOMETRY | VCT_CHANGED_POSITIONS | VCT_CHANGED_MATERIALS))
        vct_emitters_release_resident(ctx, &ds->resident);
    int rc = VCT_OK;
    if (ds->accel && !(changed & VCT_CHANGED_GEOMETRY) && !masks_changed &&
        (changed & VCT_CHANGED_POSITIONS) && ds->accel->bvh2) {
        /* instances moved, meshes kept: the top level again */
        const uint64_t before = ctx->transfers.uploaded;
        rc = vct_accel_refit(ctx, ds->accel, ds->scene, err);
        ds->stats.scene_bytes += ctx->transfers.uploaded - before;
        ++ds->stats.accel_moves;
    } else if (ds->accel && !(changed & VCT_CHANGED_GEOMETRY) && !masks_changed &&
               (changed & VCT_CHANGED_POSITIONS) && ds->accel->bvh) {
        rc = refit_one_level(ds, err);
    } else if ((changed & (VCT_CHANGED_GEOMETRY | VCT_CHANGED_POSITIONS)) || masks_changed) {
        vct_accel_release(ds->accel);
        ds->accel = NULL;
    }
    if (rc != VCT_OK) { /* built again at the next render */
        vct_accel_release(ds->accel);
        ds->accel = NULL;
    }
    if (changed & shape)
        set_voxels_aside(ds);
    else if (changed & VCT_CHANGED_LIGHTS)
        ds->light_stale = 1;
    /* the camera is read at each render; nothing holds it */
    return vct_resident_update(ctx, &ds->resident, changed, err);
}

static int need_accel(vct_device_scene *ds, const vct_accel_options *options, vct_error *err) {
    if (ds->accel && memcmp(&ds->accel_key, options, sizeof *options) == 0)
        return VCT_OK;
    vct_accel_release(ds->accel);
    const uint64_t before = ds->ctx->transfers.uploaded;
    ds->accel = vct_accel_build(ds->ctx, ds->scene, options, err);
    ds->stats.scene_bytes += ds->ctx->transfers.uploaded - before;
    if (!ds->accel)
        return err->status;
    ds->accel_key = *options;
    ds->accel_built_area = 0.0; /* measured at the first refit */
    ++ds->stats.accel_builds;
    return VCT_OK;
}

static void keys_make(const vct_render_job *job, const vct_plan *plan, voxel_key *vk,
                      light_key *lk) {
    memset(vk, 0, sizeof *vk);
    memset(lk, 0, sizeof *lk);
    /* field by field, so that the struct's padding stays zero and whole
     * keys compare */
    const vct_voxel_options *o = &job->voxel_options;
    vk->voxel.resolution = o->resolution;
    vk->voxel.thin = o->thin;
    vk->voxel.has_bounds = o->has_bounds;
    for (int k = 0; k < 3; ++k)
        vk->voxel.bounds_min[k] = o->bounds_min[k];
    vk->voxel.bounds_size = o->bounds_size;
    vk->voxel.exact_bounces = o->exact_bounces;
    vk->voxel.dense_bounces = o->dense_bounces;
    vk->bricks = job->brick_options;
    vk->bricks.radiance_later = 0;
    vk->emitters_by_cones = plan->emitters_by_cones;
    lk->lit = vct_plan_needs_voxel_light(plan);
    lk->bounces = lk->lit ? job->bounces : 0;
    if (lk->lit)
        lk->cones = job->vct.cones;
}

/* Bounces a carried light gathers after a change: enough that the light
 * from before fades below 1 % at the scene's measured bounce ratio (8
 * where none was measured), no fewer than the job's bounces, at most 16. */
static uint32_t carry_bounces(double ratio, uint32_t bounces) {
    uint32_t k = 8;
    if (ratio > 0.0 && ratio < 1.0)
        k = (uint32_t)ceil(log(0.01) / log(ratio));
    k = k < bounces ? bounces : k;
    return k > 16 ? 16 : k;
}

/* The voxels the job reads: kept when built with the same settings from
 * the same geometry, relit when only the lights or the light settings
 * changed, else built again. */
static int need_voxels(vct_device_scene *ds, const vct_render_job *job, const vct_plan *plan,
                       vct_error *err) {
    voxel_key vk;
    light_key lk;
    keys_make(job, plan, &vk, &lk);
    const int same_shape = ds->voxels && memcmp(&vk, &ds->voxel_key, sizeof vk) == 0;
    const int same_settings = memcmp(&lk, &ds->light_key, sizeof lk) == 0;
    const int same_light = same_settings && !ds->light_stale;
    const int carry = job->light_carry && same_shape && lk.lit && same_settings;
    if (same_shape && same_light && !(carry && ds->light_settling))
        return VCT_OK;
    /* a plan that drops light needs voxels without it: build them again */
    if (same_shape && lk.lit && ds->light_key.lit) {
        /* carried: the new direct light and one bounce of the light before,
         * then a bounce more at each render until `bounces` are gathered */
        const int rc = carry ? vct_vct_relight_carry(ds->ctx, ds->scene, ds->accel, ds->voxels,
                                                     &lk.cones, ds->light_stale, err)
                             : vct_vct_relight(ds->ctx, ds->scene, ds->accel, ds->voxels,
                                               lk.bounces, &lk.cones, err);
        if (rc != VCT_OK) {
            drop_voxels(ds);
            return rc;
        }
        if (carry) {
            ds->light_settling = ds->light_stale ? carry_bounces(ds->light_ratio, lk.bounces) - 1
                                                 : ds->light_settling - 1;
        } else {
            ds->light_settling = 0;
            ds->light_ratio = vct_voxels_bounce_ratio(ds->voxels);
        }
        ds->light_key = lk;
        ds->light_stale = 0;
        ++ds->stats.light_builds;
        return VCT_OK;
    }
    drop_voxels(ds);
    /* geometry moved: carried, the light of the voxels before, gathered
     * once into the new ones, then settled a bounce a render as above */
    vct_voxels *before = ds->voxels_before;
    ds->voxels_before = NULL;
    const int carry_before = job->light_carry && before && lk.lit && same_settings &&
                             memcmp(&vk, &ds->voxel_key, sizeof vk) == 0;
    int carried = 0;
    vct_voxel_carry moved = {before, 0, 0, 0, {{{0}}}, VCT_CARRY_EVERY, 0, NULL};
    moved.phase = ds->carry_renders++ % VCT_CARRY_EVERY;
    vct_moved_region_boxes(&ds->moved, &moved);
    vct_moved_region_clear(&ds->moved);
    const int rc = carry_before
                       ? vct_vct_prepare_carry(ds->ctx, ds->scene, ds->accel, plan, &vk.voxel,
                                               &vk.bricks, job->bounces, &job->vct.cones, &moved,
                                               &ds->voxels, &carried, err)
                       : vct_vct_prepare(ds->ctx, ds->scene, ds->accel, plan, &vk.voxel, &vk.bricks,
                                         job->bounces, &job->vct.cones, &ds->voxels, err);
    vct_voxels_release(before);
    if (rc != VCT_OK || !ds->voxels)
        return rc;
    ds->voxel_key = vk;
    ds->light_key = lk;
    if (carried)
        ds->light_settling = carry_bounces(ds->light_ratio, lk.bounces) - 1;
    else
        ds->light_ratio = vct_voxels_bounce_ratio(ds->voxels);
    ++ds->stats.voxel_builds;
    ds->stats.light_builds += (uint32_t)lk.lit;
    return VCT_OK;
}

/* What a job's method and plan read. */
typedef struct job_needs {
    vct_plan plan;       /* the job's, or the scene's own */
    vct_plan voxel_plan; /* what the voxels are built for */
    int voxels;          /* 1: the job reads voxels */
} job_needs;

static void needs_of(const vct_device_scene *ds, const vct_render_job *job, job_needs *n) {
    if (job->plan)
        n->plan = *job->plan;
    else
        vct_plan_make(ds->scene, NULL, &n->plan);
    n->voxel_plan = n->plan;
    if (job->method == VCT_METHOD_VOXELS && !vct_plan_needs_voxels(&n->plan))
        n->voxel_plan.on[VCT_EFFECT_AO] = 1; /* the view needs voxels, without light */
    n->voxels = job->method == VCT_METHOD_VOXELS ||
                (job->method == VCT_METHOD_VCT && vct_plan_needs_voxels(&n->plan));
}

/* Commits, then builds what the job reads. */
static int prepare(vct_device_scene *ds, const vct_render_job *job, const job_needs *n,
                   vct_error *err) {
    int rc = vct_device_scene_commit(ds, err);
    /* every method traces rays but the voxel view, and light injection
     * casts shadow rays */
    if (rc == VCT_OK && (job->method != VCT_METHOD_VOXELS || vct_plan_needs_voxel_light(&n->plan)))
        rc = need_accel(ds, &job->accel_options, err);
    if (rc == VCT_OK && n->voxels)
        rc = need_voxels(ds, job, &n->voxel_plan, err);
    else
        drop_voxels_before(ds); /* a job without voxels: their light is of no use */
    return rc;
}

int vct_device_scene_prepare(vct_device_scene *ds, const vct_render_job *job, vct_error *err) {
    job_needs n;
    needs_of(ds, job, &n);
    return prepare(ds, job, &n, err);
}

void vct_device_scene_adopt_voxels(vct_device_scene *ds, vct_voxels *voxels,
                                   const vct_device_scene *from) {
    drop_voxels(ds);
    drop_voxels_before(ds);
    ds->voxels = voxels;
    ds->voxel_key = from->voxel_key;
    ds->light_key = from->light_key;
}

vct_status vct_device_scene_render(vct_device_scene *ds, const vct_render_job *job,
                                   vct_image *image, vct_render_result *result, vct_error *err) {
    memset(image, 0, sizeof *image);
    job_needs n; /* the plan once per render: making it reads every triangle */
    needs_of(ds, job, &n);
    const int rc = prepare(ds, job, &n, err);
    if (rc != VCT_OK)
        return rc;
    vct_render_job own = *job;
    own.scene = ds->scene;
    own.plan = &n.plan;
    own.accel = ds->accel;
    own.voxels = n.voxels ? ds->voxels : NULL;
    return vct_render(ds->ctx, &own, image, result, err);
}

void vct_device_scene_stats_get(const vct_device_scene *ds, vct_device_scene_stats *stats) {
    *stats = ds->stats;
    stats->scene_bytes += ds->resident.scene_bytes;
}

vct_context *vct_device_scene_context(const vct_device_scene *ds) {
    return ds->ctx;
}

const vct_scene *vct_device_scene_scene(const vct_device_scene *ds) {
    return ds->scene;
}

const vct_accel *vct_device_scene_accel(const vct_device_scene *ds) {
    return ds->accel;
}

const vct_voxels *vct_device_scene_voxels(const vct_device_scene *ds) {
    return ds->voxels;
}

void vct_device_scene_release(vct_device_scene *ds) {
    if (!ds)
        return;
    vct_context *ctx = ds->ctx;
    drop_voxels(ds);
    drop_voxels_before(ds);
    vct_moved_region_release(&ds->moved);
    drop_accumulation(ds);
    vct_accel_release(ds->accel);
    vct_emitters_release_resident(ctx, &ds->resident);
    vct_resident_release_buffers(ctx, &ds->resident);
    for (vct_resident **at = &ctx->resident; *at; at = &(*at)->next)
        if (*at == &ds->resident) {
            *at = ds->resident.next;
            break;
        }
    free(ds);
}
