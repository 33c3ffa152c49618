/* The two-level BVH: a BVH per mesh under one over the instances.
 *
 * Rays report the same hits as the one-level BVH, bit for bit (t, triangle,
 * barycentrics; closest and any hit), and agree with a double-precision
 * brute force: on a file with one sphere placed 64 times, and on hard
 * placements (1e4 from the origin, scaled by 1e-3 and by 300, mirrored, turned
 * and stretched, flattened to zero). Moving an instance gives the hits of the
 * other structure built on the moved scene. Rays at a closed mesh's vertices
 * and edges do not leak through. AUTO picks two levels only where
 * a mesh is shared, and the shared mesh is held once. */
#include "accel/accel.h"
#include "ray_check.h"

/* levels VCT_BVH_ONE_LEVEL with grid_instead: the triangle grid. */
static int grid_instead;
static vct_accel *build(vct_context *ctx, const vct_scene *s, vct_bvh_levels levels) {
    vct_error err = {0};
    vct_accel_options o = vct_accel_options_default();
    o.bvh_levels = levels;
    if (levels == VCT_BVH_ONE_LEVEL && grid_instead)
        o.kind = VCT_ACCEL_GRID;
    vct_accel *a = vct_accel_build(ctx, s, &o, &err);
    REQUIRE_OK(a ? VCT_OK : err.status, err);
    return a;
}

/* n rays from around the scene's box towards points inside it. */
static float *rays_into(const vct_scene *s, uint32_t n, uint64_t seed) {
    float *rays = malloc(32ull * n);
    for (uint32_t i = 0; i < n; ++i) {
        float *r = &rays[8 * i], len = 0.0f;
        for (int k = 0; k < 3; ++k) {
            const float lo = s->bounds_min[k], ext = s->bounds_max[k] - lo;
            r[k] = lo - 0.5f * ext + 2.0f * ext * check_randf(&seed);
            r[4 + k] = lo + ext * check_randf(&seed) - r[k];
            len += r[4 + k] * r[4 + k];
        }
        for (int k = 0; k < 3; ++k)
            r[4 + k] /= sqrtf(len);
        r[3] = 0.0f;
        r[7] = INFINITY;
    }
    return rays;
}

/* The same hits from two levels as from one (or, with against_grid, the
 * triangle grid, which reports the same hits as the one-level BVH), bit for
 * bit. */
static void check_same_hits_as(vct_context *ctx, const vct_scene *s, const char *name,
                               int against_grid) {
    grid_instead = against_grid;
    vct_accel *one = build(ctx, s, VCT_BVH_ONE_LEVEL), *two = build(ctx, s, VCT_BVH_TWO_LEVELS);
    grid_instead = 0;
    vct_accel_info info;
    vct_error err = {0};
    REQUIRE_OK(vct_accel_info_get(ctx, two, &info, &err), err);
    CHECK(info.two_levels, "%s: two levels asked, one built", name);
    const uint32_t n = 20000;
    float *rays = rays_into(s, n, 11);
    vct_hit *a = malloc(sizeof *a * n), *b = malloc(sizeof *b * n);
    uint32_t differ = 0, hit = 0;
    for (int any = 0; any < 2; ++any) {
        REQUIRE_OK(vct_trace_rays(ctx, one, rays, n, any, a, &err), err);
        REQUIRE_OK(vct_trace_rays(ctx, two, rays, n, any, b, &err), err);
        for (uint32_t i = 0; i < n; ++i) {
            hit += !any && a[i].t >= 0.0f;
            if (any)
                differ += (a[i].t >= 0.0f) != (b[i].t >= 0.0f);
            else
                differ += memcmp(&a[i], &b[i], sizeof a[i]) != 0;
        }
    }
    CHECK(differ == 0, "%s: %u of %u rays report other hits through two levels than through %s",
          name, differ, 2 * n, against_grid ? "the grid" : "one");
    CHECK(hit > n / 4, "%s: only %u of %u rays hit: a weak test", name, hit, n);
    printf("%s: %u rays, %u hits, the same through one and two levels (%u instances, %u "
           "triangles held, %.2f MiB)\n",
           name, n, hit, info.instances, info.mesh_triangles, info.bytes / 1048576.0);
    check_rays(ctx, s, two, 400, 5, name);
    free(rays);
    free(a);
    free(b);
    vct_accel_release(one);
    vct_accel_release(two);
}

static void check_same_hits(vct_context *ctx, const vct_scene *s, const char *name) {
    check_same_hits_as(ctx, s, name, 0);
}

static void transform_of(float m[12], float sx, float sy, float sz, float angle, float tx, float ty,
                         float tz) {
    const float c = cosf(angle), s = sinf(angle);
    const float r[12] = {c * sx, 0, s * sz, tx, 0, sy, 0, ty, -s * sx, 0, c * sz, tz};
    memcpy(m, r, sizeof r);
}

/* A closed sphere placed where rounding is hardest. */
static void check_hard_placements(vct_context *ctx) {
    vct_error err = {0};
    const float centre[3] = {0, 0, 0};
    test_mesh ball = mesh_icosphere(2, 1.0f, centre);
    float m[12];
    static const char *names[] = {"scaled by 1e-3", "mirrored", "turned and stretched",
                                  "scaled by 300", "flattened to zero"};
    const float placements[][7] = {{1e-3f, 1e-3f, 1e-3f, 0.3f, 0, 2, 0},
                                   {-1, 1, 1, 0.7f, 0, 0, 3},
                                   {3, 0.2f, 1, 0.5f, -3, 1, 1},
                                   {300, 300, 300, 0.1f, 0, -400, 0},
                                   {0, 0, 0, 0.0f, 2, 2, 2}};
    /* each beside the sphere as it is, and a third copy turned */
    for (size_t p = 0; p < sizeof placements / sizeof *placements; ++p) {
        vct_scene *one = scene_of(&ball);
        const float *q = placements[p];
        transform_of(m, q[0], q[1], q[2], q[3], q[4], q[5], q[6]);
        REQUIRE_OK(vct_scene_add_instance(one, 0, m, &err), err);
        transform_of(m, 1, 1, 1, 1.3f, 2.5f, -1, 0);
        REQUIRE_OK(vct_scene_add_instance(one, 0, m, &err), err);
        /* 320 triangles at one point are more than the one-level builder
         * orders within its depth: the grid is the other structure there */
        check_same_hits_as(ctx, one, names[p], q[0] == 0.0f);
        vct_scene_release(one);
    }
    vct_scene *s = scene_of(&ball);
    transform_of(m, 1, 1, 1, 0.4f, 3, 0, 0);
    REQUIRE_OK(vct_scene_add_instance(s, 0, m, &err), err);
    transform_of(m, 2, 1, 1, 0.8f, 0, 0, 3);
    REQUIRE_OK(vct_scene_add_instance(s, 0, m, &err), err);
    /* far from the origin: the same sphere 1e4 away, alone with its copy */
    vct_scene *far = scene_of(&ball);
    transform_of(m, 1, 1, 1, 0.2f, 1e4f, 0, 0);
    REQUIRE_OK(vct_scene_set_instance_transform(far, 0, m, &err), err);
    transform_of(m, 1, 1, 1, 0.9f, 1e4f + 2.5f, 0.5f, 0);
    REQUIRE_OK(vct_scene_add_instance(far, 0, m, &err), err);
    check_same_hits(ctx, far, "1e4 from the origin");
    /* moved: both structures built again on the moved scene agree */
    transform_of(m, 0.5f, 2, 0.5f, 1.1f, 1, 1, -2);
    REQUIRE_OK(vct_scene_set_instance_transform(s, 1, m, &err), err);
    check_same_hits(ctx, s, "an instance moved");
    /* refused: a transform that is not finite leaves the scene as it was */
    m[5] = NAN;
    const uint32_t before = s->instance_count;
    CHECK(vct_scene_add_instance(s, 0, m, &err) == VCT_ERR_INPUT && s->instance_count == before &&
              strstr(err.message, "not finite"),
          "a transform with NaN: %s", err.message);
    /* rays at the vertices and edges of a closed mesh through two levels */
    vct_accel_options two = vct_accel_options_default();
    two.bvh_levels = VCT_BVH_TWO_LEVELS;
    check_watertight(ctx, &ball, centre, &two, "icosphere watertight, two levels");
    const float far_centre[3] = {3e5f, -2e5f, 1e5f};
    test_mesh far_ball = mesh_icosphere(3, 2.0f, far_centre);
    check_watertight(ctx, &far_ball, far_centre, &two, "icosphere at 3e5 watertight, two levels");
    mesh_free(&far_ball);
    vct_scene_release(far);
    vct_scene_release(s);
    mesh_free(&ball);
}

/* AUTO: two levels for the file whose sphere 64 nodes place, holding it
 * once; one level for a scene of unshared meshes. */
static void check_auto(vct_context *ctx) {
    vct_error err = {0};
    vct_scene *s = check_scene_file("scenes/instanced_spheres.gltf");
    CHECK(s->instance_count == 66 && s->mesh_count == 3,
          "the file loads as %u meshes, %u instances", s->mesh_count, s->instance_count);
    vct_accel *a = build(ctx, s, VCT_BVH_LEVELS_AUTO);
    vct_accel_info info;
    REQUIRE_OK(vct_accel_info_get(ctx, a, &info, &err), err);
    CHECK(info.two_levels && info.mesh_triangles == 5124 && info.instances == 66,
          "auto: two levels %d, %u triangles held, %u instances", info.two_levels,
          info.mesh_triangles, info.instances);
    vct_accel_release(a);
    check_same_hits(ctx, s, "64 placed spheres");
    vct_scene_release(s);
    vct_scene *box = check_cornell_box();
    a = build(ctx, box, VCT_BVH_LEVELS_AUTO);
    REQUIRE_OK(vct_accel_info_get(ctx, a, &info, &err), err);
    CHECK(!info.two_levels, "auto chose two levels for a scene without a shared mesh");
    vct_accel_release(a);
    vct_scene_release(box);
}

int main(void) {
    vct_context *ctx = check_context();
    check_auto(ctx);
    check_hard_placements(ctx);
    vct_context_release(ctx);
    return check_exit("test_bvh2");
}
