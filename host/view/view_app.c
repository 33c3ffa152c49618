/* The viewer's model (view_app.h): builds what the method and plan need,
 * lazily, and renders one frame at a time into the context's frame. */
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "cli_common.h"
#include "cli_denoise.h"
#include "view_app.h"

static const char *const METHOD_NAMES[VIEW_METHODS] = {"ray cast", "VCT",     "path tracer",
                                                       "voxels",   "Whitted", "photon mapping"};

static int input_error(vct_error *err, const char *fmt, const char *what) {
    err->status = VCT_ERR_INPUT;
    snprintf(err->message, sizeof err->message, fmt, what);
    return err->status;
}

static double now_ms(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

const char *view_method_name(view_method m) {
    return METHOD_NAMES[m];
}

static float scene_extent(const vct_scene *s) {
    float e = 0.0f;
    for (int k = 0; k < 3; ++k)
        e = s->bounds_max[k] - s->bounds_min[k] > e ? s->bounds_max[k] - s->bounds_min[k] : e;
    return e;
}

int view_app_init(view_app *app, const cli_options *opt, vct_error *err) {
    memset(app, 0, sizeof *app);
    app->opt = *opt;
    app->denoise = opt->denoise;
    const char *m = opt->method;
    app->method = strcmp(m, "raycast") == 0   ? VIEW_RAYCAST
                  : strcmp(m, "pt") == 0      ? VIEW_PATHTRACE
                  : strcmp(m, "voxels") == 0  ? VIEW_VOXELS
                  : strcmp(m, "whitted") == 0 ? VIEW_WHITTED
                  : strcmp(m, "pm") == 0      ? VIEW_PM
                                              : VIEW_VCT;
    if (strcmp(m, "vct") != 0 && app->method == VIEW_VCT)
        return input_error(err, "unknown --method %s (vct, raycast, pt, voxels, whitted, pm)", m);
    memcpy(app->force, opt->force, sizeof app->force);
    app->width = opt->width;
    app->height = opt->height;
    app->scene = cli_load_scene(opt, err);
    if (!app->scene)
        return err->status;
    vct_plan_make(app->scene, app->force, &app->plan);
    app->plan.emitters_by_cones = app->opt.emitters_by_cones;
    view_camera_init(&app->camera, &app->scene->camera, scene_extent(app->scene));
    app->dirty = 1;
    return VCT_OK;
}

/* The octree's levels follow from the voxel resolution; the voxel view
 * starts at the finest. */
static void set_levels(view_app *app) {
    vct_voxel_options vo;
    cli_voxel_options(&app->opt, 128, &vo);
    app->voxel_levels = 0;
    while ((1u << app->voxel_levels) < vo.resolution)
        ++app->voxel_levels;
    app->voxel_level = app->voxel_levels;
}

int view_app_attach(view_app *app, vct_context *ctx, vct_error *err) {
    app->ctx = ctx;
    set_levels(app);
    app->ds = vct_device_scene_create(ctx, app->scene, err);
    return app->ds ? VCT_OK : (int)err->status;
}

/* What every device of the group builds: the acceleration structure, and
 * the voxels when cone tracing's plan reads them. */
static int group_prepare(view_app *app, int with_voxels, vct_error *err) {
    vct_group_build b;
    memset(&b, 0, sizeof b);
    b.accel = app->opt.accel;
    b.plan = with_voxels ? &app->plan : NULL;
    cli_voxel_options(&app->opt, 128, &b.voxel);
    b.bricks = (vct_brick_options){app->opt.bricks, app->opt.anisotropic == 1, 0};
    b.bounces = (uint32_t)app->opt.bounces;
    b.cones = app->opt.cones;
    return vct_group_prepare(app->group, app->scene, &b, err);
}

int view_app_attach_group(view_app *app, vct_group *group, vct_error *err) {
    app->group = group;
    app->ctx = vct_group_context(group, 0);
    set_levels(app);
    return group_prepare(app, 0, err);
}

void view_app_free(view_app *app) {
    vct_image_release(&app->host_frame);
    vct_image_release(&app->albedo);
    vct_image_release(&app->normal_depth);
    vct_image_release(&app->variance);
    vct_aovs_release(&app->aovs);
    vct_device_scene_release(app->ds);
    vct_scene_release(app->scene);
    app->ds = NULL;
    app->scene = NULL;
}

/* A group's voxels: built on every device when cone tracing's plan reads
 * them, again after the light moved (one device's device scene relights
 * its own). */
static int group_voxels(view_app *app, vct_error *err) {
    if (app->method == VIEW_VOXELS)
        return input_error(err, "%s: the voxel view runs on one device: give --device one",
                           "voxels");
    const int needed = app->method == VIEW_VCT && vct_plan_needs_voxels(&app->plan);
    const int lit = vct_plan_needs_voxel_light(&app->plan);
    if (!needed && app->scene_changed) { /* the devices' BVHs follow what moved */
        app->scene_changed = 0;
        app->voxels_for_plan = 0;
        return group_prepare(app, 0, err);
    }
    if (!needed || (app->voxels_for_plan && (app->voxels_lit || !lit) && !app->scene_changed))
        return VCT_OK;
    int rc = group_prepare(app, 1, err);
    app->voxels_for_plan = rc == VCT_OK;
    app->voxels_lit = rc == VCT_OK && lit;
    app->scene_changed = 0;
    return rc;
}

/* Several devices: each one's share of the rows and its time. */
static void summarise_devices(view_app *app) {
    const vct_group_device *d;
    const int n = vct_group_devices(app->group, &d);
    size_t used = 0;
    app->stages[0] = '\0';
    for (int i = 0; i < n && used + 48 < sizeof app->stages; ++i)
        used += (size_t)snprintf(app->stages + used, sizeof app->stages - used,
                                 "%sdevice %d %s %.0f ms", i ? ", " : "", d[i].info.index,
                                 !d[i].active           ? "dropped"
                                 : d[i].last_work > 0.0 ? "working"
                                                        : "idle",
                                 d[i].last_ms);
}

static void summarise_stages(view_app *app) {
    if (app->group) {
        summarise_devices(app);
        return;
    }
    const vct_stage_stat *st = NULL;
    const int n = vct_stats(app->ctx, &st);
    size_t used = 0;
    app->stages[0] = '\0';
    for (int i = 0; i < n && used + 48 < sizeof app->stages; ++i)
        used += (size_t)snprintf(app->stages + used, sizeof app->stages - used, "%s%s %.0f",
                                 i ? ", " : "", st[i].name, st[i].host_ms);
}

int view_app_progressive(const view_app *app) {
    return app->method == VIEW_PATHTRACE || app->method == VIEW_PM;
}

static int render_method(view_app *app, vct_image *image, vct_error *err) {
    static const vct_method methods[] = {
        [VIEW_RAYCAST] = VCT_METHOD_RAYCAST,     [VIEW_VCT] = VCT_METHOD_VCT,
        [VIEW_PATHTRACE] = VCT_METHOD_PATHTRACE, [VIEW_VOXELS] = VCT_METHOD_VOXELS,
        [VIEW_WHITTED] = VCT_METHOD_WHITTED,     [VIEW_PM] = VCT_METHOD_PM};
    vct_render_job job = vct_render_job_default(methods[app->method], app->width, app->height);
    job.scene = app->scene;
    job.plan = &app->plan;
    job.accel_options = app->opt.accel;
    cli_voxel_options(&app->opt, 128, &job.voxel_options);
    job.brick_options = (vct_brick_options){app->opt.bricks, app->opt.anisotropic == 1, 0};
    job.bounces = (uint32_t)app->opt.bounces;
    job.vct.diffuse_cones = (uint32_t)app->opt.diffuse_cones;
    job.vct.cones = app->opt.cones;
    job.vct.sparse_diffuse = app->opt.sparse_diffuse;
    /* N: the indirect light through every pass of the filter */
    job.vct.indirect_passes = app->denoise && app->method == VIEW_VCT
                                  ? VCT_INDIRECT_PASSES_MAX
                                  : (uint32_t)app->opt.indirect_passes;
    /* The path tracer adds one sample per frame to the previous ones. */
    job.pathtrace.spp = 1;
    job.pathtrace.max_depth = (uint32_t)(app->opt.max_depth ? app->opt.max_depth : 16);
    if (app->opt.max_depth)
        job.whitted.max_depth = (uint32_t)app->opt.max_depth;
    job.whitted.subsample = job.raycast.subsample = (uint32_t)app->opt.subsample;
    job.whitted.subsample_unguarded = job.raycast.subsample_unguarded =
        (uint32_t)app->opt.subsample_plain;
    job.whitted.subsample_contrast = job.raycast.subsample_contrast = app->opt.contrast;
    job.pathtrace.seed = (uint32_t)app->opt.seed;
    vct_image_release(&app->variance);
    vct_aovs_release(&app->aovs);
    if (view_app_denoising(app)) {
        job.pathtrace.variance = &app->variance;
        job.pathtrace.indirect = &app->aovs.indirect; /* filtered apart from the direct light */
    }
    job.pathtrace.resume = app->pt_spp > 0;
    job.voxel_view.level = app->voxel_level;
    /* Photon mapping likewise: one pass per frame. */
    cli_pm_options(&app->opt, &job.pm);
    job.pm.passes = 1;
    job.pm.progress = 0;
    job.pm.resume = app->pt_spp > 0;
    vct_render_result result;
    if (app->group) /* a sample per device per frame */
        job.pathtrace.spp = (uint32_t)vct_group_active_count(app->group);
    const int rc = app->group ? vct_group_render(app->group, &job, image, &result, err)
                              : vct_device_scene_render(app->ds, &job, image, &result, err);
    if (view_app_progressive(app))
        app->pt_spp = rc == VCT_OK ? result.spp : 0;
    return rc;
}

int view_app_wants_frame(const view_app *app) {
    return app->dirty || app->playing ||
           (view_app_progressive(app) && app->pt_spp < VIEW_PT_MAX_SPP);
}

int view_app_denoising(const view_app *app) {
    /* one device: several hold their structures apart from the host's */
    return app->denoise && !app->group && (app->method == VIEW_PATHTRACE || app->method == VIEW_PM);
}

void view_app_toggle_denoise(view_app *app) {
    app->denoise = !app->denoise;
    app->dirty = 1;
}

/* The frame through the denoiser, with the guides of this camera (made on
 * the first denoised frame after it moved). */
static int denoise_frame(view_app *app, vct_image *image, vct_error *err) {
    vct_context *ctx = app->ctx;
    int rc = VCT_OK;
    if (!app->albedo.rgba)
        rc = vct_render_guides(ctx, app->scene, vct_device_scene_accel(app->ds), image->width,
                               image->height, 4, &app->albedo, &app->normal_depth, err);
    const vct_denoise_guides g = {&app->albedo, &app->normal_depth,
                                  app->variance.rgba ? &app->variance : NULL, NULL, 0};
    vct_image out;
    if (rc == VCT_OK)
        rc = cli_denoise_image(ctx, &g, image, app->aovs.indirect.rgba ? &app->aovs : NULL, &out,
                               err);
    if (rc == VCT_OK) {
        vct_image_release(image);
        *image = out;
    }
    return rc;
}

int view_app_render(view_app *app, vct_error *err) {
    const double t0 = now_ms();
    view_camera_get(&app->camera, &app->scene->camera);
    vct_stats_reset(app->ctx);
    int rc = app->group ? group_voxels(app, err) : VCT_OK;
    vct_image image = {0};
    const int denoise = view_app_denoising(app);
    if (denoise)
        vct_frame_host_copy(app->ctx, 1); /* the denoiser takes the frame on the host */
    if (rc == VCT_OK)
        rc = render_method(app, &image, err);
    if (denoise)
        vct_frame_host_copy(app->ctx, 0);
    if (rc == VCT_OK && denoise)
        rc = denoise_frame(app, &image, err);
    vct_image_release(&app->host_frame);
    if (rc == VCT_OK && (app->group || denoise)) /* the display takes it from the host */
        app->host_frame = image;
    else
        vct_image_release(&image);
    summarise_stages(app);
    app->frame_ms = now_ms() - t0;
    if (rc == VCT_OK)
        app->dirty = 0;
    return rc;
}

void view_app_set_method(view_app *app, view_method m) {
    if (m == app->method)
        return;
    app->method = m;
    app->pt_spp = 0;
    app->dirty = 1;
}

void view_app_toggle_effect(view_app *app, vct_effect e) {
    app->force[e] = app->plan.on[e] ? VCT_FORCE_OFF : VCT_FORCE_ON;
    vct_plan_make(app->scene, app->force, &app->plan);
    app->plan.emitters_by_cones = app->opt.emitters_by_cones;
    app->dirty = 1;
}

void view_app_set_level(view_app *app, int delta) {
    const int level = (int)app->voxel_level + delta;
    if (level < 1 || level > (int)app->voxel_levels)
        return;
    app->voxel_level = (uint32_t)level;
    if (app->method == VIEW_VOXELS)
        app->dirty = 1;
}

int view_app_move_light(view_app *app, float dx, float dy, float dz) {
    if (app->scene->light_count == 0)
        return 0;
    vct_light *l = &app->scene->lights[0];
    /* A step is a fifth of a second's flight; a direction turns by about 6 degrees. */
    float *target = l->type == VCT_LIGHT_DIRECTIONAL ? l->direction : l->position;
    const float scale = l->type == VCT_LIGHT_DIRECTIONAL ? 0.1f : 0.2f * app->camera.speed;
    target[0] += dx * scale;
    target[1] += dy * scale;
    target[2] += dz * scale;
    app->scene_changed = 1;
    app->pt_spp = 0;
    app->dirty = 1;
    return 1;
}

int view_app_step_animation(view_app *app, int delta, vct_error *err) {
    vct_scene *s = app->scene;
    if (s->animation_count == 0)
        return 0;
    const int frame = app->anim_frame + delta > 0 ? app->anim_frame + delta : 0;
    if (vct_scene_pose(s, 0, (double)frame / app->opt.fps, err) != VCT_OK)
        return -1;
    app->anim_frame = frame;
    if (s->camera_attachment.node != VCT_NO_NODE) /* the animation's camera is followed */
        view_camera_init(&app->camera, &s->camera, scene_extent(s));
    app->scene_changed = 1; /* a group prepares again: what moved is rebuilt */
    view_app_camera_changed(app);
    return 1;
}

int view_app_toggle_play(view_app *app) {
    if (app->scene->animation_count == 0)
        return 0;
    app->playing = !app->playing;
    return 1;
}

void view_app_camera_changed(view_app *app) {
    app->pt_spp = 0;
    app->dirty = 1;
    vct_image_release(&app->albedo); /* the guides follow the camera */
    vct_image_release(&app->normal_depth);
}

void view_app_status(const view_app *app, const char *display_path, char *out, size_t size) {
    char plan[160] = "";
    size_t used = 0;
    for (int e = 0; e < VCT_EFFECTS && used + 16 < sizeof plan; ++e)
        if (app->plan.on[e])
            used += (size_t)snprintf(plan + used, sizeof plan - used, "%s%s", used ? " " : "",
                                     vct_effect_name((vct_effect)e));
    char extra[64] = "";
    if (view_app_progressive(app))
        snprintf(extra, sizeof extra, app->method == VIEW_PM ? " %u passes" : " %u spp",
                 app->pt_spp);
    else if (app->method == VIEW_VOXELS)
        snprintf(extra, sizeof extra, " level %u/%u", app->voxel_level, app->voxel_levels);
    char anim[96] = "";
    if (app->scene->animation_count)
        snprintf(anim, sizeof anim, " | frame %d (%.2f s)%s", app->anim_frame,
                 app->anim_frame / app->opt.fps, app->playing ? " playing" : "");
    snprintf(out, size, "vct-view | %s%s%s%s | %dx%d %.0f ms (%s) | plan: %s | %s",
             view_method_name(app->method), extra,
             view_app_denoising(app) || (app->denoise && app->method == VIEW_VCT) ? ", denoised"
                                                                                  : "",
             anim, app->width, app->height, app->frame_ms, app->stages, plan[0] ? plan : "nothing",
             display_path);
}
