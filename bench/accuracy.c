/* Accuracy against time: runs a list of method settings on one scene, times
 * each per stage, measures its error against a reference image, and writes a
 * CSV, a Markdown table and a log-log plot of error against time with the
 * Pareto front marked.
 *
 * usage: accuracy SCENE|heavy [--reference REF.pfm] [--reference-spp N]
 *                 [--size W H] [--max-spp N] [--out DIR] [--no-vct] [--quick]
 *                 [--ambient R G B] [--accel bvh|grid] [--whitted] [--pm]
 *                 [--repeat N]
 * Without --reference, a path-traced reference of --reference-spp samples
 * (default 2048, a different seed from the runs) is rendered and saved.
 * "heavy" is bench/heavy_scene.h's 102,430-triangle scene. Voxel cone
 * tracing runs over voxel resolutions, cone presets, step sizes, cone start
 * offsets, isotropic against anisotropic bricks, 1 to 4 bounces, and 2 to 4
 * bounces without the rest of the series; its time is split into building the
 * voxel hierarchy (voxels, octree, bricks, light) and tracing.
 * --quick runs cone tracing at its default, with dense diffuse, with dense
 * bounces, with its
 * bounces exactly, with directional bricks and with 6 cones (the scene
 * suite's table); --ambient gives the scene
 * a sky; --accel picks the structure every ray goes through (its build counts as "accel ms").
 * --repeat N renders each row of the ray caster, the path tracer, photon
 * mapping and cone tracing N times, the rows in turn, and keeps each
 * stage's fastest time (default 1): one run on a shared CPU moves by a
 * fifth, and a slow spell can last several runs. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "bench_util.h"
#include "heavy_scene.h"

typedef struct settings {
    const char *scene, *reference, *out;
    int width, height;
    uint32_t reference_spp, max_spp;
    int vct;
    int quick;
    int has_ambient;
    float ambient[3];
    int whitted;
    int pm;
    int repeat;
    vct_accel_options accel;
} settings;

/* Photon mapping after `passes` passes: progressive (SPPM), with the
 * seed's fixed radii, or progressive with final gathering. */
typedef enum pm_kind { PM_PROGRESSIVE, PM_FIXED, PM_FINAL_GATHER } pm_kind;

typedef struct vct_setting {
    uint32_t res, cones, bounces;
    float step;
    int anisotropic;
    float offset;      /* cone start offset in voxels; 0: the default */
    int nearest;       /* 1: each sample reads the nearest level alone */
    int dense;         /* 1: diffuse cones at every pixel (default: every other per axis) */
    int exact;         /* 1: only the bounces asked for, no rest of the series */
    int dense_bounces; /* 1: every voxel gathers each bounce (default: half of them) */
} vct_setting;

/* One row's render: the ray caster, the path tracer at spp, photon mapping
 * of a kind after `passes`, or cone tracing at vs. */
typedef struct request {
    enum { RQ_RAYCAST, RQ_PT, RQ_PM, RQ_VCT } kind;
    uint32_t spp, seed;
    pm_kind pm;
    uint32_t passes;
    const vct_setting *vs;
} request;

typedef struct run {
    char name[128];
    double accel_ms, build_ms, render_ms, total_ms; /* device time per stage, and their sum */
    double wall_ms;
    vct_image_metrics m;
    int pareto;
    int retimed; /* 1: q renders it again, for its time (--repeat) */
    request q;
} run;

#define MAX_RUNS 64

static const char *const build_stages[] = {
    "voxelize",        "octree build",       "brick creation", "brick filtering",
    "light injection", "radiance filtering", "light bounce",   "light bounce rest"};
static const char *const trace_stages[] = {
    "vct primary", "vct soft shadows",  "vct diffuse cones",   "guides",
    "denoise",     "vct specular cone", "vct glass reflection"};

static double stages_ms(const vct_context *ctx, const char *const *names, size_t n) {
    double ms = 0.0;
    for (size_t i = 0; i < n; ++i)
        ms += stage_device_ms(ctx, names[i]);
    return ms;
}

/* A run: statistics reset, its start time, and the acceleration structure
 * its rays go through. */
static vct_accel *run_begin(vct_context *ctx, const vct_scene *s, const settings *cfg, double *t0) {
    vct_error err = {0};
    vct_stats_reset(ctx);
    *t0 = vct_now_ms();
    vct_accel *g = vct_accel_build(ctx, s, &cfg->accel, &err);
    if (!g)
        bench_die(&err);
    return g;
}

/* Wall time, the acceleration build's device time and the total, once the
 * render stage's time is in r. */
static void run_end(vct_context *ctx, vct_accel *g, double t0, run *r) {
    r->wall_ms = vct_now_ms() - t0;
    r->accel_ms = stage_device_ms(ctx, "grid build") + stage_device_ms(ctx, "bvh build");
    r->total_ms = r->accel_ms + r->render_ms;
    vct_accel_release(g);
}

/* method "raycast" or "pt"; spp for pt. */
static vct_image render(vct_context *ctx, const vct_scene *s, const settings *cfg,
                        const char *method, uint32_t spp, uint32_t seed, run *r) {
    vct_error err = {0};
    double t0;
    vct_accel *g = run_begin(ctx, s, cfg, &t0);
    vct_image im;
    r->build_ms = 0.0;
    if (strcmp(method, "pt") == 0) {
        vct_pathtrace_options o = {cfg->width,          cfg->height, spp, 0.0,  16,   seed,
                                   spp < 16 ? spp : 16, 1,           0,   NULL, NULL, 1};
        vct_pathtrace_result pr;
        if (vct_render_pathtrace(ctx, s, g, &o, &im, &pr, &err))
            bench_die(&err);
        r->render_ms = stage_device_ms(ctx, "path trace");
    } else {
        vct_render_options o = {cfg->width, cfg->height, 0, 0, 0.0f};
        if (vct_render_raycast(ctx, s, g, &o, &im, &err))
            bench_die(&err);
        r->render_ms = stage_device_ms(ctx, "ray cast");
    }
    run_end(ctx, g, t0, r);
    return im;
}

static vct_image render_vct(vct_context *ctx, const vct_scene *s, const settings *cfg,
                            const vct_setting *vs, run *r) {
    vct_error err = {0};
    double t0;
    vct_accel *g = run_begin(ctx, s, cfg, &t0);
    vct_plan plan;
    vct_plan_make(s, NULL, &plan);
    vct_voxel_options vo = {0};
    vo.resolution = vs->res;
    vo.exact_bounces = vs->exact;
    vo.dense_bounces = vs->dense_bounces;
    const vct_brick_options bo = {VCT_BRICKS_AUTO, vs->anisotropic, 0};
    vct_vct_options o = vct_vct_options_default(512, 512);
    o.width = cfg->width;
    o.height = cfg->height;
    o.diffuse_cones = vs->cones;
    o.cones.step = vs->step;
    if (vs->offset > 0.0f)
        o.cones.offset = vs->offset;
    o.cones.nearest_level = vs->nearest;
    o.sparse_diffuse = !vs->dense;
    vct_voxels *v = NULL;
    vct_image im;
    if (vct_vct_prepare(ctx, s, g, &plan, &vo, &bo, vs->bounces, &o.cones, &v, &err) ||
        vct_render_vct(ctx, s, g, v, &plan, &o, &im, NULL, &err))
        bench_die(&err);
    r->wall_ms = vct_now_ms() - t0;
    r->accel_ms = stage_device_ms(ctx, "grid build") + stage_device_ms(ctx, "bvh build");
    r->build_ms = stages_ms(ctx, build_stages, sizeof build_stages / sizeof build_stages[0]);
    r->render_ms = stages_ms(ctx, trace_stages, sizeof trace_stages / sizeof trace_stages[0]);
    r->total_ms = r->accel_ms + r->build_ms + r->render_ms;
    snprintf(r->name, sizeof r->name,
             "vct %u^3, %u cones, step %g, offset %g, %s, %u bounce%s%s%s%s%s", vs->res, vs->cones,
             vs->step, o.cones.offset, vs->anisotropic ? "aniso" : "iso", vs->bounces,
             vs->bounces == 1 ? "" : "s", vs->exact ? " exactly" : "",
             vs->nearest ? ", nearest level" : "", vs->dense ? ", dense diffuse" : "",
             vs->dense_bounces ? ", dense bounces" : "");
    vct_voxels_release(v);
    vct_accel_release(g);
    return im;
}

/* The path tracer's time to reach `error`, interpolated log-log between the
 * sample counts around it; 0 when no run was that accurate. */
static double pt_time_for(const run *runs, int n, double error) {
    const run *prev = NULL;
    for (int i = 0; i < n; ++i) {
        if (strncmp(runs[i].name, "path trace", 10) != 0)
            continue;
        if (runs[i].m.nrmse <= error) {
            if (!prev)
                return runs[i].total_ms;
            const double f = log(prev->m.nrmse / error) / log(prev->m.nrmse / runs[i].m.nrmse);
            return exp(log(prev->total_ms) + f * log(runs[i].total_ms / prev->total_ms));
        }
        prev = &runs[i];
    }
    return 0.0;
}

static vct_image render_pm(vct_context *ctx, const vct_scene *s, const settings *cfg, pm_kind kind,
                           uint32_t passes, run *r) {
    static const char *const names[] = {"photon mapping, progressive",
                                        "photon mapping, fixed radius",
                                        "photon mapping, final gathering"};
    vct_error err = {0};
    double t0;
    vct_accel *g = run_begin(ctx, s, cfg, &t0);
    vct_pm_options o = vct_pm_options_default(cfg->width, cfg->height);
    o.passes = passes;
    o.fixed_radius = kind == PM_FIXED;
    o.final_gather = kind == PM_FINAL_GATHER;
    vct_image im;
    if (vct_render_pm(ctx, s, g, &o, &im, NULL, &err))
        bench_die(&err);
    r->render_ms = stage_device_ms(ctx, "photon mapping");
    r->build_ms = 0.0;
    run_end(ctx, g, t0, r);
    snprintf(r->name, sizeof r->name, "%s, %u passes", names[kind], passes);
    return im;
}

/* One row's render (run.q). */
static vct_image render_once(vct_context *ctx, const vct_scene *s, const settings *cfg,
                             const request *q, run *r) {
    switch (q->kind) {
    case RQ_RAYCAST:
        return render(ctx, s, cfg, "raycast", 0, 0, r);
    case RQ_PT:
        return render(ctx, s, cfg, "pt", q->spp, q->seed, r);
    case RQ_PM:
        return render_pm(ctx, s, cfg, q->pm, q->passes, r);
    default:
        return render_vct(ctx, s, cfg, q->vs, r);
    }
}

/* A row's image, rendered once; --repeat renders it again later for its
 * time (retime_rows). */
static vct_image render_row(vct_context *ctx, const vct_scene *s, const settings *cfg,
                            const request *q, run *r) {
    vct_image im = render_once(ctx, s, cfg, q, r);
    r->q = *q;
    r->retimed = 1;
    return im;
}

/* --repeat N: every row rendered N - 1 times more, a row at a time in
 * turn, so that a slow spell of a shared CPU falls on one of each row's
 * runs, not on all of them; each stage keeps its fastest time (the image
 * is the same bits every time) and the total is their sum. */
static void retime_rows(vct_context *ctx, const vct_scene *s, const settings *cfg, run *runs,
                        int n) {
    for (int k = 1; k < cfg->repeat; ++k)
        for (int i = 0; i < n; ++i) {
            run *r = &runs[i];
            if (!r->retimed)
                continue;
            run again;
            vct_image other = render_once(ctx, s, cfg, &r->q, &again);
            vct_image_release(&other);
            r->accel_ms = fmin(r->accel_ms, again.accel_ms);
            r->build_ms = fmin(r->build_ms, again.build_ms);
            r->render_ms = fmin(r->render_ms, again.render_ms);
            r->wall_ms = fmin(r->wall_ms, again.wall_ms);
            r->total_ms = r->accel_ms + r->build_ms + r->render_ms;
        }
}

static int pm_rows(vct_context *ctx, const vct_scene *s, const settings *cfg, const vct_image *ref,
                   run *runs, int n) {
    static const struct {
        pm_kind kind;
        uint32_t passes;
    } rows[] = {{PM_PROGRESSIVE, 1},  {PM_PROGRESSIVE, 4},  {PM_PROGRESSIVE, 16},
                {PM_PROGRESSIVE, 64}, {PM_FIXED, 4},        {PM_FIXED, 16},
                {PM_FIXED, 64},       {PM_FINAL_GATHER, 4}, {PM_FINAL_GATHER, 16}};
    vct_error err = {0};
    for (size_t i = 0; i < sizeof rows / sizeof rows[0] && n < MAX_RUNS; ++i) {
        const request q = {RQ_PM, 0, 0, rows[i].kind, rows[i].passes, NULL};
        vct_image im = render_row(ctx, s, cfg, &q, &runs[n]);
        if (vct_image_compare(&im, ref, &runs[n].m, &err))
            bench_die(&err);
        vct_image_release(&im);
        fprintf(stderr, "%-48s %9.1f ms  NRMSE %.4f\n", runs[n].name, runs[n].total_ms,
                runs[n].m.nrmse);
        ++n;
    }
    return n;
}

/* Whitted ray tracing, subsampled at n (0: every pixel), guarded or not,
 * with a contrast test or not; writes the pixels traced and the rays cast. */
static vct_image render_whitted(vct_context *ctx, const vct_scene *s, const settings *cfg,
                                uint32_t n, int guarded, float contrast, uint64_t *traced,
                                uint64_t *rays, run *r) {
    vct_error err = {0};
    double t0;
    vct_accel *g = run_begin(ctx, s, cfg, &t0);
    const vct_whitted_options o = {cfg->width, cfg->height,        8,       1e-3f,
                                   n,          (uint32_t)!guarded, contrast};
    vct_whitted_result res = {0, 0, NULL, 0};
    vct_image im;
    if (vct_render_whitted(ctx, s, g, &o, &im, &res, &err))
        bench_die(&err);
    *traced = res.traced_pixels;
    *rays = res.camera_rays;
    r->render_ms = stage_device_ms(ctx, "whitted");
    r->build_ms = 0.0;
    run_end(ctx, g, t0, r);
    if (n)
        snprintf(r->name, sizeof r->name, "whitted, subsample %u%s%s", n,
                 guarded ? "" : " (no guard)", contrast > 0.0f ? ", contrast 0.05" : "");
    else
        snprintf(r->name, sizeof r->name, "whitted");
    return im;
}

/* Whitted at every pixel and subsampled at 4, 8 and 16, with and without
 * the guard, and guarded with the contrast test at 0.05: rows against the
 * reference, and whitted.md with each setting's error against full Whitted
 * and the shares of pixels it traced and rays it cast. */
static int whitted_rows(vct_context *ctx, const vct_scene *s, const settings *cfg,
                        const vct_image *ref, run *runs, int n) {
    char path[1200];
    snprintf(path, sizeof path, "%s/whitted.md", cfg->out);
    FILE *md = fopen(path, "w");
    if (md)
        fprintf(md,
                "| setting | pixels traced | rays cast | time (ms, device) | NRMSE against "
                "full Whitted | NRMSE against the reference |\n|---|---:|---:|---:|---:|---:|\n");
    vct_image full = {0};
    static const uint32_t sizes[] = {0, 4, 8, 16};
    for (size_t i = 0; i < sizeof sizes / sizeof *sizes; ++i)
        for (int variant = 0; variant < (sizes[i] ? 3 : 1) && n < MAX_RUNS; ++variant) {
            /* guarded; unguarded; guarded with the contrast test */
            const int guarded = variant != 1;
            const float contrast = variant == 2 ? 0.05f : 0.0f;
            vct_error err = {0};
            uint64_t traced = 0, rays = 0;
            vct_image im =
                render_whitted(ctx, s, cfg, sizes[i], guarded, contrast, &traced, &rays, &runs[n]);
            vct_image_metrics own = {0};
            if (vct_image_compare(&im, ref, &runs[n].m, &err) ||
                (full.rgba && vct_image_compare(&im, &full, &own, &err)))
                bench_die(&err);
            const double pixels = (double)cfg->width * cfg->height;
            const double share = (double)traced / pixels, ray_share = (double)rays / pixels;
            fprintf(stderr,
                    "%-48s %9.1f ms  NRMSE %.4f, against full Whitted %.4f, %.1f %% traced\n",
                    runs[n].name, runs[n].total_ms, runs[n].m.nrmse, own.nrmse, 100.0 * share);
            if (md)
                fprintf(md, "| %s | %.1f %% | %.1f %% | %.1f | %.4f | %.4f |\n", runs[n].name,
                        100.0 * share, 100.0 * ray_share, runs[n].total_ms, own.nrmse,
                        runs[n].m.nrmse);
            if (!full.rgba)
                full = im;
            else
                vct_image_release(&im);
            ++n;
        }
    vct_image_release(&full);
    if (md)
        fclose(md);
    return n;
}

static void mark_pareto(run *runs, int n) {
    for (int i = 0; i < n; ++i) {
        runs[i].pareto = 1;
        for (int j = 0; j < n; ++j)
            if (j != i && runs[j].total_ms <= runs[i].total_ms &&
                runs[j].m.nrmse <= runs[i].m.nrmse &&
                (runs[j].total_ms < runs[i].total_ms || runs[j].m.nrmse < runs[i].m.nrmse))
                runs[i].pareto = 0;
    }
}

static void write_outputs(const settings *cfg, const run *runs, int n, const char *device) {
    char path[1200];
    snprintf(path, sizeof path, "%s/accuracy.csv", cfg->out);
    FILE *csv = fopen(path, "w");
    snprintf(path, sizeof path, "%s/accuracy.md", cfg->out);
    FILE *md = fopen(path, "w");
    if (!csv || !md) {
        fprintf(stderr, "accuracy: cannot write into %s\n", cfg->out);
        exit(1);
    }
    fprintf(csv, "setting,accel_ms,build_ms,render_ms,total_ms,wall_ms,nrmse,rmse,relative_rmse,"
                 "relative_mse,mae,psnr_db,pareto,mean_ratio\n");
    fprintf(md, "Scene `%s`, %dx%d, on %s; error against the reference `%s`.\n\n", cfg->scene,
            cfg->width, cfg->height, device, cfg->reference);
    fprintf(md, "| setting | accel ms | voxel build ms | render ms | total ms | NRMSE | mean / "
                "reference mean | relative RMSE | PSNR dB | Pareto | path tracer's time to this "
                "error |\n"
                "|---|---:|---:|---:|---:|---:|---:|---:|---:|:---:|---:|\n");
    for (int i = 0; i < n; ++i) {
        const run *r = &runs[i];
        const double ratio = r->m.reference_mean > 0.0 ? r->m.test_mean / r->m.reference_mean : 0;
        fprintf(csv, "\"%s\",%.3f,%.3f,%.3f,%.3f,%.3f,%.6g,%.6g,%.6g,%.6g,%.6g,%.4g,%d,%.4f\n",
                r->name, r->accel_ms, r->build_ms, r->render_ms, r->total_ms, r->wall_ms,
                r->m.nrmse, r->m.rmse, r->m.relative_rmse, r->m.relative_mse, r->m.mae, r->m.psnr,
                r->pareto, ratio);
        char pt[96] = "";
        const double pt_ms = pt_time_for(runs, n, r->m.nrmse);
        if (strncmp(r->name, "vct", 3) == 0)
            snprintf(pt, sizeof pt,
                     pt_ms > 0 ? "%.0f ms: %.2fx total, %.1fx render" : "not reached", pt_ms,
                     pt_ms / r->total_ms, pt_ms / r->render_ms);
        fprintf(md, "| %s | %.1f | %.1f | %.1f | %.1f | %.4f | %.3f | %.4f | %.2f | %s | %s |\n",
                r->name, r->accel_ms, r->build_ms, r->render_ms, r->total_ms, r->m.nrmse, ratio,
                r->m.relative_rmse, r->m.psnr, r->pareto ? "yes" : "", pt);
    }
    fclose(csv);
    fclose(md);
    snprintf(path, sizeof path, "%s/accuracy.gp", cfg->out);
    FILE *gp = fopen(path, "w");
    if (!gp)
        exit(1);
    fprintf(gp,
            "set terminal pngcairo size 900,600 font ',11'\n"
            "set output '%s/accuracy.png'\n"
            "set datafile separator ','\n"
            "set logscale xy\nset grid\n"
            "set xlabel 'time (ms, device: acceleration structure, voxel hierarchy, render)'\n"
            "set ylabel 'NRMSE against the reference (RMSE / reference mean)'\n"
            "set key top right\n"
            "plot '%s/accuracy.csv' skip 1 using 5:7 with points pt 7 ps 1.2 title 'settings', \\\n"
            "     '' skip 1 using ($13 == 1 ? $5 : 1/0):7 with linespoints lw 2 pt 6 ps 2 "
            "title 'Pareto front', \\\n"
            "     '' skip 1 using 5:7:1 with labels offset 0,1 font ',7' notitle\n",
            cfg->out, cfg->out);
    fclose(gp);
    char cmd[1400];
    snprintf(cmd, sizeof cmd, "gnuplot '%s/accuracy.gp' 2>/dev/null", cfg->out);
    if (system(cmd) != 0)
        fprintf(stderr, "accuracy: gnuplot failed or is missing; the CSV and table are written\n");
}

int main(int argc, char **argv) {
    settings cfg = {NULL, NULL, "out/accuracy", 128, 128, 2048, 256, 1,
                    0,    0,    {0, 0, 0},      0,   0,   1,    {0}};
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--reference") == 0 && i + 1 < argc)
            cfg.reference = argv[++i];
        else if (strcmp(argv[i], "--reference-spp") == 0 && i + 1 < argc)
            cfg.reference_spp = (uint32_t)atoi(argv[++i]);
        else if (strcmp(argv[i], "--max-spp") == 0 && i + 1 < argc)
            cfg.max_spp = (uint32_t)atoi(argv[++i]);
        else if (strcmp(argv[i], "--size") == 0 && i + 2 < argc) {
            cfg.width = atoi(argv[++i]);
            cfg.height = atoi(argv[++i]);
        } else if (strcmp(argv[i], "--out") == 0 && i + 1 < argc)
            cfg.out = argv[++i];
        else if (strcmp(argv[i], "--whitted") == 0)
            cfg.whitted = 1;
        else if (strcmp(argv[i], "--pm") == 0)
            cfg.pm = 1;
        else if (strcmp(argv[i], "--quick") == 0)
            cfg.quick = 1;
        else if (strcmp(argv[i], "--repeat") == 0 && i + 1 < argc)
            cfg.repeat = atoi(argv[++i]) > 0 ? atoi(argv[i]) : 1;
        else if (strcmp(argv[i], "--accel") == 0 && i + 1 < argc) {
            const int kind = vct_accel_kind_from_name(argv[++i]);
            if (kind < 0) {
                fprintf(stderr, "accuracy: --accel takes bvh or grid\n");
                return 1;
            }
            cfg.accel.kind = (vct_accel_kind)kind;
        } else if (strcmp(argv[i], "--no-vct") == 0)
            cfg.vct = 0;
        else if (strcmp(argv[i], "--ambient") == 0 && i + 3 < argc) {
            cfg.has_ambient = 1;
            for (int k = 0; k < 3; ++k)
                cfg.ambient[k] = (float)atof(argv[++i]);
        } else if (argv[i][0] != '-' && !cfg.scene)
            cfg.scene = argv[i];
        else {
            fprintf(stderr, "usage: accuracy SCENE [--reference REF.pfm] [--reference-spp N] "
                            "[--size W H] [--max-spp N] [--out DIR] [--no-vct] [--quick] "
                            "[--ambient R G B] [--accel bvh|grid] [--whitted] [--pm] "
                            "[--repeat N]\n");
            return 2;
        }
    }
    if (!cfg.scene) {
        fprintf(stderr, "accuracy: name a scene\n");
        return 2;
    }
    vct_error err = {0};
    const char *src = getenv("VCT_SOURCE_DIR") ? getenv("VCT_SOURCE_DIR") : ".";
    vct_scene *s = strcmp(cfg.scene, "heavy") == 0 ? heavy_scene_load(src, &err)
                                                   : vct_scene_load(cfg.scene, &err);
    if (!s)
        bench_die(&err);
    if (cfg.has_ambient)
        memcpy(s->ambient, cfg.ambient, sizeof s->ambient);
    vct_context *ctx = vct_context_create(NULL, &err);
    if (!ctx)
        bench_die(&err);
    char cmd[1200];
    snprintf(cmd, sizeof cmd, "mkdir -p '%s'", cfg.out);
    if (system(cmd) != 0)
        return 1;
    vct_image ref;
    char ref_path[1200];
    if (cfg.reference) {
        if (vct_image_read_pfm(cfg.reference, &ref, &err))
            bench_die(&err);
        cfg.width = ref.width;
        cfg.height = ref.height;
    } else {
        run r;
        fprintf(stderr, "rendering the reference: path tracing, %u spp...\n", cfg.reference_spp);
        ref = render(ctx, s, &cfg, "pt", cfg.reference_spp, 0x5eed, &r);
        snprintf(ref_path, sizeof ref_path, "%s/reference.pfm", cfg.out);
        if (vct_image_write_pfm(&ref, ref_path, &err))
            bench_die(&err);
        fprintf(stderr, "reference: %.1f s\n", r.wall_ms / 1e3);
        cfg.reference = ref_path;
    }
    run runs[MAX_RUNS];
    memset(runs, 0, sizeof runs);
    int n = 0;
    {
        const request q = {RQ_RAYCAST, 0, 0, PM_PROGRESSIVE, 0, NULL};
        vct_image im = render_row(ctx, s, &cfg, &q, &runs[n]);
        snprintf(runs[n].name, sizeof runs[n].name, "ray cast (direct only)");
        if (vct_image_compare(&im, &ref, &runs[n].m, &err))
            bench_die(&err);
        vct_image_release(&im);
        ++n;
    }
    for (uint32_t spp = 1; spp <= cfg.max_spp && n < MAX_RUNS; spp *= 2) {
        const request q = {RQ_PT, spp, 1, PM_PROGRESSIVE, 0, NULL};
        vct_image im = render_row(ctx, s, &cfg, &q, &runs[n]);
        snprintf(runs[n].name, sizeof runs[n].name, "path trace %u spp", spp);
        if (vct_image_compare(&im, &ref, &runs[n].m, &err))
            bench_die(&err);
        vct_image_release(&im);
        fprintf(stderr, "%-24s %9.1f ms  NRMSE %.4f\n", runs[n].name, runs[n].total_ms,
                runs[n].m.nrmse);
        ++n;
    }
    if (cfg.whitted)
        n = whitted_rows(ctx, s, &cfg, &ref, runs, n);
    if (cfg.pm)
        n = pm_rows(ctx, s, &cfg, &ref, runs, n);
    /* The default (128^3, 9 cones, step 1, isotropic, VCT_DEFAULT_BOUNCES) and one
     * setting changed at a time. */
    enum { D = VCT_DEFAULT_BOUNCES };
    static const vct_setting vct_runs[] = {
        {64, 9, D, 1.0f, 0, 0.0f, 0, 0, 0, 0},   {128, 9, D, 1.0f, 0, 0.0f, 0, 0, 0, 0},
        {256, 9, D, 1.0f, 0, 0.0f, 0, 0, 0, 0},  {128, 1, D, 1.0f, 0, 0.0f, 0, 0, 0, 0},
        {128, 5, D, 1.0f, 0, 0.0f, 0, 0, 0, 0},  {128, 6, D, 1.0f, 0, 0.0f, 0, 0, 0, 0},
        {128, 16, D, 1.0f, 0, 0.0f, 0, 0, 0, 0}, {128, 9, D, 0.25f, 0, 0.0f, 0, 0, 0, 0},
        {128, 9, D, 0.5f, 0, 0.0f, 0, 0, 0, 0},  {128, 9, D, 1.0f, 1, 0.0f, 0, 0, 0, 0},
        {128, 9, 1, 1.0f, 0, 0.0f, 0, 0, 0, 0},  {128, 9, 2, 1.0f, 0, 0.0f, 0, 0, 0, 0},
        {128, 9, 3, 1.0f, 0, 0.0f, 0, 0, 0, 0},  {64, 9, D, 1.0f, 0, 2.0f, 0, 0, 0, 0},
        {64, 9, D, 1.0f, 0, 8.0f, 0, 0, 0, 0},   {128, 9, D, 1.0f, 0, 2.0f, 0, 0, 0, 0},
        {128, 9, D, 1.0f, 0, 8.0f, 0, 0, 0, 0},  {128, 9, D, 1.0f, 0, 16.0f, 0, 0, 0, 0},
        {256, 9, D, 1.0f, 0, 8.0f, 0, 0, 0, 0},  {256, 9, D, 1.0f, 0, 16.0f, 0, 0, 0, 0},
        {256, 9, D, 1.0f, 0, 32.0f, 0, 0, 0, 0}, {64, 9, D, 1.0f, 0, 0.0f, 1, 0, 0, 0},
        {128, 9, D, 1.0f, 0, 0.0f, 1, 0, 0, 0},  {256, 9, D, 1.0f, 0, 0.0f, 1, 0, 0, 0},
        {128, 9, D, 1.0f, 0, 2.0f, 1, 0, 0, 0},  {128, 16, D, 1.0f, 0, 0.0f, 1, 0, 0, 0},
        {64, 9, D, 1.0f, 0, 0.0f, 0, 1, 0, 0},   {128, 9, D, 1.0f, 0, 0.0f, 0, 1, 0, 0},
        {256, 9, D, 1.0f, 0, 0.0f, 0, 1, 0, 0},  {128, 9, D, 1.0f, 0, 0.0f, 1, 1, 0, 0},
        {128, 9, D, 1.0f, 0, 0.0f, 0, 0, 1, 0},  {128, 9, 2, 1.0f, 0, 0.0f, 0, 0, 1, 0},
        {128, 9, 3, 1.0f, 0, 0.0f, 0, 0, 1, 0}};
    static const vct_setting quick_runs[] = {
        {128, 9, D, 1.0f, 0, 0.0f, 0, 0, 0, 0}, {128, 9, D, 1.0f, 0, 0.0f, 0, 1, 0, 0},
        {128, 9, D, 1.0f, 0, 0.0f, 0, 0, 0, 1}, {128, 9, D, 1.0f, 0, 0.0f, 0, 0, 1, 0},
        {128, 9, D, 1.0f, 1, 0.0f, 0, 0, 0, 0}, {128, 6, D, 1.0f, 0, 0.0f, 0, 0, 0, 0}};
    const vct_setting *list = cfg.quick ? quick_runs : vct_runs;
    const size_t listed =
        cfg.quick ? sizeof quick_runs / sizeof quick_runs[0] : sizeof vct_runs / sizeof vct_runs[0];
    for (size_t i = 0; cfg.vct && i < listed && n < MAX_RUNS; ++i) {
        const request q = {RQ_VCT, 0, 0, PM_PROGRESSIVE, 0, &list[i]};
        vct_image im = render_row(ctx, s, &cfg, &q, &runs[n]);
        if (vct_image_compare(&im, &ref, &runs[n].m, &err))
            bench_die(&err);
        vct_image_release(&im);
        fprintf(stderr, "%-48s %9.1f ms  NRMSE %.4f\n", runs[n].name, runs[n].total_ms,
                runs[n].m.nrmse);
        ++n;
    }
    retime_rows(ctx, s, &cfg, runs, n);
    mark_pareto(runs, n);
    write_outputs(&cfg, runs, n, ctx->info.name);
    printf("wrote %s/accuracy.csv, accuracy.md, accuracy.png\n", cfg.out);
    vct_image_release(&ref);
    vct_context_release(ctx);
    vct_scene_release(s);
    return 0;
}
