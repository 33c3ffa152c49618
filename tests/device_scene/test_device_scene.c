/* The committed device scene: its renders equal those made from structures
 * built by hand, bit for bit; an unchanged scene's second render uploads no
 * scene data and rebuilds nothing; a change rebuilds only what depends on
 * it (a moved light: no BVH and no voxels; a changed material: no BVH), and
 * what it renders then equals a fresh device scene of the changed scene;
 * resumed progressive renders add to their scene's own sums and start over
 * on a change; objects of another context are refused. */
#include <math.h>
#include <string.h>

#include "check.h"

#define SIZE 32

static vct_context *ctx;

static vct_render_job job_for(vct_method method) {
    vct_render_job job = vct_render_job_default(method, SIZE, SIZE);
    job.voxel_options.resolution = 32;
    job.bounces = 2;
    job.pathtrace.spp = 4;
    job.pathtrace.seed = 7;
    job.pm.passes = 2;
    job.pm.photons_per_pass = 4096;
    return job;
}

/* The same render from structures built by hand (vct_accel_build,
 * vct_vct_prepare, vct_render). */
static vct_image by_hand(const vct_scene *s, vct_method method) {
    vct_error err = {0};
    vct_render_job job = job_for(method);
    vct_accel *a = vct_accel_build(ctx, s, &job.accel_options, &err);
    REQUIRE_OK(a ? VCT_OK : err.status, err);
    vct_plan plan;
    vct_plan_make(s, NULL, &plan);
    vct_voxels *v = NULL;
    if (method == VCT_METHOD_VCT || method == VCT_METHOD_VOXELS)
        REQUIRE_OK(vct_vct_prepare(ctx, s, a, &plan, &job.voxel_options, &job.brick_options,
                                   job.bounces, &job.vct.cones, &v, &err),
                   err);
    job.scene = s;
    job.accel = a;
    job.voxels = v;
    vct_image im;
    REQUIRE_OK(vct_render(ctx, &job, &im, NULL, &err), err);
    vct_voxels_release(v);
    vct_accel_release(a);
    return im;
}

static vct_image by_device_scene(vct_device_scene *ds, vct_method method) {
    vct_error err = {0};
    vct_render_job job = job_for(method);
    vct_image im;
    REQUIRE_OK(vct_device_scene_render(ds, &job, &im, NULL, &err), err);
    return im;
}

static double sum(const vct_image *a) {
    double total = 0.0;
    for (size_t i = 0; i < (size_t)a->width * a->height * 4; i += 4)
        total += a->rgba[i] + a->rgba[i + 1] + a->rgba[i + 2];
    return total;
}

static const vct_method methods[] = {VCT_METHOD_RAYCAST, VCT_METHOD_WHITTED, VCT_METHOD_PATHTRACE,
                                     VCT_METHOD_PM,      VCT_METHOD_VCT,     VCT_METHOD_VOXELS};

/* Every method through one device scene equals the same method by hand;
 * rendering it again uploads no scene data and builds nothing. */
static void check_same_images(const char *name, const vct_scene *s) {
    vct_error err = {0};
    vct_device_scene *ds = vct_device_scene_create(ctx, s, &err);
    REQUIRE_OK(ds ? VCT_OK : err.status, err);
    for (size_t m = 0; m < sizeof methods / sizeof *methods; ++m) {
        const char *method = vct_method_name(methods[m]);
        vct_image hand = by_hand(s, methods[m]);
        vct_image first = by_device_scene(ds, methods[m]);
        vct_device_scene_stats before;
        vct_device_scene_stats_get(ds, &before);
        vct_transfer_stats up0, up1;
        vct_context_transfer_stats(ctx, &up0);
        vct_image again = by_device_scene(ds, methods[m]);
        vct_context_transfer_stats(ctx, &up1);
        vct_device_scene_stats after;
        vct_device_scene_stats_get(ds, &after);
        CHECK(check_differing(&hand, &first) == 0,
              "%s, %s: %zu values differ from the render by hand", name, method,
              check_differing(&hand, &first));
        CHECK(sum(&hand) > 0.0, "%s, %s: a black image proves nothing", name, method);
        if (methods[m] != VCT_METHOD_PM) /* photon mapping's second call goes on */
            CHECK(check_differing(&first, &again) == 0, "%s, %s: the second render differs", name,
                  method);
        CHECK(after.scene_bytes == before.scene_bytes,
              "%s, %s: the second render uploaded %llu bytes of scene data", name, method,
              (unsigned long long)(after.scene_bytes - before.scene_bytes));
        CHECK(after.accel_builds == before.accel_builds &&
                  after.voxel_builds == before.voxel_builds &&
                  after.light_builds == before.light_builds,
              "%s, %s: the second render built something", name, method);
        printf("%s, %s: identical to the render by hand; second render: %llu bytes uploaded "
               "(camera and parameters), none of them scene data\n",
               name, method, (unsigned long long)(up1.uploaded - up0.uploaded));
        vct_image_release(&hand);
        vct_image_release(&first);
        vct_image_release(&again);
    }
    vct_device_scene_stats st;
    vct_device_scene_stats_get(ds, &st);
    CHECK(st.accel_builds == 1, "%s: %u BVH builds for one unchanged scene", name, st.accel_builds);
    CHECK(st.voxel_builds == 1, "%s: %u voxel builds for one unchanged scene", name,
          st.voxel_builds);
    CHECK(st.scene_bytes > 0, "%s: no scene data counted at all", name);
    vct_device_scene_release(ds);
}

/* A fresh device scene's cone-traced image of s. */
static vct_image fresh(const vct_scene *s, vct_method method) {
    vct_error err = {0};
    vct_device_scene *ds = vct_device_scene_create(ctx, s, &err);
    REQUIRE_OK(ds ? VCT_OK : err.status, err);
    vct_image im = by_device_scene(ds, method);
    vct_device_scene_release(ds);
    return im;
}

typedef struct builds {
    int accel, voxels, light;
    int moves; /* the BVH placed again or refit */
} builds;

/* Renders ds after `what` changed s, compares with a fresh device scene of
 * the changed s, and checks which structures were built again. */
static void check_change(vct_device_scene *ds, const vct_scene *s, const char *what,
                         builds expect) {
    vct_device_scene_stats before, after;
    vct_device_scene_stats_get(ds, &before);
    vct_image kept = by_device_scene(ds, VCT_METHOD_VCT);
    vct_device_scene_stats_get(ds, &after);
    /* and the render after it builds nothing more */
    vct_device_scene_stats again;
    vct_image twice = by_device_scene(ds, VCT_METHOD_VCT);
    vct_device_scene_stats_get(ds, &again);
    CHECK(again.accel_builds == after.accel_builds && again.voxel_builds == after.voxel_builds &&
              again.light_builds == after.light_builds && check_differing(&kept, &twice) == 0,
          "%s: the render after the change built again (%u light builds)", what,
          again.light_builds - after.light_builds);
    vct_image_release(&twice);
    vct_image pt = by_device_scene(ds, VCT_METHOD_PATHTRACE);
    /* the device scene above is set aside while a fresh one renders */
    vct_image new_vct, new_pt;
    {
        vct_scene copy = *s; /* another address: another resident copy */
        new_vct = fresh(&copy, VCT_METHOD_VCT);
        new_pt = fresh(&copy, VCT_METHOD_PATHTRACE);
    }
    CHECK(check_differing(&kept, &new_vct) == 0,
          "%s: cone tracing: %zu values differ from a fresh scene", what,
          check_differing(&kept, &new_vct));
    CHECK(check_differing(&pt, &new_pt) == 0,
          "%s: path tracing: %zu values differ from a fresh scene", what,
          check_differing(&pt, &new_pt));
    const int accel = (int)(after.accel_builds - before.accel_builds),
              voxels = (int)(after.voxel_builds - before.voxel_builds),
              light = (int)(after.light_builds - before.light_builds);
    CHECK(accel == expect.accel && voxels == expect.voxels && light == expect.light,
          "%s: built %d BVH, %d voxels, %d light; expected %d, %d, %d", what, accel, voxels, light,
          expect.accel, expect.voxels, expect.light);
    CHECK(after.changes == before.changes + 1, "%s: the commit saw %u changes", what,
          after.changes - before.changes);
    CHECK((int)(after.accel_moves - before.accel_moves) == expect.moves,
          "%s: the BVH moved %u times, expected %d", what, after.accel_moves - before.accel_moves,
          expect.moves);
    printf("%s: rebuilt %d BVH, %d voxels, %d light; images equal a fresh device scene's\n", what,
           accel, voxels, light);
    vct_image_release(&kept);
    vct_image_release(&pt);
    vct_image_release(&new_vct);
    vct_image_release(&new_pt);
}

static void check_changes(void) {
    vct_error err = {0};
    vct_scene *s = check_cornell_box_point_light();
    vct_device_scene *ds = vct_device_scene_create(ctx, s, &err);
    REQUIRE_OK(ds ? VCT_OK : err.status, err);
    vct_image first = by_device_scene(ds, VCT_METHOD_VCT);
    vct_image_release(&first);

    s->lights[0].position[0] += 0.2f;
    check_change(ds, s, "a moved light", (builds){0, 0, 1, 0});
    s->lights[0].color[1] *= 0.5f;
    check_change(ds, s, "a dimmer light", (builds){0, 0, 1, 0});
    s->materials[0].albedo[0] *= 0.5f;
    check_change(ds, s, "a changed material", (builds){0, 1, 1, 0});
    /* one level: its boxes refit to the moved vertices, the same hits */
    for (uint32_t v = 0; v < s->vertex_count; ++v)
        s->positions[3 * v + 1] *= 0.9f;
    check_change(ds, s, "moved geometry", (builds){0, 1, 1, 1});
    /* a wall torn far away: the refit tree much worse than a built one, so
     * built again */
    const uint32_t wall = s->instances[1].first_vertex;
    for (uint32_t v = 0; v < s->meshes[s->instances[1].mesh].vertex_count; ++v)
        s->positions[3 * (wall + v)] += 5000.0f;
    check_change(ds, s, "a wall torn away", (builds){1, 1, 1, 0});
    s->camera.position[0] += 0.1f;
    check_change(ds, s, "a moved camera", (builds){0, 0, 0, 0});

    /* nothing changed: a commit finds nothing */
    vct_device_scene_stats st0, st1;
    vct_device_scene_stats_get(ds, &st0);
    REQUIRE_OK(vct_device_scene_commit(ds, &err), err);
    vct_device_scene_stats_get(ds, &st1);
    CHECK(st1.changes == st0.changes, "an unchanged scene's commit found a change");

    /* one device scene per scene and context */
    vct_device_scene *twice = vct_device_scene_create(ctx, s, &err);
    CHECK(!twice && err.status == VCT_ERR_INPUT && strstr(err.message, "already committed"),
          "a second device scene of one scene on one context: %s", err.message);
    vct_device_scene_release(twice);
    vct_device_scene_release(ds);
    vct_scene_release(s);
}

/* Instances moved through the scene's API: a two-level structure rebuilds
 * its top level alone, and the images equal a fresh device scene's; flat
 * positions edited alone (the instances no longer say where the vertices
 * are) get one level built again, with the same images as a fresh scene. */
static void check_moved_instances(void) {
    vct_error err = {0};
    vct_scene *s = check_scene_file("scenes/instanced_spheres.gltf");
    vct_device_scene *ds = vct_device_scene_create(ctx, s, &err);
    REQUIRE_OK(ds ? VCT_OK : err.status, err);
    vct_image first = by_device_scene(ds, VCT_METHOD_RAYCAST);
    vct_image_release(&first);
    vct_device_scene_stats before, after;
    vct_device_scene_stats_get(ds, &before);
    float m[12];
    memcpy(m, s->instances[10].transform, sizeof m);
    m[3] += 0.7f;
    m[11] -= 0.4f;
    REQUIRE_OK(vct_scene_set_instance_transform(s, 10, m, &err), err);
    vct_image kept = by_device_scene(ds, VCT_METHOD_RAYCAST);
    vct_device_scene_stats_get(ds, &after);
    vct_scene copy = *s;
    vct_image fresh_image = fresh(&copy, VCT_METHOD_RAYCAST);
    CHECK(check_differing(&kept, &fresh_image) == 0,
          "a moved instance: %zu values differ from a fresh scene",
          check_differing(&kept, &fresh_image));
    CHECK(after.accel_moves == before.accel_moves + 1 && after.accel_builds == before.accel_builds,
          "a moved instance: %u top-level rebuilds, %u full builds",
          after.accel_moves - before.accel_moves, after.accel_builds - before.accel_builds);
    printf("a moved instance: the top level built again, the meshes kept; the image equals a "
           "fresh device scene's\n");
    vct_image_release(&kept);
    vct_image_release(&fresh_image);
    /* the flat positions of one sphere edited alone */
    const uint32_t v0 = s->instances[20].first_vertex;
    for (uint32_t v = 0; v < s->meshes[s->instances[20].mesh].vertex_count; ++v)
        s->positions[3 * (v0 + v) + 1] += 0.3f;
    vct_device_scene_stats_get(ds, &before);
    kept = by_device_scene(ds, VCT_METHOD_RAYCAST);
    vct_device_scene_stats_get(ds, &after);
    copy = *s;
    fresh_image = fresh(&copy, VCT_METHOD_RAYCAST);
    CHECK(check_differing(&kept, &fresh_image) == 0,
          "positions edited alone: %zu values differ from a fresh scene",
          check_differing(&kept, &fresh_image));
    CHECK(after.accel_builds == before.accel_builds + 1,
          "positions edited alone: %u builds (the structure must be built again)",
          after.accel_builds - before.accel_builds);
    const vct_accel *a = vct_device_scene_accel(ds);
    vct_accel_info info;
    REQUIRE_OK(vct_accel_info_get(ctx, a, &info, &err), err);
    CHECK(!info.two_levels, "positions that are not the instances' got two levels");
    vct_image_release(&kept);
    vct_image_release(&fresh_image);
    vct_device_scene_release(ds);
    vct_scene_release(s);
}

/* A render of `steps` (samples or passes) through ds, resumed or not. */
static vct_image progressive(vct_device_scene *ds, vct_method method, uint32_t steps, int resume) {
    vct_error err = {0};
    vct_render_job job = job_for(method);
    job.pathtrace.spp = steps;
    job.pathtrace.resume = resume;
    job.pm.passes = steps;
    job.pm.resume = resume;
    vct_image im;
    REQUIRE_OK(vct_device_scene_render(ds, &job, &im, NULL, &err), err);
    return im;
}

static vct_image progressive_fresh(const vct_scene *s, vct_method method, uint32_t steps) {
    vct_error err = {0};
    vct_scene copy = *s; /* another address: another resident copy */
    vct_device_scene *ds = vct_device_scene_create(ctx, &copy, &err);
    REQUIRE_OK(ds ? VCT_OK : err.status, err);
    vct_image im = progressive(ds, method, steps, 0);
    vct_device_scene_release(ds);
    return im;
}

static void check_same(const char *what, const char *method, vct_image *got, vct_image *expect) {
    const size_t n = check_differing(got, expect);
    CHECK(n == 0, "%s (%s): %zu values differ", what, method, n);
    vct_image_release(got);
    vct_image_release(expect);
}

/* The path tracer and photon mapping resumed through a device scene add to
 * that scene's own sums (another scene rendered in between on the same
 * context leaves them alone), and start over by themselves when a commit
 * finds the scene changed. */
static void check_resume(void) {
    vct_error err = {0};
    vct_scene *s = check_cornell_box_point_light(), *other = check_cornell_box();
    vct_device_scene *ds = vct_device_scene_create(ctx, s, &err);
    REQUIRE_OK(ds ? VCT_OK : err.status, err);
    vct_device_scene *ds_other = vct_device_scene_create(ctx, other, &err);
    REQUIRE_OK(ds_other ? VCT_OK : err.status, err);
    const vct_method progressive_methods[] = {VCT_METHOD_PATHTRACE, VCT_METHOD_PM};
    for (int m = 0; m < 2; ++m) {
        const vct_method method = progressive_methods[m];
        const char *name = vct_method_name(method);
        vct_image im = progressive(ds, method, 1, 0);
        vct_image_release(&im);
        im = progressive(ds_other, method, 2, 0); /* same size, another scene */
        vct_image_release(&im);
        vct_image resumed = progressive(ds, method, 2, 1);
        vct_image whole = progressive_fresh(s, method, 3);
        check_same("1 + 2 resumed against 3 at once", name, &resumed, &whole);

        s->lights[0].position[1] -= 0.1f;
        vct_image after_light = progressive(ds, method, 2, 1);
        vct_image fresh_light = progressive_fresh(s, method, 2);
        check_same("resumed after a moved light, against a fresh render", name, &after_light,
                   &fresh_light);
        s->camera.position[2] += 0.05f;
        vct_image after_camera = progressive(ds, method, 1, 1);
        vct_image fresh_camera = progressive_fresh(s, method, 1);
        check_same("resumed after a moved camera, against a fresh render", name, &after_camera,
                   &fresh_camera);
        printf("%s: resumed renders add to their own scene's sums and start over on a change\n",
               name);
    }
    vct_device_scene_release(ds_other);
    vct_device_scene_release(ds);
    vct_scene_release(other);
    vct_scene_release(s);
}

static double nrmse(const vct_image *a, const vct_image *ref) {
    double e = 0.0, m = 0.0;
    for (size_t i = 0; i < (size_t)a->width * a->height * 4; ++i) {
        if (i % 4 == 3)
            continue;
        e += (a->rgba[i] - ref->rgba[i]) * (a->rgba[i] - ref->rgba[i]);
        m += ref->rgba[i];
    }
    const double n = (double)a->width * a->height * 3;
    return sqrt(e / n) / (m / n);
}

/* Cone tracing's indirect light (its AOV), where the voxels' light shows. */
static vct_image indirect_of(vct_device_scene *ds, const vct_render_job *job) {
    vct_error err = {0};
    vct_aovs aovs;
    memset(&aovs, 0, sizeof aovs);
    vct_render_job own = *job;
    own.aovs = &aovs;
    vct_image im;
    REQUIRE_OK(vct_device_scene_render(ds, &own, &im, NULL, &err), err);
    vct_image_release(&im);
    vct_image indirect = aovs.indirect;
    aovs.indirect.rgba = NULL;
    vct_aovs_release(&aovs);
    return indirect;
}

/* Renders a carrying job on ds until its light has settled, and more: how
 * many renders in a row relit (settle expected: as many as the measured
 * bounce ratio asks), the first render's indirect light and the last's. */
typedef struct carried_renders {
    uint32_t settle, relit_in_a_row, relit_after; /* relit_after: in the 2 renders after */
    vct_image first, last;
    vct_device_scene_stats before, after;
} carried_renders;

static uint32_t settle_renders(double ratio) {
    uint32_t settle = ratio > 0.0 ? (uint32_t)ceil(log(0.01) / log(ratio)) : 8;
    return settle < 4 ? 4 : settle > 16 ? 16 : settle;
}

static carried_renders render_until_settled(vct_device_scene *ds, const vct_render_job *job,
                                            double ratio) {
    carried_renders c;
    memset(&c, 0, sizeof c);
    c.settle = settle_renders(ratio);
    vct_device_scene_stats_get(ds, &c.before);
    uint32_t relit[18] = {0};
    for (uint32_t r = 0; r < c.settle + 2; ++r) {
        vct_device_scene_stats a, b;
        vct_device_scene_stats_get(ds, &a);
        vct_image im = indirect_of(ds, job);
        vct_device_scene_stats_get(ds, &b);
        relit[r] = b.light_builds - a.light_builds;
        if (r == 0)
            c.first = im;
        else {
            vct_image_release(&c.last);
            c.last = im;
        }
    }
    while (c.relit_in_a_row < c.settle + 2 && relit[c.relit_in_a_row] == 1)
        ++c.relit_in_a_row;
    c.relit_after = relit[c.settle] + relit[c.settle + 1];
    vct_device_scene_stats_get(ds, &c.after);
    return c;
}

/* The indirect light of a fresh device scene of s, every bounce built. */
static vct_image fresh_indirect_of(const vct_scene *s, vct_render_job job) {
    vct_error err = {0};
    vct_scene copy = *s; /* another address: another resident copy */
    vct_device_scene *again = vct_device_scene_create(ctx, &copy, &err);
    REQUIRE_OK(again ? VCT_OK : err.status, err);
    job.light_carry = 0;
    vct_image im = indirect_of(again, &job);
    vct_device_scene_release(again);
    return im;
}

static void move_light(vct_scene *s) {
    s->lights[0].position[0] += 200.0f; /* towards a coloured wall (millimetres) */
}

static void move_green_wall(vct_scene *s) {
    vct_error err = {0};
    for (uint32_t i = 0; i < s->instance_count; ++i) {
        if (strcmp(s->materials[s->triangle_material[s->instances[i].first_triangle]].name,
                   "green") != 0)
            continue;
        float m[12];
        memcpy(m, s->instances[i].transform, sizeof m);
        m[3] += 60.0f; /* inward: the scene's bounds stay */
        REQUIRE_OK(vct_scene_set_instance_transform(s, i, m, &err), err);
    }
}

/* Light carried over (light_carry) after `change`, on the Cornell box:
 * the voxels built `voxel_builds` times (0 for a light, once for moved
 * geometry), one bounce a render until the light from before has faded (as
 * many renders as the measured bounce ratio asks), then nothing more;
 * settled, the indirect light is a fresh build's within 2 %, where the
 * light from before differs from it by more than ten times that. first:
 * where not 0, the bound at the first render (moved geometry gathers from
 * the voxels before, every bounce of the frame before: without them the
 * first render would hold one bounce alone). */
static void check_carry(const char *what, void (*change)(vct_scene *), uint32_t voxel_builds,
                        double first) {
    vct_error err = {0};
    vct_scene *s = check_cornell_box_point_light();
    vct_device_scene *ds = vct_device_scene_create(ctx, s, &err);
    REQUIRE_OK(ds ? VCT_OK : err.status, err);
    vct_render_job job = job_for(VCT_METHOD_VCT);
    job.light_carry = 1;
    job.bounces = 4; /* measures the bounce ratio that sets how long the light settles */
    vct_image old_indirect = indirect_of(ds, &job);
    const double ratio = vct_voxels_bounce_ratio(vct_device_scene_voxels(ds));
    change(s);
    carried_renders c = render_until_settled(ds, &job, ratio);
    CHECK(c.after.accel_builds == c.before.accel_builds &&
              c.after.voxel_builds == c.before.voxel_builds + voxel_builds,
          "%s: %u BVH and %u voxel builds, expected 0 and %u", what,
          c.after.accel_builds - c.before.accel_builds,
          c.after.voxel_builds - c.before.voxel_builds, voxel_builds);
    CHECK(c.relit_in_a_row == c.settle && c.relit_after == 0,
          "%s: relit in %u renders in a row, expected %u (bounce ratio %.3f)", what,
          c.relit_in_a_row, c.settle, ratio);
    vct_image fresh = fresh_indirect_of(s, job);
    const double e_first = nrmse(&c.first, &fresh), e = nrmse(&c.last, &fresh),
                 moved = nrmse(&old_indirect, &fresh);
    CHECK(e < 0.02 && moved > 10.0 * e && (!(first > 0.0) || e_first < first),
          "%s: indirect NRMSE %.4f at the first render, %.4f settled, against a fresh build "
          "(the light before the change: %.4f)",
          what, e_first, e, moved);
    printf("%s: %u voxel builds, one bounce a render, settled after %u (bounce ratio %.3f); "
           "indirect NRMSE %.4f at the first render, %.4f settled, %.4f before the change\n",
           what, voxel_builds, c.settle, ratio, e_first, e, moved);
    vct_image_release(&c.first);
    vct_image_release(&c.last);
    vct_image_release(&old_indirect);
    vct_image_release(&fresh);
    vct_device_scene_release(ds);
    vct_scene_release(s);
}

/* A structure of another context is refused by name. */
static void check_other_context(void) {
    vct_error err = {0};
    vct_scene *s = check_cornell_box_point_light();
    vct_context *other = check_context();
    vct_accel *a = vct_accel_build(other, s, NULL, &err);
    REQUIRE_OK(a ? VCT_OK : err.status, err);
    vct_render_job job = job_for(VCT_METHOD_RAYCAST);
    job.scene = s;
    job.accel = a;
    vct_image im;
    const int rc = vct_render(ctx, &job, &im, NULL, &err);
    CHECK(rc == VCT_ERR_INPUT && strstr(err.message, "another context"),
          "an acceleration structure of another context: rc %d, %s", rc, err.message);
    vct_accel_release(a);
    vct_context_release(other);
    vct_scene_release(s);
}

int main(void) {
    ctx = check_context();
    vct_scene *box = check_cornell_box_point_light();
    check_same_images("cornell box", box);
    vct_scene_release(box);
    vct_scene *lit = check_cornell_box();
    check_same_images("emissive cornell box", lit);
    vct_scene_release(lit);
    check_changes();
    check_moved_instances();
    check_resume();
    check_carry("carried light, a light moved", move_light, 0, 0.0);
    check_carry("carried light, the green wall moved", move_green_wall, 1, 0.05);
    check_other_context();
    vct_context_release(ctx);
    return check_exit("test_device_scene");
}
