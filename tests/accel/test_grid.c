/* The triangle grid and its traversal: per-cell lists against an exact
 * triangle/box test on the host; closest hits against a double-precision
 * brute force over every triangle on random and axis-parallel rays; and
 * watertightness: rays through shared vertices and edges of a closed mesh
 * never pass through. */
#include "accel/accel.h"
#include "accel/tri_box.h"
#include "ray_check.h"

/* Every triangle that truly overlaps a cell is listed there (conservative);
 * every listed one overlaps the cell widened by 2e-5 of the scene's extent
 * plus 8 float ulps of its coordinates (tight); lists are ascending
 * (deterministic). */
static void check_cells(vct_context *ctx, const vct_scene *s, const vct_grid *g, const char *name) {
    size_t cells = (size_t)g->res[0] * g->res[1] * g->res[2];
    uint32_t *start = malloc(4 * cells), *end = malloc(4 * cells);
    uint32_t *ids = malloc(4ull * g->references + 4);
    vct_error err = {0};
    REQUIRE_OK(vct_grid_read(ctx, g, start, end, ids, &err), err);
    uint32_t missing = 0, loose = 0, unordered = 0;
    char *listed = calloc(s->triangle_count, 1);
    float extent = 0.0f, magnitude = 0.0f;
    for (int k = 0; k < 3; ++k) {
        extent = fmaxf(extent, s->bounds_max[k] - s->bounds_min[k]);
        magnitude = fmaxf(magnitude, fmaxf(fabsf(s->bounds_min[k]), fabsf(s->bounds_max[k])));
    }
    const float widen = 2e-5f * extent + 8.0f * FLT_EPSILON * magnitude;
    for (uint32_t z = 0; z < g->res[2]; ++z)
        for (uint32_t y = 0; y < g->res[1]; ++y)
            for (uint32_t x = 0; x < g->res[0]; ++x) {
                size_t c = x + g->res[0] * ((size_t)y + g->res[1] * z);
                float centre[3], half[3], wide[3];
                uint32_t idx[3] = {x, y, z};
                for (int k = 0; k < 3; ++k) {
                    centre[k] = g->origin[k] + (idx[k] + 0.5f) * g->cell_size[k];
                    half[k] = 0.5f * g->cell_size[k] * (1.0f - 1e-4f);
                    wide[k] = 0.5f * g->cell_size[k] + widen;
                }
                for (uint32_t i = start[c]; i < end[c]; ++i) {
                    listed[ids[i]] = 1;
                    if (i > start[c] && ids[i] <= ids[i - 1])
                        ++unordered;
                }
                for (uint32_t t = 0; t < s->triangle_count; ++t) {
                    const uint32_t *tr = &s->triangles[3 * t];
                    const float *a = &s->positions[3 * tr[0]], *b = &s->positions[3 * tr[1]],
                                *cc = &s->positions[3 * tr[2]];
                    int in_list = 0;
                    for (uint32_t i = start[c]; i < end[c] && !in_list; ++i)
                        in_list = ids[i] == t;
                    if (!in_list && tri_box_overlap(a, b, cc, centre, half))
                        ++missing;
                    if (in_list && !tri_box_overlap(a, b, cc, centre, wide) && loose++ < 3)
                        fprintf(stderr, "%s: triangle %u listed in cell (%u %u %u)\n", name, t, x,
                                y, z);
                }
            }
    CHECK(missing == 0, "%s: %u (cell, triangle) overlaps missing from the grid", name, missing);
    CHECK(loose == 0, "%s: %u listed triangles do not touch their cell", name, loose);
    CHECK(unordered == 0, "%s: %u cell lists not ascending", name, unordered);
    free(listed);
    free(start);
    free(end);
    free(ids);
}

static void run_scene(vct_context *ctx, vct_scene *s, const uint32_t *res, uint32_t rays, int cells,
                      const char *name) {
    vct_error err = {0};
    vct_accel_options o = {VCT_ACCEL_GRID, {0, 0, 0}, VCT_BVH_PLOC, VCT_BVH_LEVELS_AUTO};
    if (res)
        memcpy(o.grid_res, res, sizeof o.grid_res);
    vct_accel *a = vct_accel_build(ctx, s, &o, &err);
    REQUIRE_OK(a ? VCT_OK : err.status, err);
    const vct_grid *g = a->grid;
    printf("%s: %u triangles, grid %ux%ux%u, %u references\n", name, s->triangle_count, g->res[0],
           g->res[1], g->res[2], g->references);
    if (cells)
        check_cells(ctx, s, g, name);
    check_rays(ctx, s, a, rays, 42, name);
    vct_accel_release(a);
}

int main(void) {
    vct_context *ctx = check_context();
    const float origin[3] = {0, 0, 0}, far_centre[3] = {1e5f, -2e5f, 3e5f};
    const vct_accel_options grid = {VCT_ACCEL_GRID, {0, 0, 0}, VCT_BVH_PLOC, VCT_BVH_LEVELS_AUTO};

    test_mesh soup = mesh_soup(1500, 0.0f, 7);
    vct_scene *s = scene_of(&soup);
    run_scene(ctx, s, NULL, 4000, 1, "soup");
    const uint32_t coarse[3] = {1, 1, 1}, fine[3] = {37, 5, 64};
    run_scene(ctx, s, coarse, 2000, 1, "soup, one cell");
    run_scene(ctx, s, fine, 4000, 1, "soup, 37x5x64");
    CHECK(s->degenerate_triangles >= 15, "soup: %u degenerate triangles counted",
          s->degenerate_triangles);
    vct_scene_release(s);
    mesh_free(&soup);

    test_mesh far_soup = mesh_soup(800, 1e5f, 9);
    s = scene_of(&far_soup);
    run_scene(ctx, s, NULL, 3000, 1, "soup at 1e5");
    vct_scene_release(s);
    mesh_free(&far_soup);

    test_mesh sphere = mesh_icosphere(3, 1.0f, origin);
    s = scene_of(&sphere);
    run_scene(ctx, s, NULL, 3000, 1, "icosphere");
    vct_scene_release(s);
    check_watertight(ctx, &sphere, origin, &grid, "icosphere watertight");
    mesh_free(&sphere);

    test_mesh far_sphere = mesh_icosphere(3, 10.0f, far_centre);
    check_watertight(ctx, &far_sphere, far_centre, &grid, "icosphere at 3e5 watertight");
    mesh_free(&far_sphere);

    char path[1024];
    const char *src = getenv("VCT_SOURCE_DIR");
    snprintf(path, sizeof path, "%s/scenes/cornell_box.obj", src ? src : ".");
    vct_error err = {0};
    s = vct_scene_load(path, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    run_scene(ctx, s, NULL, 4000, 1, "cornell box");
    vct_scene_release(s);

    vct_context_release(ctx);
    return check_exit("test_grid");
}
