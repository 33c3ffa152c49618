/* vct devices | info | render | compare. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli_common.h"
#include "cluster.h"
#include "cli_denoise.h"
#include "cli_video.h"
#include "cmd_render_frame.h"
#include "cmd_render_group.h"
#include "cmd_render_vct.h"
#include "commands.h"

int cmd_devices(const cli_options *opt) {
    (void)opt;
    vct_error err = {0};
    vct_device_info info[32];
    int n = vct_list_devices(info, 32, &err);
    if (n < 0)
        return cli_fail(&err);
    for (int i = 0; i < n; ++i) {
        const vct_device_info *d = &info[i];
        printf("[%d] %s — %s (%s)\n", d->index, d->name, d->platform, d->is_gpu ? "GPU" : "CPU");
        printf("    %s, driver %s\n", d->version, d->driver);
        printf("    compute units %u, global memory %.0f MiB, max allocation %.0f MiB, "
               "work-group %zu\n",
               d->compute_units, d->global_mem / 1048576.0, d->max_alloc / 1048576.0,
               d->max_work_group);
        printf("    images %s, fp64 %s, GL sharing %s\n", d->image_support ? "yes" : "no",
               d->fp64 ? "yes" : "no", d->gl_sharing ? "yes" : "no");
        printf("    extensions: %s\n", d->extensions);
    }
    if (n == 0)
        printf("no OpenCL devices\n");
    return 0;
}

int cmd_info(const cli_options *opt) {
    vct_error err = {0};
    vct_scene *s = cli_load_scene(opt, &err);
    if (!s)
        return cli_fail(&err);
    cli_print_scene(s, stdout);
    printf("bounds (%g %g %g) .. (%g %g %g)\n", s->bounds_min[0], s->bounds_min[1],
           s->bounds_min[2], s->bounds_max[0], s->bounds_max[1], s->bounds_max[2]);
    uint32_t held = 0;
    for (uint32_t m = 0; m < s->mesh_count; ++m)
        held += s->meshes[m].triangle_count;
    printf("%u meshes (%u triangles) placed by %u instances\n", s->mesh_count, held,
           s->instance_count);
    for (uint32_t a = 0; a < s->animation_count; ++a)
        printf("animation \"%s\": %.3f s, %u node%s\n", s->animations[a].name,
               s->animations[a].duration_s, s->animations[a].channels,
               s->animations[a].channels == 1 ? "" : "s");
    printf("camera %s: position (%g %g %g), look-at (%g %g %g), up (%g %g %g), fov %g\n",
           s->has_camera ? "from the file" : "default", s->camera.position[0],
           s->camera.position[1], s->camera.position[2], s->camera.look_at[0], s->camera.look_at[1],
           s->camera.look_at[2], s->camera.up[0], s->camera.up[1], s->camera.up[2],
           s->camera.fov_y_deg);
    static const char *kinds[] = {"point", "spot", "directional"};
    for (uint32_t i = 0; i < s->light_count; ++i) {
        const vct_light *l = &s->lights[i];
        printf("light %u: %s at (%g %g %g) towards (%g %g %g), colour (%g %g %g)\n", i,
               kinds[l->type], l->position[0], l->position[1], l->position[2], l->direction[0],
               l->direction[1], l->direction[2], l->color[0], l->color[1], l->color[2]);
    }
    for (uint32_t i = 0; i < s->material_count; ++i) {
        const vct_material *m = &s->materials[i];
        printf("material %u \"%s\": albedo (%g %g %g), emission (%g %g %g), roughness %g, "
               "metallic %g, transmission %g, ior %g\n",
               i, m->name, m->albedo[0], m->albedo[1], m->albedo[2], m->emission[0], m->emission[1],
               m->emission[2], m->roughness, m->metallic, m->transmission, m->ior);
        if (m->albedo_texture)
            printf("  base colour texture %u (\"%s\", %dx%d), %s in s, %s in t\n",
                   m->albedo_texture - 1, s->textures[m->albedo_texture - 1].name,
                   s->textures[m->albedo_texture - 1].width,
                   s->textures[m->albedo_texture - 1].height,
                   m->texture_wrap & VCT_WRAP_CLAMP_S ? "clamped" : "repeated",
                   m->texture_wrap & VCT_WRAP_CLAMP_T ? "clamped" : "repeated");
        if (m->alpha_cutoff > 0.0f)
            printf("  alpha mask: rays pass where %g x %s is below %g\n", m->alpha,
                   m->albedo_texture ? "the texture's alpha" : "1", m->alpha_cutoff);
    }
    if (s->texture_count)
        printf("%u texture%s, texture coordinates %s\n", s->texture_count,
               s->texture_count == 1 ? "" : "s", s->uvs ? "present" : "absent (all 0)");
    /* What rays would traverse: built on the device, as a render builds it. */
    vct_context *ctx = cli_open_context(opt, &err);
    vct_accel *accel = ctx ? cli_accel_build(ctx, s, opt, &err) : NULL;
    int rc = accel ? cli_print_accel(ctx, accel, stdout, &err) : (int)err.status;
    vct_accel_release(accel);
    vct_context_release(ctx);
    vct_scene_release(s);
    return rc == VCT_OK ? 0 : cli_fail(&err);
}

/* A sequence's frames on one device, through its device scene. */
typedef struct one_device {
    vct_context *ctx;
    vct_device_scene *ds;
    const vct_scene *scene;
    const cli_options *opt;
    vct_method method;
} one_device;

static int one_device_frame(void *user, cli_frame *frame, vct_error *err) {
    const one_device *d = user;
    return cli_frame_make(d->ctx, d->ds, d->scene, d->opt, d->method, frame, err);
}

/* The render itself: one device, several, or several processes. */
static int render(const cli_options *opt, vct_method method, const char *out);

int cmd_render(const cli_options *opt) {
    vct_error err = {0};
    const char *out = opt->output ? opt->output : "render.png";
    if (cli_check_output("vct render", out))
        return 1;
    if (cli_video_check(opt, out, &err) != VCT_OK)
        return cli_fail(&err);
    const int method = vct_method_from_name(opt->method);
    if (method < 0 || method == VCT_METHOD_VOXELS) {
        fprintf(stderr, "vct: unknown --method %s (available: vct, raycast, pt, whitted, pm)\n",
                opt->method);
        return 1;
    }
    const int rc = render(opt, (vct_method)method, out);
    /* the video of a sequence, once every frame is written (by rank 0) */
    if (rc == 0 && opt->video && cli_cluster_rank() == 0 &&
        cli_video_make(opt, out, &err) != VCT_OK)
        return cli_fail(&err);
    return rc;
}

static int render(const cli_options *opt, vct_method method, const char *out) {
    vct_error err = {0};
    if (opt->denoise && method != VCT_METHOD_PATHTRACE && method != VCT_METHOD_PM &&
        method != VCT_METHOD_VCT) {
        fprintf(stderr, "vct render: --denoise is for --method pt, pm and vct\n");
        return 1;
    }
    if (opt->subsample && method != VCT_METHOD_WHITTED && method != VCT_METHOD_RAYCAST) {
        fprintf(stderr, "vct: --subsample is for --method whitted and raycast\n");
        return 1;
    }
    vct_scene *s = cli_load_scene(opt, &err);
    if (!s)
        return cli_fail(&err);
    cli_print_scene(s, stderr);
    if (cli_cluster_size() > 1) {
        const int rc = cli_render_cluster(opt, s, (vct_method)method, out);
        vct_scene_release(s);
        return rc;
    }
    int emissive = 0;
    for (uint32_t m = 0; m < s->material_count; ++m)
        for (int c = 0; c < 3; ++c)
            emissive |= s->materials[m].emission[c] > 0.0f;
    if (s->light_count == 0 && !emissive)
        fprintf(stderr, "vct: the scene has no lights and nothing emits: only ambient light will "
                        "show (add --point-light, --dir-light or --ambient)\n");
    if (cli_device_list(opt)) {
        const int rc = cli_render_group(opt, s, (vct_method)method, out);
        vct_scene_release(s);
        return rc;
    }
    vct_context *ctx = cli_open_context(opt, &err);
    if (!ctx) {
        vct_scene_release(s);
        return cli_fail(&err);
    }
    vct_device_scene *ds = vct_device_scene_create(ctx, s, &err);
    int rc = ds ? VCT_OK : err.status;
    if (rc == VCT_OK && opt->frames[1] >= 0) {
        one_device dev = {ctx, ds, s, opt, method};
        const cli_frame_source source = {one_device_frame, &dev, ds};
        rc = cli_render_frames(opt, s, out, &source, &err);
    } else if (rc == VCT_OK)
        rc = cli_render_frame(ctx, ds, s, opt, (vct_method)method, out, &err);
    if (rc == VCT_OK) {
        rc = cli_print_accel(ctx, vct_device_scene_accel(ds), stderr, &err);
        if (opt->stats)
            cli_print_stats(ctx);
    }
    vct_device_scene_release(ds);
    vct_context_release(ctx);
    vct_scene_release(s);
    return rc == VCT_OK ? 0 : cli_fail(&err);
}

int cmd_compare(const cli_options *opt) {
    vct_error err = {0};
    vct_image test = {0}, ref = {0}, map = {0};
    int rc = vct_image_read(opt->inputs[0], &test, &err);
    if (rc == VCT_OK)
        rc = vct_image_read(opt->inputs[1], &ref, &err);
    vct_image_metrics m;
    if (rc == VCT_OK)
        rc = vct_image_compare(&test, &ref, &m, &err);
    if (rc == VCT_OK && opt->error_image) {
        rc = vct_image_error_map(&test, &ref, opt->error_scale, &map, &err);
        if (rc == VCT_OK)
            rc = cli_make_parent_dir(opt->error_image, &err);
        if (rc == VCT_OK)
            rc = vct_image_write_png(&map, opt->error_image, 0.0f, &err);
    }
    if (rc == VCT_OK) {
        printf("nrmse %.6g\nrmse %.6g\nrelative_rmse %.6g\nrelative_mse %.6g\nmae %.6g\n"
               "psnr_db %.4g\nmean_ratio %.6g\n",
               m.nrmse, m.rmse, m.relative_rmse, m.relative_mse, m.mae, m.psnr,
               m.reference_mean > 0.0 ? m.test_mean / m.reference_mean : 0.0);
        if (m.nonfinite)
            printf("nonfinite %zu\n", m.nonfinite);
        if (opt->error_image)
            printf("wrote %s (mean absolute error per pixel, blue 0 to red %s)\n", opt->error_image,
                   opt->error_scale > 0 ? "at --error-scale" : "at the largest");
    }
    vct_image_release(&test);
    vct_image_release(&ref);
    vct_image_release(&map);
    return rc == VCT_OK ? 0 : cli_fail(&err);
}
