/* Helpers shared by the commands: messages, scene loading and printing,
 * the context, output directories, voxel options and the plan. */
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

#include "cli_common.h"
#include "cluster.h"

int cli_fail_input(vct_error *err, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err->message, sizeof err->message, fmt, ap);
    va_end(ap);
    err->status = VCT_ERR_INPUT;
    return VCT_ERR_INPUT;
}

int cli_fail(const vct_error *err) {
    const char *tag;
    FILE *out = cli_cluster_errors(&tag);
    fprintf(out, "vct%s: %s\n", tag, err->message);
    fflush(out);
    return 1;
}

vct_scene *cli_load_scene(const cli_options *opt, vct_error *err) {
    if (opt->input_count < 1) {
        cli_fail_input(err, "vct %s needs a scene file", opt->command->name);
        return NULL;
    }
    vct_scene *s = vct_scene_load(opt->inputs[0], err);
    if (s && opt->frame >= 0 && s->animation_count == 0) {
        cli_fail_input(err, "vct %s: --frame: %s has no animation", opt->command->name,
                       opt->inputs[0]);
        vct_scene_release(s);
        return NULL;
    }
    if (s && opt->frame >= 0 &&
        vct_scene_pose(s, 0, (double)opt->frame / opt->fps, err) != VCT_OK) {
        vct_scene_release(s);
        return NULL;
    }
    if (s && cli_apply_scene_overrides(opt, s, err) != VCT_OK) {
        vct_scene_release(s);
        return NULL;
    }
    return s;
}

void cli_print_scene(const vct_scene *s, FILE *out) {
    fprintf(out,
            "scene %s: %u triangles (%u degenerate, never hit), %u vertices, %u materials, "
            "%u lights\n",
            s->source, s->triangle_count, s->degenerate_triangles, s->vertex_count,
            s->material_count, s->light_count);
    if (s->ignored_lights)
        fprintf(out,
                "vct: %u light%s of the file %s of a type vct does not render (area or "
                "ambient lights): ignored\n",
                s->ignored_lights, s->ignored_lights == 1 ? "" : "s",
                s->ignored_lights == 1 ? "is" : "are");
}

void cli_print_stats(const vct_context *ctx) {
    const vct_stage_stat *st;
    int n = vct_stats(ctx, &st);
    printf("%-20s %10s %10s %10s %9s\n", "stage", "device ms", "host ms", "peak MiB", "launches");
    for (int i = 0; i < n; ++i)
        printf("%-20s %10.2f %10.2f %10.2f %9d\n", st[i].name, st[i].device_ms, st[i].host_ms,
               st[i].mib, st[i].launches);
    vct_program_stats programs;
    vct_context_program_stats(ctx, &programs);
    printf("kernel programs: %d compiled, %d from the cache, in %.2f s\n", programs.compiled,
           programs.cached, programs.ms / 1000.0);
    const vct_kernel_stat *k;
    n = vct_kernel_stats(ctx, &k);
    printf("%-31s %10s %9s\n", "kernel or transfer", "device ms", "launches");
    for (int i = 0; i < n; ++i)
        printf("%-31s %10.2f %9d\n", k[i].name, k[i].device_ms, k[i].launches);
}

void cli_log(void *user, const char *message) {
    (void)user;
    fprintf(stderr, "vct: %s\n", message);
    fflush(stderr);
}

vct_context *cli_open_context(const cli_options *opt, vct_error *err) {
    vct_context *ctx = vct_context_create(opt->device, err);
    if (ctx)
        vct_context_set_log(ctx, cli_log, NULL);
    if (ctx)
        fprintf(stderr, "device: %s (%s)\n", vct_context_device(ctx)->name,
                vct_context_device(ctx)->platform);
    return ctx;
}

/* Creates the output's parent directory, so `-o out/x.png` works from a clean tree. */
int cli_make_parent_dir(const char *path, vct_error *err) {
    char dir[4096];
    snprintf(dir, sizeof dir, "%s", path);
    char *slash = strrchr(dir, '/');
    if (!slash || slash == dir)
        return VCT_OK;
    *slash = '\0';
    for (char *p = dir + 1; *p; ++p) {
        if (*p == '/') {
            *p = '\0';
            mkdir(dir, 0755);
            *p = '/';
        }
    }
    if (mkdir(dir, 0755) != 0 && errno != EEXIST)
        return cli_fail_input(err, "cannot create directory %s for the output", dir);
    return VCT_OK;
}

void cli_voxel_options(const cli_options *opt, uint32_t default_res, vct_voxel_options *vo) {
    memset(vo, 0, sizeof *vo);
    vo->resolution = opt->voxel_res ? (uint32_t)opt->voxel_res : default_res;
    vo->thin = opt->thin_voxels;
    vo->exact_bounces = opt->exact_bounces;
    vo->dense_bounces = opt->dense_bounces;
    vo->has_bounds = opt->has_voxel_bounds;
    for (int k = 0; k < 3; ++k)
        vo->bounds_min[k] = opt->voxel_bounds[k];
    vo->bounds_size = opt->voxel_bounds[3];
}

void cli_print_plan(const vct_plan *plan, FILE *out) {
    fprintf(out, "effect plan:\n");
    for (int e = 0; e < VCT_EFFECTS; ++e)
        fprintf(out, "  %-12s %-3s  %s\n", vct_effect_name((vct_effect)e),
                plan->on[e] ? "on" : "off", plan->why[e]);
    fprintf(out, "  %-12s %-5s%s\n", "emitters", plan->emitters_by_cones ? "cones" : "rays",
            plan->emitters_by_cones ? "their emission stays in the voxels; cones gather it"
                                    : "sampled as lights with shadow rays (--emitters cones: by "
                                      "the voxels alone)");
}

vct_accel *cli_accel_build(vct_context *ctx, const vct_scene *s, const cli_options *opt,
                           vct_error *err) {
    return vct_accel_build(ctx, s, &opt->accel, err);
}

int cli_print_accel(vct_context *ctx, const vct_accel *accel, FILE *out, vct_error *err) {
    vct_accel_info in;
    int rc = vct_accel_info_get(ctx, accel, &in, err);
    if (rc != VCT_OK)
        return rc;
    if (in.kind == VCT_ACCEL_GRID)
        fprintf(out, "accel: grid %ux%ux%u cells, %u references, %.2f MiB, built in %.1f ms\n",
                in.grid.res[0], in.grid.res[1], in.grid.res[2], in.grid.references,
                in.bytes / 1048576.0, in.build_ms);
    else if (in.two_levels)
        fprintf(out,
                "accel: bvh 4-wide, two levels: %u instances over meshes of %u triangles, %u "
                "nodes, %.2f MiB, built in %.1f ms\n",
                in.instances, in.mesh_triangles, in.nodes, in.bytes / 1048576.0, in.build_ms);
    else
        fprintf(out,
                "accel: bvh 4-wide, %s (%u passes), %u nodes, %u leaves, %u levels, SAH cost %.2f, "
                "%.2f MiB, built in %.1f ms\n",
                in.bvh_builder == VCT_BVH_LINEAR ? "linear" : "clustered", in.passes, in.nodes,
                in.leaves, in.depth, in.sah_cost, in.bytes / 1048576.0, in.build_ms);
    return VCT_OK;
}

void cli_pm_options(const cli_options *opt, vct_pm_options *pm) {
    const cli_pm *c = &opt->pm;
    *pm = vct_pm_options_default(opt->width, opt->height);
    pm->passes = (uint32_t)(opt->spp ? opt->spp : (opt->time_limit > 0 ? 0 : 64));
    pm->time_limit_s = opt->time_limit;
    if (opt->max_depth)
        pm->max_depth = (uint32_t)opt->max_depth;
    pm->seed = (uint32_t)opt->seed;
    pm->progress = 1;
    if (c->photons)
        pm->photons_per_pass = (uint32_t)c->photons;
    pm->radius = c->radius;
    pm->caustic_radius = c->caustic_radius;
    pm->fixed_radius = c->fixed;
    if (c->has_alpha)
        pm->alpha = c->alpha;
    pm->final_gather = c->final_gather_rays > 0;
    if (c->final_gather_rays)
        pm->gather_rays = (uint32_t)c->final_gather_rays;
    pm->direct_photons = c->direct_photons;
    if (c->kernel_box)
        pm->kernel = VCT_PM_KERNEL_BOX;
    if (c->has_normal_cos)
        pm->normal_cos = c->normal_cos;
}

void cli_print_pm(const vct_pm_result *r, FILE *out) {
    fprintf(out, "photon mapping: %u passes, %llu photons emitted in %.2f s (%.2f M/s traced)\n",
            r->passes, (unsigned long long)r->photons_emitted, r->seconds,
            r->trace_ms > 0 ? r->photons_emitted / (r->trace_ms * 1e3) : 0.0);
    const char *names[2] = {"global", "caustic"};
    const int on[2] = {r->global_map, r->caustic_map};
    for (int m = 0; m < 2; ++m) {
        if (!on[m]) {
            fprintf(out, "  %s map: none (%s)\n", names[m],
                    m ? "nothing in the scene is a mirror or glass"
                      : "the plan has no indirect light");
            continue;
        }
        fprintf(out, "  %s map: %llu photons stored, last grid %s, cell %.4g, %.2f MiB\n", names[m],
                (unsigned long long)r->photons_stored[m], r->hashed[m] ? "hashed" : "dense",
                r->cell[m], r->grid_bytes[m] / 1048576.0);
    }
    fprintf(out, "  device time: photons %.1f ms, grids %.1f ms, gathers %.1f ms\n", r->trace_ms,
            r->grid_ms, r->gather_ms);
}

vct_render_job cli_render_job(const cli_options *opt, vct_method method, const vct_scene *s) {
    vct_render_job job = vct_render_job_default(method, opt->width, opt->height);
    job.scene = s;
    job.pathtrace.spp = (uint32_t)(opt->spp ? opt->spp : (opt->time_limit > 0 ? 0 : 64));
    job.pathtrace.time_limit_s = opt->time_limit;
    job.pathtrace.max_depth = (uint32_t)(opt->max_depth ? opt->max_depth : 16);
    if (opt->max_depth)
        job.whitted.max_depth = (uint32_t)opt->max_depth;
    job.whitted.subsample = (uint32_t)opt->subsample;
    job.whitted.subsample_unguarded = (uint32_t)opt->subsample_plain;
    job.raycast.subsample = job.whitted.subsample;
    job.raycast.subsample_unguarded = job.whitted.subsample_unguarded;
    job.whitted.subsample_contrast = job.raycast.subsample_contrast = opt->contrast;
    job.pathtrace.seed = (uint32_t)opt->seed;
    job.pathtrace.progress = 1;
    /* without the denoiser or the AOVs nothing resolves the sums' moments */
    job.pathtrace.colour_only = !opt->denoise && !opt->aov;
    cli_pm_options(opt, &job.pm);
    vct_vct_options *vo = &job.vct;
    vo->diffuse_cones = (uint32_t)opt->diffuse_cones;
    vo->cones = opt->cones;
    vo->sparse_diffuse = opt->sparse_diffuse;
    vo->edge_samples = (uint32_t)opt->edge_samples;
    vo->indirect_passes = opt->denoise ? VCT_INDIRECT_PASSES_MAX : (uint32_t)opt->indirect_passes;
    vo->aovs = opt->aov;
    /* what a device scene builds for it; 128^3 voxels by default (the scene
     * suite's page shows what it costs) */
    job.accel_options = opt->accel;
    cli_voxel_options(opt, 128, &job.voxel_options);
    job.brick_options = (vct_brick_options){opt->bricks, opt->anisotropic == 1, 0};
    job.bounces = (uint32_t)opt->bounces;
    job.light_carry = opt->light_carry;
    return job;
}

void cli_print_result(const cli_options *opt, const vct_render_result *r) {
    const double pixels = (double)opt->width * opt->height;
    if (r->method == VCT_METHOD_WHITTED)
        fprintf(stderr,
                "whitted: %llu of %.0f pixels traced (%.1f %% interpolated), %llu camera rays "
                "(%.1f %% of a full render's)\n",
                (unsigned long long)r->traced, pixels, 100.0 * (1.0 - (double)r->traced / pixels),
                (unsigned long long)r->camera_rays, 100.0 * (double)r->camera_rays / pixels);
    if (r->method == VCT_METHOD_PATHTRACE)
        fprintf(stderr,
                "path tracing: %u spp in %.2f s (%.1f spp/s), %u samples discarded as "
                "not finite\n",
                r->spp, r->seconds, r->seconds > 0 ? r->spp / r->seconds : 0.0, r->discarded);
}

int cli_check_output(const char *who, const char *out) {
    const char *dot = strrchr(out, '.');
    if (dot && (strcmp(dot, ".png") == 0 || strcmp(dot, ".pfm") == 0 || strcmp(dot, ".exr") == 0))
        return 0;
    fprintf(stderr, "%s: output %s must end in .exr, .pfm or .png\n", who, out);
    return 1;
}

int cli_device_list(const cli_options *opt) {
    const char *list = opt->device && *opt->device ? opt->device : getenv("VCT_DEVICE");
    return list && (strchr(list, ',') || strcasecmp(list, "all") == 0 ||
                    strcasecmp(list, "gpu") == 0 || strcasecmp(list, "cpu") == 0);
}
int cli_apply_scene_overrides(const cli_options *opt, vct_scene *s, vct_error *err) {
    for (int k = 0; k < 3; ++k) {
        if (opt->has_camera_pos)
            s->camera.position[k] = opt->camera_pos[k];
        if (opt->has_look_at)
            s->camera.look_at[k] = opt->look_at[k];
        if (opt->has_up)
            s->camera.up[k] = opt->up[k];
    }
    if (opt->has_fov)
        s->camera.fov_y_deg = opt->fov;
    if (opt->has_ambient) {
        memcpy(s->ambient, opt->ambient, sizeof s->ambient);
        int rc = vct_scene_validate(s, err);
        if (rc)
            return rc;
    }
    for (int i = 0; i < opt->light_count; ++i) {
        int rc = vct_scene_add_light(s, &opt->lights[i], err);
        if (rc)
            return rc;
    }
    for (uint32_t i = 0; opt->has_light_radius && i < s->light_count; ++i)
        s->lights[i].radius = opt->light_radius;
    return opt->has_light_radius ? vct_scene_validate(s, err) : VCT_OK;
}
