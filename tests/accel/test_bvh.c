/* The 4-wide BVH built on the device and its traversal.
 *
 * Structure, read back and walked on the host: every triangle in exactly one
 * leaf, each leaf's box holding its triangles, each child box holding its
 * node's children, no deeper than traversal's stack. Rays, against a
 * double-precision brute force (closest and any hit, random and axis-parallel
 * rays), and through shared vertices and edges of closed meshes (no leak), on
 * the soup with slivers and degenerates, a mesh 1e5 from the origin, one
 * triangle, triangles sharing one centroid, a dense object in a large room and
 * an empty scene. The same hits as the grid, bit for bit. Refit after moving
 * every vertex gives the hits of a rebuild. */
#include "accel/accel.h"
#include "ray_check.h"
#include "raytrace/ray_packets.h"

static void box_grow(float lo[3], float hi[3], const float *p) {
    for (int k = 0; k < 3; ++k) {
        lo[k] = fminf(lo[k], p[k]);
        hi[k] = fmaxf(hi[k], p[k]);
    }
}

static int box_holds(const float lo[3], const float hi[3], const float clo[3], const float chi[3]) {
    for (int k = 0; k < 3; ++k)
        if (clo[k] < lo[k] || chi[k] > hi[k])
            return 0;
    return 1;
}

typedef struct walk {
    const float *nodes;
    const uint32_t *ids;
    const vct_scene *s;
    uint32_t *seen; /* per sorted position */
    uint32_t node_count, bad_box, bad_ref, deepest, visited;
} walk;

/* Checks node w, whose own box (as its parent holds it) is lo..hi. */
static void walk_node(walk *wk, uint32_t w, const float lo[3], const float hi[3], uint32_t depth) {
    if (w >= wk->node_count) {
        ++wk->bad_ref;
        return;
    }
    ++wk->visited;
    if (depth > wk->deepest)
        wk->deepest = depth;
    const float *nd = &wk->nodes[32 * w];
    uint32_t refs[4];
    memcpy(refs, &nd[24], sizeof refs);
    for (int c = 0; c < 4; ++c) {
        if (refs[c] == 0xFFFFFFFFu)
            continue;
        float clo[3], chi[3];
        for (int k = 0; k < 3; ++k) {
            clo[k] = nd[8 * k + c];
            chi[k] = nd[8 * k + 4 + c];
        }
        if (!box_holds(lo, hi, clo, chi))
            ++wk->bad_box;
        if (!(refs[c] & 0x80000000u)) {
            walk_node(wk, refs[c], clo, chi, depth + 1);
            continue;
        }
        const uint32_t first = refs[c] & 0x07FFFFFFu, count = ((refs[c] >> 27) & 15u) + 1u;
        for (uint32_t i = first; i < first + count; ++i) {
            if (i >= wk->s->triangle_count) {
                ++wk->bad_ref;
                continue;
            }
            ++wk->seen[i];
            const uint32_t *tr = &wk->s->triangles[3 * wk->ids[i]];
            float tlo[3] = {INFINITY, INFINITY, INFINITY},
                  thi[3] = {-INFINITY, -INFINITY, -INFINITY};
            for (int v = 0; v < 3; ++v)
                box_grow(tlo, thi, &wk->s->positions[3 * tr[v]]);
            if (!box_holds(clo, chi, tlo, thi))
                ++wk->bad_box;
        }
    }
}

static void check_structure(vct_context *ctx, const vct_scene *s, const vct_accel *a,
                            const char *name) {
    const vct_bvh *b = a->bvh;
    const uint32_t n = s->triangle_count;
    float *nodes = malloc(128ull * b->node_count);
    uint32_t *ids = malloc(4ull * (n ? n : 1)), *seen = calloc(n ? n : 1, 4);
    vct_error err = {0};
    REQUIRE_OK(vct_bvh_read(ctx, b, nodes, ids, &err), err);
    walk wk = {nodes, ids, s, seen, b->node_count, 0, 0, 0, 0};
    const float everything_lo[3] = {-INFINITY, -INFINITY, -INFINITY},
                everything_hi[3] = {INFINITY, INFINITY, INFINITY};
    walk_node(&wk, 0, everything_lo, everything_hi, 1);
    uint32_t once = 0, permutation = 1;
    char *taken = calloc(n ? n : 1, 1);
    for (uint32_t i = 0; i < n; ++i) {
        once += seen[i] == 1;
        if (ids[i] >= n || taken[ids[i]]++)
            permutation = 0;
    }
    CHECK(permutation, "%s: the sorted order is not a permutation of the triangles", name);
    CHECK(once == n, "%s: %u of %u triangles are in exactly one leaf", name, once, n);
    CHECK(wk.bad_box == 0, "%s: %u boxes do not hold what is under them", name, wk.bad_box);
    CHECK(wk.bad_ref == 0, "%s: %u refs point outside the nodes or triangles", name, wk.bad_ref);
    CHECK(wk.visited == b->node_count, "%s: %u of %u nodes reached from the root", name, wk.visited,
          b->node_count);
    CHECK(wk.deepest == b->depth && b->depth <= VCT_BVH_MAX_DEPTH,
          "%s: %u levels walked, %u reported (at most %d)", name, wk.deepest, b->depth,
          VCT_BVH_MAX_DEPTH);
    free(taken);
    free(nodes);
    free(ids);
    free(seen);
}

static float *random_rays(const vct_scene *s, uint32_t n, uint64_t seed) {
    float *rays = malloc(32ull * n);
    for (uint32_t i = 0; i < n; ++i) {
        float *r = &rays[8 * i], len = 0.0f;
        for (int k = 0; k < 3; ++k) {
            const float e = s->bounds_max[k] - s->bounds_min[k];
            r[k] = s->bounds_min[k] - 0.25f * e + 1.5f * e * check_randf(&seed);
            r[4 + k] = 2.0f * check_randf(&seed) - 1.0f;
            len += r[4 + k] * r[4 + k];
        }
        for (int k = 0; k < 3; ++k)
            r[4 + k] /= sqrtf(len);
        r[3] = 0.0f;
        r[7] = INFINITY;
    }
    return rays;
}

/* Hits of a and b on the same rays: the same triangle at the same t, bit for
 * bit, unless two triangles lie at exactly that distance. */
static void check_same_hits(vct_context *ctx, const vct_scene *s, const vct_accel *a,
                            const vct_accel *b, const char *what, const char *name) {
    const uint32_t n = 3000;
    float *rays = random_rays(s, n, 77);
    vct_hit *ha = malloc(sizeof *ha * n), *hb = malloc(sizeof *hb * n);
    vct_error err = {0};
    REQUIRE_OK(vct_trace_rays(ctx, a, rays, n, 0, ha, &err), err);
    REQUIRE_OK(vct_trace_rays(ctx, b, rays, n, 0, hb, &err), err);
    uint32_t differ = 0, ties = 0, hits = 0;
    for (uint32_t i = 0; i < n; ++i) {
        hits += ha[i].t >= 0.0f;
        if (memcmp(&ha[i].t, &hb[i].t, 4) != 0) {
            ++differ;
        } else if (ha[i].t >= 0.0f && ha[i].triangle != hb[i].triangle) {
            ++ties;
        } else if (ha[i].t >= 0.0f &&
                   (memcmp(&ha[i].u, &hb[i].u, 4) || memcmp(&ha[i].v, &hb[i].v, 4))) {
            ++differ;
        }
    }
    CHECK(differ == 0 && ties == 0,
          "%s: %u of %u rays hit differently %s (%u ties went to other triangles)", name, differ, n,
          what, ties);
    CHECK(hits > n / 20, "%s: only %u rays hit: a weak test", name, hits);
    printf("%s: %u rays, %u hits the same %s\n", name, n, hits, what);
    free(rays);
    free(ha);
    free(hb);
}

/* Bundles of 16 alike rays, as packets take them: from one point towards
 * nearby points of a random target (camera rays), and from nearby points
 * towards one point, stopping short of it (shadow rays); every third
 * bundle axis-parallel, with a lane or two turned away. */
static float *ray_bundles(const vct_scene *s, uint32_t bundles, uint64_t seed) {
    float *rays = malloc(32ull * 16 * bundles);
    float ext = 0.0f;
    for (int k = 0; k < 3; ++k)
        ext = fmaxf(ext, s->bounds_max[k] - s->bounds_min[k]);
    for (uint32_t b = 0; b < bundles; ++b) {
        float from[3], to[3];
        for (int k = 0; k < 3; ++k) {
            const float e = s->bounds_max[k] - s->bounds_min[k];
            from[k] = s->bounds_min[k] - 0.25f * e + 1.5f * e * check_randf(&seed);
            to[k] = s->bounds_min[k] + e * check_randf(&seed);
        }
        if (b % 3 == 2) /* along an axis */
            for (int k = 0; k < 3; ++k)
                if (k != (int)(b / 3) % 3)
                    to[k] = from[k];
        const int shadow = b % 2;
        for (uint32_t i = 0; i < 16; ++i) {
            float *r = &rays[8 * (16 * b + i)], len = 0.0f;
            for (int k = 0; k < 3; ++k) {
                const float jitter =
                    (b % 3 == 2 && i < 14) ? 0.0f : 0.02f * ext * (check_randf(&seed) - 0.5f);
                r[k] = shadow ? from[k] + jitter : from[k];
                r[4 + k] = shadow ? to[k] - r[k] : to[k] + jitter - from[k];
            }
            if (i == 7) /* a lane turned away */
                for (int k = 0; k < 3; ++k)
                    r[4 + k] = -r[4 + k];
            for (int k = 0; k < 3; ++k)
                len += r[4 + k] * r[4 + k];
            if (!(len > 0.0f))
                r[4] = 1.0f, len = 1.0f;
            for (int k = 0; k < 3; ++k)
                r[4 + k] /= sqrtf(len);
            r[3] = 0.0f;
            r[7] = shadow ? 0.999f * sqrtf(len) : INFINITY;
        }
    }
    return rays;
}

/* Rays traced in packets (16 to a work-item) against the same rays traced
 * one by one: the same closest hits bit for bit, the same blocked rays, on
 * bundles of alike rays and on rays with nothing alike (random ones, a
 * count that leaves the last packet partly empty, and one that leaves it
 * too few to trace as a packet). */
static void check_packets(vct_context *ctx, const vct_scene *s, const vct_accel *a,
                          const char *name) {
    const uint32_t bundles = 160, n = 16 * bundles + 16 * 40 + 5;
    float *rays = malloc(32ull * n), *bundled = ray_bundles(s, bundles, 91),
          *loose = random_rays(s, n - 16 * bundles, 92);
    memcpy(rays, bundled, 32ull * 16 * bundles);
    memcpy(rays + 8 * 16 * bundles, loose, 32ull * (n - 16 * bundles));
    vct_hit *one = malloc(sizeof *one * n), *packed = malloc(sizeof *packed * n);
    vct_error err = {0};
    uint32_t hits = 0, blocked = 0;
    for (int pass = 0; pass < 3; ++pass) {
        const int any = pass == 1;
        /* the last pass leaves 3 rays in the last packet, which packets
         * trace one by one */
        const uint32_t count = pass == 2 ? n - 2 : n;
        REQUIRE_OK(vct_trace_rays(ctx, a, rays, count, any, one, &err), err);
        REQUIRE_OK(vct_trace_ray_packets(ctx, a, rays, count, any, packed, &err), err);
        uint32_t differ = 0;
        for (uint32_t i = 0; i < count; ++i) {
            const int same = any ? (one[i].t >= 0.0f) == (packed[i].t >= 0.0f)
                                 : memcmp(&one[i], &packed[i], sizeof one[i]) == 0;
            if (!same && differ++ < 3)
                fprintf(stderr,
                        "%s: ray %u (%s): one by one t=%.9g tri %u, in a packet t=%.9g tri %u\n",
                        name, i, any ? "any hit" : "closest", one[i].t, one[i].triangle,
                        packed[i].t, packed[i].triangle);
            if (pass == 1)
                blocked += one[i].t >= 0.0f;
            else if (pass == 0)
                hits += one[i].t >= 0.0f;
        }
        CHECK(differ == 0, "%s: %u of %u rays hit differently in packets (%s)", name, differ, count,
              any ? "any hit" : "closest hit");
    }
    CHECK(hits > n / 20 && blocked > n / 20 && blocked < n,
          "%s: %u closest and %u any hits of %u rays in packets: a weak test", name, hits, blocked,
          n);
    printf("%s: %u rays in packets, %u hits, %u blocked, the same one by one\n", name, n, hits,
           blocked);
    free(rays);
    free(bundled);
    free(loose);
    free(one);
    free(packed);
}

static const vct_accel_options bvh_options = {
    VCT_ACCEL_BVH, {0, 0, 0}, VCT_BVH_PLOC, VCT_BVH_LEVELS_AUTO};
static const vct_accel_options linear_options = {
    VCT_ACCEL_BVH, {0, 0, 0}, VCT_BVH_LINEAR, VCT_BVH_LEVELS_AUTO};
static const vct_accel_options grid_options = {
    VCT_ACCEL_GRID, {0, 0, 0}, VCT_BVH_PLOC, VCT_BVH_LEVELS_AUTO};

/* Both builders: structure, rays against the brute force, hits as the grid's. */
static void run_scene(vct_context *ctx, vct_scene *s, uint32_t rays, const char *name) {
    vct_error err = {0};
    vct_accel *g = vct_accel_build(ctx, s, &grid_options, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    const vct_accel_options *builders[2] = {&bvh_options, &linear_options};
    for (int i = 0; i < 2; ++i) {
        vct_accel *a = vct_accel_build(ctx, s, builders[i], &err);
        REQUIRE_OK(a ? VCT_OK : err.status, err);
        vct_accel_info info;
        REQUIRE_OK(vct_accel_info_get(ctx, a, &info, &err), err);
        char label[128];
        snprintf(label, sizeof label, "%s, %s", name, i ? "linear" : "clustered");
        printf("%s: %u triangles, %u nodes, %u leaves, %u levels, %u passes, SAH cost %.2f\n",
               label, s->triangle_count, info.nodes, info.leaves, info.depth, info.passes,
               info.sah_cost);
        check_structure(ctx, s, a, label);
        check_rays(ctx, s, a, rays, 42, label);
        check_same_hits(ctx, s, a, g, "as the grid", label);
        check_packets(ctx, s, a, label);
        vct_accel_release(a);
    }
    vct_accel_release(g);
}

/* Every vertex moved (a shear, a scale and a wobble): the refit BVH and a
 * BVH built on the moved scene give the same hits, and agree with the brute
 * force. */
static void check_refit(vct_context *ctx, const test_mesh *m, const char *name) {
    vct_scene *s = scene_of(m);
    vct_error err = {0};
    vct_accel *a = vct_accel_build(ctx, s, &bvh_options, &err);
    REQUIRE_OK(a ? VCT_OK : err.status, err);
    test_mesh moved = *m;
    moved.pos = malloc(12ull * m->nv);
    uint64_t seed = 5;
    for (uint32_t i = 0; i < m->nv; ++i) {
        const float *p = &m->pos[3 * i];
        float *q = &moved.pos[3 * i];
        q[0] = 1.5f * p[0] + 0.4f * p[1] + 0.02f * check_randf(&seed);
        q[1] = 0.7f * p[1] + 0.3f + 0.02f * check_randf(&seed);
        q[2] = p[2] - 0.5f * p[0] + 0.02f * check_randf(&seed);
    }
    vct_scene *ms = scene_of(&moved);
    REQUIRE_OK(vct_accel_refit(ctx, a, ms, &err), err);
    vct_accel *rebuilt = vct_accel_build(ctx, ms, &bvh_options, &err);
    REQUIRE_OK(rebuilt ? VCT_OK : err.status, err);
    char label[128];
    snprintf(label, sizeof label, "%s, refit", name);
    check_structure(ctx, ms, a, label);
    check_rays(ctx, ms, a, 2000, 11, label);
    check_same_hits(ctx, ms, a, rebuilt, "as a rebuild", label);
    /* A scene with other triangles cannot be refit. */
    test_mesh fewer = moved;
    fewer.nt = moved.nt - 1;
    vct_scene *fs = scene_of(&fewer);
    CHECK(vct_accel_refit(ctx, a, fs, &err) == VCT_ERR_INPUT && strstr(err.message, "rebuild"),
          "%s: refit to a scene with fewer triangles is not refused (%s)", name, err.message);
    vct_scene_release(fs);
    vct_accel_release(rebuilt);
    vct_accel_release(a);
    vct_scene_release(ms);
    vct_scene_release(s);
    free(moved.pos);
}

/* n triangles of random orientation and size, all with the centroid c:
 * every Morton code is the same. */
static test_mesh mesh_same_centroid(uint32_t n, const float c[3], uint64_t seed) {
    test_mesh m = {malloc(36ull * n), malloc(12ull * n), 3 * n, n};
    for (uint32_t t = 0; t < n; ++t) {
        float v[2][3], size = 0.05f + check_randf(&seed);
        for (int j = 0; j < 2; ++j)
            for (int k = 0; k < 3; ++k)
                v[j][k] = (2.0f * check_randf(&seed) - 1.0f) * size;
        for (int k = 0; k < 3; ++k) {
            m.pos[9 * t + k] = c[k] + v[0][k];
            m.pos[9 * t + 3 + k] = c[k] + v[1][k];
            m.pos[9 * t + 6 + k] = c[k] - v[0][k] - v[1][k];
        }
        for (int k = 0; k < 3; ++k)
            m.tri[3 * t + k] = 3 * t + k;
    }
    return m;
}

/* A closed room 100 wide around a detailed sphere 1 wide (seed 000's ball in
 * a stadium). */
static test_mesh mesh_ball_in_room(void) {
    const float centre[3] = {3.0f, 1.0f, -2.0f};
    test_mesh ball = mesh_icosphere(5, 0.5f, centre);
    const float L = 50.0f;
    const float walls[6][12] = {
        {-L, -L, -L, L, -L, -L, L, -L, L, -L, -L, L}, {-L, L, -L, -L, L, L, L, L, L, L, L, -L},
        {-L, -L, -L, -L, -L, L, -L, L, L, -L, L, -L}, {L, -L, -L, L, L, -L, L, L, L, L, -L, L},
        {-L, -L, -L, -L, L, -L, L, L, -L, L, -L, -L}, {-L, -L, L, L, -L, L, L, L, L, -L, L, L}};
    test_mesh room = mesh_quads(&walls[0][0], 6);
    test_mesh m = {malloc(12ull * (ball.nv + room.nv)), malloc(12ull * (ball.nt + room.nt)),
                   ball.nv + room.nv, ball.nt + room.nt};
    memcpy(m.pos, ball.pos, 12ull * ball.nv);
    memcpy(m.pos + 3 * ball.nv, room.pos, 12ull * room.nv);
    memcpy(m.tri, ball.tri, 12ull * ball.nt);
    for (uint32_t i = 0; i < 3 * room.nt; ++i)
        m.tri[3 * ball.nt + i] = room.tri[i] + ball.nv;
    mesh_free(&ball);
    mesh_free(&room);
    return m;
}

/* Rays from inside the room at the ball: most hit it, all agree with the
 * brute force (check_rays' rays mostly hit the walls). */
static void check_ball_rays(vct_context *ctx, const vct_scene *s, const char *name) {
    vct_error err = {0};
    vct_accel *a = vct_accel_build(ctx, s, &bvh_options, &err);
    REQUIRE_OK(a ? VCT_OK : err.status, err);
    const uint32_t n = 2000;
    float *rays = malloc(32ull * n);
    vct_hit *hits = malloc(sizeof *hits * n);
    uint64_t seed = 3;
    for (uint32_t i = 0; i < n; ++i) {
        float *r = &rays[8 * i], target[3] = {3.0f, 1.0f, -2.0f}, len = 0.0f;
        for (int k = 0; k < 3; ++k) {
            r[k] = 40.0f * (2.0f * check_randf(&seed) - 1.0f);
            target[k] += 0.6f * (2.0f * check_randf(&seed) - 1.0f);
            r[4 + k] = target[k] - r[k];
            len += r[4 + k] * r[4 + k];
        }
        for (int k = 0; k < 3; ++k)
            r[4 + k] /= sqrtf(len);
        r[3] = 0.0f;
        r[7] = INFINITY;
    }
    REQUIRE_OK(vct_trace_rays(ctx, a, rays, n, 0, hits, &err), err);
    uint32_t wrong = 0, on_ball = 0;
    for (uint32_t i = 0; i < n; ++i) {
        const float *r = &rays[8 * i];
        const double o[3] = {r[0], r[1], r[2]}, d[3] = {r[4], r[5], r[6]};
        double best = INFINITY, border;
        uint32_t best_tri = 0;
        for (uint32_t t = 0; t < s->triangle_count; ++t) {
            const uint32_t *tr = &s->triangles[3 * t];
            const double th =
                ref_intersect(o, d, &s->positions[3 * tr[0]], &s->positions[3 * tr[1]],
                              &s->positions[3 * tr[2]], &border);
            if (th > 0 && th < best)
                best = th, best_tri = t;
        }
        on_ball += isfinite(best) && best_tri < s->triangle_count - 12;
        wrong += !(hits[i].t >= 0.0f) || fabs(hits[i].t - best) > 1e-4 * (1.0 + best);
    }
    CHECK(wrong == 0, "%s: %u of %u rays at the ball disagree with the brute force", name, wrong,
          n);
    CHECK(on_ball > n / 2, "%s: only %u rays reach the ball: a weak test", name, on_ball);
    printf("%s: %u rays at the ball, %u hit it\n", name, n, on_ball);
    free(rays);
    free(hits);
    vct_accel_release(a);
}

/* No triangles: every ray misses (the scene API refuses an empty scene, so
 * this one is made by hand, as an embedding host might). */
static void check_empty(vct_context *ctx) {
    test_mesh one = mesh_soup(1, 0.0f, 1);
    vct_scene *s = scene_of(&one);
    vct_scene empty = *s;
    empty.triangle_count = 0;
    vct_error err = {0};
    vct_accel *a = vct_accel_build(ctx, &empty, &bvh_options, &err);
    REQUIRE_OK(a ? VCT_OK : err.status, err);
    const uint32_t n = 256;
    float *rays = random_rays(s, n, 9);
    vct_hit *hits = malloc(sizeof *hits * n);
    REQUIRE_OK(vct_trace_rays(ctx, a, rays, n, 0, hits, &err), err);
    uint32_t hit = 0;
    for (uint32_t i = 0; i < n; ++i)
        hit += hits[i].t >= 0.0f;
    REQUIRE_OK(vct_trace_rays(ctx, a, rays, n, 1, hits, &err), err);
    for (uint32_t i = 0; i < n; ++i)
        hit += hits[i].t >= 0.0f;
    for (int any = 0; any < 2; ++any) {
        REQUIRE_OK(vct_trace_ray_packets(ctx, a, rays, n, any, hits, &err), err);
        for (uint32_t i = 0; i < n; ++i)
            hit += hits[i].t >= 0.0f;
    }
    CHECK(hit == 0, "empty scene: %u rays hit something", hit);
    printf("empty scene: %u rays, no hits (one by one and in packets)\n", 4 * n);
    free(rays);
    free(hits);
    vct_accel_release(a);
    vct_scene_release(s);
    mesh_free(&one);
}

/* Coincident triangles (a sphere and the same sphere again, its copy
 * first in the triangle order): every hit is a tie
 * at equal distance, and each structure (both builders, a refit one, the
 * grid) gives the lower index of the pair, whatever its order of tests. */
static void check_ties(vct_context *ctx, const test_mesh *m) {
    test_mesh twice = {malloc(24ull * m->nv), malloc(24ull * m->nt), 2 * m->nv, 2 * m->nt};
    memcpy(twice.pos, m->pos, 12ull * m->nv);
    memcpy(twice.pos + 3ull * m->nv, m->pos, 12ull * m->nv);
    for (uint32_t t = 0; t < m->nt; ++t)
        for (int k = 0; k < 3; ++k) {
            twice.tri[3 * t + k] = m->tri[3 * t + k] + m->nv;
            twice.tri[3ull * (m->nt + t) + k] = m->tri[3 * t + k];
        }
    vct_scene *s = scene_of(&twice);
    vct_error err = {0};
    const vct_accel_options *kinds[3] = {&bvh_options, &linear_options, &grid_options};
    const char *names[4] = {"clustered", "linear", "grid", "refit"};
    const uint32_t n = 3000;
    float *rays = random_rays(s, n, 91);
    vct_hit *hits = malloc(sizeof *hits * n);
    for (int i = 0; i < 4; ++i) {
        vct_accel *a = vct_accel_build(ctx, s, kinds[i < 3 ? i : 0], &err);
        REQUIRE_OK(a ? VCT_OK : err.status, err);
        if (i == 3)
            REQUIRE_OK(vct_accel_refit(ctx, a, s, &err), err);
        REQUIRE_OK(vct_trace_rays(ctx, a, rays, n, 0, hits, &err), err);
        uint32_t hit = 0, wrong = 0;
        for (uint32_t r = 0; r < n; ++r) {
            hit += hits[r].t >= 0.0f;
            wrong += hits[r].t >= 0.0f && hits[r].triangle >= m->nt;
        }
        CHECK(wrong == 0 && hit > n / 20,
              "ties, %s: %u of %u hits took the higher index of two coincident triangles", names[i],
              wrong, hit);
        printf("ties, %s: %u hits on coincident triangles, each the lower index\n", names[i], hit);
        vct_accel_release(a);
    }
    free(rays);
    free(hits);
    vct_scene_release(s);
    mesh_free(&twice);
}

int main(void) {
    vct_context *ctx = check_context();
    const float origin[3] = {0, 0, 0}, far_centre[3] = {1e5f, -2e5f, 3e5f};

    test_mesh soup = mesh_soup(3000, 0.0f, 7);
    vct_scene *s = scene_of(&soup);
    run_scene(ctx, s, 4000, "soup");
    vct_scene_release(s);
    check_refit(ctx, &soup, "soup");
    mesh_free(&soup);

    test_mesh far_soup = mesh_soup(800, 1e5f, 9);
    s = scene_of(&far_soup);
    run_scene(ctx, s, 3000, "soup at 1e5");
    vct_scene_release(s);
    mesh_free(&far_soup);

    test_mesh one = mesh_soup(1, 0.0f, 3);
    s = scene_of(&one);
    run_scene(ctx, s, 2000, "one triangle");
    vct_scene_release(s);
    mesh_free(&one);

    test_mesh same = mesh_same_centroid(2000, origin, 13);
    s = scene_of(&same);
    run_scene(ctx, s, 3000, "one centroid");
    vct_scene_release(s);
    mesh_free(&same);

    test_mesh sphere = mesh_icosphere(3, 1.0f, origin);
    s = scene_of(&sphere);
    run_scene(ctx, s, 3000, "icosphere");
    vct_scene_release(s);
    check_watertight(ctx, &sphere, origin, &bvh_options, "icosphere watertight");
    check_refit(ctx, &sphere, "icosphere");
    check_ties(ctx, &sphere);
    mesh_free(&sphere);

    test_mesh far_sphere = mesh_icosphere(3, 10.0f, far_centre);
    check_watertight(ctx, &far_sphere, far_centre, &bvh_options, "icosphere at 3e5 watertight");
    mesh_free(&far_sphere);

    test_mesh room = mesh_ball_in_room();
    s = scene_of(&room);
    run_scene(ctx, s, 3000, "ball in a room");
    check_ball_rays(ctx, s, "ball in a room");
    vct_scene_release(s);
    const float inside[3] = {0.0f, 0.0f, 0.0f};
    check_watertight(ctx, &room, inside, &bvh_options, "ball in a room watertight");
    mesh_free(&room);

    /* Two flat quads, one leaf: every box is flat but for its padding. */
    const float plates[24] = {-4, 0, -4, 4, 0, -4, 4, 0, 4, -4, 0, 4,
                              -1, 1, -1, 1, 1, -1, 1, 1, 1, -1, 1, 1};
    test_mesh flat = mesh_quads(plates, 2);
    s = scene_of(&flat);
    run_scene(ctx, s, 3000, "floor and plate");
    vct_scene_release(s);
    mesh_free(&flat);

    s = check_cornell_box();
    run_scene(ctx, s, 4000, "cornell box");
    vct_scene_release(s);

    check_empty(ctx);

    vct_context_release(ctx);
    return check_exit("test_bvh");
}
