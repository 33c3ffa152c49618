/* Bricks and their filtering against the dense plain-C reference of
 * brick_ref.h: every texel of every brick, every channel, both pool kinds,
 * isotropic and directional. Also: samples shared by neighbouring bricks are
 * bit-identical, two builds are bit-identical, a moved light re-filters, and
 * hard cases with known answers (a single voxel, a full block, a one-voxel
 * wall that must not leak, geometry on the volume's faces). */
#include <math.h>
#include <string.h>

#include "brick_case.h"

typedef struct compare_result {
    uint64_t texels, wrong, shared, unshared;
    double worst;
} compare_result;

/* Anisotropic bricks keep isotropic radiance at the finest level only,
 * from this brick on; coarser levels hold the six directions instead. */
static uint32_t radiance_first(const brick_case *c) {
    return c->bricks.anisotropic ? c->bricks.directional_bricks : 0;
}

static int has_level(const brick_case *c, int channel, int level) {
    return channel != VCT_BRICK_RADIANCE || !c->bricks.anisotropic ||
           level == (int)c->info.levels - 1;
}

/* Every brick of `level` in `channel` against lattice `ref`; shared lattice
 * points must hold bit-identical texels in every brick that has them. */
static void compare_level(const brick_case *c, int channel, uint32_t level, const ref_lattice *ref,
                          compare_result *r) {
    const uint32_t count = c->bricks.level_bricks[level], first = c->bricks.level_first[level];
    float *got = malloc(27ull * 16 * count + 16);
    vct_error err = {0};
    REQUIRE_OK(vct_bricks_read(ctx, c->voxels, channel, first, count, got, &err), err);
    const uint64_t points = (uint64_t)ref->n * ref->n * ref->n;
    float *seen = malloc(16 * points);
    uint8_t *has = calloc(points, 1);
    const uint32_t start = c->info.level_start[level], nodes = c->info.level_nodes[level];
    for (uint32_t n = start; n < start + nodes; ++n) {
        if (c->child[n] == VCT_NODE_NULL)
            continue;
        const uint32_t b = (c->child[n] - 1) / 8 - first, p = c->cell[n];
        const int64_t base[3] = {2 * (p & 1023), 2 * ((p >> 10) & 1023), 2 * (p >> 20)};
        for (int t = 0; t < 27; ++t) {
            const int64_t x = base[0] + t % 3, y = base[1] + t / 3 % 3, z = base[2] + t / 9;
            const float *g = got + 4 * (27ull * b + t), *e = ref_at(ref, x, y, z);
            int bad = 0;
            for (int k = 0; k < 4; ++k) {
                const double d = fabs((double)g[k] - e[k]);
                r->worst = fmax(r->worst, d / fmax(fabs(e[k]), 1e-3));
                bad |= !(d <= fabs(e[k]) * (1.0 / 512) + 1e-6);
            }
            if (bad && r->wrong++ < 3)
                fprintf(stderr,
                        "%s: channel %d level %u brick %u texel (%d %d %d) at (%lld %lld %lld): "
                        "got %g %g %g %g, expected %g %g %g %g\n",
                        c->name, channel, level, b + first, t % 3, t / 3 % 3, t / 9, (long long)x,
                        (long long)y, (long long)z, g[0], g[1], g[2], g[3], e[0], e[1], e[2], e[3]);
            const uint64_t at = ((uint64_t)z * ref->n + y) * ref->n + x;
            if (has[at]) {
                r->shared++;
                r->unshared += memcmp(seen + 4 * at, g, 16) != 0;
            } else {
                memcpy(seen + 4 * at, g, 16);
                has[at] = 1;
            }
            r->texels++;
        }
    }
    free(has);
    free(seen);
    free(got);
}

/* The whole hierarchy of one channel; `value` per voxel (NULL: zero). The
 * directional channels are checked when the bricks have them. Returns the
 * finest lattice of `channel` for further checks by the caller. */
static ref_lattice check_channel(const brick_case *c, int channel, const float *value) {
    float *alpha = opacities(c);
    const uint32_t levels = c->info.levels;
    ref_lattice lat = ref_leaf_lattice(c->info.resolution, c->voxel_of, value, alpha);
    const ref_lattice finest = {lat.n, malloc(16ull * lat.n * lat.n * lat.n)};
    memcpy(finest.v, lat.v, 16ull * lat.n * lat.n * lat.n);
    compare_result r = {0};
    ref_lattice dir[6] = {{0}};
    for (int level = (int)levels - 1; level >= 0; --level) {
        if (has_level(c, channel, level))
            compare_level(c, channel, (uint32_t)level, &lat, &r);
        const int directional = channel == VCT_BRICK_RADIANCE && c->bricks.anisotropic;
        for (int d = 0; d < 6 && directional && level < (int)levels - 1; ++d) {
            compare_result rd = {0};
            compare_level(c, VCT_BRICK_RADIANCE_DIR0 + d, (uint32_t)level, &dir[d], &rd);
            CHECK(rd.wrong == 0 && rd.unshared == 0,
                  "%s: direction %d level %d: %llu of %llu texels wrong, %llu shared differ",
                  c->name, d, level, (unsigned long long)rd.wrong, (unsigned long long)rd.texels,
                  (unsigned long long)rd.unshared);
        }
        if (level == 0)
            break;
        for (int d = 0; d < 6 && channel == VCT_BRICK_RADIANCE && c->bricks.anisotropic; ++d) {
            ref_lattice next = ref_filter_dir(dir[d].v ? &dir[d] : &lat, d);
            free(dir[d].v);
            dir[d] = next;
        }
        ref_lattice next = ref_filter(&lat);
        free(lat.v);
        lat = next;
    }
    for (int d = 0; d < 6; ++d)
        free(dir[d].v);
    free(lat.v);
    free(alpha);
    CHECK(r.wrong == 0, "%s: channel %d: %llu of %llu texels differ from the reference", c->name,
          channel, (unsigned long long)r.wrong, (unsigned long long)r.texels);
    CHECK(r.unshared == 0, "%s: channel %d: %llu of %llu shared samples differ between bricks",
          c->name, channel, (unsigned long long)r.unshared, (unsigned long long)r.shared);
    printf("%-28s channel %d: %8llu texels, %8llu shared, worst relative %.2g\n", c->name, channel,
           (unsigned long long)r.texels, (unsigned long long)r.shared, r.worst);
    return finest;
}

static void check_all_channels(const brick_case *c) {
    const int channels[3] = {VCT_BRICK_ALBEDO, VCT_BRICK_NORMAL, VCT_BRICK_RADIANCE};
    const float *values[3] = {c->albedo, c->normal, c->scene->light_count ? c->radiance : NULL};
    for (int i = 0; i < 3; ++i)
        free(check_channel(c, channels[i], values[i]).v);
}

/* The level-`level` node at `cell`, or VCT_NODE_NULL (host descent). */
/* brick_sample, as a cone reads it, at random points of every level of
 * `channel` against trilinear interpolation of the reference lattice, in
 * nodes that have a brick (others must read 0). `tol`: absolute plus
 * relative; `weight_step`: for image pools, the step of the interpolation
 * weights hardware may use (8-bit weights, 1/256, on GPUs): each of the
 * three weights may be off by one step, so the value by 3 steps of the
 * spread of the 8 texels it mixes (seen on an H100: 0.018 where they
 * spread 1.5). */
static void check_sampling(const brick_case *c, int channel, const float *value, double tol,
                           double weight_step) {
    float *alpha = opacities(c);
    const uint32_t res = c->info.resolution, levels = c->info.levels, n = 4000;
    ref_lattice lat = ref_leaf_lattice(res, c->voxel_of, value, alpha);
    float *points = malloc(16ull * n), *got = malloc(16ull * n);
    uint64_t seed = 99, checked = 0, wrong = 0, inside = 0;
    const double side = c->info.side;
    for (int level = (int)levels - 1; level >= 0; --level) {
        for (uint32_t i = 0; i < n; ++i)
            for (int k = 0; k < 4; ++k)
                points[4 * i + k] = (float)(c->info.origin[k % 3] + side * check_randf(&seed));
        vct_error err = {0};
        REQUIRE_OK(
            vct_bricks_sample(ctx, c->voxels, channel, (uint32_t)level, points, n, got, &err), err);
        const double cells = (double)(1u << level);
        for (uint32_t i = 0; i < n; ++i) {
            double at[3], lp[3];
            uint32_t cell[3];
            for (int k = 0; k < 3; ++k) {
                at[k] = (points[4 * i + k] - c->info.origin[k]) / side * cells;
                cell[k] = (uint32_t)fmin(floor(at[k]), cells - 1);
                lp[k] = 2.0 * at[k];
            }
            const uint32_t node = node_at(c, cell, (uint32_t)level);
            double e[4] = {0, 0, 0, 0}, spread[4] = {0, 0, 0, 0};
            if (node != VCT_NODE_NULL && c->child[node] != VCT_NODE_NULL) {
                ref_trilinear_spread(&lat, lp, e, spread);
                ++inside;
            }
            int bad = 0;
            for (int k = 0; k < 4; ++k)
                bad |= !(fabs(got[4 * i + k] - e[k]) <=
                         tol * (1.0 + fabs(e[k])) + 3.0 * weight_step * spread[k]);
            if (bad && wrong++ < 3)
                fprintf(stderr, "%s: level %d point %u: got %g %g %g %g, expected %g %g %g %g\n",
                        c->name, level, i, got[4 * i], got[4 * i + 1], got[4 * i + 2],
                        got[4 * i + 3], e[0], e[1], e[2], e[3]);
            ++checked;
        }
        if (!has_level(c, channel, level - 1))
            break;
        if (level > 0) {
            ref_lattice next = ref_filter(&lat);
            free(lat.v);
            lat = next;
        }
    }
    /* one level alone (the leaves of a thin wall) has fewer points in bricks */
    const uint64_t enough = has_level(c, channel, (int)levels - 2) ? n / 4 : n / 32;
    CHECK(wrong == 0 && inside > enough, "%s: sampling: %llu of %llu points wrong (%llu in bricks)",
          c->name, (unsigned long long)wrong, (unsigned long long)checked,
          (unsigned long long)inside);
    printf("%-28s sampled %llu points, %llu in bricks\n", c->name, (unsigned long long)checked,
           (unsigned long long)inside);
    free(lat.v);
    free(points);
    free(got);
    free(alpha);
}

/* Random sparse soups at several sizes, lit, both pool kinds, directional. */
static void random_volumes(void) {
    const uint32_t sizes[] = {2, 8, 32, 64};
    vct_material mats[4];
    for (int i = 0; i < 4; ++i)
        mats[i] = soup_material(i);
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; ++s) {
        test_mesh m = mesh_soup(sizes[s] <= 8 ? 20 : 400, 0.0f, 17 + s);
        vct_scene *scene = scene_of(&m, mats, 4);
        mesh_free(&m);
        add_point_light(scene, 0.3f, 0.8f, 0.6f, 0.5f);
        char name[64];
        snprintf(name, sizeof name, "soup %u^3, directional", sizes[s]);
        const vct_brick_options opt = {VCT_BRICKS_BUFFER, 1, 0};
        brick_case c = make_case(name, scene, sizes[s], 1.0f, &opt);
        CHECK(c.bricks.bricks == (c.info.nodes - 1) / 8, "%s: one brick per node with children",
              name);
        check_all_channels(&c);

        /* The image pool holds the same texels, read through the image path. */
        const vct_brick_options image = {VCT_BRICKS_IMAGE, 1, 0};
        vct_error err = {0};
        const uint32_t rf = radiance_first(&c), n = c.bricks.bricks - rf;
        float *a = malloc(27ull * 16 * n + 16), *b = malloc(27ull * 16 * n + 16);
        REQUIRE_OK(vct_bricks_read(ctx, c.voxels, VCT_BRICK_RADIANCE, rf, n, a, &err), err);
        REQUIRE_OK(vct_bricks_build(ctx, c.voxels, &image, &err), err);
        REQUIRE_OK(vct_voxels_inject_light(ctx, scene, c.accel, c.voxels, &err), err);
        vct_brick_info info;
        vct_bricks_info_get(c.voxels, &info);
        CHECK(info.image == 1, "%s: image pool", name);
        REQUIRE_OK(vct_bricks_read(ctx, c.voxels, VCT_BRICK_RADIANCE, rf, n, b, &err), err);
        CHECK(memcmp(a, b, 27ull * 16 * n) == 0, "%s: image and buffer pools differ", name);
        free(a);
        free(b);
        if (sizes[s] == 32) {
            c.name = "soup 32^3, image pool";
            check_all_channels(&c);
            check_sampling(&c, VCT_BRICK_RADIANCE, c.radiance, 1e-3, 1.0 / 256.0);
            REQUIRE_OK(vct_bricks_build(ctx, c.voxels, &opt, &err), err);
            REQUIRE_OK(vct_voxels_inject_light(ctx, scene, c.accel, c.voxels, &err), err);
            c.name = "soup 32^3, buffer pool";
            check_sampling(&c, VCT_BRICK_RADIANCE, c.radiance, 1e-5, 0.0);
            check_sampling(&c, VCT_BRICK_ALBEDO, c.albedo, 1e-5, 0.0);
        }
        case_free(&c);
    }
}

/* A moved light re-injects and re-filters; two builds are bit-identical. */
static void moved_light_and_determinism(void) {
    vct_material mats[4];
    for (int i = 0; i < 4; ++i)
        mats[i] = soup_material(i);
    test_mesh m = mesh_icosphere(3, 0.35f, (const float[3]){0.5f, 0.5f, 0.5f});
    vct_scene *scene = scene_of(&m, mats, 4);
    mesh_free(&m);
    add_point_light(scene, 0.9f, 0.9f, 0.2f, 1.0f);
    const vct_brick_options opt = {VCT_BRICKS_AUTO, 1, 0};
    brick_case c = make_case("icosphere 64^3, light moved", scene, 64, 1.0f, &opt);
    scene->lights[0].position[0] = 0.05f;
    scene->lights[0].position[2] = 0.95f;
    vct_error err = {0};
    REQUIRE_OK(vct_voxels_inject_light(ctx, scene, c.accel, c.voxels, &err), err);
    REQUIRE_OK(vct_voxels_read_radiance(ctx, c.voxels, c.radiance, &err), err);
    free(check_channel(&c, VCT_BRICK_RADIANCE, c.radiance).v);

    const uint32_t n = c.bricks.bricks, rf = radiance_first(&c);
    float *a = malloc(27ull * 16 * n), *b = malloc(27ull * 16 * n);
    REQUIRE_OK(vct_bricks_read(ctx, c.voxels, VCT_BRICK_RADIANCE, rf, n - rf, a, &err), err);
    REQUIRE_OK(vct_bricks_build(ctx, c.voxels, &opt, &err), err);
    REQUIRE_OK(vct_voxels_inject_light(ctx, scene, c.accel, c.voxels, &err), err);
    REQUIRE_OK(vct_bricks_read(ctx, c.voxels, VCT_BRICK_RADIANCE, rf, n - rf, b, &err), err);
    CHECK(memcmp(a, b, 27ull * 16 * (n - rf)) == 0, "two builds of the same scene differ");
    /* No isotropic radiance above the leaves of anisotropic bricks: asked
     * for, it is refused, not read from memory nothing wrote. */
    vct_error coarse = {0};
    const float centre[4] = {0.5f, 0.5f, 0.5f, 0.0f};
    float texels[27 * 4];
    CHECK(rf > 0 &&
              vct_bricks_read(ctx, c.voxels, VCT_BRICK_RADIANCE, 0, 1, texels, &coarse) ==
                  VCT_ERR_INPUT &&
              strstr(coarse.message, "anisotropic") &&
              vct_bricks_sample(ctx, c.voxels, VCT_BRICK_RADIANCE, 0, centre, 1, texels, &coarse) ==
                  VCT_ERR_INPUT,
          "isotropic radiance above the leaves of anisotropic bricks: %s", coarse.message);

    /* Radiance left for the injection: refused until then, then the same
     * bricks, every channel, as a build that filled it first. */
    const int last = VCT_BRICK_RADIANCE_DIR0 + 5;
    const uint32_t nd = c.bricks.directional_bricks;
    float *full[VCT_BRICK_CHANNELS] = {0};
    for (int ch = 0; ch <= last; ++ch) {
        const uint32_t first = ch == VCT_BRICK_RADIANCE ? rf : 0;
        const uint32_t count = (ch >= VCT_BRICK_RADIANCE_DIR0 ? nd : n) - first;
        full[ch] = malloc(27ull * 16 * count + 16);
        REQUIRE_OK(vct_bricks_read(ctx, c.voxels, ch, first, count, full[ch], &err), err);
    }
    const vct_brick_options later = {VCT_BRICKS_AUTO, 1, 1};
    REQUIRE_OK(vct_bricks_build(ctx, c.voxels, &later, &err), err);
    vct_error refused = {0};
    const int rc = vct_bricks_read(ctx, c.voxels, VCT_BRICK_RADIANCE, rf, n - rf, b, &refused);
    CHECK(rc == VCT_ERR_INPUT && strstr(refused.message, "vct_voxels_inject_light"),
          "radiance read before injection: status %d (%s)", rc, refused.message);
    const float probe[8] = {0.1f, 0.5f, 0.5f, 0.0f, 1.0f, 0.0f, 0.0f, 0.2f};
    const vct_cone_settings cs = vct_cone_settings_default();
    const float sky[3] = {0, 0, 0};
    float out[8];
    memset(&refused, 0, sizeof refused);
    CHECK(vct_cone_trace(ctx, c.voxels, &cs, sky, probe, 1, out, &refused) == VCT_ERR_INPUT,
          "a cone before injection: %s", refused.message);
    REQUIRE_OK(vct_voxels_inject_light(ctx, scene, c.accel, c.voxels, &err), err);
    int same = 1;
    for (int ch = 0; ch <= last; ++ch) {
        const uint32_t first = ch == VCT_BRICK_RADIANCE ? rf : 0;
        const uint32_t count = (ch >= VCT_BRICK_RADIANCE_DIR0 ? nd : n) - first;
        REQUIRE_OK(vct_bricks_read(ctx, c.voxels, ch, first, count, b, &err), err);
        const int equal = memcmp(full[ch], b, 27ull * 16 * count) == 0;
        CHECK(equal, "radiance_later: channel %d differs from the full build", ch);
        same &= equal;
        free(full[ch]);
    }
    printf("radiance left for the injection: refused before it, every channel bit-identical "
           "after it: %s\n",
           same ? "yes" : "no");
    free(a);
    free(b);
    case_free(&c);
}

/* One small quad (0.6 x 0.6 voxels) inside voxel (3, 4, 5) of 8^3: exactly
 * the voxel's 8 corners are non-zero at the finest level, with the quad's
 * share of a voxel face, 0.36, as opacity and its albedo times that. */
static void single_voxel(void) {
    const float q[12] = {3.2f, 4.2f, 5.5f, 3.8f, 4.2f, 5.5f, 3.8f, 4.8f, 5.5f, 3.2f, 4.8f, 5.5f};
    brick_case c = make_case("single voxel", quads_scene(q, 1), 8, 8.0f, NULL);
    CHECK(c.info.voxels == 1, "single voxel: %u voxels", c.info.voxels);
    ref_lattice fine = check_channel(&c, VCT_BRICK_ALBEDO, c.albedo);
    check_all_channels(&c);
    /* independent of the reference: count the finest lattice's non-zero points */
    int lit = 0, exact = 0;
    const double albedo = vct_material_default().albedo[0], opacity = 0.6 * 0.6;
    for (int64_t z = 0; z < fine.n; ++z)
        for (int64_t y = 0; y < fine.n; ++y)
            for (int64_t x = 0; x < fine.n; ++x) {
                const float *p = ref_at(&fine, x, y, z);
                if (p[3] == 0.0f)
                    continue;
                ++lit;
                /* half floats: 2^-11 of relative precision */
                exact += x >= 3 && x <= 4 && y >= 4 && y <= 5 && z >= 5 && z <= 6 &&
                         fabs(p[3] - opacity) < 1e-3 && fabs(p[0] - albedo * opacity) < 1e-3;
            }
    CHECK(lit == 8 && exact == 8, "single voxel: %d corners non-zero, %d as expected", lit, exact);
    free(fine.v);
    case_free(&c);
}

/* A full 8^3 block (a quad through every voxel layer): every finest sample
 * has opacity 1, and the filtered interior stays exactly 1. */
static void full_block(void) {
    float q[8 * 12];
    for (int k = 0; k < 8; ++k) {
        const float z = (float)k + 0.5f;
        const float quad[12] = {0, 0, z, 8, 0, z, 8, 8, z, 0, 8, z};
        memcpy(q + 12 * k, quad, sizeof quad);
    }
    brick_case c = make_case("full block", quads_scene(q, 8), 8, 8.0f, NULL);
    CHECK(c.info.voxels == 512, "full block: %u voxels", c.info.voxels);
    check_all_channels(&c);
    /* level L-1 = 2 bricks read directly: every opacity 1 */
    const uint32_t count = c.bricks.level_bricks[2], first = c.bricks.level_first[2];
    float *t = malloc(27ull * 16 * count);
    vct_error err = {0};
    REQUIRE_OK(vct_bricks_read(ctx, c.voxels, VCT_BRICK_ALBEDO, first, count, t, &err), err);
    int not_one = 0;
    for (uint32_t i = 0; i < 27 * count; ++i)
        not_one += t[4 * i + 3] != 1.0f;
    CHECK(count == 64 && not_one == 0, "full block: %u finest bricks, %d samples not opaque", count,
          not_one);
    /* level 1: the brick centres (interior lattice points) are exactly 1 */
    REQUIRE_OK(
        vct_bricks_read(ctx, c.voxels, VCT_BRICK_ALBEDO, c.bricks.level_first[1], 8, t, &err), err);
    for (int b = 0; b < 8; ++b)
        CHECK(t[4 * (27 * b + 13) + 3] == 1.0f, "full block: level-1 brick %d centre %g", b,
              t[4 * (27 * b + 13) + 3]);
    free(t);
    case_free(&c);
}

/* A one-voxel-thick lit wall (x in [10, 11] of 32^3, facing +x, light at x = 20): at the
 * finest level both of its faces are fully opaque, so nothing can be seen
 * through it, and nothing lies beyond it. Seen along x one level up, its
 * directional opacity is 1 where the isotropic average is 3/4. */
static void thin_wall(void) {
    const float q[12] = {10.5f, 0, 0, 10.5f, 32, 0, 10.5f, 32, 32, 10.5f, 0, 32};
    vct_scene *s = quads_scene(q, 1);
    add_point_light(s, 20.0f, 16.0f, 16.0f, 50.0f);
    const vct_brick_options opt = {VCT_BRICKS_BUFFER, 1, 0};
    brick_case c = make_case("one-voxel wall", s, 32, 32.0f, &opt);
    CHECK(c.info.voxels == 32 * 32, "wall: %u voxels", c.info.voxels);
    check_all_channels(&c);
    float *alpha = opacities(&c);
    ref_lattice fine = ref_leaf_lattice(32, c.voxel_of, c.radiance, alpha);
    int open = 0, beyond = 0;
    for (int64_t z = 0; z <= 32; ++z)
        for (int64_t y = 0; y <= 32; ++y)
            for (int64_t x = 0; x <= 32; ++x) {
                const float *p = ref_at(&fine, x, y, z);
                if (x == 10 || x == 11)
                    open += p[3] != 1.0f;
                else
                    beyond += p[3] != 0.0f || p[0] != 0.0f;
            }
    CHECK(open == 0 && beyond == 0, "wall: %d open samples in it, %d non-empty off it", open,
          beyond);
    /* what a cone reads crossing the wall at the finest level: opaque throughout */
    float line[4 * 64], seen[4 * 64];
    for (int i = 0; i < 64; ++i) {
        line[4 * i] = 10.0f + (float)i / 63.0f;
        line[4 * i + 1] = 3.0f + 0.4f * (float)i;
        line[4 * i + 2] = 29.0f - 0.37f * (float)i;
        line[4 * i + 3] = 0.0f;
    }
    vct_error serr = {0};
    REQUIRE_OK(vct_bricks_sample(ctx, c.voxels, VCT_BRICK_RADIANCE, 4, line, 64, seen, &serr),
               serr);
    int leaks = 0;
    for (int i = 0; i < 64; ++i)
        leaks += !(seen[4 * i + 3] >= 0.9999f);
    CHECK(leaks == 0, "wall: %d of 64 samples inside it read as not opaque", leaks);
    check_sampling(&c, VCT_BRICK_RADIANCE, c.radiance, 1e-5, 0.0);
    /* Level L-2 = 3 (lattice spacing 2 voxels): x = 5 is the wall's plane. */
    const uint32_t level = 3, first = c.bricks.level_first[level];
    const uint32_t count = c.bricks.level_bricks[level];
    float *iso = malloc(27ull * 16 * count), *dir = malloc(27ull * 16 * count);
    vct_error err = {0};
    /* isotropic opacity from the albedo channel: anisotropic bricks keep no
     * isotropic radiance above the leaves */
    REQUIRE_OK(vct_bricks_read(ctx, c.voxels, VCT_BRICK_ALBEDO, first, count, iso, &err), err);
    REQUIRE_OK(vct_bricks_read(ctx, c.voxels, VCT_BRICK_RADIANCE_DIR0, first, count, dir, &err),
               err);
    int checked = 0, wrong = 0;
    for (uint32_t n = c.info.level_start[level]; n < c.info.level_start[level + 1]; ++n) {
        if (c.child[n] == VCT_NODE_NULL)
            continue;
        const uint32_t b = (c.child[n] - 1) / 8 - first, p = c.cell[n];
        const uint32_t cx = p & 1023, cy = p >> 10 & 1023, cz = p >> 20;
        for (int t = 0; t < 27; ++t) {
            const uint32_t x = 2 * cx + t % 3, y = 2 * cy + t / 3 % 3, z = 2 * cz + t / 9;
            if (x != 5 || y == 0 || z == 0 || y == 16 || z == 16)
                continue; /* the volume's faces average in empty space */
            ++checked;
            wrong += dir[4 * (27 * b + t) + 3] != 1.0f || iso[4 * (27 * b + t) + 3] != 0.75f;
        }
    }
    CHECK(checked > 100 && wrong == 0,
          "wall: +x opacity 1 and isotropic 3/4 on the wall's plane: %d of %d wrong", wrong,
          checked);
    free(iso);
    free(dir);
    free(fine.v);
    free(alpha);
    case_free(&c);
}

/* Geometry on the volume's own faces: lattice points on the boundary. */
static void boundary(void) {
    const float q[24] = {0, 0,  0, 0,  16, 0, 0,  16, 16, 0, 0,  16,
                         0, 16, 0, 16, 16, 0, 16, 16, 16, 0, 16, 16};
    vct_scene *s = quads_scene(q, 2);
    add_point_light(s, 8.0f, 8.0f, 8.0f, 20.0f);
    const vct_brick_options opt = {VCT_BRICKS_BUFFER, 1, 0};
    brick_case c = make_case("faces of the volume", s, 16, 16.0f, &opt);
    CHECK(c.info.voxels == 2 * 256 - 16, "boundary: %u voxels", c.info.voxels);
    check_all_channels(&c);
    case_free(&c);
}

/* A volume with no geometry in it: no bricks, any pool kind, samples 0. */
static void empty_volume(void) {
    const float q[12] = {100, 100, 100, 101, 100, 100, 101, 101, 100, 100, 101, 100};
    vct_scene *s = quads_scene(q, 1);
    vct_error err = {0};
    vct_voxel_options o = {0};
    o.resolution = 16;
    o.has_bounds = 1;
    o.bounds_size = 16;
    vct_voxels *v = vct_voxelize(ctx, s, &o, &err);
    REQUIRE_OK(v ? VCT_OK : err.status, err);
    REQUIRE_OK(vct_octree_build(ctx, v, &err), err);
    const vct_brick_options image = {VCT_BRICKS_IMAGE, 1, 0};
    REQUIRE_OK(vct_bricks_build(ctx, v, &image, &err), err);
    vct_brick_info info;
    CHECK(vct_bricks_info_get(v, &info) && info.bricks == 0, "empty volume: %u bricks",
          info.bricks);
    float point[4] = {8, 8, 8, 0}, got[4] = {1, 1, 1, 1};
    REQUIRE_OK(vct_bricks_sample(ctx, v, VCT_BRICK_RADIANCE, 2, point, 1, got, &err), err);
    CHECK(got[0] == 0 && got[3] == 0, "empty volume samples %g %g", got[0], got[3]);
    vct_voxels_release(v);
    vct_scene_release(s);
}

int main(void) {
    ctx = check_context();
    single_voxel();
    full_block();
    thin_wall();
    boundary();
    empty_volume();
    random_volumes();
    moved_light_and_determinism();
    vct_context_release(ctx);
    return check_exit("test_bricks");
}
