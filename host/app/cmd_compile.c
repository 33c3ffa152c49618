/* vct compile: the kernel programs a scene's renders need, built into the
 * kernel cache before the first render, as engines compile their shaders at
 * install time. Each method renders the scene once at a thumbnail's size;
 * nothing is written but the cache. */
#include <stdio.h>
#include <string.h>

#include "cli_common.h"
#include "cmd_render_frame.h"
#include "commands.h"

/* Every method, with the passes a user may ask of it: the denoiser for the
 * estimators, adaptive subsampling for the ray caster and Whitted (whose
 * programs are then built for both, plain and subsampled); the path tracer
 * also without the denoiser, whose sums then hold the colour alone. */
static const struct {
    vct_method method;
    const char *name;
    int denoise, subsample;
} methods[] = {{VCT_METHOD_VCT, "vct", 1, 0},         {VCT_METHOD_PATHTRACE, "pt", 1, 0},
               {VCT_METHOD_PATHTRACE, "pt", 0, 0},    {VCT_METHOD_PM, "pm", 1, 0},
               {VCT_METHOD_RAYCAST, "raycast", 0, 8}, {VCT_METHOD_WHITTED, "whitted", 0, 8}};

static int compile_all(vct_context *ctx, vct_device_scene *ds, const vct_scene *s,
                       const cli_options *opt, vct_error *err) {
    for (size_t i = 0; i < sizeof methods / sizeof methods[0]; ++i) {
        cli_options o = *opt;
        o.width = 32;
        o.height = 24;
        o.spp = 1;
        o.stats = 0;
        o.aov = 0;
        o.method = methods[i].name;
        o.denoise = methods[i].denoise;
        o.subsample = methods[i].subsample;
        o.pm.photons = 4096; /* programs do not depend on the count */
        vct_program_stats before, after;
        vct_context_program_stats(ctx, &before);
        cli_frame f;
        int rc = cli_frame_make(ctx, ds, s, &o, methods[i].method, &f, err);
        if (rc != VCT_OK)
            return rc;
        cli_frame_release(&f);
        vct_context_program_stats(ctx, &after);
        fprintf(stderr, "vct compile: --method %s%s ready (%d programs compiled for it)\n",
                methods[i].name,
                methods[i].denoise     ? " --denoise"
                : methods[i].subsample ? " --subsample"
                                       : "",
                after.compiled - before.compiled);
    }
    return VCT_OK;
}

int cmd_compile(const cli_options *opt) {
    if (cli_device_list(opt)) {
        fprintf(stderr, "vct compile: give one device at a time (--device N), as each device "
                        "has its own kernel binaries\n");
        return 1;
    }
    vct_error err = {0};
    vct_scene *s = cli_load_scene(opt, &err);
    if (!s)
        return cli_fail(&err);
    vct_context *ctx = cli_open_context(opt, &err);
    vct_device_scene *ds = ctx ? vct_device_scene_create(ctx, s, &err) : NULL;
    int rc = ds ? compile_all(ctx, ds, s, opt, &err) : (int)err.status;
    if (rc == VCT_OK) {
        vct_program_stats st;
        vct_context_program_stats(ctx, &st);
        fprintf(stderr,
                "vct compile: %d kernel programs compiled, %d were in the cache, in %.1f s\n",
                st.compiled, st.cached, st.ms / 1000.0);
    }
    vct_device_scene_release(ds);
    vct_context_release(ctx);
    vct_scene_release(s);
    return rc == VCT_OK ? 0 : cli_fail(&err);
}
