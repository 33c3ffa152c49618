/* Light injection against analytic direct light: a plane through the
 * centres of one voxel layer under a point light (with and without an
 * occluder), a directional light, emission, and a moved light re-injected
 * without re-voxelizing. Radiance = albedo / pi * I cos(theta) / d^2. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "mesh_gen.h"
#include "voxel_ref.h"

#define RES 16
#define PLANE_Z 8.5 /* voxel centres of layer 8 (bounds [0, 16]^3: a voxel is a unit) */

static vct_context *ctx;

typedef struct inject_case {
    vct_scene *scene;
    vct_accel *accel;
    vct_voxels *voxels;
    vct_voxel_info info;
    uint32_t *keys;
    float *radiance;
    float *sides; /* vct_voxels_read_sides: 8 per voxel */
} inject_case;

static void case_free(inject_case *c) {
    vct_voxels_release(c->voxels);
    vct_accel_release(c->accel);
    vct_scene_release(c->scene);
    free(c->keys);
    free(c->radiance);
    free(c->sides);
}

static void inject(inject_case *c) {
    vct_error err = {0};
    REQUIRE_OK(vct_voxels_inject_light(ctx, c->scene, c->accel, c->voxels, &err), err);
    REQUIRE_OK(vct_voxels_read_radiance(ctx, c->voxels, c->radiance, &err), err);
    REQUIRE_OK(vct_voxels_read_sides(ctx, c->voxels, c->sides, &err), err);
}

/* The grid and the voxels of c.scene in [0, 16]^3, its voxel keys read
 * back (the previous ones released). */
static void case_build(inject_case *c) {
    vct_error err = {0};
    vct_accel_release(c->accel);
    vct_voxels_release(c->voxels);
    free(c->keys);
    free(c->radiance);
    free(c->sides);
    c->accel = vct_accel_build(ctx, c->scene, NULL, &err);
    REQUIRE_OK(c->accel ? VCT_OK : err.status, err);
    vct_voxel_options o = {0};
    o.resolution = RES;
    o.has_bounds = 1;
    o.bounds_size = RES;
    c->voxels = vct_voxelize(ctx, c->scene, &o, &err);
    REQUIRE_OK(c->voxels ? VCT_OK : err.status, err);
    vct_voxels_info_get(c->voxels, &c->info);
    c->keys = malloc(4ull * c->info.voxels);
    c->radiance = malloc(16ull * c->info.voxels);
    c->sides = malloc(32ull * c->info.voxels);
    REQUIRE_OK(vct_voxels_read(ctx, c->voxels, c->keys, NULL, NULL, NULL, &err), err);
}

/* Plane z = PLANE_Z over [0, 16]^2 facing +z, plus an optional occluder
 * square at z = 11.5 over [3, 9]^2 and a material for the plane. */
static inject_case make_case(int occluder, const vct_material *plane_material) {
    const float pos[] = {0, 0, PLANE_Z, 16, 0, PLANE_Z, 16, 16, PLANE_Z, 0, 16, PLANE_Z,
                         3, 3, 11.5f,   9,  3, 11.5f,   9,  9,  11.5f,   3, 9,  11.5f};
    const uint32_t tri[] = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
    const uint32_t mat[] = {0, 0, 1, 1};
    vct_material m[2] = {*plane_material, vct_material_default()};
    vct_error err = {0};
    inject_case c = {0};
    c.scene = vct_scene_from_arrays(pos, 8, tri, occluder ? 4 : 2, mat, m, 2, &err);
    REQUIRE_OK(c.scene ? VCT_OK : err.status, err);
    case_build(&c);
    return c;
}

static void decode(uint32_t key, uint32_t cell[3]) {
    cell[0] = cell[1] = cell[2] = 0;
    for (int b = 0; b < 10; ++b)
        for (int k = 0; k < 3; ++k)
            cell[k] |= ((key >> (3 * b + k)) & 1u) << b;
}

/* Where the segment from p to the light crosses z = 11.5: inside the
 * occluder (1), clear of it (0), or within `margin` of its edge (-1). */
static int shadowed(const double p[3], const double light[3], double margin) {
    const double t = (11.5 - p[2]) / (light[2] - p[2]);
    const double x = p[0] + t * (light[0] - p[0]), y = p[1] + t * (light[1] - p[1]);
    const double inside = fmin(fmin(x - 3, 9 - x), fmin(y - 3, 9 - y));
    return inside > margin ? 1 : (inside < -margin ? 0 : -1);
}

/* Checks every plane voxel against I cos / d^2 * albedo / pi (0 in shadow).
 * A light of radius r widens the band left out around the shadow's edge by
 * r (the occluder lies halfway between plane and light), and inside that
 * band some voxels must see part of the light. */
static void check_point_light(const char *name, inject_case *c, const double light[3],
                              double intensity, int occluder, float radius) {
    vct_light l = {VCT_LIGHT_POINT, {0}, {0, 0, 0}, {0}, 0, 0, radius};
    for (int k = 0; k < 3; ++k) {
        l.position[k] = (float)light[k];
        l.color[k] = (float)intensity;
    }
    c->scene->light_count = 0;
    vct_error err = {0};
    REQUIRE_OK(vct_scene_add_light(c->scene, &l, &err), err);
    inject(c);
    const double albedo = c->scene->materials[0].albedo[0];
    int checked = 0, bad = 0, dark = 0, partial = 0;
    double worst = 0.0;
    for (uint32_t v = 0; v < c->info.voxels; ++v) {
        uint32_t cell[3];
        decode(c->keys[v], cell);
        if (cell[2] != 8)
            continue; /* the occluder's own voxels */
        const double p[3] = {cell[0] + 0.5, cell[1] + 0.5, PLANE_Z};
        const double d[3] = {light[0] - p[0], light[1] - p[1], light[2] - p[2]};
        const double dist = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        double expected = albedo / CHECK_PI * intensity * (fabs(d[2]) / dist) / (dist * dist);
        if (occluder) {
            /* Shadow rays start up to a voxel off the centre: edges are
             * only known to a voxel. */
            const int s = shadowed(p, light, 1.0 + radius);
            if (s < 0) {
                const double got = c->radiance[4 * v];
                partial += got > 0.05 * expected && got < 0.95 * expected;
                continue;
            }
            if (s) {
                expected = 0.0;
                ++dark;
            }
        }
        const double got = c->radiance[4 * v];
        const double rel = fabs(got - expected) / fmax(expected, 1e-6);
        worst = fmax(worst, expected > 0 ? rel : fabs(got));
        if (!(expected > 0 ? rel < 1e-4 : got == 0.0) && bad++ < 3)
            CHECK(0, "%s: voxel (%u %u %u) radiance %g, expected %g", name, cell[0], cell[1],
                  cell[2], got, expected);
        ++checked;
    }
    /* A radius leaves out a wider band: fewer voxels are known exactly. */
    const int enough = radius > 0.0f ? 30 : 150, enough_dark = radius > 0.0f ? 4 : 50;
    CHECK(checked >= enough && bad == 0, "%s: %d of %d voxels wrong", name, bad, checked);
    if (occluder)
        CHECK(dark >= enough_dark, "%s: %d voxels in the occluder's shadow", name, dark);
    if (radius > 0.0f)
        CHECK(partial >= 20, "%s: %d voxels see part of the light", name, partial);
    printf("%-34s %3d voxels checked (%d in shadow, %d partly lit), worst relative error %.2g\n",
           name, checked, dark, partial, worst);
}

/* A floor at z = 4.5 under a slab over [2, 14]^2 whose two faces lie at
 * z = bottom and z = top, each wound up (+z) or down as `winding` bits 0 and
 * 1 say, and the light above it. Voxels holding only the dark face, and the
 * floor in the slab's shadow, get nothing; voxels holding the lit face get
 * the analytic light at their centres, also when they hold both faces: the
 * sides the faces turn into the slab are hidden, and the mean is over the
 * lit face's upper side and the dark face's lower one. That light is
 * one-sided: it leaves upwards only (vct_voxels_read_sides: the difference
 * to the dark side is all of it, the brighter side's normal +z, its plane
 * the faces' mean height). Returns the radiance. */
static float *thin_slab(const char *name, float bottom, float top, unsigned winding,
                        uint32_t *voxels) {
    const float pos[] = {0, 0, 4.5f,   16, 0, 4.5f,   16, 16, 4.5f,   0, 16, 4.5f,
                         2, 2, bottom, 14, 2, bottom, 14, 14, bottom, 2, 14, bottom,
                         2, 2, top,    14, 2, top,    14, 14, top,    2, 14, top};
    const uint32_t up[] = {0, 1, 2, 0, 2, 3}, down[] = {0, 2, 1, 0, 3, 2};
    uint32_t tri[18], mat[6] = {0};
    for (int i = 0; i < 6; ++i) {
        tri[i] = up[i];
        tri[6 + i] = 4 + ((winding & 1u) ? down[i] : up[i]);
        tri[12 + i] = 8 + ((winding & 2u) ? down[i] : up[i]);
    }
    vct_material white = vct_material_default();
    vct_error err = {0};
    inject_case c = {0};
    c.scene = vct_scene_from_arrays(pos, 12, tri, 6, mat, &white, 1, &err);
    REQUIRE_OK(c.scene ? VCT_OK : err.status, err);
    const double light[3] = {8.3, 7.7, 14.5}, intensity = 100.0;
    vct_light l = {VCT_LIGHT_POINT, {8.3f, 7.7f, 14.5f}, {0}, {100, 100, 100}, 0, 0, 0};
    REQUIRE_OK(vct_scene_add_light(c.scene, &l, &err), err);
    case_build(&c);
    inject(&c);
    const uint32_t lit_layer = (uint32_t)top, dark_layer = (uint32_t)bottom;
    const int shared = lit_layer == dark_layer;
    int lit = 0, dark = 0, floor_dark = 0, bad = 0;
    for (uint32_t v = 0; v < c.info.voxels; ++v) {
        uint32_t cell[3];
        decode(c.keys[v], cell);
        const double p[3] = {cell[0] + 0.5, cell[1] + 0.5, cell[2] + 0.5};
        const int inner = cell[0] >= 3 && cell[0] <= 12 && cell[1] >= 3 && cell[1] <= 12;
        const double got = c.radiance[4 * v];
        double expected = -1.0; /* not known exactly: left out */
        if (cell[2] == 4) {
            /* where the segment to the light crosses z = 9 */
            const double t = (9.0 - p[2]) / (light[2] - p[2]);
            const double x = p[0] + t * (light[0] - p[0]), y = p[1] + t * (light[1] - p[1]);
            if (fmin(fmin(x - 2, 14 - x), fmin(y - 2, 14 - y)) > 1.0) {
                expected = 0.0;
                ++floor_dark;
            }
        } else if (inner && cell[2] == lit_layer) {
            const double d[3] = {light[0] - p[0], light[1] - p[1], light[2] - p[2]};
            const double dist = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            expected = 0.8 / CHECK_PI * intensity * (d[2] / dist) / (dist * dist);
            ++lit;
        } else if (inner && cell[2] == dark_layer) {
            expected = 0.0;
            ++dark;
        }
        if (expected < 0.0)
            continue;
        int ok = expected > 0.0 ? fabs(got - expected) < 1e-4 * expected : got == 0.0;
        const float *side = c.sides + 8 * v;
        if (inner && cell[2] == lit_layer) {
            /* the faces in the voxel: the lit one, and the dark one too when they share it */
            const double height = shared ? 0.5 * (bottom + top) : top;
            const double plane = height / RES - 0.5;
            ok &= fabs(side[0] - expected) < 1e-4 * expected && side[6] > 0.9999f &&
                  fabs(side[7] - plane) < 1e-5;
            if (!ok && bad < 3)
                fprintf(stderr, "%s: sides %g (normal z %g, plane %g), expected %g (+1, %g)\n",
                        name, side[0], side[6], side[7], expected, plane);
        } else if (expected == 0.0) {
            ok &= side[0] == 0.0f && side[3] == 0.0f;
        }
        if (!ok && bad++ < 3)
            CHECK(0, "%s: voxel (%u %u %u) radiance %g, expected %g", name, cell[0], cell[1],
                  cell[2], got, expected);
    }
    CHECK(bad == 0 && lit >= 100 && floor_dark >= 60 && (shared || dark >= 100),
          "%s: %d wrong (%d lit, %d dark, %d floor voxels in shadow)", name, bad, lit, dark,
          floor_dark);
    printf("%-34s %d lit%s, %d dark, %d floor voxels in shadow\n", name, lit,
           shared ? " (both faces in one voxel)" : "", dark, floor_dark);
    float *out = c.radiance;
    c.radiance = NULL;
    *voxels = c.info.voxels;
    case_free(&c);
    return out;
}

/* The plane lit on both faces, by a light above (intensity 100) and a
 * dimmer one below (30, elsewhere): each face sends out its own light's
 * I cos / d^2 * albedo / pi, the brighter one as the radiance, and the
 * sides hold the difference, the upper face's normal and the plane's
 * height. Both windings. */
static void two_faces(void) {
    const double above[3] = {8.3, 7.7, 14.5}, below[3] = {5.2, 9.9, 3.0};
    const double power[2] = {100.0, 30.0};
    const double plane = PLANE_Z / RES - 0.5;
    for (int wound = 0; wound < 2; ++wound) {
        vct_material white = vct_material_default();
        inject_case c = make_case(0, &white);
        for (uint32_t t = 0; t < c.scene->triangle_count && wound; ++t) {
            const uint32_t keep = c.scene->triangles[3 * t + 1];
            c.scene->triangles[3 * t + 1] = c.scene->triangles[3 * t + 2];
            c.scene->triangles[3 * t + 2] = keep;
        }
        case_build(&c);
        vct_error err = {0};
        for (int i = 0; i < 2; ++i) {
            const double *at = i ? below : above;
            vct_light l = {VCT_LIGHT_POINT, {0}, {0, 0, 0}, {0}, 0, 0, 0};
            for (int k = 0; k < 3; ++k) {
                l.position[k] = (float)at[k];
                l.color[k] = (float)power[i];
            }
            REQUIRE_OK(vct_scene_add_light(c.scene, &l, &err), err);
        }
        inject(&c);
        const double albedo = white.albedo[0];
        double worst = 0.0;
        int bad = 0;
        for (uint32_t v = 0; v < c.info.voxels; ++v) {
            uint32_t cell[3];
            decode(c.keys[v], cell);
            const double p[3] = {cell[0] + 0.5, cell[1] + 0.5, PLANE_Z};
            double face[2];
            for (int i = 0; i < 2; ++i) {
                const double *at = i ? below : above;
                const double d[3] = {at[0] - p[0], at[1] - p[1], at[2] - p[2]};
                const double dist = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                face[i] = albedo / CHECK_PI * power[i] * (fabs(d[2]) / dist) / (dist * dist);
            }
            const double up = fmax(face[0], face[1]), down = fmin(face[0], face[1]);
            const float *side = c.sides + 8 * v;
            const double e =
                fmax(fabs(c.radiance[4 * v] - up) / up, fabs(side[0] - (up - down)) / up);
            worst = fmax(worst, e);
            const int normal_up = face[0] >= face[1] ? side[6] > 0.9999f : side[6] < -0.9999f;
            const int ok = e < 1e-4 && normal_up && fabs(fabs(side[7]) - fabs(plane)) < 1e-5;
            if (!ok && bad++ < 3)
                CHECK(0,
                      "two faces, wound %d: voxel (%u %u) radiance %g shade %g normal z %g "
                      "plane %g, expected %g %g (facing the brighter light) %g",
                      wound, cell[0], cell[1], c.radiance[4 * v], side[0], side[6], side[7], up,
                      up - down, plane);
        }
        CHECK(bad == 0, "two faces, wound %d: %d voxels wrong", wound, bad);
        /* The voxel view shows each face from its own side: from above the
         * upper light's, from below the lower's (at the voxel (8, 7) the
         * centre rays meet). */
        REQUIRE_OK(vct_octree_build(ctx, c.voxels, &err), err);
        for (int from_below = 0; from_below < 2; ++from_below) {
            const float eye[3] = {8.5f, 7.5f, from_below ? 2.0f : 15.0f};
            const float look[3] = {8.5f, 7.5f, (float)PLANE_Z}, up[3] = {0, 1, 0};
            memcpy(c.scene->camera.position, eye, sizeof eye);
            memcpy(c.scene->camera.look_at, look, sizeof look);
            memcpy(c.scene->camera.up, up, sizeof up);
            c.scene->camera.fov_y_deg = 20.0f;
            vct_image im = {0};
            REQUIRE_OK(vct_render_voxels(ctx, c.scene, c.voxels, 9, 9, &im, &err), err);
            const double *at = from_below ? below : above;
            const double d[3] = {at[0] - 8.5, at[1] - 7.5, at[2] - PLANE_Z};
            const double dist = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            const double want =
                albedo / CHECK_PI * power[from_below] * (fabs(d[2]) / dist) / (dist * dist);
            const float got = im.rgba[4 * (4 * 9 + 4)];
            CHECK(fabs(got - want) < 1e-4 * want,
                  "two faces, wound %d: the voxel view from %s shows %g, expected %g", wound,
                  from_below ? "below" : "above", got, want);
            vct_image_release(&im);
        }
        printf("plane lit on both faces, wound %d  %u voxels, worst relative error %.2g\n", wound,
               c.info.voxels, worst);
        case_free(&c);
    }
}

/* Thin walls lit from one side stay dark on the other, for every winding
 * of their faces, and every winding gives the same radiance. */
static void thin_walls(void) {
    const struct {
        const char *name;
        float bottom, top;
    } walls[] = {{"slab across two voxel layers", 8.8f, 9.2f},
                 {"slab inside one voxel layer", 8.3f, 8.7f}};
    for (int w = 0; w < 2; ++w) {
        float *first = NULL;
        uint32_t count = 0;
        for (unsigned winding = 0; winding < 4; ++winding) {
            char name[96];
            snprintf(name, sizeof name, "%s, winding %u", walls[w].name, winding);
            uint32_t voxels = 0;
            float *r = thin_slab(name, walls[w].bottom, walls[w].top, winding, &voxels);
            if (!first) {
                first = r;
                count = voxels;
                continue;
            }
            double diff = voxels == count ? 0.0 : INFINITY;
            for (size_t i = 0; i < 4ull * count && voxels == count; ++i)
                if (r[i] != first[i])
                    diff = fmax(diff, fabs(r[i] - first[i]));
            CHECK(diff == 0.0, "%s: differs from winding 0 by %g", name, diff);
            free(r);
        }
        free(first);
    }
}

/* Irradiance at (x, y) on the plane from a square of radiance L over
 * [4, 12]^2, h under it, integrated on a fine grid. */
static double square_irradiance(double x, double y, double h, double L) {
    const int grid = 200;
    double E = 0.0;
    for (int j = 0; j < grid; ++j)
        for (int i = 0; i < grid; ++i) {
            const double dx = 4.0 + 8.0 * (i + 0.5) / grid - x,
                         dy = 4.0 + 8.0 * (j + 0.5) / grid - y;
            const double d2 = dx * dx + dy * dy + h * h;
            E += L * (h * h / d2) / d2 * (64.0 / ((double)grid * grid));
        }
    return E;
}

/* An emissive square (radiance L, over [4, 12]^2) parallel to the plane,
 * `below` units under it. Returns the ratio of the plane's radiance over the
 * square's central 8 x 8 voxels to albedo / pi times the irradiance there;
 * *worst: the largest radiance over the square's inner 6 x 6 voxels;
 * *rim: the sum of the radiance of the voxels over its edge and the ring
 * around it (up to a voxel from the edge); *beside: the same ratio as
 * returned over the plane's voxels further out. */
static double panel_under_plane(double below, double L, double albedo, double *worst, double *rim,
                                double *beside) {
    const float z = (float)(PLANE_Z - below);
    const float pos[] = {0, 0, PLANE_Z, 16, 0, PLANE_Z, 16, 16, PLANE_Z, 0, 16, PLANE_Z,
                         4, 4, z,       12, 4, z,       12, 12, z,       4, 12, z};
    const uint32_t tri[] = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
    const uint32_t mat[] = {0, 0, 1, 1};
    vct_material m[2] = {vct_material_default(), vct_material_default()};
    m[1].albedo[0] = m[1].albedo[1] = m[1].albedo[2] = 0.0f;
    m[1].emission[0] = m[1].emission[1] = m[1].emission[2] = (float)L;
    vct_error err = {0};
    inject_case c = {0};
    c.scene = vct_scene_from_arrays(pos, 8, tri, 4, mat, m, 2, &err);
    REQUIRE_OK(c.scene ? VCT_OK : err.status, err);
    case_build(&c);
    inject(&c);
    double got = 0.0, expected = 0.0, got_beside = 0.0, expected_beside = 0.0;
    *worst = *rim = 0.0;
    for (uint32_t v = 0; v < c.info.voxels; ++v) {
        uint32_t cell[3];
        decode(c.keys[v], cell);
        if (cell[2] != 8)
            continue;
        const double want =
            albedo / CHECK_PI * square_irradiance(cell[0] + 0.5, cell[1] + 0.5, below, L);
        if (cell[0] >= 4 && cell[0] < 12 && cell[1] >= 4 && cell[1] < 12) {
            got += c.radiance[4 * v];
            expected += want;
        }
        if (cell[0] >= 5 && cell[0] < 11 && cell[1] >= 5 && cell[1] < 11)
            *worst = fmax(*worst, c.radiance[4 * v]);
        else if (cell[0] >= 3 && cell[0] < 13 && cell[1] >= 3 && cell[1] < 13)
            *rim += c.radiance[4 * v];
        else {
            got_beside += c.radiance[4 * v];
            expected_beside += want;
        }
    }
    case_free(&c);
    *beside = expected_beside > 0.0 ? got_beside / expected_beside : -1.0;
    return expected > 0.0 ? got / expected : -1.0;
}

/* A panel hung a third of a voxel under the plane lights the plane over it
 * only in the gap between them, and shares the plane's voxels there: none
 * of that light may show (it would glow on the panel's face) but what
 * leaves through the gap's rim: per unit of rim, pi albedo L g 0.40 (the
 * share of a half plane's light that gets out of a slit g high,
 * inject_light.cl's gap_escape), sent out by the voxels the rim crosses
 * over their face, with the light of the band beside the rim that sees the
 * panel's upper face edge-on within a voxel of it (the half plane's
 * irradiance integrated over the band): their radiance sums to albedo L
 * (g 0.40 + (w + g - 1) / 2) times the perimeter (32 voxels), w =
 * sqrt(1 - g^2). Beyond a voxel from its edge, the plane sees the
 * panel's upper face edge-on and gets albedo / pi times that irradiance: a
 * ceiling's share of a panel hung under it. Three voxels under it, its
 * light on the plane is albedo / pi times the irradiance of the square.
 * The emitter's light is exact where nothing occludes it (Lambert's formula
 * for a scene of few emitter triangles): within 1 % of the reference's
 * numerical integral. */
static void trapped_light(void) {
    const double L = 2.0, albedo = 0.8, gap = 1.0 / 3.0;
    double worst, rim, beside;
    panel_under_plane(gap, L, albedo, &worst, &rim, &beside);
    CHECK(worst < 0.01 * albedo * L,
          "a panel a third of a voxel under the plane: voxels over it up to %.4g (unhidden, up "
          "to about %.3g)",
          worst, albedo * L);
    /* and the band beside the rim within a voxel of the panel, whose
     * fragments are taken as trapped: the half plane's light there, albedo
     * L (w + g - 1) / 2 per unit of rim, w = sqrt(1 - g^2) */
    const double band = 0.5 * (sqrt(1.0 - gap * gap) + gap - 1.0);
    const double escape = albedo * L * (gap * 0.40 + band) * 32.0;
    CHECK(fabs(rim / escape - 1.0) < 0.01,
          "a panel a third of a voxel under the plane: its rim's voxels send out %.4g, expected "
          "%.4g",
          rim, escape);
    CHECK(fabs(beside - 1.0) < 0.01,
          "a panel a third of a voxel under the plane: %.4f of the light beside it", beside);
    printf("%-34s over it at most %.2g, its rim %.4f of the escape, beside it %.4f of the light "
           "there\n",
           "panel a third of a voxel under", worst, rim / escape, beside);
    double unused, unused_rim;
    const double ratio = panel_under_plane(3.0, L, albedo, &worst, &unused_rim, &unused);
    CHECK(fabs(ratio - 1.0) < 0.01,
          "a panel three voxels under the plane: %.4f of the light over it", ratio);
    printf("%-34s %.4f of the light over it\n", "panel three voxels under", ratio);
}

/* A sphere's facets lie side by side, nearly parallel, a little apart
 * along their normals: none hides another's side, as a closed thin object's
 * faces do. Under a sun straight down of irradiance pi each fragment sends
 * out albedo cos(theta) <= albedo, so no voxel may send out more than the
 * albedo, and the voxels over the top come close to it. */
static void curved_facets(void) {
    const float centre[3] = {8.0f, 8.0f, 8.0f};
    test_mesh t = mesh_icosphere(4, 5.0f, centre);
    uint32_t *mat = calloc(t.nt, sizeof *mat);
    vct_material white = vct_material_default();
    vct_error err = {0};
    inject_case c = {0};
    c.scene = vct_scene_from_arrays(t.pos, t.nv, t.tri, t.nt, mat, &white, 1, &err);
    REQUIRE_OK(c.scene ? VCT_OK : err.status, err);
    free(mat);
    mesh_free(&t);
    const vct_light sun = {
        VCT_LIGHT_DIRECTIONAL, {0}, {0, 0, -1}, {3.14159265f, 3.14159265f, 3.14159265f}, 0, 0, 0};
    REQUIRE_OK(vct_scene_add_light(c.scene, &sun, &err), err);
    case_build(&c);
    inject(&c);
    const double albedo = white.albedo[0];
    double brightest = 0.0;
    int over = 0;
    for (uint32_t v = 0; v < c.info.voxels; ++v) {
        brightest = fmax(brightest, c.radiance[4 * v]);
        over += c.radiance[4 * v] > albedo * (1.0 + 1e-4);
    }
    CHECK(over == 0 && brightest > 0.9 * albedo,
          "sphere's facets: %d of %u voxels send out more than the albedo (brightest %g of %g)",
          over, c.info.voxels, brightest, albedo);
    printf("%-34s %u voxels, brightest %.4f of the albedo's %.4f\n", "sphere's facets",
           c.info.voxels, brightest, albedo);
    case_free(&c);
}

/* A voxel sends the area-weighted mean of what its surfaces reflect, so
 * how a surface is cut into triangles does not change it: a closed slab a
 * fifth of a voxel thick (a blind's slat) under a light straight above, its
 * two edges (the strips joining its faces along y) once two triangles each
 * and once 64 quads each. The voxels along the edges hold half a voxel of
 * each face and a fifth of one of the edge; weighed by their count, the
 * cut edges' many dark fragments took most of the lit face's light from
 * those voxels (a slat's 2 mm edges counted as much as its 3 cm faces). */
static float *slab_light(int cuts, inject_case *c) {
    enum { PIECES = 64 };
    const float x0 = 2.5f, x1 = 13.5f, z0 = 8.4f, z1 = 8.6f;
    const int pieces = cuts ? PIECES : 1, quads = 2 + 2 * pieces;
    float *pos = malloc(sizeof(float) * 12 * (size_t)quads);
    uint32_t *tri = malloc(sizeof(uint32_t) * 6 * (size_t)quads);
    uint32_t *mat = calloc(2 * (size_t)quads, sizeof(uint32_t));
    const float faces[24] = {x0, 0, z1, x1, 0,  z1, x1, 16, z1, x0, 16, z1,  /* top */
                             x0, 0, z0, x0, 16, z0, x1, 16, z0, x1, 0,  z0}; /* bottom */
    memcpy(pos, faces, sizeof faces);
    int q = 2;
    for (int e = 0; e < 2; ++e) /* the edges at x0 and x1, cut along y */
        for (int k = 0; k < pieces; ++k, ++q) {
            const float x = e ? x1 : x0, ya = 16.0f * k / pieces, yb = 16.0f * (k + 1) / pieces;
            const float w[12] = {x, ya, z0, x, yb, z0, x, yb, z1, x, ya, z1};
            memcpy(pos + 12 * q, w, sizeof w);
        }
    const uint32_t quad[6] = {0, 1, 2, 0, 2, 3};
    for (int k = 0; k < quads; ++k)
        for (int i = 0; i < 6; ++i)
            tri[6 * k + i] = 4u * (uint32_t)k + quad[i];
    vct_material white = vct_material_default();
    vct_error err = {0};
    *c = (inject_case){0};
    c->scene = vct_scene_from_arrays(pos, 4u * (uint32_t)quads, tri, 2u * (uint32_t)quads, mat,
                                     &white, 1, &err);
    REQUIRE_OK(c->scene ? VCT_OK : err.status, err);
    const vct_light sun = {VCT_LIGHT_DIRECTIONAL, {0}, {0, 0, -1}, {2, 2, 2}, 0, 0, 0};
    REQUIRE_OK(vct_scene_add_light(c->scene, &sun, &err), err);
    case_build(c);
    inject(c);
    float *radiance = malloc(16ull * c->info.voxels);
    memcpy(radiance, c->radiance, 16ull * c->info.voxels);
    free(pos);
    free(tri);
    free(mat);
    return radiance;
}

static void tessellation_invariant(void) {
    inject_case whole, cut;
    float *a = slab_light(0, &whole), *b = slab_light(1, &cut);
    CHECK(whole.info.voxels == cut.info.voxels, "the cut slab voxelizes alike (%u, %u voxels)",
          whole.info.voxels, cut.info.voxels);
    double worst = 0.0, edge = 0.0;
    for (uint32_t v = 0; v < whole.info.voxels && whole.info.voxels == cut.info.voxels; ++v) {
        uint32_t cell[3];
        decode(whole.keys[v], cell);
        worst = fmax(worst, fabs(a[4 * v] - b[4 * v]) / fmax(a[4 * v], 1e-3));
        if (cell[0] == 2 || cell[0] == 13)
            edge = fmax(edge, a[4 * v]);
    }
    CHECK(worst < 1e-3 && edge > 0.0,
          "a slab's edges cut into 128 triangles change its voxels' light by up to %.3g of it",
          worst);
    printf("%-34s %u voxels, worst relative difference %.2g\n", "slab edges cut into triangles",
           whole.info.voxels, worst);
    free(a);
    free(b);
    case_free(&whole);
    case_free(&cut);
}

int main(void) {
    ctx = check_context();
    trapped_light();
    curved_facets();
    vct_material white = vct_material_default();
    const double light[3] = {8.3, 7.7, 14.5}, moved[3] = {3.1, 12.6, 13.0};

    inject_case c = make_case(0, &white);
    CHECK(c.info.voxels == RES * RES, "the plane makes one layer: %u voxels", c.info.voxels);
    check_point_light("point light", &c, light, 100.0, 0, 0.0f);
    float *wound_up = malloc(16ull * c.info.voxels);
    memcpy(wound_up, c.radiance, 16ull * c.info.voxels);
    /* A moved light: re-injected, nothing re-voxelized. */
    check_point_light("point light, moved", &c, moved, 250.0, 0, 0.0f);
    case_free(&c);
    /* The same plane wound the other way sends out the same light. */
    c = make_case(0, &white);
    for (uint32_t t = 0; t < c.scene->triangle_count; ++t) {
        const uint32_t keep = c.scene->triangles[3 * t + 1];
        c.scene->triangles[3 * t + 1] = c.scene->triangles[3 * t + 2];
        c.scene->triangles[3 * t + 2] = keep;
    }
    case_build(&c);
    check_point_light("point light, winding reversed", &c, light, 100.0, 0, 0.0f);
    double winding_diff = 0.0;
    for (uint32_t i = 0; i < 4 * c.info.voxels; ++i)
        winding_diff = fmax(winding_diff, fabs(c.radiance[i] - wound_up[i]));
    CHECK(winding_diff == 0.0, "winding reversed: radiance differs by up to %g", winding_diff);
    free(wound_up);
    /* A directional light at 60 degrees from the normal: E cos / pi * albedo everywhere. */
    vct_light sun = {VCT_LIGHT_DIRECTIONAL, {0}, {0.0f, -0.8660254f, -0.5f}, {2, 2, 2}, 0, 0, 0};
    c.scene->light_count = 0;
    vct_error err = {0};
    REQUIRE_OK(vct_scene_add_light(c.scene, &sun, &err), err);
    inject(&c);
    const double expected = white.albedo[0] / CHECK_PI * 2.0 * 0.5;
    double worst = 0.0;
    for (uint32_t v = 0; v < c.info.voxels; ++v)
        worst = fmax(worst, fabs(c.radiance[4 * v] - expected) / expected);
    CHECK(worst < 1e-5, "directional light: worst relative error %g", worst);
    /* Two-sided: a light under the plane lights it as its mirror image
     * above does. */
    const double mirrored[3] = {light[0], light[1], 2.0 * PLANE_Z - 3.0};
    check_point_light("point light, mirrored below", &c, mirrored, 100.0, 0, 0.0f);
    case_free(&c);

    c = make_case(1, &white);
    check_point_light("point light, occluder", &c, light, 100.0, 1, 0.0f);
    check_point_light("light of radius 1.5, occluder", &c, light, 100.0, 1, 1.5f);
    case_free(&c);

    /* An emissive plane is sampled as an area light: it cannot light itself
     * (its own samples lie in its plane), and its voxels leave its emission
     * out, which cones would otherwise count a second time. */
    vct_material lamp = white;
    lamp.emission[0] = 3.0f;
    lamp.emission[1] = 2.0f;
    lamp.emission[2] = 1.0f;
    c = make_case(0, &lamp);
    c.scene->light_count = 0;
    inject(&c);
    int wrong = 0;
    for (uint32_t v = 0; v < c.info.voxels; ++v)
        wrong += c.radiance[4 * v] != 0.0f || c.radiance[4 * v + 1] != 0.0f ||
                 c.radiance[4 * v + 2] != 0.0f;
    CHECK(wrong == 0, "emissive voxels hold no emission (%d wrong)", wrong);
    case_free(&c);
    thin_walls();
    two_faces();
    tessellation_invariant();
    vct_context_release(ctx);
    return check_exit("test_inject");
}
