/* Build time and rays per second of the triangle grid and the BVH, beside
 * Embree (its BVH build, rtcIntersect1 / rtcOccluded1 on as many threads as
 * the OpenCL device has compute units), on the same rays in the same run:
 * primary rays, shadow rays to the light, and diffuse bounce rays (cosine
 * directions from the primary hits: incoherent), on the 102k-triangle heavy
 * scene and on a dense ball in a large room (seed 000's "ball in a
 * stadium"). Ratios are times measured in this run. */
#include <math.h>
#include <pthread.h>

#include "accel/accel.h"
#include "bench_util.h"
#include "heavy_scene.h"

#ifdef VCT_WITH_EMBREE
#include <embree3/rtcore.h>
#endif

#define SIDE 1024
#define MAX_STRUCTS 3

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

/* One run on `threads` threads, wall time. */
static double embree_trace(RTCScene scene, const ray_set *r, int occluded, int threads,
                           uint32_t *hits) {
    pthread_t tid[64];
    embree_job jobs[64];
    const double t0 = vct_now_ms();
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
    return vct_now_ms() - t0;
}
#endif

/* Cosine-distributed directions about each primary hit's normal, turned
 * towards the camera side; misses get an empty ray. */
static ray_set diffuse_rays(const vct_scene *s, const ray_set *prim, const vct_hit *hits) {
    ray_set r = {malloc(32ull * prim->n), prim->n};
    float extent = 0.0f;
    for (int k = 0; k < 3; ++k)
        extent = fmaxf(extent, s->bounds_max[k] - s->bounds_min[k]);
    uint64_t seed = 1;
    for (uint32_t i = 0; i < prim->n; ++i) {
        const float *p = &prim->rays[8 * i];
        float *o = &r.rays[8 * i];
        memset(o, 0, 32);
        if (!(hits[i].t >= 0))
            continue;
        const uint32_t *tr = &s->triangles[3 * hits[i].triangle];
        const float *a = &s->positions[3 * tr[0]], *b = &s->positions[3 * tr[1]],
                    *c = &s->positions[3 * tr[2]];
        float e1[3], e2[3], n[3], t[3], bt[3];
        for (int k = 0; k < 3; ++k)
            e1[k] = b[k] - a[k], e2[k] = c[k] - a[k];
        n[0] = e1[1] * e2[2] - e1[2] * e2[1];
        n[1] = e1[2] * e2[0] - e1[0] * e2[2];
        n[2] = e1[0] * e2[1] - e1[1] * e2[0];
        float len = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        const float side = n[0] * p[4] + n[1] * p[5] + n[2] * p[6] > 0 ? -1.0f : 1.0f;
        for (int k = 0; k < 3; ++k)
            n[k] *= side / len;
        /* A tangent frame and a cosine sample in it. */
        const float up[3] = {fabsf(n[0]) < 0.9f ? 1.0f : 0.0f, fabsf(n[0]) < 0.9f ? 0.0f : 1.0f,
                             0.0f};
        t[0] = up[1] * n[2] - up[2] * n[1];
        t[1] = up[2] * n[0] - up[0] * n[2];
        t[2] = up[0] * n[1] - up[1] * n[0];
        len = sqrtf(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
        for (int k = 0; k < 3; ++k)
            t[k] /= len;
        bt[0] = n[1] * t[2] - n[2] * t[1];
        bt[1] = n[2] * t[0] - n[0] * t[2];
        bt[2] = n[0] * t[1] - n[1] * t[0];
        const float u1 = check_randf(&seed), u2 = check_randf(&seed);
        const float rad = sqrtf(u1), phi = 6.2831853f * u2, z = sqrtf(fmaxf(0.0f, 1.0f - u1));
        for (int k = 0; k < 3; ++k) {
            o[k] = p[k] + p[4 + k] * hits[i].t + n[k] * 1e-4f * extent;
            o[4 + k] = rad * cosf(phi) * t[k] + rad * sinf(phi) * bt[k] + z * n[k];
        }
        o[7] = INFINITY;
    }
    return r;
}

/* One run: device time of the trace stage. */
static double trace_once(vct_context *ctx, const vct_accel *a, const ray_set *r, int any,
                         vct_hit *hits) {
    vct_error err = {0};
    vct_stats_reset(ctx);
    if (vct_trace_rays(ctx, a, r->rays, r->n, any, hits, &err))
        bench_die(&err);
    return stage_device_ms(ctx, any ? "trace rays (any hit)" : "trace rays");
}

/* Best of the repeats: device time of the build stage and wall time. */
static vct_accel *build_best(vct_context *ctx, const vct_scene *s, const vct_accel_options *o,
                             double *device_ms, double *wall_ms) {
    vct_error err = {0};
    vct_accel *a = NULL;
    *device_ms = *wall_ms = 1e30;
    for (int i = 0; i < bench_repeats(); ++i) {
        vct_accel_release(a);
        vct_stats_reset(ctx);
        const double t0 = vct_now_ms();
        a = vct_accel_build(ctx, s, o, &err);
        const double wall = vct_now_ms() - t0;
        if (!a)
            bench_die(&err);
        const double dev =
            stage_device_ms(ctx, o->kind == VCT_ACCEL_BVH ? "bvh build" : "grid build");
        *device_ms = dev < *device_ms ? dev : *device_ms;
        *wall_ms = wall < *wall_ms ? wall : *wall_ms;
    }
    return a;
}

/* A dense ball (icosphere, 81,920 triangles, 1 wide) in a closed room 100
 * wide, the camera and light inside the room. */
static vct_scene *ball_room_scene(vct_error *err) {
    const float centre[3] = {3.0f, 1.0f, -2.0f}, L = 50.0f;
    test_mesh ball = mesh_icosphere(6, 0.5f, centre);
    const float walls[6][12] = {
        {-L, -L, -L, L, -L, -L, L, -L, L, -L, -L, L}, {-L, L, -L, -L, L, L, L, L, L, L, L, -L},
        {-L, -L, -L, -L, -L, L, -L, L, L, -L, L, -L}, {L, -L, -L, L, L, -L, L, L, L, L, -L, L},
        {-L, -L, -L, -L, L, -L, L, L, -L, L, -L, -L}, {-L, -L, L, L, -L, L, L, L, L, -L, L, L}};
    test_mesh room = mesh_quads(&walls[0][0], 6);
    const uint32_t nv = ball.nv + room.nv, nt = ball.nt + room.nt;
    float *pos = malloc(12ull * nv);
    uint32_t *tri = malloc(12ull * nt), *mat = calloc(nt, 4);
    memcpy(pos, ball.pos, 12ull * ball.nv);
    memcpy(pos + 3 * ball.nv, room.pos, 12ull * room.nv);
    memcpy(tri, ball.tri, 12ull * ball.nt);
    for (uint32_t i = 0; i < 3 * room.nt; ++i)
        tri[3 * ball.nt + i] = room.tri[i] + ball.nv;
    vct_scene *s = vct_scene_from_arrays(pos, nv, tri, nt, mat, NULL, 0, err);
    if (s) {
        const vct_camera cam = {{3.0f, 2.0f, 2.0f}, {3.0f, 1.0f, -2.0f}, {0, 1, 0}, 30.0f};
        s->camera = cam;
        vct_light light = {0};
        light.type = VCT_LIGHT_POINT;
        light.position[0] = -10.0f, light.position[1] = 30.0f, light.position[2] = 10.0f;
        light.color[0] = light.color[1] = light.color[2] = 1000.0f;
        if (vct_scene_add_light(s, &light, err) != VCT_OK) {
            vct_scene_release(s);
            s = NULL;
        }
    }
    free(pos), free(tri), free(mat);
    mesh_free(&ball);
    mesh_free(&room);
    return s;
}

static void bench_scene(vct_context *ctx, const vct_scene *s, const char *name, int threads) {
    printf("\n### %s: %u triangles, %dx%d rays\n\n", name, s->triangle_count, SIDE, SIDE);
    /* The grid, the linear BVH and the clustered BVH (the default). */
    const vct_accel_options kinds[MAX_STRUCTS] = {
        {VCT_ACCEL_GRID, {0, 0, 0}, VCT_BVH_PLOC, VCT_BVH_LEVELS_AUTO},
        {VCT_ACCEL_BVH, {0, 0, 0}, VCT_BVH_LINEAR, VCT_BVH_LEVELS_AUTO},
        {VCT_ACCEL_BVH, {0, 0, 0}, VCT_BVH_PLOC, VCT_BVH_LEVELS_AUTO}};
    vct_accel *acc[MAX_STRUCTS];
    double build_dev[MAX_STRUCTS], build_wall[MAX_STRUCTS];
    for (int i = 0; i < MAX_STRUCTS; ++i)
        acc[i] = build_best(ctx, s, &kinds[i], &build_dev[i], &build_wall[i]);
    vct_error err = {0};
    vct_accel_info info;
    for (int i = 1; i < MAX_STRUCTS; ++i) {
        if (vct_accel_info_get(ctx, acc[i], &info, &err))
            bench_die(&err);
        printf("bvh (%s): %u nodes, %u leaves, %u levels, %u passes, SAH cost %.2f, %.1f MiB\n",
               i == 1 ? "linear" : "clustered", info.nodes, info.leaves, info.depth, info.passes,
               info.sah_cost, info.bytes / 1048576.0);
    }
    if (vct_accel_info_get(ctx, acc[0], &info, &err))
        bench_die(&err);
    printf("grid: %ux%ux%u cells, %u references, %.1f MiB\n", info.grid.res[0], info.grid.res[1],
           info.grid.res[2], info.grid.references, info.bytes / 1048576.0);

    ray_set sets[3];
    sets[0] = primary_rays(s);
    vct_hit *hits = malloc(sizeof *hits * sets[0].n), *scratch = malloc(sizeof *hits * sets[0].n);
    double ms[MAX_STRUCTS][3];
    ms[2][0] = trace_once(ctx, acc[2], &sets[0], 0, hits);
    sets[1] = shadow_rays(s, &sets[0], hits);
    sets[2] = diffuse_rays(s, &sets[0], hits);
    double e_ms[3] = {0, 0, 0}, e_build = 0;
    uint32_t e_counts[3] = {0, 0, 0};
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
    e_build = vct_now_ms() - t0;
#else
    (void)threads;
#endif
    uint32_t counts[MAX_STRUCTS][3] = {{0}};
    /* VCT_BENCH_NO_GRID=1 leaves the grid out (its worst case takes minutes). */
    const int first = getenv("VCT_BENCH_NO_GRID") ? 1 : 0;
    for (int i = 0; i < MAX_STRUCTS; ++i)
        for (int r = 0; r < 3; ++r)
            ms[i][r] = 1e30;
    for (int r = 0; r < 3; ++r)
        e_ms[r] = 1e30;
    /* Rounds: every structure and Embree once per round, best of the rounds,
     * so that a slow spell of the machine touches all of them alike. */
    for (int round = 0; round < bench_repeats(); ++round)
        for (int r = 0; r < 3; ++r) {
            for (int i = first; i < MAX_STRUCTS; ++i) {
                if (i == 0 && round > 0 && ms[0][r] > 10000.0)
                    continue; /* the grid's worst case: one run says enough */
                const double t = trace_once(ctx, acc[i], &sets[r], r == 1, scratch);
                ms[i][r] = t < ms[i][r] ? t : ms[i][r];
                counts[i][r] = 0;
                for (uint32_t j = 0; j < sets[r].n; ++j)
                    counts[i][r] += scratch[j].t >= 0;
            }
#ifdef VCT_WITH_EMBREE
            const double t = embree_trace(scene, &sets[r], r == 1, threads, &e_counts[r]);
            e_ms[r] = t < e_ms[r] ? t : e_ms[r];
#endif
        }
#ifdef VCT_WITH_EMBREE
    rtcReleaseScene(scene);
    rtcReleaseDevice(dev);
#endif
    const char *rows[3] = {"primary", "shadow", "diffuse bounce"};
    printf(
        "\n| | grid | bvh, linear | bvh, clustered | Embree 3 (%d threads) | bvh / Embree rays/s "
        "| bvh / grid rays/s |\n",
        threads);
    printf("|---|---:|---:|---:|---:|---:|---:|\n");
    printf("| build (ms, wall) | %.1f | %.1f | %.1f | %.1f | %.2f (time) | %.2f (time) |\n",
           build_wall[0], build_wall[1], build_wall[2], e_build,
           e_build > 0 ? build_wall[2] / e_build : 0.0, build_wall[2] / build_wall[0]);
    printf("| build (ms, device) | %.1f | %.1f | %.1f | - | - | - |\n", build_dev[0], build_dev[1],
           build_dev[2]);
    for (int r = 0; r < 3; ++r)
        printf("| %s (M rays/s) | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f |\n", rows[r],
               sets[r].n / ms[0][r] / 1e3, sets[r].n / ms[1][r] / 1e3, sets[r].n / ms[2][r] / 1e3,
               e_ms[r] > 0 ? sets[r].n / e_ms[r] / 1e3 : 0.0,
               e_ms[r] > 0 ? e_ms[r] / ms[2][r] : 0.0, ms[0][r] / ms[2][r]);
    printf("\nhits (grid, linear, clustered, Embree): primary %u %u %u %u; occluded %u %u %u %u; "
           "diffuse %u %u %u %u\n",
           counts[0][0], counts[1][0], counts[2][0], e_counts[0], counts[0][1], counts[1][1],
           counts[2][1], e_counts[1], counts[0][2], counts[1][2], counts[2][2], e_counts[2]);
    for (int r = 0; r < 3; ++r)
        free(sets[r].rays);
    free(hits);
    free(scratch);
    for (int i = 0; i < MAX_STRUCTS; ++i)
        vct_accel_release(acc[i]);
}

int main(void) {
    vct_error err = {0};
    const char *src = getenv("VCT_SOURCE_DIR");
    vct_scene *heavy = heavy_scene_load(src ? src : ".", &err);
    vct_scene *ball = heavy ? ball_room_scene(&err) : NULL;
    if (!ball)
        bench_die(&err);
    vct_context *ctx = vct_context_create(NULL, &err);
    if (!ctx)
        bench_die(&err);
    const int threads = (int)ctx->info.compute_units;
    printf("device: %s, %d compute units\n", ctx->info.name, threads);
    bench_scene(ctx, heavy, "heavy scene (Cornell box and 80 spheres)", threads);
    bench_scene(ctx, ball, "dense ball in a large room", threads);
    vct_context_release(ctx);
    vct_scene_release(heavy);
    vct_scene_release(ball);
    return 0;
}
