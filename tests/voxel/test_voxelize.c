/* Voxelization against the plain-C reference (voxel_ref.h): the same voxel
 * set, fragment counts and averaged attributes on random soups, a sphere, a
 * far-offset mesh and hard cases, plus analytic counts where geometry sits
 * exactly on voxel faces, edges and the volume's boundary. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "runtime/runtime.h"
#include "voxel/voxels.h"
#include "mesh_gen.h"
#include "voxel_ref.h"

static vct_context *ctx;

static const vct_material test_materials[3] = {
    {"red", {0.9f, 0.1f, 0.1f}, {0, 0, 0}, {0, 0, 0}, 0, 1, 0, 1.5f, 0, 0, 1, 0},
    {"lamp", {0.5f, 0.5f, 0.5f}, {4, 3, 2}, {0, 0, 0}, 0, 1, 0, 1.5f, 0, 0, 1, 0},
    {"glass", {0.2f, 0.6f, 0.9f}, {0, 0, 0}, {0, 0, 0}, 0, 0, 0.75f, 1.5f, 0, 0, 1, 0},
};

/* Below this area (in voxel faces) a voxel's means are plain, not weighted:
 * its fragments only touch it (the kernel's CLIP_AREA_WEIGHED_MIN). */
#define VCT_AREA_WEIGHED_MIN 1e-6

static vct_scene *scene_of(const float *pos, uint32_t nv, const uint32_t *tri, uint32_t nt) {
    uint32_t *mat = malloc(4ull * (nt ? nt : 1));
    for (uint32_t t = 0; t < nt; ++t)
        mat[t] = t % 3;
    vct_error err = {0};
    vct_scene *s = vct_scene_from_arrays(pos, nv, tri, nt, mat, test_materials, 3, &err);
    free(mat);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    return s;
}

static vct_scene *scene_of_mesh(const test_mesh *m) {
    return scene_of(m->pos, m->nv, m->tri, m->nt);
}

/* Bounds [0, res]^3 by hand, so that world units are voxels. */
/* The eigenvalues of a symmetric 3x3 m by cyclic Jacobi rotations (each
 * zeroes one off-diagonal entry), with the eigenvector of the largest in
 * `axis`; *gap: its distance to the next. Returns the largest. */
static double ref_principal_axis(double m[3][3], double axis[3], double *gap) {
    double a[3][3], v[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    memcpy(a, m, sizeof a);
    for (int sweep = 0; sweep < 50; ++sweep) {
        const double off = fabs(a[0][1]) + fabs(a[0][2]) + fabs(a[1][2]);
        if (off < 1e-300)
            break;
        for (int p = 0; p < 2; ++p)
            for (int q = p + 1; q < 3; ++q) {
                if (a[p][q] == 0.0)
                    continue;
                const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                const double t =
                    (theta >= 0 ? 1.0 : -1.0) / (fabs(theta) + sqrt(theta * theta + 1));
                const double c = 1.0 / sqrt(t * t + 1), s = t * c;
                for (int k = 0; k < 3; ++k) { /* a = J^T a J, v = v J */
                    const double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < 3; ++k) {
                    const double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                for (int k = 0; k < 3; ++k) {
                    const double vkp = v[k][p], vkq = v[k][q];
                    v[k][p] = c * vkp - s * vkq;
                    v[k][q] = s * vkp + c * vkq;
                }
            }
    }
    int top = 0;
    for (int k = 1; k < 3; ++k)
        top = a[k][k] > a[top][top] ? k : top;
    double next = -INFINITY;
    for (int k = 0; k < 3; ++k)
        if (k != top)
            next = fmax(next, a[k][k]);
    for (int k = 0; k < 3; ++k)
        axis[k] = v[k][top];
    *gap = a[top][top] - next;
    return a[top][top];
}

static vct_voxel_options unit_voxels(uint32_t res, int thin) {
    vct_voxel_options o = {0};
    o.resolution = res;
    o.thin = thin;
    o.has_bounds = 1;
    o.bounds_size = res;
    return o;
}

static vct_voxel_options auto_voxels(uint32_t res, int thin) {
    vct_voxel_options o = {0};
    o.resolution = res;
    o.thin = thin;
    return o;
}

/* Voxelizes s, compares every voxel and attribute with the reference;
 * returns the voxel count. */
static uint32_t check_against_reference(const char *name, const vct_scene *s,
                                        const vct_voxel_options *o) {
    vct_error err = {0};
    vct_voxels *v = vct_voxelize(ctx, s, o, &err);
    REQUIRE_OK(v ? VCT_OK : err.status, err);
    vct_voxel_info info;
    vct_voxels_info_get(v, &info);
    ref_voxels r = ref_voxelize(s, &info, o->thin);
    CHECK(info.voxels == r.voxels, "%s: %u voxels, reference %u", name, info.voxels, r.voxels);
    CHECK(info.fragments == r.count, "%s: %u fragments, reference %zu", name, info.fragments,
          r.count);
    const uint32_t n = info.voxels < r.voxels ? info.voxels : r.voxels;
    uint32_t *keys = malloc(4ull * (info.voxels + 1));
    float *albedo = malloc(16ull * (info.voxels + 1)), *normal = malloc(16ull * (info.voxels + 1)),
          *emission = malloc(16ull * (info.voxels + 1));
    REQUIRE_OK(vct_voxels_read(ctx, v, keys, albedo, normal, emission, &err), err);
    int key_bad = 0, attr_bad = 0;
    for (uint32_t i = 0; i < n; ++i) {
        if (keys[i] != r.keys[i]) {
            if (key_bad++ < 5)
                CHECK(0, "%s: voxel %u key %u, reference %u", name, i, keys[i], r.keys[i]);
            continue;
        }
        /* albedo and emission: means weighted by each fragment's area
         * inside the voxel (plain means where none has any); opacity: the
         * opaque share of that area, at most 1 */
        double a[4] = {0}, e[3] = {0}, aw[3] = {0}, ew[3] = {0}, area = 0.0, m[3][3] = {{0}};
        const uint32_t count = r.first[i + 1] - r.first[i];
        int64_t cell[3];
        ref_unmorton(r.keys[i], cell);
        for (uint32_t f = r.first[i]; f < r.first[i + 1]; ++f) {
            const uint32_t t = r.frags[f].tri;
            const vct_material *mat = &s->materials[s->triangle_material[t]];
            int64_t q[3][3];
            ref_quantise(s, &info, t, q);
            const double inside = ref_area_in_voxel(q, cell, info.units / info.resolution);
            double e0[3], e1[3], len = 0.0, nn[3];
            for (int k = 0; k < 3; ++k) {
                a[k] += mat->albedo[k];
                e[k] += mat->emission[k];
                aw[k] += inside * mat->albedo[k];
                ew[k] += inside * mat->emission[k];
                e0[k] = (double)(q[1][k] - q[0][k]);
                e1[k] = (double)(q[2][k] - q[1][k]);
            }
            area += inside;
            a[3] += inside * (1.0 - mat->transmission);
            nn[0] = e0[1] * e1[2] - e0[2] * e1[1];
            nn[1] = e0[2] * e1[0] - e0[0] * e1[2];
            nn[2] = e0[0] * e1[1] - e0[1] * e1[0];
            len = sqrt(nn[0] * nn[0] + nn[1] * nn[1] + nn[2] * nn[2]);
            /* two-sided: n n^T is the same for either winding */
            for (int j = 0; j < 3; ++j)
                for (int k = 0; k < 3; ++k)
                    m[j][k] += len > 0 ? nn[j] * nn[k] / (len * len) : 0.0;
        }
        double axis[3], gap;
        const double top = ref_principal_axis(m, axis, &gap);
        double worst = fabs(emission[4 * i + 3] - count);
        /* the device clips in float: on a corner of area A cut from a
         * triangle hundreds of voxels long, the weights carry about 1e-6 / A
         * of error, which the weighted means may show beyond 1e-4 */
        const int weighed = area > VCT_AREA_WEIGHED_MIN;
        const double slack = weighed ? 1e-4 / (1e-4 + 1e-6 / area) : 1.0;
        for (int k = 0; k < 3; ++k) {
            worst = fmax(worst,
                         slack * fabs(albedo[4 * i + k] - (weighed ? aw[k] / area : a[k] / count)));
            worst = fmax(
                worst,
                slack * fabs(emission[4 * i + k] - (weighed ? ew[k] / area : e[k] / count)) / 4.0);
        }
        worst = fmax(worst, fabs(albedo[4 * i + 3] - fmin(a[3], 1.0)));
        /* the axis, where the largest eigenvalue stands clear of the next;
         * its sign: its largest component positive */
        const float *got = &normal[4 * i];
        if (gap > 0.25 * top) {
            const double along = fabs(got[0] * axis[0] + got[1] * axis[1] + got[2] * axis[2]);
            worst = fmax(worst, 1.0 - along);
        }
        int big = 0;
        for (int k = 1; k < 3; ++k)
            big = fabsf(got[k]) > fabsf(got[big]) ? k : big;
        worst = fmax(worst, got[big] < 0.0f ? 1.0 : 0.0);
        /* how well the axis fits: sqrt(axis . m axis / count), which where
         * the two largest eigenvalues nearly tie lies between theirs */
        const double fit = normal[4 * i + 3];
        if (gap > 0.25 * top)
            worst = fmax(worst, fabs(fit - sqrt(top / count)));
        else
            worst = fmax(worst, fmax(fit - sqrt(top / count), sqrt((top - gap) / count) - fit));
        if (!(worst < 1e-4) && attr_bad++ < 5)
            CHECK(0,
                  "%s: voxel %u (key %u, %u fragments) attributes off by %g (area %g; albedo %g %g "
                  "%g %g, expected %g %g %g %g)",
                  name, i, keys[i], count, worst, area, albedo[4 * i], albedo[4 * i + 1],
                  albedo[4 * i + 2], albedo[4 * i + 3], weighed ? aw[0] / area : a[0] / count,
                  weighed ? aw[1] / area : a[1] / count, weighed ? aw[2] / area : a[2] / count,
                  fmin(a[3], 1.0));
    }
    CHECK(key_bad == 0 && attr_bad == 0, "%s: %d keys and %d attribute sets differ", name, key_bad,
          attr_bad);
    free(keys);
    free(albedo);
    free(normal);
    free(emission);
    ref_free(&r);
    const uint32_t voxels = info.voxels;
    vct_voxels_release(v);
    printf("%-34s %2s %4u^3: %7u voxels, %7u fragments\n", name, o->thin ? "6" : "26",
           o->resolution, voxels, info.fragments);
    return voxels;
}

static void test_random_and_sphere(void) {
    test_mesh soup = mesh_soup(3000, 0.0f, 7);
    vct_scene *s = scene_of_mesh(&soup);
    const uint32_t res[] = {2, 16, 64, 256};
    for (int i = 0; i < 4; ++i) {
        vct_voxel_options o = auto_voxels(res[i], 0);
        check_against_reference("random soup", s, &o);
        o.thin = 1;
        check_against_reference("random soup", s, &o);
    }
    vct_scene_release(s);
    mesh_free(&soup);

    const float centre[3] = {0.5f, 0.5f, 0.5f};
    test_mesh sphere = mesh_icosphere(4, 0.4f, centre);
    s = scene_of_mesh(&sphere);
    vct_voxel_options o = auto_voxels(128, 0);
    const uint32_t near = check_against_reference("icosphere", s, &o);
    o.thin = 1;
    const uint32_t thin = check_against_reference("icosphere", s, &o);
    CHECK(thin < near, "thin voxels (%u) are fewer than conservative ones (%u)", thin, near);
    vct_scene_release(s);
    mesh_free(&sphere);

    /* The same sphere a million units away: as many voxels, give or take
     * the float spacing of its vertices there (1/16). */
    const float far_centre[3] = {1e6f, 1e6f + 500.0f, 1e6f};
    test_mesh far = mesh_icosphere(4, 400.0f, far_centre);
    s = scene_of_mesh(&far);
    o = auto_voxels(128, 0);
    const uint32_t far_voxels = check_against_reference("icosphere offset by 1e6", s, &o);
    CHECK(fabs((double)far_voxels - near) < 0.02 * near, "offset sphere: %u voxels, near %u",
          far_voxels, near);
    vct_scene_release(s);
    mesh_free(&far);
}

/* Counts voxels of s at unit bounds and checks the analytic expectation
 * (expected < 0: reference only). */
static uint32_t check_unit_case(const char *name, const float *pos, uint32_t nt, uint32_t res,
                                long expected, int thin) {
    uint32_t *tri = malloc(12ull * nt);
    for (uint32_t i = 0; i < 3 * nt; ++i)
        tri[i] = i;
    vct_scene *s = scene_of(pos, 3 * nt, tri, nt);
    vct_voxel_options o = unit_voxels(res, thin);
    const uint32_t got = check_against_reference(name, s, &o);
    if (expected >= 0)
        CHECK(got == (uint32_t)expected, "%s: %u voxels, expected %ld", name, got, expected);
    vct_scene_release(s);
    free(tri);
    return got;
}

static void test_hard_cases(void) {
    /* An axis-aligned quad on the face z = 3: both layers of closed boxes,
     * x and y from 0 (touching x = 1) to 5. */
    const float quad_z[] = {1, 1, 3, 5, 1, 3, 5, 5, 3, 1, 1, 3, 5, 5, 3, 1, 5, 3};
    check_unit_case("quad on a voxel face", quad_z, 2, 16, 6 * 6 * 2, 0);
    check_unit_case("quad on a voxel face", quad_z, 2, 16, -1, 1);
    /* A triangle in the plane x = 4 with an edge along the voxel edge y = 4. */
    const float on_edge[] = {4, 4, 1, 4, 4, 9, 4, 8.5f, 5};
    check_unit_case("triangle with an edge on voxel edges", on_edge, 1, 16, -1, 0);
    check_unit_case("triangle with an edge on voxel edges", on_edge, 1, 16, -1, 1);
    /* A segment-like triangle lying along a voxel edge line. */
    const float along[] = {2, 3, 3, 12, 3, 3, 7, 3.25f, 3};
    check_unit_case("triangle along a voxel edge line", along, 1, 16, -1, 0);
    /* A sliver along the diagonal: edges (N, N + 1) and (N - 1, N) in units
     * of 1/16384 with N = 10 voxels, area half a unit, aspect about 5e10. It
     * passes through the 11 diagonal voxels and, above each voxel corner,
     * one more. */
    const float u = 1.0f / 16384.0f;
    const float sliver[] = {0.5f, 0.5f, 0.5f, 10.5f, 10.5f + u, 0.5f, 10.5f - u, 10.5f, 0.5f};
    CHECK(check_unit_case("sliver, aspect 5e10", sliver, 1, 16, 21, 0) == 21, "sliver voxels");
    check_unit_case("sliver, aspect 5e10", sliver, 1, 16, -1, 1);
    /* Zero-area triangles (repeated and collinear vertices): no surface. */
    const float zero[] = {1, 1, 1, 1, 1, 1, 5, 5, 5, 1, 2, 3, 2, 3, 4, 3, 4, 5};
    check_unit_case("zero-area triangles", zero, 2, 16, 0, 0);
    /* Smaller than a voxel, inside voxel (3, 4, 5). */
    const float tiny[] = {3.2f, 4.2f, 5.2f, 3.3f, 4.2f, 5.2f, 3.2f, 4.3f, 5.25f};
    check_unit_case("triangle smaller than a voxel", tiny, 1, 16, 1, 0);
    check_unit_case("triangle smaller than a voxel", tiny, 1, 16, 1, 1);
    /* On the volume's faces x = 0 and x = 16: one layer each. */
    const float walls[] = {0,  0, 0, 0,  16, 0, 0,  16, 16, 0,  0, 0, 0,  16, 16, 0,  0, 16,
                           16, 0, 0, 16, 16, 0, 16, 16, 16, 16, 0, 0, 16, 16, 16, 16, 0, 16};
    check_unit_case("quads on the volume's faces", walls, 4, 16, 2 * 16 * 16, 0);
    /* Partly and wholly outside: cut at the faces, or nothing. */
    const float outside[] = {-3, 2, 2, 8, 2, 2, 8, 9, 2, 20, 1, 1, 30, 1, 1, 25, 9, 1};
    check_unit_case("triangles partly and wholly outside", outside, 2, 16, -1, 0);
    /* One triangle across the whole volume: thousands of columns, split into chunks. */
    const float big[] = {0.3f, 0.2f, 63.1f, 63.7f, 0.9f, 0.4f, 31.5f, 63.9f, 31.0f};
    check_unit_case("one triangle across the volume", big, 1, 64, -1, 0);
    check_unit_case("one triangle across the volume", big, 1, 64, -1, 1);
}

/* 1200 small triangles in one voxel, of three materials: one voxel holding
 * the means weighted by the triangles' areas (each lies wholly inside it),
 * with no counter that saturates. */
static void test_many_fragments(void) {
    const uint32_t n = 1200;
    float *pos = malloc(36ull * n);
    uint32_t *tri = malloc(12ull * n);
    uint64_t seed = 11;
    double area[3] = {0, 0, 0};
    for (uint32_t t = 0; t < n; ++t) {
        for (int i = 0; i < 9; ++i)
            pos[9 * t + i] = 5.1f + 0.8f * check_randf(&seed);
        for (int i = 0; i < 3; ++i)
            tri[3 * t + i] = 3 * t + i;
        const float *p = pos + 9 * t;
        const double u[3] = {p[3] - p[0], p[4] - p[1], p[5] - p[2]};
        const double w[3] = {p[6] - p[0], p[7] - p[1], p[8] - p[2]};
        const double c[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                             u[0] * w[1] - u[1] * w[0]};
        area[t % 3] += 0.5 * sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    }
    vct_scene *s = scene_of(pos, 3 * n, tri, n);
    vct_voxel_options o = unit_voxels(16, 0);
    CHECK(check_against_reference("1200 fragments in one voxel", s, &o) == 1,
          "1200 fragments make one voxel");
    vct_error err = {0};
    vct_voxels *v = vct_voxelize(ctx, s, &o, &err);
    REQUIRE_OK(v ? VCT_OK : err.status, err);
    float albedo[4], emission[4];
    REQUIRE_OK(vct_voxels_read(ctx, v, NULL, albedo, NULL, emission, &err), err);
    /* materials t % 3 (test_materials): albedo.r 0.9, 0.5, 0.2, emission.r
     * 0, 4, 0; the area they cover is some 30 voxel faces, so opaque */
    const double total = area[0] + area[1] + area[2];
    const double want_albedo = (0.9 * area[0] + 0.5 * area[1] + 0.2 * area[2]) / total;
    CHECK(fabs(emission[3] - 1200.0) < 0.5, "fragment count %g", emission[3]);
    CHECK(fabs(albedo[0] - want_albedo) < 1e-4, "albedo %g, expected %g", albedo[0], want_albedo);
    CHECK(total > 2.0 && albedo[3] == 1.0f, "opacity %g of area %g", albedo[3], total);
    CHECK(fabs(emission[0] - 4.0 * area[1] / total) < 1e-4, "emission %g, expected %g", emission[0],
          4.0 * area[1] / total);
    vct_voxels_release(v);
    vct_scene_release(s);
    free(pos);
    free(tri);
}

static void test_determinism_and_errors(void) {
    vct_scene *s = check_cornell_box();
    vct_voxel_options o = auto_voxels(256, 0);
    check_against_reference("Cornell box", s, &o);
    vct_error err = {0};
    vct_voxels *a = vct_voxelize(ctx, s, &o, &err);
    vct_voxels *b = a ? vct_voxelize(ctx, s, &o, &err) : NULL;
    REQUIRE_OK(b ? VCT_OK : err.status, err);
    vct_voxel_info info;
    vct_voxels_info_get(a, &info);
    const size_t n = info.voxels;
    float *fa = malloc(48 * n), *fb = malloc(48 * n);
    uint32_t *ka = malloc(4 * n), *kb = malloc(4 * n);
    REQUIRE_OK(vct_voxels_read(ctx, a, ka, fa, fa + 4 * n, fa + 8 * n, &err), err);
    REQUIRE_OK(vct_voxels_read(ctx, b, kb, fb, fb + 4 * n, fb + 8 * n, &err), err);
    CHECK(memcmp(ka, kb, 4 * n) == 0 && memcmp(fa, fb, 48 * n) == 0,
          "two voxelizations of the Cornell box are bit-identical");
    /* The same with the GPU-shaped scan and sort kernels. */
    vct_voxels_release(b);
    setenv("VCT_TUNING", "gpu", 1);
    vct_context *gpu_shaped = check_context();
    unsetenv("VCT_TUNING");
    b = vct_voxelize(gpu_shaped, s, &o, &err);
    REQUIRE_OK(b ? VCT_OK : err.status, err);
    REQUIRE_OK(vct_voxels_read(gpu_shaped, b, kb, fb, fb + 4 * n, fb + 8 * n, &err), err);
    CHECK(memcmp(ka, kb, 4 * n) == 0 && memcmp(fa, fb, 48 * n) == 0,
          "CPU- and GPU-shaped kernels voxelize the Cornell box bit-identically");
    vct_voxels_release(b);
    b = NULL;
    vct_context_release(gpu_shaped);
    free(fa);
    free(fb);
    free(ka);
    free(kb);
    vct_voxels_release(a);
    vct_voxels_release(b);

    o.resolution = 100;
    CHECK(vct_voxelize(ctx, s, &o, &err) == NULL && err.status == VCT_ERR_INPUT &&
              strstr(err.message, "power of two"),
          "resolution 100 refused: %s", err.message);
    o.resolution = 2048;
    CHECK(vct_voxelize(ctx, s, &o, &err) == NULL && err.status == VCT_ERR_INPUT,
          "resolution 2048 refused: %s", err.message);
    vct_scene_release(s);

    /* A triangle that crosses the bounds and reaches far beyond them. */
    const float far[] = {1, 1, 1, 1e4f, 1, 1, 1, 9, 1};
    const uint32_t tri[] = {0, 1, 2};
    s = scene_of(far, 3, tri, 1);
    o = unit_voxels(16, 0);
    CHECK(vct_voxelize(ctx, s, &o, &err) == NULL && err.status == VCT_ERR_INPUT &&
              strstr(err.message, "--voxel-bounds"),
          "far-reaching triangle refused: %s", err.message);
    vct_scene_release(s);
}

/* Voxelizing only what moved (vct_voxelize_moved: the fragments of the
 * rest kept, the moved triangles' merged in) gives the voxels a full
 * voxelization gives, bit for bit: count, keys, albedo, normals, emission,
 * and each voxel's fragments in the same order. Over several moves in a row,
 * each update taking the one before. */
static void read_fragments(const vct_voxels *v, uint32_t **start, uint32_t **tri) {
    vct_error err = {0};
    *start = malloc(4ull * v->info.voxels + 4);
    *tri = malloc(4ull * v->info.fragments + 4);
    REQUIRE_OK(
        vct_buffer_read(ctx, "test", v->fragment_start, 0, 4ull * v->info.voxels, *start, &err),
        err);
    REQUIRE_OK(
        vct_buffer_read(ctx, "test", v->fragment_tri, 0, 4ull * v->info.fragments, *tri, &err),
        err);
}

static uint32_t voxels_differ(const vct_voxels *a, const vct_voxels *b) {
    if (a->info.voxels != b->info.voxels || a->info.fragments != b->info.fragments)
        return UINT32_MAX;
    vct_error err = {0};
    const uint32_t n = a->info.voxels;
    uint32_t *ka = malloc(4ull * n + 4), *kb = malloc(4ull * n + 4);
    float *fa = malloc(48ull * n + 16), *fb = malloc(48ull * n + 16);
    REQUIRE_OK(vct_voxels_read(ctx, a, ka, fa, fa + 4ull * n, fa + 8ull * n, &err), err);
    REQUIRE_OK(vct_voxels_read(ctx, b, kb, fb, fb + 4ull * n, fb + 8ull * n, &err), err);
    uint32_t *sa, *ta, *sb, *tb;
    read_fragments(a, &sa, &ta);
    read_fragments(b, &sb, &tb);
    uint32_t differ = 0;
    for (uint32_t v = 0; v < n; ++v)
        differ += ka[v] != kb[v] || sa[v] != sb[v] ||
                  memcmp(&fa[4ull * v], &fb[4ull * v], 16) != 0 ||
                  memcmp(&fa[4ull * (n + v)], &fb[4ull * (n + v)], 16) != 0 ||
                  memcmp(&fa[4ull * (2 * n + v)], &fb[4ull * (2 * n + v)], 16) != 0;
    for (uint32_t f = 0; f < a->info.fragments; ++f)
        differ += ta[f] != tb[f];
    free(ka), free(kb), free(fa), free(fb), free(sa), free(ta), free(sb), free(tb);
    return differ;
}

static void check_moved(const char *file, uint32_t instance, uint32_t resolution) {
    vct_error err = {0};
    vct_scene *s = check_scene_file(file);
    vct_voxel_options o = vct_voxel_options_default();
    o.resolution = resolution;
    vct_voxels *before = vct_voxelize(ctx, s, &o, &err);
    REQUIRE_OK(before ? VCT_OK : err.status, err);
    const uint32_t lo = s->instances[instance].first_triangle,
                   hi = lo + s->meshes[s->instances[instance].mesh].triangle_count;
    for (int step = 1; step <= 3; ++step) {
        float m[12];
        memcpy(m, s->instances[instance].transform, sizeof m);
        const float extent = s->bounds_max[0] - s->bounds_min[0];
        m[3] += 0.013f * extent * (float)step; /* inside the scene's box */
        m[11] -= 0.007f * extent;
        REQUIRE_OK(vct_scene_set_instance_transform(s, instance, m, &err), err);
        vct_voxels *moved = vct_voxelize_moved(ctx, s, &o, before, lo, hi, &err);
        REQUIRE_OK(moved ? VCT_OK : err.status, err);
        vct_voxels *full = vct_voxelize(ctx, s, &o, &err);
        REQUIRE_OK(full ? VCT_OK : err.status, err);
        const uint32_t differ = voxels_differ(moved, full);
        CHECK(differ == 0 && moved->tris != NULL,
              "%s at %u^3, move %d: %u voxels or fragments differ from a full voxelization "
              "(%u and %u voxels)",
              file, resolution, step, differ, moved->info.voxels, full->info.voxels);
        vct_voxels_release(before);
        vct_voxels_release(full);
        before = moved;
    }
    printf("%s at %u^3: instance %u moved three times, voxelized alone (triangles %u..%u of %u) "
           "and merged: the voxels of a full voxelization bit for bit\n",
           file, resolution, instance, lo, hi - 1, s->triangle_count);
    vct_voxels_release(before);
    vct_scene_release(s);
}

int main(void) {
    ctx = check_context();
    test_hard_cases();
    test_many_fragments();
    test_random_and_sphere();
    test_determinism_and_errors();
    check_moved("scenes/instanced_spheres.gltf", 10, 64);
    check_moved("scenes/suite/lamp_room.gltf", 2, 128);
    vct_context_release(ctx);
    return check_exit("test_voxelize");
}
