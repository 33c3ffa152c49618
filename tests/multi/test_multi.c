/* Several devices render one frame (PoCL exposing two: POCL_DEVICES="pthread
 * pthread", one thread each). Every method's image equals one device's, bit
 * for bit: with equal shares, with the shares a slowed device earns, and
 * with a device that fails mid-frame. Device lists are read as written and
 * refused with the devices there are. */
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "multi/balance.h"
#include "multi/group.h"
#include "multi/pass_sync.h"
#include "runtime/runtime.h"

#define WIDTH 40
#define HEIGHT 37 /* neither a multiple of the subsampling nor even */

typedef struct method_case {
    const char *name;
    vct_method method;
    uint32_t subsample;
    int sparse;
    float contrast;
} method_case;

static const method_case cases[] = {
    {"raycast", VCT_METHOD_RAYCAST, 0, 0, 0.0f},
    {"raycast, subsample 4", VCT_METHOD_RAYCAST, 4, 0, 0.0f},
    {"whitted", VCT_METHOD_WHITTED, 0, 0, 0.0f},
    {"whitted, subsample 8", VCT_METHOD_WHITTED, 8, 0, 0.0f},
    {"vct", VCT_METHOD_VCT, 0, 0, 0.0f},
    {"vct, sparse diffuse", VCT_METHOD_VCT, 0, 1, 0.0f},
    {"pt", VCT_METHOD_PATHTRACE, 0, 0, 0.0f},
    {"voxels", VCT_METHOD_VOXELS, 0, 0, 0.0f},
    {"pm", VCT_METHOD_PM, 0, 0, 0.0f},
    {"whitted, subsample 8, contrast 0.05", VCT_METHOD_WHITTED, 8, 0, 0.05f},
};
#define CASES (int)(sizeof cases / sizeof *cases)

static vct_plan plan;

static vct_group_build build_options(const vct_scene *s) {
    vct_group_build b;
    memset(&b, 0, sizeof b);
    b.accel.kind = VCT_ACCEL_BVH;
    vct_plan_make(s, NULL, &plan);
    b.plan = &plan;
    b.voxel.resolution = 32;
    b.bricks = (vct_brick_options){VCT_BRICKS_AUTO, 0, 0}; /* isotropic, the default */
    b.bounces = 1;
    b.cones = vct_vct_options_default(512, 512).cones;
    return b;
}

static vct_render_job job_of(const method_case *c, const vct_scene *s) {
    vct_render_job job = vct_render_job_default(c->method, WIDTH, HEIGHT);
    job.scene = s;
    job.pathtrace.spp = 16;
    job.pathtrace.seed = 5;
    job.pm.passes = 3;
    job.pm.photons_per_pass = 20000;
    job.raycast.subsample = job.whitted.subsample = c->subsample;
    job.whitted.subsample_contrast = c->contrast;
    job.vct.sparse_diffuse = c->sparse;
    job.voxel_view.level = 4;
    return job;
}

/* One device's image: a group of one, built as a single context would. */
static vct_image single(const method_case *c, const vct_scene *s) {
    vct_error err = {0};
    vct_context *ctx = vct_context_create("0", &err);
    REQUIRE_OK(ctx ? VCT_OK : err.status, err);
    const vct_group_build b = build_options(s);
    vct_accel *a = vct_accel_build(ctx, s, &b.accel, &err);
    REQUIRE_OK(a ? VCT_OK : err.status, err);
    vct_voxels *v = NULL;
    REQUIRE_OK(
        vct_vct_prepare(ctx, s, a, b.plan, &b.voxel, &b.bricks, b.bounces, &b.cones, &v, &err),
        err);
    vct_render_job job = job_of(c, s);
    job.accel = a;
    job.voxels = v;
    vct_image im;
    REQUIRE_OK(vct_render(ctx, &job, &im, NULL, &err), err);
    vct_voxels_release(v);
    vct_accel_release(a);
    vct_context_release(ctx);
    return im;
}

/* Mean radiance over red, green and blue (alpha is 1 everywhere). */
static double mean(const vct_image *a) {
    double sum = 0.0;
    for (size_t i = 0; i < (size_t)a->width * a->height * 4; ++i)
        sum += i % 4 == 3 ? 0.0 : a->rgba[i];
    return sum / ((double)a->width * a->height * 3);
}

static vct_group *group_for(const vct_scene *s) {
    vct_error err = {0};
    vct_group *g = vct_group_create("0,1", &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    const vct_group_build b = build_options(s);
    REQUIRE_OK(vct_group_prepare(g, s, &b, &err), err);
    return g;
}

/* The path tracer's per-pixel variance and indirect light (the denoiser's
 * guides) from the devices' summed samples: one device's, bit for bit. */
static void check_variance(const vct_scene *s) {
    const method_case *c = &cases[6]; /* pt */
    vct_error err = {0};
    vct_context *ctx = vct_context_create("0", &err);
    REQUIRE_OK(ctx ? VCT_OK : err.status, err);
    vct_accel *a = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(a ? VCT_OK : err.status, err);
    vct_render_job job = job_of(c, s);
    vct_image one, one_var, one_ind, both, both_var, both_ind;
    job.accel = a;
    job.pathtrace.variance = &one_var;
    job.pathtrace.indirect = &one_ind;
    REQUIRE_OK(vct_render(ctx, &job, &one, NULL, &err), err);
    vct_group *g = group_for(s);
    job.accel = NULL;
    job.pathtrace.variance = &both_var;
    job.pathtrace.indirect = &both_ind;
    REQUIRE_OK(vct_group_render(g, &job, &both, NULL, &err), err);
    const size_t diff = check_differing(&one_var, &both_var);
    CHECK(diff == 0 && mean(&one_var) > 0.0,
          "pt variance on two devices: %zu values differ from one device's (mean %g)", diff,
          mean(&one_var));
    const size_t diff_ind = check_differing(&one_ind, &both_ind);
    CHECK(diff_ind == 0 && mean(&one_ind) > 0.0,
          "pt indirect light on two devices: %zu values differ from one device's (mean %g)",
          diff_ind, mean(&one_ind));
    vct_image *all[] = {&one, &one_var, &one_ind, &both, &both_var, &both_ind};
    for (int i = 0; i < 6; ++i)
        vct_image_release(all[i]);
    vct_group_release(g);
    vct_accel_release(a);
    vct_context_release(ctx);
}

static void check_lists(void) {
    vct_error err = {0};
    vct_group *g = vct_group_create("all", &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    CHECK(vct_group_size(g) == 2, "\"all\": %d devices, expected the 2 PoCL exposes",
          vct_group_size(g));
    vct_group_release(g);
    g = vct_group_create("1", &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    const vct_group_device *d;
    CHECK(vct_group_devices(g, &d) == 1 && d[0].info.index == 1, "\"1\" is device 1 alone");
    vct_group_release(g);
    const char *bad[] = {"0,0", "0,7", "gpu", "0,,nothing-like-this"};
    const char *why[] = {"named twice", "no device \"7\"", "no device is a GPU", "no device"};
    for (int i = 0; i < 4; ++i) {
        memset(&err, 0, sizeof err);
        g = vct_group_create(bad[i], &err);
        CHECK(!g && strstr(err.message, why[i]) && strstr(err.message, "the devices are: [0]"),
              "list \"%s\" refused with the devices there are: %s", bad[i], err.message);
        vct_group_release(g);
    }
}

/* Every method on two devices equals one device, over several frames while
 * the shares move. */
static void check_methods(const char *scene_name, const vct_scene *s) {
    vct_group *g = group_for(s);
    for (int m = 0; m < CASES; ++m) {
        const method_case *c = &cases[m];
        vct_image one = single(c, s);
        for (int frame = 0; frame < 2; ++frame) {
            vct_render_job job = job_of(c, s);
            vct_image two;
            vct_render_result result;
            vct_error err = {0};
            uint64_t scene_bytes[2];
            for (int i = 0; i < 2; ++i) {
                vct_device_scene_stats st;
                vct_device_scene_stats_get(g->ds[i], &st);
                scene_bytes[i] = st.scene_bytes;
            }
            REQUIRE_OK(vct_group_render(g, &job, &two, &result, &err), err);
            for (int i = 0; frame == 1 && i < 2; ++i) {
                vct_device_scene_stats st;
                vct_device_scene_stats_get(g->ds[i], &st);
                CHECK(st.scene_bytes == scene_bytes[i],
                      "%s, %s: device %d uploaded %llu bytes of scene data for a second frame",
                      scene_name, c->name, i,
                      (unsigned long long)(st.scene_bytes - scene_bytes[i]));
            }
            const size_t d = check_differing(&one, &two);
            CHECK(d == 0, "%s, %s, frame %d: %zu values differ between 1 and 2 devices", scene_name,
                  c->name, frame, d);
            CHECK(mean(&one) > 0.0, "%s, %s: a black image proves nothing", scene_name, c->name);
            vct_image_release(&two);
        }
        const vct_group_device *dev;
        vct_group_devices(g, &dev);
        printf("%s, %s: identical on 2 devices; work %.0f + %.0f, shares %.2f/%.2f\n", scene_name,
               c->name, dev[0].last_work, dev[1].last_work, dev[0].share, dev[1].share);
        vct_image_release(&one);
    }
    vct_group_release(g);
}

/* A moved light: preparing the group again relights every device's voxels
 * and keeps their BVHs (each device holds a device scene); the frame equals
 * one device's render of the moved scene, and so does a resumed path trace
 * (the running sums of the scene before are dropped). */
static void check_moved_light(vct_scene *s) {
    int vct_case = 0;
    while (cases[vct_case].method != VCT_METHOD_VCT)
        ++vct_case;
    const method_case *c = &cases[vct_case];
    int pt_case = 0;
    while (cases[pt_case].method != VCT_METHOD_PATHTRACE)
        ++pt_case;
    vct_group *g = group_for(s);
    vct_error err = {0};
    vct_render_job pt_job = job_of(&cases[pt_case], s);
    vct_image pt_before;
    REQUIRE_OK(vct_group_render(g, &pt_job, &pt_before, NULL, &err), err);
    vct_image_release(&pt_before);
    vct_device_scene_stats before[2], after[2];
    for (int i = 0; i < 2; ++i)
        vct_device_scene_stats_get(g->ds[i], &before[i]);
    s->lights[0].position[0] += 0.25f;
    const vct_group_build b = build_options(s);
    REQUIRE_OK(vct_group_prepare(g, s, &b, &err), err);
    vct_render_job job = job_of(c, s);
    vct_image two, one = single(c, s);
    REQUIRE_OK(vct_group_render(g, &job, &two, NULL, &err), err);
    for (int i = 0; i < 2; ++i) {
        vct_device_scene_stats_get(g->ds[i], &after[i]);
        CHECK(after[i].accel_builds == before[i].accel_builds &&
                  after[i].voxel_builds == before[i].voxel_builds &&
                  after[i].light_builds == before[i].light_builds + 1,
              "a moved light, device %d: %u BVH, %u voxel and %u light builds (expected 0, 0, 1)",
              i, after[i].accel_builds - before[i].accel_builds,
              after[i].voxel_builds - before[i].voxel_builds,
              after[i].light_builds - before[i].light_builds);
    }
    CHECK(check_differing(&one, &two) == 0, "a moved light: %zu values differ from one device's",
          check_differing(&one, &two));
    /* the path tracer resumed after the change starts over, on every device */
    pt_job.pathtrace.resume = 1;
    vct_image pt_two, pt_one = single(&cases[pt_case], s);
    REQUIRE_OK(vct_group_render(g, &pt_job, &pt_two, NULL, &err), err);
    CHECK(check_differing(&pt_one, &pt_two) == 0,
          "a moved light, the path tracer resumed: %zu values differ from a fresh render",
          check_differing(&pt_one, &pt_two));
    vct_image_release(&pt_one);
    vct_image_release(&pt_two);
    printf("a moved light on 2 devices: voxels relit, BVHs kept, the image one device's; the "
           "path tracer resumed starts over\n");
    s->lights[0].position[0] -= 0.25f;
    vct_image_release(&one);
    vct_image_release(&two);
    vct_group_release(g);
}

/* Fixed splits, the smallest bands included: every row method's image is
 * one device's whatever the shares (photon mapping's bands agree on their
 * grids pass by pass). */
static void check_fixed_splits(const vct_scene *s) {
    const char *splits[] = {"0.95,0.05", "0.05,0.95", "0.5,0.5", "0.7,0.3"};
    vct_group *g = group_for(s);
    for (int m = 0; m < CASES; ++m) {
        const method_case *c = &cases[m];
        if (c->method == VCT_METHOD_PATHTRACE)
            continue; /* split by samples, not rows */
        vct_image one = single(c, s);
        for (int k = 0; k < 4; ++k) {
            setenv("VCT_GROUP_SHARES", splits[k], 1);
            vct_render_job job = job_of(c, s);
            vct_image two;
            vct_error err = {0};
            REQUIRE_OK(vct_group_render(g, &job, &two, NULL, &err), err);
            const vct_group_device *dev;
            vct_group_devices(g, &dev);
            CHECK(check_differing(&one, &two) == 0,
                  "%s, shares %s (rows %.0f + %.0f): the image differs", c->name, splits[k],
                  dev[0].last_work, dev[1].last_work);
            vct_image_release(&two);
        }
        unsetenv("VCT_GROUP_SHARES");
        vct_image_release(&one);
    }
    vct_group_release(g);
}

/* Device 1 made 4x slower: its share of rows falls towards 1/5 and the
 * image stays the same. */
static void check_slowed(const vct_scene *s) {
    const method_case *c = &cases[2]; /* whitted */
    vct_image one = single(c, s);
    vct_group *g = group_for(s);
    setenv("VCT_SLOW_LAUNCH", "1:4", 1);
    const vct_group_device *dev;
    vct_group_devices(g, &dev);
    double shares[8];
    for (int frame = 0; frame < 8; ++frame) {
        vct_render_job job = job_of(c, s);
        job.width = job.height = 256; /* work enough to measure */
        vct_image two;
        vct_error err = {0};
        REQUIRE_OK(vct_group_render(g, &job, &two, NULL, &err), err);
        vct_image_release(&two);
        shares[frame] = dev[1].share;
        printf("slowed device: frame %d, share %.3f (%.1f ms for %.0f rows; device 0 %.1f ms "
               "for %.0f)\n",
               frame, dev[1].share, dev[1].last_ms, dev[1].last_work, dev[0].last_ms,
               dev[0].last_work);
    }
    /* Measured times drive the shares, and a loaded machine (ctest -j)
     * moves them between frames (this test failed once in about a dozen
     * loaded runs, its output not kept; these are its only checks on
     * measured times). A balancer that does not balance stays at 0.5. */
    CHECK(shares[7] > 0.05 && shares[7] < 0.4,
          "the 4x slower device's share %.3f is not near the 0.2 its speed predicts", shares[7]);
    CHECK(fabs(shares[7] - shares[6]) < 0.1, "shares still moving after 8 frames: %.3f, %.3f",
          shares[6], shares[7]);
    vct_render_job job = job_of(c, s);
    vct_image two;
    vct_error err = {0};
    REQUIRE_OK(vct_group_render(g, &job, &two, NULL, &err), err);
    CHECK(check_differing(&one, &two) == 0, "uneven shares changed the image");
    unsetenv("VCT_SLOW_LAUNCH");
    vct_image_release(&two);
    vct_image_release(&one);
    vct_group_release(g);
}

/* What the group says through its log. */
static char group_said[4096];
static void group_log(void *user, const char *message) {
    (void)user;
    snprintf(group_said, sizeof group_said, "%s", message);
}

/* Device 1 fails a few launches into the frame: the other completes it,
 * unchanged, and the failure is counted once and said through the log. */
static void check_failure(const vct_scene *s, int method_index) {
    const method_case *c = &cases[method_index];
    vct_image one = single(c, s);
    vct_group *g = group_for(s);
    group_said[0] = '\0';
    vct_group_set_log(g, group_log, NULL);
    char at[32];
    snprintf(at, sizeof at, "1:%ld", vct_group_context(g, 1)->launch_count + 3);
    setenv("VCT_FAIL_LAUNCH", at, 1);
    for (int frame = 0; frame < 2; ++frame) {
        vct_render_job job = job_of(c, s);
        /* a sample a launch: the path tracer's frame holds enough launches
         * on each device for the failure to land inside it */
        job.pathtrace.samples_per_pass = 1;
        vct_image two;
        vct_error err = {0};
        REQUIRE_OK(vct_group_render(g, &job, &two, NULL, &err), err);
        CHECK(check_differing(&one, &two) == 0, "%s, frame %d: a failed device changed the image",
              c->name, frame);
        vct_image_release(&two);
    }
    unsetenv("VCT_FAIL_LAUNCH");
    const vct_group_device *dev;
    vct_group_devices(g, &dev);
    CHECK(vct_group_faults(g) == 1 && !dev[1].active && dev[0].active,
          "%s: %d failures reported, device 1 %s", c->name, vct_group_faults(g),
          dev[1].active ? "still active" : "dropped");
    CHECK(strstr(dev[1].dropped, "VCT_FAIL_LAUNCH") != NULL, "the reason names the failure: %s",
          dev[1].dropped);
    CHECK(strstr(group_said, "dropped") && strstr(group_said, "VCT_FAIL_LAUNCH"),
          "the log was told of the dropped device: \"%s\"", group_said);
    vct_image_release(&one);
    vct_group_release(g);
}

/* Voxels built once and copied: cone tracing on the copy gives the image
 * of voxels built there. */
static void check_copied_voxels(const vct_scene *s) {
    vct_error err = {0};
    vct_group *g = vct_group_create("0,1", &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    vct_group_build b = build_options(s);
    b.copy_voxels = 1;
    REQUIRE_OK(vct_group_prepare(g, s, &b, &err), err);
    const vct_group_device *dev;
    vct_group_devices(g, &dev);
    CHECK(!dev[0].voxels_copied && dev[1].voxels_copied, "device 1's voxels are device 0's copy");
    for (int m = 4; m <= 5; ++m) { /* vct, plain and sparse */
        vct_image one = single(&cases[m], s);
        setenv("VCT_GROUP_SHARES", "0.3,0.7", 1);
        vct_render_job job = job_of(&cases[m], s);
        vct_image two;
        REQUIRE_OK(vct_group_render(g, &job, &two, NULL, &err), err);
        unsetenv("VCT_GROUP_SHARES");
        CHECK(check_differing(&one, &two) == 0, "%s on copied voxels differs", cases[m].name);
        vct_image_release(&two);
        vct_image_release(&one);
    }
    printf("voxels built in %.1f ms, copied in %.1f ms\n", dev[0].voxels_ms, dev[1].voxels_ms);
    vct_group_release(g);
}

/* Device 1 cannot hold the structures: left out with a message, the frame
 * made by device 0. */
static void check_small_device(const vct_scene *s) {
    setenv("VCT_MAX_ALLOC_MIB", "1:0.002", 1);
    vct_error err = {0};
    vct_group *g = vct_group_create("0,1", &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    unsetenv("VCT_MAX_ALLOC_MIB");
    const vct_group_build b = build_options(s);
    REQUIRE_OK(vct_group_prepare(g, s, &b, &err), err);
    const vct_group_device *dev;
    vct_group_devices(g, &dev);
    CHECK(dev[0].active && !dev[1].active && strstr(dev[1].dropped, "MiB"),
          "the small device is left out, saying why: %s", dev[1].dropped);
    const method_case *c = &cases[0];
    vct_image one = single(c, s);
    vct_render_job job = job_of(c, s);
    vct_image two;
    REQUIRE_OK(vct_group_render(g, &job, &two, NULL, &err), err);
    CHECK(check_differing(&one, &two) == 0, "the device left out changed the image");
    vct_image_release(&two);
    vct_image_release(&one);
    vct_group_release(g);
}

/* Photon mapping's barrier: three bands report radii per pass; each gets
 * the largest of the three, pass after pass; a band that fails releases
 * the others, which learn the frame stopped. */
typedef struct sync_member {
    vct_pass_sync *sync;
    int id, fail_at;
    uint32_t got[4][2];
    int stopped_at;
} sync_member;

static void *sync_member_run(void *p) {
    sync_member *m = p;
    m->stopped_at = -1;
    for (uint32_t pass = 0; pass < 4; ++pass) {
        if ((int)pass == m->fail_at) {
            vct_pass_sync_fail(m->sync, m->id);
            return NULL;
        }
        uint32_t bits[2] = {100u * pass + (uint32_t)m->id, (uint32_t)(7 - m->id)};
        if (vct_pass_sync_wait(m->sync, pass, bits)) {
            m->stopped_at = (int)pass;
            return NULL;
        }
        m->got[pass][0] = bits[0], m->got[pass][1] = bits[1];
    }
    return NULL;
}

static void check_pass_sync(int fail_at) {
    vct_pass_sync sync;
    vct_pass_sync_init(&sync, 3);
    sync_member members[3];
    pthread_t threads[3];
    for (int i = 0; i < 3; ++i) {
        members[i] = (sync_member){&sync, i, i == 1 ? fail_at : -1, {{0}}, -1};
        pthread_create(&threads[i], NULL, sync_member_run, &members[i]);
    }
    for (int i = 0; i < 3; ++i)
        pthread_join(threads[i], NULL);
    for (int i = 0; i < 3; i += 2) {
        const int passes = fail_at < 0 ? 4 : fail_at;
        for (int pass = 0; pass < passes; ++pass)
            CHECK(members[i].got[pass][0] == 100u * (uint32_t)pass + 2u &&
                      members[i].got[pass][1] == 7u,
                  "band %d, pass %d: got %u, %u, the largest are %u, 7", i, pass,
                  members[i].got[pass][0], members[i].got[pass][1], 100u * pass + 2u);
        CHECK(members[i].stopped_at == (fail_at < 0 ? -1 : fail_at),
              "band %d stopped at pass %d, the failure came at %d", i, members[i].stopped_at,
              fail_at);
    }
    CHECK(fail_at < 0 || (sync.culprit[1] && !sync.culprit[0] && !sync.culprit[2]),
          "the band that failed is the one to blame");
    vct_pass_sync_destroy(&sync);
}

/* The scheduler's arithmetic against values worked by hand. */
static void check_balance(void) {
    const int active[2] = {1, 1};
    double share[2] = {0.5, 0.5};
    const double speed[2] = {3.0, 1.0};
    CHECK(vct_balance_shares(2, active, speed, share) && fabs(share[0] - 0.625) < 1e-12,
          "half way from 0.5 to the 0.75 speeds 3:1 ask: %g", share[0]);
    int frames = 1;
    while (vct_balance_shares(2, active, speed, share) && frames < 20)
        ++frames;
    CHECK(frames <= 5 && fabs(share[0] - 0.75) < VCT_BALANCE_DEAD_BAND,
          "settled within the dead band of 0.75 in %d frames: %g", frames, share[0]);
    const double lopsided[2] = {100.0, 1.0};
    vct_balance_shares(2, active, lopsided, share);
    CHECK(share[1] == 0.0 && share[0] == 1.0, "a device worth under 3 %% gets nothing: %g",
          share[1]);
    const double split_share[3] = {0.625, 0.0, 0.375};
    int counts[3];
    vct_balance_split(3, split_share, 37, counts);
    CHECK(counts[0] == 23 && counts[1] == 0 && counts[2] == 14, "37 rows split %d/%d/%d", counts[0],
          counts[1], counts[2]);
    const double tiny[2] = {0.999, 0.001};
    vct_balance_split(2, tiny, 3, counts);
    CHECK(counts[0] == 2 && counts[1] == 1, "a share gets a unit at least: %d/%d", counts[0],
          counts[1]);
    vct_solo solo = {0};
    vct_solo_next(&solo, 30.0, 1, 0);
    CHECK(solo.state == VCT_ALL_DEVICES, "no probe after the first frame, settled or not");
    solo = (vct_solo){0};
    vct_solo_next(&solo, 10.0, 0, 0);
    CHECK(solo.state == VCT_ALL_DEVICES, "no probe before the shares settle");
    vct_solo_next(&solo, 10.0, 1, 1);
    CHECK(solo.state == VCT_SOLO_PROBE && solo.device == 1, "settled: the fastest is tried alone");
    vct_solo_next(&solo, 9.0, 1, 1);
    CHECK(solo.state == VCT_SOLO, "alone 9 ms against 10 together: it stays alone");
    for (int f = 0; f <= VCT_SOLO_RETRY; ++f)
        vct_solo_next(&solo, 9.0, 1, 1);
    CHECK(solo.state == VCT_ALL_DEVICES, "the devices together are tried again");
    vct_solo_next(&solo, 8.0, 1, 1);
    vct_solo_next(&solo, 8.5, 1, 1);
    CHECK(solo.state == VCT_ALL_DEVICES, "together 8 ms, alone 8.5: together it is");
}

/* Photon mapping's outer sync, as the only other band: the group's own
 * radii back, counted. */
static int outer_calls;
static int outer_alone(void *user, uint32_t pass, uint32_t radius_bits[2]) {
    (void)user;
    (void)pass;
    (void)radius_bits;
    ++outer_calls;
    return 0;
}

/* Parts of a frame (vct/partial.h) on a group: a band of rows equals those
 * rows of one device's whole image, the halos rendered by the group; the
 * path tracer's samples in two ranges, added and resolved, equal one
 * device's render. */
static void check_parts(const vct_scene *s) {
    vct_error err = {0};
    vct_group *g = group_for(s);
    const int first = 16, rows = 16; /* both ends on every alignment */
    for (int c = 0; c < CASES; ++c) {
        if (cases[c].method == VCT_METHOD_PATHTRACE || cases[c].method == VCT_METHOD_VOXELS)
            continue;
        vct_image one = single(&cases[c], s);
        vct_render_job job = job_of(&cases[c], s);
        job.height = rows;
        job.band.first = first;
        job.band.height = HEIGHT;
        outer_calls = 0;
        /* photon mapping's band alone (its radii are not the whole
         * image's): compared with one device's render of the same band */
        if (job.method == VCT_METHOD_PM)
            job.band.pass_sync = outer_alone;
        vct_image band;
        REQUIRE_OK(vct_group_render(g, &job, &band, NULL, &err), err);
        const int group_outer_calls = outer_calls;
        size_t differ = 0;
        if (job.method == VCT_METHOD_PM) {
            vct_error e1 = {0};
            vct_context *ctx = vct_context_create("0", &e1);
            REQUIRE_OK(ctx ? VCT_OK : e1.status, e1);
            vct_device_scene *ds = vct_device_scene_create(ctx, s, &e1);
            REQUIRE_OK(ds ? VCT_OK : e1.status, e1);
            vct_render_job alone = job;
            alone.accel_options = build_options(s).accel;
            vct_image ref;
            REQUIRE_OK(vct_device_scene_render(ds, &alone, &ref, NULL, &e1), e1);
            differ = check_differing(&ref, &band);
            CHECK(group_outer_calls == (int)job.pm.passes,
                  "pm band: the outer sync was called %d times for %u passes", group_outer_calls,
                  job.pm.passes);
            vct_image_release(&ref);
            vct_device_scene_release(ds);
            vct_context_release(ctx);
        } else {
            for (int y = 0; y < rows; ++y)
                for (int x = 0; x < 4 * WIDTH; ++x)
                    differ += band.rgba[(size_t)y * 4 * WIDTH + x] !=
                              one.rgba[(size_t)(first + y) * 4 * WIDTH + x];
        }
        CHECK(differ == 0, "%s: a band of rows %d to %d on 2 devices: %zu values differ",
              cases[c].name, first, first + rows - 1, differ);
        vct_image_release(&band);
        vct_image_release(&one);
    }
    int pt_case = 0;
    while (cases[pt_case].method != VCT_METHOD_PATHTRACE)
        ++pt_case;
    vct_render_job job = job_of(&cases[pt_case], s);
    vct_sample_sums a, b;
    REQUIRE_OK(vct_group_render_samples(g, &job, 5, job.pathtrace.spp - 5, &a, &err), err);
    REQUIRE_OK(vct_group_render_samples(g, &job, 0, 5, &b, &err), err);
    REQUIRE_OK(vct_sample_sums_add(&a, &b, &err), err);
    vct_image put, one = single(&cases[pt_case], s);
    REQUIRE_OK(vct_group_resolve_samples(g, &job, &a, &put, &err), err);
    CHECK(check_differing(&one, &put) == 0,
          "pt: two sample ranges on 2 devices, added: %zu values differ from one device's",
          check_differing(&one, &put));
    printf("parts on 2 devices: bands of every row method equal the whole image's rows; two "
           "sample ranges add up to one device's image\n");
    vct_image_release(&put);
    vct_image_release(&one);
    vct_sample_sums_release(&a);
    vct_sample_sums_release(&b);
    vct_group_release(g);
}

int main(void) {
    check_balance();
    check_pass_sync(-1);
    check_pass_sync(2);
    check_lists();
    vct_scene *box = check_cornell_box_point_light();
    check_methods("cornell box", box);
    check_variance(box);
    check_fixed_splits(box);
    check_slowed(box);
    check_failure(box, 3); /* whitted, subsampled: rows */
    check_failure(box, 6); /* pt: samples */
    check_failure(box, 8); /* pm: bands in lockstep, started again */
    check_small_device(box);
    check_copied_voxels(box);
    check_moved_light(box);
    check_parts(box);
    vct_scene_release(box);
    vct_scene *lit = check_cornell_box();
    check_methods("emissive cornell box", lit);
    vct_scene_release(lit);
    return check_exit("test_multi");
}
