/* Voxel cone tracing frame times: a 512x512 frame at 256^3 voxels with 5
 * diffuse cones and a specular cone (cone tracing only, the voxel
 * hierarchy already built), per stage, on the Cornell box and on the heavy
 * scene with a glossy material; and what the effect plan saves: the
 * planned variant of the diffuse Cornell box against every effect forced
 * on, as a ratio measured in the same run; and sparse diffuse (cones at
 * every other pixel per axis) against every pixel's, on the same voxels.
 *
 * usage: VCT_SOURCE_DIR=. bench_vct [RES] [SIZE]   (defaults 256, 512) */
#include <math.h>

#include "bench_util.h"
#include "heavy_scene.h"

typedef struct frame_times {
    double primary, diffuse, specular, total;
} frame_times;

/* Best of the repeats, per stage. */
static frame_times render_best(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                               const vct_voxels *v, const vct_plan *plan,
                               const vct_vct_options *o) {
    frame_times best = {INFINITY, INFINITY, INFINITY, INFINITY};
    for (int r = 0; r < bench_repeats(); ++r) {
        vct_error err = {0};
        vct_image im;
        vct_stats_reset(ctx);
        if (vct_render_vct(ctx, s, g, v, plan, o, &im, NULL, &err))
            bench_die(&err);
        vct_image_release(&im);
        const frame_times t = {stage_device_ms(ctx, "vct primary"),
                               stage_device_ms(ctx, "vct diffuse cones"),
                               stage_device_ms(ctx, "vct specular cone"), 0.0};
        best.primary = fmin(best.primary, t.primary);
        best.diffuse = fmin(best.diffuse, t.diffuse);
        best.specular = fmin(best.specular, t.specular);
        best.total = fmin(best.total, t.primary + t.diffuse + t.specular);
    }
    return best;
}

static vct_voxels *prepare(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                           const vct_plan *plan, uint32_t res, int anisotropic, double *ms) {
    vct_error err = {0};
    vct_voxel_options vo = {0};
    vo.resolution = res;
    const vct_brick_options bo = {VCT_BRICKS_AUTO, anisotropic, 0};
    const vct_cone_settings cs = vct_cone_settings_default();
    vct_voxels *v = NULL;
    const double t0 = vct_now_ms();
    if (vct_vct_prepare(ctx, s, g, plan, &vo, &bo, 2, &cs, &v, &err))
        bench_die(&err);
    *ms = vct_now_ms() - t0;
    return v;
}

static void frame_row(const char *scene, const char *what, const frame_times *t) {
    printf("| %s | %s | %.1f | %.1f | %.1f | **%.1f** |\n", scene, what, t->primary, t->diffuse,
           t->specular, t->total);
}

int main(int argc, char **argv) {
    const char *src = getenv("VCT_SOURCE_DIR") ? getenv("VCT_SOURCE_DIR") : ".";
    const uint32_t res = argc > 1 ? (uint32_t)atoi(argv[1]) : 256;
    const int size = argc > 2 ? atoi(argv[2]) : 512;
    vct_error err = {0};
    vct_context *ctx = vct_context_create(NULL, &err);
    if (!ctx)
        bench_die(&err);
    char path[1024];
    snprintf(path, sizeof path, "%s/scenes/cornell_box.gltf", src);
    vct_scene *box = vct_scene_load(path, &err);
    vct_scene *heavy = box ? heavy_scene_load(src, &err) : NULL;
    if (!heavy)
        bench_die(&err);
    /* A glossy white (roughness 0.3) so that the plan traces the specular cone. */
    vct_scene *scenes[2] = {box, heavy};
    const char *names[2] = {"Cornell box (30 tris)", "heavy (102,430 tris)"};
    printf("Device %s; %dx%d pixels, %u^3 voxels, best of %d; device ms per stage.\n\n",
           vct_context_device(ctx)->name, size, size, res, bench_repeats());
    printf("| scene | setting | primary | diffuse cones | specular cone | cone tracing total |\n"
           "|---|---|---:|---:|---:|---:|\n");
    double planned_ms = 0.0, all_ms = 0.0;
    for (int i = 0; i < 2; ++i) {
        vct_scene *s = scenes[i];
        vct_accel *g = vct_accel_build(ctx, s, NULL, &err);
        if (!g)
            bench_die(&err);
        vct_vct_options o = vct_vct_options_default(512, 512);
        o.sparse_diffuse = 0; /* the rows time every pixel's cones, then sparse */
        o.width = o.height = size;
        o.diffuse_cones = 5;
        vct_plan plan;
        vct_plan_make(s, NULL, &plan);
        for (int aniso = 1; aniso >= 0; --aniso) {
            double build_ms;
            vct_voxels *v = prepare(ctx, s, g, &plan, res, aniso, &build_ms);
            if (i == 0 && aniso) {
                /* What the plan saves: the diffuse box as planned, then with
                 * every effect forced on (specular, refraction, AO, emission). */
                const frame_times planned = render_best(ctx, s, g, v, &plan, &o);
                vct_effect_force all[VCT_EFFECTS];
                for (int e = 0; e < VCT_EFFECTS; ++e)
                    all[e] = VCT_FORCE_ON;
                vct_plan every;
                vct_plan_make(s, all, &every);
                const frame_times forced = render_best(ctx, s, g, v, &every, &o);
                frame_row(names[i], "5 cones, as planned (no specular)", &planned);
                frame_row(names[i], "5 cones, every effect forced on", &forced);
                planned_ms = planned.total;
                all_ms = forced.total;
            }
            vct_voxels_release(v);
        }
        /* The same scene with its white glossy, at both brick kinds. */
        s->materials[0].specular[0] = s->materials[0].specular[1] = s->materials[0].specular[2] =
            0.3f;
        s->materials[0].roughness = 0.3f;
        vct_plan_make(s, NULL, &plan);
        for (int aniso = 1; aniso >= 0; --aniso) {
            double build_ms;
            vct_voxels *v = prepare(ctx, s, g, &plan, res, aniso, &build_ms);
            const frame_times t = render_best(ctx, s, g, v, &plan, &o);
            char what[128];
            snprintf(what, sizeof what, "5 cones + specular, %s (built in %.0f ms)",
                     aniso ? "anisotropic" : "isotropic", build_ms);
            frame_row(names[i], what, &t);
            o.sparse_diffuse = 1;
            const frame_times sparse = render_best(ctx, s, g, v, &plan, &o);
            o.sparse_diffuse = 0;
            snprintf(what, sizeof what,
                     "5 cones + specular, %s, sparse diffuse (diffuse %.2fx faster)",
                     aniso ? "anisotropic" : "isotropic", t.diffuse / sparse.diffuse);
            frame_row(names[i], what, &sparse);
            vct_voxels_release(v);
        }
        vct_accel_release(g);
    }
    printf("\nThe plan: every effect forced on takes %.2fx the planned frame's time "
           "(%.1f ms against %.1f ms).\n",
           planned_ms > 0 ? all_ms / planned_ms : 0.0, all_ms, planned_ms);
    vct_scene_release(box);
    vct_scene_release(heavy);
    vct_context_release(ctx);
    return 0;
}
