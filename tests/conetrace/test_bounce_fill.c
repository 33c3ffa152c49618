/* Sparse bounces (kernels/conetrace/inject_bounce.cl): one bounce on the
 * Cornell box at 32^3, gathered by every voxel and by a quarter of them.
 * The voxels whose x + y + z is a multiple of 4 gather either way and must
 * agree bit for bit. Each other voxel must hold what a plain-C fill gives
 * it: the mean of what the gathering voxels one and two steps away along
 * the axes, on its own surface, received (read back from the dense bounce
 * and the direct light before it), or, with none, its own gather (the dense
 * bounce's bits). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "voxel_ref.h"

static vct_context *ctx;

typedef struct light_state {
    vct_voxels *v;
    uint32_t n;
    uint32_t *keys;
    float *albedo, *radiance, *sides;
} light_state;

static light_state prepare(const vct_scene *s, const vct_accel *g, uint32_t bounces, int dense) {
    vct_error err = {0};
    vct_plan p;
    vct_plan_make(s, NULL, &p);
    vct_voxel_options vo = vct_voxel_options_default();
    vo.resolution = 32;
    vo.exact_bounces = 1;
    vo.dense_bounces = dense;
    vct_cone_settings cones = vct_cone_settings_default();
    light_state l = {0};
    REQUIRE_OK(vct_vct_prepare(ctx, s, g, &p, &vo, NULL, bounces, &cones, &l.v, &err), err);
    vct_voxel_info info;
    vct_voxels_info_get(l.v, &info);
    l.n = info.voxels;
    l.keys = malloc(4ull * l.n);
    l.albedo = malloc(16ull * l.n);
    l.radiance = malloc(16ull * l.n);
    l.sides = malloc(32ull * l.n);
    REQUIRE_OK(vct_voxels_read(ctx, l.v, l.keys, l.albedo, NULL, NULL, &err), err);
    REQUIRE_OK(vct_voxels_read_radiance(ctx, l.v, l.radiance, &err), err);
    REQUIRE_OK(vct_voxels_read_sides(ctx, l.v, l.sides, &err), err);
    return l;
}

static void release(light_state *l) {
    vct_voxels_release(l->v);
    free(l->keys);
    free(l->albedo);
    free(l->radiance);
    free(l->sides);
}

static double luminance(const double c[3]) {
    return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
}

static int find(const uint32_t *keys, uint32_t n, uint32_t key) {
    uint32_t lo = 0, hi = n;
    while (lo < hi) {
        const uint32_t mid = lo + (hi - lo) / 2;
        if (keys[mid] < key)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < n && keys[lo] == key ? (int)lo : -1;
}

/* What voxel u's front (along its direct plane's normal) and back received
 * in the dense bounce: its sides' light less the direct light, over its
 * albedo. 0 where the albedo cannot be divided by. */
static int received(const light_state *direct, const light_state *bounce, int u, double front[3],
                    double back[3]) {
    const float *ds = direct->sides + 8 * u, *bs = bounce->sides + 8 * u;
    const float *r = bounce->radiance + 4 * u, *d = direct->radiance + 4 * u;
    const int same = ds[4] * bs[4] + ds[5] * bs[5] + ds[6] * bs[6] > 0.0f;
    for (int c = 0; c < 3; ++c) {
        const double rho = direct->albedo[4 * u + c];
        if (!(rho > 1e-3))
            return 0;
        const double bright = r[c], dark = r[c] - bs[c];
        const double toward = same ? bright : dark, away = same ? dark : bright;
        front[c] = (toward - d[c]) / rho;
        back[c] = (away - (d[c] - ds[c])) / rho;
    }
    return 1;
}

int main(void) {
    ctx = check_context();
    vct_error err = {0};
    vct_scene *box = check_cornell_box();
    vct_accel *g = vct_accel_build(ctx, box, NULL, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    light_state direct = prepare(box, g, 1, 1), dense = prepare(box, g, 2, 1),
                sparse = prepare(box, g, 2, 0);
    const uint32_t n = direct.n;
    CHECK(dense.n == n && sparse.n == n && !memcmp(direct.keys, dense.keys, 4ull * n) &&
              !memcmp(direct.keys, sparse.keys, 4ull * n),
          "the three builds voxelize alike: %u, %u, %u voxels", n, dense.n, sparse.n);
    int gatherers_differ = 0, filled = 0, fill_wrong = 0, own = 0, own_differ = 0, skipped = 0;
    double worst = 0.0;
    for (uint32_t v = 0; v < n; ++v) {
        int64_t c[3];
        ref_unmorton(direct.keys[v], c);
        const int skips = (c[0] + c[1] + c[2]) % 4 != 0;
        const int bits_equal = !memcmp(dense.radiance + 4 * v, sparse.radiance + 4 * v, 16) &&
                               !memcmp(dense.sides + 8 * v, sparse.sides + 8 * v, 32);
        if (!skips) {
            gatherers_differ += !bits_equal;
            continue;
        }
        const float *pv = direct.sides + 8 * v + 4;
        const int has_normal = pv[0] != 0.0f || pv[1] != 0.0f || pv[2] != 0.0f;
        double front[3] = {0}, back[3] = {0};
        int found = 0, known = 1;
        for (int k = 0; k < 12; ++k) {
            int64_t q[3] = {c[0], c[1], c[2]};
            q[k % 3] += (k % 6 < 3 ? 1 : -1) * (k < 6 ? 1 : 2);
            if (q[k % 3] < 0 || q[k % 3] >= 32 || (q[0] + q[1] + q[2]) % 4 != 0)
                continue;
            const int u =
                find(direct.keys, n, ref_morton((uint32_t)q[0], (uint32_t)q[1], (uint32_t)q[2]));
            if (u < 0)
                continue;
            const float *pu = direct.sides + 8 * u + 4;
            const int u_normal = pu[0] != 0.0f || pu[1] != 0.0f || pu[2] != 0.0f;
            if (u_normal != has_normal)
                continue;
            const double facing = has_normal ? pu[0] * pv[0] + pu[1] * pv[1] + pu[2] * pv[2] : 1.0;
            const int same = facing > 0.95, flipped = facing < -0.95;
            const double offset = 0.1 / 32.0;
            if (has_normal && !((same && fabs(pu[3] - pv[3]) < offset) ||
                                (flipped && fabs(pu[3] + pv[3]) < offset)))
                continue;
            double f[3] = {0}, b[3] = {0};
            known &= received(&direct, &dense, u, f, b);
            for (int ch = 0; ch < 3; ++ch) {
                front[ch] += flipped ? b[ch] : f[ch];
                back[ch] += flipped ? f[ch] : b[ch];
            }
            ++found;
        }
        if (!found) {
            ++own;
            own_differ += !bits_equal;
            continue;
        }
        if (!has_normal || !known) { /* a voxel without a plane sends its brighter side both ways */
            ++skipped;
            continue;
        }
        /* the fill's two sides, then the brighter one as the radiance */
        double toward[3], away[3];
        const float *d = direct.radiance + 4 * v, *ds = direct.sides + 8 * v;
        for (int ch = 0; ch < 3; ++ch) {
            const double rho = direct.albedo[4 * v + ch];
            toward[ch] = d[ch] + rho * front[ch] / found;
            away[ch] = d[ch] - ds[ch] + rho * back[ch] / found;
        }
        const double *bright = luminance(away) > luminance(toward) ? away : toward;
        const float *got = sparse.radiance + 4 * v;
        double e = 0.0;
        for (int ch = 0; ch < 3; ++ch)
            e = fmax(e, fabs(got[ch] - bright[ch]) / fmax(fabs(bright[ch]), 1e-3));
        worst = fmax(worst, e);
        ++filled;
        if (e > 1e-3 && fill_wrong++ < 3)
            fprintf(stderr, "voxel (%lld %lld %lld): %g %g %g, expected %g %g %g (%d neighbours)\n",
                    (long long)c[0], (long long)c[1], (long long)c[2], got[0], got[1], got[2],
                    bright[0], bright[1], bright[2], found);
    }
    CHECK(gatherers_differ == 0, "%d gathering voxels differ from the dense bounce",
          gatherers_differ);
    CHECK(fill_wrong == 0 && filled > (int)n / 2,
          "%d of %d filled voxels differ from the plain-C fill (worst %.3g)", fill_wrong, filled,
          worst);
    CHECK(own_differ == 0,
          "%d of %d voxels with no neighbour on their surface differ from their "
          "own gather",
          own_differ, own);
    printf("sparse bounce: %u voxels, %d filled (worst relative difference %.2g), %d gathered "
           "alone, %d without a plane\n",
           n, filled, worst, own, skipped);
    release(&direct);
    release(&dense);
    release(&sparse);
    vct_accel_release(g);
    vct_scene_release(box);
    vct_context_release(ctx);
    return check_exit("test_bounce_fill");
}
