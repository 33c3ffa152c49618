/* Ray queries of any acceleration structure against a double-precision
 * brute force over every triangle, and rays through a closed mesh's shared
 * vertices and edges that must not leak. */
#ifndef VCT_TEST_RAY_CHECK_H
#define VCT_TEST_RAY_CHECK_H

#include <float.h>
#include <math.h>
#include <string.h>

#include "check.h"
#include "mesh_gen.h"
#include "ray_ref.h"
#include "raytrace/ray_packets.h"

static vct_scene *scene_of(const test_mesh *m) {
    vct_error err = {0};
    uint32_t *mats = calloc(m->nt, 4);
    vct_scene *s = vct_scene_from_arrays(m->pos, m->nv, m->tri, m->nt, mats, NULL, 0, &err);
    free(mats);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    return s;
}

/* Random rays (some axis-parallel, some starting inside the scene) against
 * the brute force; disagreements are allowed only for grazing hits within
 * 1e-5 (barycentric) of a triangle's border. */
static void check_rays(vct_context *ctx, const vct_scene *s, const vct_accel *g, uint32_t n,
                       uint64_t seed, const char *name) {
    float *rays = malloc(32ull * n);
    vct_hit *hits = malloc(sizeof *hits * n);
    float lo[3], ext[3];
    double extent = 0;
    for (int k = 0; k < 3; ++k) {
        ext[k] = s->bounds_max[k] - s->bounds_min[k];
        lo[k] = s->bounds_min[k] - 0.25f * ext[k];
        extent = fmax(extent, ext[k]);
    }
    for (uint32_t i = 0; i < n; ++i) {
        float *r = &rays[8 * i];
        double len = 0;
        for (int k = 0; k < 3; ++k) {
            r[k] = lo[k] + 1.5f * ext[k] * check_randf(&seed);
            r[4 + k] = check_randf(&seed) * 2.0f - 1.0f;
        }
        if (i % 7 == 0) /* axis-parallel: zero direction components */
            r[4 + (i / 7) % 3] = 0.0f, r[4 + (i / 7 + 1) % 3] = 0.0f;
        for (int k = 0; k < 3; ++k)
            len += (double)r[4 + k] * r[4 + k];
        if (len == 0)
            r[4] = 1.0f, len = 1;
        for (int k = 0; k < 3; ++k)
            r[4 + k] = (float)(r[4 + k] / sqrt(len));
        r[3] = 0.0f;
        r[7] = INFINITY;
    }
    vct_error err = {0};
    REQUIRE_OK(vct_trace_rays(ctx, g, rays, n, 0, hits, &err), err);
    /* Any-hit (occlusion) queries agree with closest hits on hit or miss. */
    vct_hit *any = malloc(sizeof *any * n);
    REQUIRE_OK(vct_trace_rays(ctx, g, rays, n, 1, any, &err), err);
    uint32_t any_wrong = 0;
    for (uint32_t i = 0; i < n; ++i)
        any_wrong += (any[i].t >= 0) != (hits[i].t >= 0) ||
                     (any[i].t >= 0 && any[i].t < hits[i].t * (1.0f - 1e-6f));
    CHECK(any_wrong == 0, "%s: %u any-hit answers disagree with closest hits", name, any_wrong);
    free(any);
    uint32_t wrong = 0, grazing = 0, hits_ref = 0;
    for (uint32_t i = 0; i < n; ++i) {
        const float *r = &rays[8 * i];
        double o[3] = {r[0], r[1], r[2]}, d[3] = {r[4], r[5], r[6]};
        double best = INFINITY;
        int any_grazing = 0;
        for (uint32_t t = 0; t < s->triangle_count; ++t) {
            const uint32_t *tr = &s->triangles[3 * t];
            double border = 1.0;
            double th = ref_intersect(o, d, &s->positions[3 * tr[0]], &s->positions[3 * tr[1]],
                                      &s->positions[3 * tr[2]], &border);
            if (fabs(border) < 1e-5)
                any_grazing = 1;
            if (th > 0 && th < best)
                best = th;
        }
        double got = hits[i].t >= 0 ? hits[i].t : INFINITY;
        hits_ref += isfinite(best);
        int agree = (!isfinite(best) && !isfinite(got)) ||
                    (isfinite(best) && isfinite(got) &&
                     fabs(best - got) <= 1e-5 * (extent + fabs(o[0]) + fabs(o[1]) + fabs(o[2])));
        if (!agree && any_grazing) {
            ++grazing;
        } else if (!agree && wrong++ < 5) {
            fprintf(stderr, "%s: ray %u: traced t=%.9g, brute force t=%.9g\n", name, i, got, best);
        }
    }
    CHECK(wrong == 0, "%s: %u of %u rays disagree with the brute force", name, wrong, n);
    CHECK(hits_ref > n / 20, "%s: only %u rays hit anything: a weak test", name, hits_ref);
    printf("%s: %u rays, %u hits, %u grazing disagreements tolerated\n", name, n, hits_ref,
           grazing);
    free(rays);
    free(hits);
}

/* Rays aimed exactly at vertices and edge midpoints of a closed mesh, from
 * inside and from outside: each must hit. */
static void check_watertight(vct_context *ctx, const test_mesh *m, const float centre[3],
                             const vct_accel_options *options, const char *name) {
    vct_scene *s = scene_of(m);
    vct_error err = {0};
    vct_accel *g = vct_accel_build(ctx, s, options, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    uint32_t n = m->nv + 3 * m->nt;
    float *rays = malloc(32ull * 2 * n);
    vct_hit *hits = malloc(sizeof *hits * 2 * n);
    for (uint32_t i = 0; i < n; ++i) {
        float target[3];
        if (i < m->nv) {
            memcpy(target, &m->pos[3 * i], 12);
        } else {
            uint32_t e = i - m->nv, t = e / 3, k = e % 3;
            const float *a = &m->pos[3 * m->tri[3 * t + k]],
                        *b = &m->pos[3 * m->tri[3 * t + (k + 1) % 3]];
            for (int c = 0; c < 3; ++c)
                target[c] = 0.5f * a[c] + 0.5f * b[c];
        }
        float *in = &rays[16 * i], *out = &rays[16 * i + 8];
        for (int c = 0; c < 3; ++c) {
            /* From inside: centre towards the target. */
            in[c] = centre[c];
            in[4 + c] = target[c] - centre[c];
            /* From outside: through the target towards the centre. */
            out[c] = centre[c] + 3.0f * (target[c] - centre[c]);
            out[4 + c] = centre[c] - out[c];
        }
        in[3] = out[3] = 0.0f;
        in[7] = out[7] = INFINITY;
    }
    uint32_t leaks = 0;
    for (int packets = 0; packets < 2; ++packets) { /* one by one, then 16 to a packet */
        REQUIRE_OK(
            (packets ? vct_trace_ray_packets : vct_trace_rays)(ctx, g, rays, 2 * n, 0, hits, &err),
            err);
        for (uint32_t i = 0; i < 2 * n; ++i)
            leaks += !(hits[i].t > 0);
    }
    CHECK(leaks == 0, "%s: %u of %u rays through vertices and edges leaked", name, leaks, 4 * n);
    printf("%s: %u rays through shared vertices and edges, one by one and in packets, %u leaks\n",
           name, 2 * n, leaks);
    free(rays);
    free(hits);
    vct_accel_release(g);
    vct_scene_release(s);
}

#endif
