/* Grid build time and primary / shadow rays per second on a 100k+ triangle
 * scene, beside Embree (BVH build, rtcIntersect1 / rtcOccluded1 on as many
 * threads as the OpenCL device has compute units) on the same rays in the
 * same run. */
#include <math.h>
#include <pthread.h>

#include "accel/grid.h"
#include "bench_util.h"
#include "heavy_scene.h"

#ifdef VCT_WITH_EMBREE
#include <embree3/rtcore.h>
#endif

#define SIDE 1024

typedef struct ray_set {
    float *rays; /* 8 floats per ray */
    uint32_t n;
} ray_set;

static ray_set primary_rays(const vct_scene *s) {
    ray_set r = {malloc(32ull * SIDE * SIDE), SIDE * SIDE};
    const vct_camera *c = &s->camera;
    float f[3], right[3], up[3];
    for (int k = 0; k < 3; ++k)
        f[k] = c->look_at[k] - c->position[k];
    float fl = sqrtf(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (int k = 0; k < 3; ++k)
        f[k] /= fl;
    right[0] = f[1] * c->up[2] - f[2] * c->up[1];
    right[1] = f[2] * c->up[0] - f[0] * c->up[2];
    right[2] = f[0] * c->up[1] - f[1] * c->up[0];
    float rl = sqrtf(right[0] * right[0] + right[1] * right[1] + right[2] * right[2]);
    for (int k = 0; k < 3; ++k)
        right[k] /= rl;
    up[0] = right[1] * f[2] - right[2] * f[1];
    up[1] = right[2] * f[0] - right[0] * f[2];
    up[2] = right[0] * f[1] - right[1] * f[0];
    float th = tanf(c->fov_y_deg * 3.14159265f / 360.0f);
    for (uint32_t y = 0; y < SIDE; ++y)
        for (uint32_t x = 0; x < SIDE; ++x) {
            float sx = (2.0f * (x + 0.5f) / SIDE - 1.0f) * th;
            float sy = (1.0f - 2.0f * (y + 0.5f) / SIDE) * th;
            float *ray = &r.rays[8 * ((size_t)y * SIDE + x)];
            float d[3], len = 0;
            for (int k = 0; k < 3; ++k) {
                d[k] = f[k] + sx * right[k] + sy * up[k];
                len += d[k] * d[k];
            }
            len = sqrtf(len);
            for (int k = 0; k < 3; ++k) {
                ray[k] = c->position[k];
                ray[4 + k] = d[k] / len;
            }
            ray[3] = 0.0f;
            ray[7] = INFINITY;
        }
    return r;
}

/* From each primary hit towards the first light (misses get an empty ray). */
static ray_set shadow_rays(const vct_scene *s, const ray_set *prim, const vct_hit *hits) {
    ray_set r = {malloc(32ull * prim->n), prim->n};
    const float *L = s->lights[0].position;
    for (uint32_t i = 0; i < prim->n; ++i) {
        const float *p = &prim->rays[8 * i];
        float *o = &r.rays[8 * i];
        float t = hits[i].t > 0 ? hits[i].t : 0.0f, d[3], len = 0;
        for (int k = 0; k < 3; ++k) {
            o[k] = p[k] + p[4 + k] * t * 0.9999f;
            d[k] = L[k] - o[k];
            len += d[k] * d[k];
        }
        len = sqrtf(len);
        for (int k = 0; k < 3; ++k)
            o[4 + k] = d[k] / len;
        o[3] = 0.0f;
        o[7] = hits[i].t > 0 ? len * 0.9999f : 0.0f;
    }
    return r;
}

static double trace_best(vct_context *ctx, vct_grid *g, const ray_set *r, int any, vct_hit *hits) {
    double best = 1e30;
    vct_error err = {0};
    for (int i = 0; i < bench_repeats(); ++i) {
        vct_stats_reset(ctx);
        if (vct_trace_rays(ctx, g, r->rays, r->n, any, hits, &err))
            bench_die(&err);
        double ms = stage_device_ms(ctx, any ? "trace rays (any hit)" : "trace rays");
        best = ms < best ? ms : best;
    }
    return best;
}

#ifdef VCT_WITH_EMBREE
typedef struct embree_job {
    RTCScene scene;
    const ray_set *rays;
    uint32_t begin, end;
    int occluded;
    uint32_t hits;
} embree_job;

static void *embree_worker(void *arg) {
    embree_job *j = arg;
    struct RTCIntersectContext ictx;
    rtcInitIntersectContext(&ictx);
    for (uint32_t i = j->begin; i < j->end; ++i) {
        const float *r = &j->rays->rays[8 * i];
        struct RTCRayHit rh;
        rh.ray.org_x = r[0], rh.ray.org_y = r[1], rh.ray.org_z = r[2], rh.ray.tnear = r[3];
        rh.ray.dir_x = r[4], rh.ray.dir_y = r[5], rh.ray.dir_z = r[6], rh.ray.tfar = r[7];
        rh.ray.mask = 0xffffffffu, rh.ray.flags = 0, rh.ray.time = 0;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        if (j->occluded) {
            rtcOccluded1(j->scene, &ictx, &rh.ray);
            j->hits += rh.ray.tfar < 0;
        } else {
            rtcIntersect1(j->scene, &ictx, &rh);
            j->hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
        }
    }
    return NULL;
}

static double embree_trace(RTCScene scene, const ray_set *r, int occluded, int threads,
                           uint32_t *hits) {
    double best = 1e30;
    for (int rep = 0; rep < bench_repeats(); ++rep) {
        pthread_t tid[64];
        embree_job jobs[64];
        double t0 = vct_now_ms();
        for (int i = 0; i < threads; ++i) {
            jobs[i] = (embree_job){scene,
                                   r,
                                   (uint32_t)((uint64_t)r->n * i / threads),
                                   (uint32_t)((uint64_t)r->n * (i + 1) / threads),
                                   occluded,
                                   0};
            pthread_create(&tid[i], NULL, embree_worker, &jobs[i]);
        }
        *hits = 0;
        for (int i = 0; i < threads; ++i) {
            pthread_join(tid[i], NULL);
            *hits += jobs[i].hits;
        }
        double ms = vct_now_ms() - t0;
        best = ms < best ? ms : best;
    }
    return best;
}
#endif

int main(void) {
    vct_error err = {0};
    const char *src = getenv("VCT_SOURCE_DIR");
    vct_scene *s = heavy_scene_load(src ? src : ".", &err);
    if (!s)
        bench_die(&err);
    vct_context *ctx = vct_context_create(NULL, &err);
    if (!ctx)
        bench_die(&err);
    const int threads = (int)ctx->info.compute_units;
    printf("scene: %u triangles; device: %s, %d compute units; %dx%d rays\n\n", s->triangle_count,
           ctx->info.name, threads, SIDE, SIDE);

    /* VCT_GRID_RES=N overrides the automatic resolution (for sweeps). */
    uint32_t res[3] = {0, 0, 0};
    if (getenv("VCT_GRID_RES"))
        res[0] = res[1] = res[2] = (uint32_t)atoi(getenv("VCT_GRID_RES"));
    vct_grid *g = NULL;
    double build_dev = 1e30, build_host = 1e30;
    for (int i = 0; i < bench_repeats(); ++i) {
        vct_grid_free(g);
        vct_stats_reset(ctx);
        double t0 = vct_now_ms();
        g = vct_grid_build(ctx, s, res, &err);
        double host = vct_now_ms() - t0;
        if (!g)
            bench_die(&err);
        double dev = stage_device_ms(ctx, "grid build");
        build_dev = dev < build_dev ? dev : build_dev;
        build_host = host < build_host ? host : build_host;
    }
    printf("grid %ux%ux%u, %u references: build %.1f ms device time, %.1f ms wall\n", g->res[0],
           g->res[1], g->res[2], g->references, build_dev, build_host);

    ray_set prim = primary_rays(s);
    vct_hit *hits = malloc(sizeof *hits * prim.n), *shadow_hits = malloc(sizeof *hits * prim.n);
    double prim_ms = trace_best(ctx, g, &prim, 0, hits);
    ray_set shadow = shadow_rays(s, &prim, hits);
    double shadow_ms = trace_best(ctx, g, &shadow, 1, shadow_hits);
    uint32_t prim_hits = 0, occluded = 0;
    for (uint32_t i = 0; i < prim.n; ++i) {
        prim_hits += hits[i].t >= 0;
        occluded += shadow_hits[i].t >= 0;
    }
    printf("\n| | vct grid (OpenCL) | Embree 3 (%d threads) | vct / Embree time |\n", threads);
    printf("|---|---:|---:|---:|\n");
#ifdef VCT_WITH_EMBREE
    char cfg[32];
    snprintf(cfg, sizeof cfg, "threads=%d", threads);
    RTCDevice dev = rtcNewDevice(cfg);
    double t0 = vct_now_ms();
    RTCScene scene = rtcNewScene(dev);
    RTCGeometry geom = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
    float *vb = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 12,
                                        s->vertex_count);
    unsigned *ib = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 12,
                                           s->triangle_count);
    memcpy(vb, s->positions, 12ull * s->vertex_count);
    memcpy(ib, s->triangles, 12ull * s->triangle_count);
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
    rtcCommitScene(scene);
    double embree_build = vct_now_ms() - t0;
    uint32_t e_hits = 0, e_occ = 0;
    double e_prim = embree_trace(scene, &prim, 0, threads, &e_hits);
    double e_shadow = embree_trace(scene, &shadow, 1, threads, &e_occ);
    printf("| acceleration structure build (ms) | %.1f | %.1f | %.2f |\n", build_dev, embree_build,
           build_dev / embree_build);
    printf("| primary rays (M rays/s) | %.2f | %.2f | %.2f |\n", prim.n / prim_ms / 1e3,
           prim.n / e_prim / 1e3, prim_ms / e_prim);
    printf("| shadow rays (M rays/s) | %.2f | %.2f | %.2f |\n", shadow.n / shadow_ms / 1e3,
           shadow.n / e_shadow / 1e3, shadow_ms / e_shadow);
    printf("\nhits: vct %u, Embree %u; occluded: vct %u, Embree %u\n", prim_hits, e_hits, occluded,
           e_occ);
    rtcReleaseScene(scene);
    rtcReleaseDevice(dev);
#else
    printf("| grid build (ms) | %.1f | - | - |\n", build_dev);
    printf("| primary rays (M rays/s) | %.2f | - | - |\n", prim.n / prim_ms / 1e3);
    printf("| shadow rays (M rays/s) | %.2f | - | - |\n", shadow.n / shadow_ms / 1e3);
    printf("\nhits %u, occluded %u\n", prim_hits, occluded);
#endif
    free(prim.rays);
    free(shadow.rays);
    free(hits);
    free(shadow_hits);
    vct_grid_free(g);
    vct_context_destroy(ctx);
    vct_scene_free(s);
    return 0;
}
