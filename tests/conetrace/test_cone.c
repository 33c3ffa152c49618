/* Cone marching (kernels/conetrace/cone_trace.h) against a plain-C marcher over the
 * dense reference lattices of brick_ref.h, isotropic and directional, on
 * buffer and image pools; the diffuse presets' weights against an
 * independent Monte Carlo estimate; and hard cases: an empty volume, cones
 * that start inside geometry, outside the volume, grazing a wall, and
 * crossing a one-voxel wall. Results are never NaN and opacity never
 * exceeds 1. */
#include "brick_case.h"
#include "ray_ref.h"
#include "vec3d.h"

/* ---- the reference marcher ---------------------------------------------- */

typedef struct ref_pyramid {
    uint32_t levels;
    ref_lattice iso[11];
    ref_lattice shade[11], plane[11]; /* the sides (kernels/voxel/voxel_side.h) */
    ref_lattice dir[6][11];           /* levels 0 .. L-2 */
    ref_lattice dark[6][11];          /* the same of the darker sides */
} ref_pyramid;

/* The sides' leaf values, premultiplied as the bricks hold them: shade
 * (opacity (brighter - darker), opacity k), plane opacity k (n, h). */
static void side_values(const brick_case *c, double *shade, double *plane) {
    for (uint32_t v = 0; v < c->info.voxels; ++v) {
        const double a = c->radiance[4 * v + 3], k = c->sides[8 * v + 3];
        for (int i = 0; i < 4; ++i) {
            shade[4 * v + i] = a * c->sides[8 * v + i];
            plane[4 * v + i] = a * k * c->sides[8 * v + 4 + i];
        }
    }
}

static ref_pyramid pyramid_of(const brick_case *c, int directional) {
    ref_pyramid p;
    memset(&p, 0, sizeof p);
    p.levels = c->info.levels;
    float *alpha = opacities(c);
    double *shade = malloc(32ull * c->info.voxels + 32),
           *plane = malloc(32ull * c->info.voxels + 32);
    side_values(c, shade, plane);
    const int top = (int)c->info.levels - 1;
    p.iso[top] = ref_leaf_lattice(c->info.resolution, c->voxel_of, c->radiance, alpha);
    p.shade[top] = ref_leaf_lattice4(c->info.resolution, c->voxel_of, shade);
    p.plane[top] = ref_leaf_lattice4(c->info.resolution, c->voxel_of, plane);
    ref_lattice dark_leaf = ref_dark_lattice(&p.iso[top], &p.shade[top]);
    for (int l = top - 1; l >= 0; --l) {
        p.iso[l] = ref_filter(&p.iso[l + 1]);
        p.shade[l] = ref_filter(&p.shade[l + 1]);
        p.plane[l] = ref_filter(&p.plane[l + 1]);
        for (int d = 0; d < 6 && directional; ++d) {
            p.dir[d][l] = ref_filter_dir(l == top - 1 ? &p.iso[l + 1] : &p.dir[d][l + 1], d);
            p.dark[d][l] = ref_filter_dir(l == top - 1 ? &dark_leaf : &p.dark[d][l + 1], d);
        }
    }
    free(dark_leaf.v);
    free(alpha);
    free(shade);
    free(plane);
    return p;
}

static void pyramid_free(ref_pyramid *p) {
    for (int l = 0; l < 11; ++l) {
        free(p->iso[l].v);
        free(p->shade[l].v);
        free(p->plane[l].v);
        for (int d = 0; d < 6; ++d) {
            free(p->dir[d][l].v);
            free(p->dark[d][l].v);
        }
    }
}

/* How far a sample of level `level` at lattice point lp is seen from its
 * darker side by a cone from o (volume units less 0.5; o[3] how far it was
 * lifted off its surface, < 0 for none) along d, its shade, how much of its
 * brighter (*front) and darker (*back) side the cone sees by the way it
 * heads, and how much of it counts (*keep: less where its plane lies within
 * a sample spacing of the lift, the cone's own surface): cone_trace.h's
 * rule, written out. */
static double ref_turn(const ref_pyramid *p, uint32_t level, const double lp[3], const double o[4],
                       const double d[3], double shade[4], double *front, double *back,
                       double *coherence, double *keep) {
    double pl[4];
    ref_trilinear(&p->plane[level], lp, pl);
    for (int k = 0; k < 4; ++k)
        shade[k] = 0.0;
    *front = *back = *keep = 1.0;
    *coherence = 1.0;
    const double len = sqrt(pl[0] * pl[0] + pl[1] * pl[1] + pl[2] * pl[2]);
    if (!(len > 1e-6))
        return 0.0;

    const double tolerance = 0.05, spacing = 0.5 / (double)(1u << level);
    const double dist = (pl[0] * o[0] + pl[1] * o[1] + pl[2] * o[2] - pl[3]) / len;
    ref_trilinear(&p->shade[level], lp, shade);
    const double coherent = fmin(fmax((len / fmax(shade[3], 1e-6) - 0.3) / 0.4, 0.0), 1.0);
    *coherence = coherent;
    const double facing = (pl[0] * d[0] + pl[1] * d[1] + pl[2] * d[2]) / len;
    *front = 1.0 + coherent * (fmin(fmax(1.0 - 2.0 * facing, 0.0), 1.0) - 1.0);
    *back = 1.0 + coherent * (fmin(fmax(1.0 + 2.0 * facing, 0.0), 1.0) - 1.0);
    if (o[3] >= 0.0 && dist * facing >= 0.0) /* not a plane it heads for */
        *keep = 1.0 - coherent * fmin(fmax(1.0 - fabs(fabs(dist) - o[3]) / spacing, 0.0), 1.0);
    const double behind = fmin(fmax(0.5 - dist / (2.0 * tolerance * spacing), 0.0), 1.0);
    return dist < tolerance * spacing ? behind * coherent : 0.0;
}

/* A level's value at volume point at ([0,1)^3) seen along d from o (volume
 * units less 0.5, and its lift: ref_turn), 0 in nodes without a brick;
 * *coherence (when given): its one-sided planes' agreement, 1 where it has
 * none. */
static void ref_level_sample_coherence(const brick_case *c, const ref_pyramid *p, int directional,
                                       uint32_t level, const double at[3], const double d[3],
                                       const double o[4], double out[4], double *coherence) {
    double unused;
    if (!coherence)
        coherence = &unused;
    *coherence = 1.0;
    const double cells = (double)(1u << level);
    uint32_t cell[3];
    double lp[3];
    for (int k = 0; k < 3; ++k) {
        cell[k] = (uint32_t)fmin(floor(at[k] * cells), cells - 1);
        lp[k] = 2.0 * at[k] * cells;
    }
    for (int k = 0; k < 4; ++k)
        out[k] = 0.0;
    const uint32_t node = node_at(c, cell, level);
    if (node == VCT_NODE_NULL || c->child[node] == VCT_NODE_NULL)
        return;
    double shade[4], front, back, coherent, keep;
    const double turn = ref_turn(p, level, lp, o, d, shade, &front, &back, &coherent, &keep);
    if (!directional || level + 1 >= p->levels) {
        ref_trilinear(&p->iso[level], lp, out);
        if (!(out[3] > 0.0))
            return; /* empty: no side to see */
        *coherence = coherent;
        for (int k = 0; k < 3; ++k)
            out[k] = keep * ((1.0 - turn) * front * out[k] + turn * back * (out[k] - shade[k]));
        out[3] *= keep;
        return;
    }
    const double w[3] = {d[0] * d[0], d[1] * d[1], d[2] * d[2]};
    double opacity = 0.0; /* the directional values' own, before the side's */
    for (int axis = 0; axis < 3; ++axis) {
        const int dir = d[axis] >= 0 ? axis : axis + 3;
        double s[4], dark[4];
        ref_trilinear(&p->dir[dir][level], lp, s);
        ref_trilinear(&p->dark[dir][level], lp, dark);
        for (int k = 0; k < 4; ++k)
            out[k] += w[axis] *
                      (k < 3 ? (1.0 - turn) * front * s[k] + turn * back * dark[k]
                             : s[k] + turn * (dark[k] - s[k])) /
                      (w[0] + w[1] + w[2]);
        opacity += w[axis] * s[3] / (w[0] + w[1] + w[2]);
    }
    for (int k = 0; k < 4; ++k)
        out[k] *= keep;
    if (opacity > 0.0)
        *coherence = coherent;
}

static void ref_level_sample(const brick_case *c, const ref_pyramid *p, int directional,
                             uint32_t level, const double at[3], const double d[3],
                             const double o[4], double out[4]) {
    ref_level_sample_coherence(c, p, directional, level, at, d, o, out, NULL);
}

typedef struct ref_cone {
    double radiance[3], alpha, ao_alpha;
    int left;
} ref_cone;

/* The march of kernels/conetrace/cone_trace.h, written out in double precision. */
static ref_cone ref_march(const brick_case *c, const ref_pyramid *p, int directional,
                          const vct_cone_settings *s, const double ambient[3], const double o[3],
                          const double d[3], double tan_half, double reach) {
    ref_cone r = {{0, 0, 0}, 0, 0, 0};
    const double side = c->info.side, voxel = side / c->info.resolution;
    const double finest = c->info.levels - 1.0, min_d = 2.0 * voxel;
    /* where the ray leaves the volume: the nearest face ahead on each axis */
    double exit = INFINITY;
    for (int k = 0; k < 3; ++k) {
        const double lo = c->info.origin[k], hi = lo + side;
        if (d[k] > 0.0)
            exit = fmin(exit, (hi - o[k]) / d[k]);
        else if (d[k] < 0.0)
            exit = fmin(exit, (lo - o[k]) / d[k]);
    }
    double t = voxel, last = 0.0; /* last: the final sample's thickness */
    double from[4];               /* the origin as the bricks' planes measure it, and its lift */
    for (int k = 0; k < 3; ++k)
        from[k] = (o[k] - c->info.origin[k]) / side - 0.5;
    from[3] = s->offset / c->info.resolution;
    for (int i = 0; i < 4096 && t <= reach; ++i) {
        double at[3];
        int outside = 0;
        for (int k = 0; k < 3; ++k) {
            at[k] = (o[k] + t * d[k] - c->info.origin[k]) / side;
            outside |= at[k] < 0.0 || at[k] >= 1.0;
        }
        if (outside) {
            r.left = 1;
            break;
        }
        const double diameter = fmax(2.0 * t * tan_half, min_d);
        double level = fmin(fmax(finest - log2(diameter / min_d), 0.0), finest);
        if (s->nearest_level)
            level = nearbyint(level); /* one level, its own spacing below */
        const uint32_t coarse = (uint32_t)level,
                       fine = coarse + 1 < p->levels ? coarse + 1 : coarse;
        double a[4], b[4], v[4];
        ref_level_sample(c, p, directional, coarse, at, d, from, a);
        ref_level_sample(c, p, directional, fine, at, d, from, b);
        for (int k = 0; k < 4; ++k)
            v[k] = a[k] + (level - coarse) * (b[k] - a[k]);
        const double step = s->step * diameter, spacing = voxel * exp2(finest - level);
        const double a_in = fmin(fmax(v[3], 0.0), 1.0);
        const double thickness = last > 0.0 ? last : step;
        const double alpha = a_in > 0 ? 1.0 - pow(1.0 - a_in, thickness / spacing) : 0.0;
        for (int k = 0; k < 3; ++k)
            r.radiance[k] += (1.0 - r.alpha) * (a_in > 0 ? v[k] * alpha / a_in : 0.0);
        r.alpha += (1.0 - r.alpha) * alpha;
        if (t <= s->ao_distance * side)
            r.ao_alpha = r.alpha;
        if (r.alpha >= s->stop_alpha || last > 0.0)
            break;
        /* The sample stood for [t - step / 2, t + step / 2]. If the next one
         * would lie outside, a last one just inside the boundary stands for
         * the rest of the way. */
        if (t + step >= exit && exit - (t + 0.5 * step) > 0.0 && exit <= reach) {
            last = exit - (t + 0.5 * step);
            t = exit * (1.0 - 1e-5);
            r.left = 1;
        } else {
            t += step;
        }
    }
    for (int k = 0; r.left && k < 3; ++k)
        r.radiance[k] += (1.0 - r.alpha) * ambient[k];
    return r;
}

/* ---- checks ----------------------------------------------------------------- */

static int result_sane(const float *o) {
    for (int k = 0; k < 8; ++k)
        if (!isfinite(o[k]))
            return 0;
    return o[3] >= 0.0f && o[3] <= 1.0f && o[4] >= 0.0f && o[4] <= o[3] + 1e-6f && o[0] >= 0.0f &&
           o[1] >= 0.0f && o[2] >= 0.0f;
}

/* n random cones (8 floats each): origins anywhere in the volume (some in
 * geometry), a fifth along an axis, a fifth grazing (nearly in an axis
 * plane), apertures from 0 to 60 degrees, some with a short reach. */
static void random_cones(const brick_case *c, uint32_t n, uint64_t seed, float *cones) {
    for (uint32_t i = 0; i < n; ++i) {
        float *q = cones + 8 * i;
        for (int k = 0; k < 3; ++k)
            q[k] = (float)(c->info.origin[k] + c->info.side * check_randf(&seed));
        q[3] = (float)tan(check_randf(&seed) * CHECK_PI / 3.0);
        double d[3], len = 0.0;
        for (int k = 0; k < 3; ++k) {
            d[k] = 2.0 * check_randf(&seed) - 1.0;
            len += d[k] * d[k];
        }
        if (i % 5 == 1)
            d[0] = d[1] = 0.0, d[2] = 1.0 - 2.0 * (i % 2), len = 1.0;
        if (i % 5 == 2)
            d[2] *= 1e-3, len = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        for (int k = 0; k < 3; ++k)
            q[4 + k] = (float)(d[k] / sqrt(len));
        q[7] = i % 7 == 3 ? (float)(0.3 * c->info.side) : INFINITY;
    }
}

/* Kernel cones against the reference. A sample next to an empty node jumps
 * to 0, so a position rounded differently in float can land on the other
 * side: nearly every cone must agree within `tol`, and the mean error must
 * be small. Image pools get a wider `tol`: GPUs may interpolate with 8-bit
 * weights (measured on an H100: 1 % of cones off by up to 6e-3). */
static void compare_cones(const brick_case *c, int directional, const char *pool, float step,
                          int nearest, double tol) {
    const uint32_t n = 3000;
    float *cones = malloc(32ull * n), *out = malloc(32ull * n);
    random_cones(c, n, 1234 + c->info.resolution, cones);
    vct_cone_settings s = vct_cone_settings_default();
    s.step = step;
    s.nearest_level = nearest;
    const float ambient[3] = {0.25f, 0.5f, 1.0f};
    const double amb[3] = {0.25, 0.5, 1.0};
    vct_error err = {0};
    REQUIRE_OK(vct_cone_trace(ctx, c->voxels, &s, ambient, cones, n, out, &err), err);
    ref_pyramid p = pyramid_of(c, directional);
    uint32_t insane = 0, off = 0, left = 0, stopped = 0;
    double sum_err = 0.0;
    for (uint32_t i = 0; i < n; ++i) {
        const float *q = cones + 8 * i, *o = out + 8 * i;
        insane += !result_sane(o);
        const double org[3] = {q[0], q[1], q[2]}, d[3] = {q[4], q[5], q[6]};
        const ref_cone r = ref_march(c, &p, directional, &s, amb, org, d, q[3], q[7]);
        double e = fabs(o[3] - r.alpha);
        for (int k = 0; k < 3; ++k)
            e = fmax(e, fabs(o[k] - r.radiance[k]) / (1.0 + fabs(r.radiance[k])));
        sum_err += e;
        if (!(e <= tol) && off++ < 3)
            fprintf(stderr, "%s: cone %u: got %g %g %g a %g, expected %g %g %g a %g\n", c->name, i,
                    o[0], o[1], o[2], o[3], r.radiance[0], r.radiance[1], r.radiance[2], r.alpha);
        left += o[7] == 1.0f;
        stopped += o[3] >= s.stop_alpha;
    }
    CHECK(insane == 0,
          "%s (%s, step %g%s): %u cones with NaN, negative radiance or opacity above 1", c->name,
          pool, step, nearest ? ", nearest level" : "", insane);
    CHECK(off <= n / 100, "%s (%s, step %g%s): %u of %u cones differ from the reference marcher",
          c->name, pool, step, nearest ? ", nearest level" : "", off, n);
    CHECK(sum_err / n < 1e-3, "%s (%s, step %g%s): mean error %g", c->name, pool, step,
          nearest ? ", nearest level" : "", sum_err / n);
    CHECK(left > n / 10 && stopped > n / 20,
          "%s (%s, step %g): %u cones left the volume, %u stopped", c->name, pool, step, left,
          stopped);
    printf("%-28s %-6s step %-4g%s %u cones, %u off, mean error %.2g, %u left, %u stopped\n",
           c->name, pool, step, nearest ? " nearest" : "", n, off, sum_err / n, left, stopped);
    pyramid_free(&p);
    free(cones);
    free(out);
}

static void random_volumes(void) {
    vct_material mats[4];
    for (int i = 0; i < 4; ++i)
        mats[i] = soup_material(i);
    const uint32_t sizes[] = {8, 32};
    for (size_t s = 0; s < 2; ++s) {
        for (int directional = 0; directional < 2; ++directional) {
            test_mesh m = mesh_soup(sizes[s] == 8 ? 150 : 500, 0.0f, 41 + s);
            /* opacity is the share of a voxel a surface covers: the soup's
             * triangles grow 4x about their centres, so that enough voxels
             * are opaque for cones to stop in them as well as leave */
            for (uint32_t t = 0; t < m.nt; ++t)
                for (int k = 0; k < 3; ++k) {
                    float *p = m.pos + 9 * t + k;
                    const float centre = (p[0] + p[3] + p[6]) / 3.0f;
                    for (int v = 0; v < 3; ++v)
                        p[3 * v] = fminf(fmaxf(centre + 4.0f * (p[3 * v] - centre), 0.0f), 1.0f);
                }
            vct_scene *scene = scene_of(&m, mats, 4);
            mesh_free(&m);
            add_point_light(scene, 0.3f, 0.8f, 0.6f, 0.5f);
            char name[64];
            snprintf(name, sizeof name, "soup %u^3 %s", sizes[s],
                     directional ? "directional" : "isotropic");
            const vct_brick_options buffer = {VCT_BRICKS_BUFFER, directional, 0};
            brick_case c = make_case(name, scene, sizes[s], 1.0f, &buffer);
            /* the default step, and steps whose opacity correction takes
             * nothing, a square root or pow */
            const float steps[] = {vct_cone_settings_default().step, 0.5f, 0.25f, 0.3f};
            for (int k = 0; k < 4; ++k)
                compare_cones(&c, directional, "buffer", steps[k], 0, 2e-3);
            /* one level per sample instead of two blended (--cone-levels nearest) */
            compare_cones(&c, directional, "buffer", vct_cone_settings_default().step, 1, 2e-3);
            const vct_brick_options image = {VCT_BRICKS_IMAGE, directional, 0};
            vct_error err = {0};
            REQUIRE_OK(vct_bricks_build(ctx, c.voxels, &image, &err), err);
            REQUIRE_OK(vct_voxels_inject_light(ctx, scene, c.accel, c.voxels, &err), err);
            compare_cones(&c, directional, "image", vct_cone_settings_default().step, 0, 1.5e-2);
            case_free(&c);
        }
    }
}

/* Each preset weight against the cosine-weighted share of the hemisphere
 * nearest its direction, and each aperture against the cone whose solid
 * angle is that of its cell (at most the presets' 20 degrees; the cell's
 * own, the open rest's spread, up to 45), both estimated by Monte Carlo
 * with uniform directions. */
static void presets(void) {
    const uint32_t counts[] = {1, 5, 6, 9, 16};
    for (size_t p = 0; p < 5; ++p) {
        float dirs[64], tan_half[16], cell_tan[16];
        vct_error err = {0};
        REQUIRE_OK(vct_cone_preset(counts[p], dirs, tan_half, cell_tan, &err), err);
        double share[16] = {0}, cell[16] = {0}, total = 0.0, sum = 0.0;
        uint64_t seed = 5;
        const int samples = 400000;
        for (int i = 0; i < samples; ++i) {
            const double z = check_randf(&seed), phi = 2.0 * CHECK_PI * check_randf(&seed);
            const double r = sqrt(fmax(0.0, 1.0 - z * z));
            const double w[3] = {r * cos(phi), r * sin(phi), z};
            uint32_t best = 0;
            double best_dot = -2.0;
            for (uint32_t k = 0; k < counts[p]; ++k) {
                const double dot =
                    w[0] * dirs[4 * k] + w[1] * dirs[4 * k + 1] + w[2] * dirs[4 * k + 2];
                if (dot > best_dot)
                    best_dot = dot, best = k;
            }
            share[best] += z;
            cell[best] += 1.0;
            total += z;
        }
        double worst = 0.0, worst_aperture = 0.0, worst_cell = 0.0;
        int bad_dir = 0;
        for (uint32_t k = 0; k < counts[p]; ++k) {
            worst = fmax(worst, fabs(share[k] / total - dirs[4 * k + 3]));
            sum += dirs[4 * k + 3];
            const double len = sqrt(dirs[4 * k] * dirs[4 * k] + dirs[4 * k + 1] * dirs[4 * k + 1] +
                                    dirs[4 * k + 2] * dirs[4 * k + 2]);
            bad_dir |= fabs(len - 1.0) > 1e-5 || dirs[4 * k + 2] <= 0.0f;
            /* the cell's solid angle over the hemisphere's 2 pi is its share
             * of the uniform samples; a cone of solid angle W has half
             * angle acos(1 - W / 2 pi) */
            const double cell_half = acos(1.0 - cell[k] / samples),
                         half = fmin(cell_half, 20.0 * CHECK_PI / 180.0);
            worst_aperture = fmax(worst_aperture, fabs(atan(tan_half[k]) - half));
            worst_cell = fmax(worst_cell,
                              fabs(atan(cell_tan[k]) - fmin(cell_half, 45.0 * CHECK_PI / 180.0)));
        }
        CHECK(fabs(sum - 1.0) < 1e-6, "preset %u: weights sum to %.9f", counts[p], sum);
        CHECK(worst < 0.005, "preset %u: a weight is %.4f off its cosine-weighted share", counts[p],
              worst);
        CHECK(!bad_dir, "preset %u: a direction is not a unit vector above the surface", counts[p]);
        /* the preset integrates its cells on a grid: half a degree */
        CHECK(worst_aperture < 0.5 * CHECK_PI / 180.0,
              "preset %u: an aperture is %.2f degrees off its cell's (capped at 20)", counts[p],
              worst_aperture * 180.0 / CHECK_PI);
        CHECK(worst_cell < 0.5 * CHECK_PI / 180.0,
              "preset %u: a cell's half-angle is %.2f degrees off (capped at 45)", counts[p],
              worst_cell * 180.0 / CHECK_PI);
        printf("preset %2u cones: weights sum to 1 within %.1g, worst share error %.4f, worst "
               "aperture %.3f degrees off, worst cell %.3f\n",
               counts[p], fabs(sum - 1.0), worst, worst_aperture * 180.0 / CHECK_PI,
               worst_cell * 180.0 / CHECK_PI);
    }
    float dirs[64], tan_half[16];
    vct_error err = {0};
    CHECK(vct_cone_preset(7, dirs, tan_half, NULL, &err) == VCT_ERR_INPUT &&
              strstr(err.message, "16"),
          "an unknown preset is refused with the list: %s", err.message);
}

/* Cones given by hand: origin, direction, tan(half-angle), reach. */
static void trace(const brick_case *c, const float ambient[3], const float *cones, uint32_t n,
                  float *out) {
    vct_cone_settings s = vct_cone_settings_default();
    vct_error err = {0};
    REQUIRE_OK(vct_cone_trace(ctx, c->voxels, &s, ambient, cones, n, out, &err), err);
}

/* One quad (a wall) in a 32^3 buffer pool of the unit cube, lit by a point
 * light at (light_x, 0.5, 0.5). */
static brick_case lit_wall_case(const float quad[12], float light_x, int directional,
                                const char *name) {
    vct_scene *s = quads_scene(quad, 1);
    add_point_light(s, light_x, 0.5f, 0.5f, 0.1f);
    const vct_brick_options opt = {VCT_BRICKS_BUFFER, directional, 0};
    return make_case(name, s, 32, 1.0f, &opt);
}

static void hard_cases(void) {
    const float ambient[3] = {0.5f, 1.0f, 2.0f};
    vct_error err = {0};
    /* Nothing inside the volume: every cone leaves, seeing exactly the environment. */
    {
        const float quad[12] = {5, 5, 5, 6, 5, 5, 6, 6, 5, 5, 6, 5};
        vct_scene *s = quads_scene(quad, 1);
        const vct_brick_options opt = {VCT_BRICKS_AUTO, 1, 0};
        brick_case c = make_case("empty volume", s, 16, 1.0f, &opt);
        float cones[16] = {0.5f, 0.5f, 0.5f, 0.3f, 0,    1,    0,    INFINITY,
                           0.1f, 0.9f, 0.2f, 0.0f, 0.6f, 0.0f, 0.8f, INFINITY};
        float out[16];
        trace(&c, ambient, cones, 2, out);
        for (int i = 0; i < 2; ++i)
            CHECK(out[8 * i + 7] == 1.0f && out[8 * i + 3] == 0.0f && out[8 * i] == ambient[0] &&
                      out[8 * i + 1] == ambient[1] && out[8 * i + 2] == ambient[2],
                  "empty volume: cone %d saw %g %g %g a %g (left %g)", i, out[8 * i],
                  out[8 * i + 1], out[8 * i + 2], out[8 * i + 3], out[8 * i + 7]);
        case_free(&c);
    }
    /* A lit one-voxel wall at x = 0.5 of a 32^3 volume. */
    const float wall[12] = {0.5f, 0.01f, 0.01f, 0.5f, 0.99f, 0.01f,
                            0.5f, 0.99f, 0.99f, 0.5f, 0.01f, 0.99f};
    for (int directional = 0; directional < 2; ++directional) {
        brick_case c = lit_wall_case(wall, 0.2f, directional,
                                     directional ? "wall, directional" : "wall, isotropic");
        /* Thin cones crossing it at 0 to 75 degrees stop at it: no leak. */
        enum { CROSS = 16 };
        float cones[8 * (CROSS + 4)], out[8 * (CROSS + 4)];
        for (int i = 0; i < CROSS; ++i) {
            const double a = (i / (double)CROSS) * 75.0 * CHECK_PI / 180.0;
            const float q[8] = {0.3f,
                                0.5f,
                                0.5f,
                                0.0f,
                                (float)cos(a),
                                (float)sin(a) * 0.6f,
                                (float)sin(a) * 0.8f,
                                INFINITY};
            memcpy(cones + 8 * i, q, sizeof q);
        }
        /* Starting inside the wall: opaque at once, finite. */
        const float inside[8] = {0.5f, 0.5f, 0.5f, 0.2f, 0.0f, 0.0f, 1.0f, INFINITY};
        /* Grazing along it, just off its face, and outside the volume. */
        const float graze[8] = {0.52f, 0.05f, 0.5f, 0.1f, 0.0f, 1.0f, 0.0f, INFINITY};
        const float graze2[8] = {0.5f, 0.05f,       0.05f,       0.05f,
                                 0.0f, 0.70710678f, 0.70710678f, INFINITY};
        const float away[8] = {2.0f, 2.0f, 2.0f, 0.3f, 1.0f, 0.0f, 0.0f, INFINITY};
        memcpy(cones + 8 * CROSS, inside, 32);
        memcpy(cones + 8 * (CROSS + 1), graze, 32);
        memcpy(cones + 8 * (CROSS + 2), graze2, 32);
        memcpy(cones + 8 * (CROSS + 3), away, 32);
        trace(&c, ambient, cones, CROSS + 4, out);
        int leaks = 0, insane = 0;
        for (int i = 0; i < CROSS + 4; ++i)
            insane += !result_sane(out + 8 * i);
        for (int i = 0; i < CROSS; ++i)
            leaks += out[8 * i + 3] < 0.99f || out[8 * i + 7] != 0.0f;
        CHECK(leaks == 0, "%s: %d of %d thin cones crossed the wall", c.name, leaks, CROSS);
        CHECK(insane == 0, "%s: %d cones with NaN or opacity above 1", c.name, insane);
        const float *in = out + 8 * CROSS;
        CHECK(in[3] >= 0.99f && in[6] <= 2.0f,
              "%s: a cone inside the wall: opacity %g after %g samples", c.name, in[3], in[6]);
        const float *aw = out + 8 * (CROSS + 3);
        CHECK(aw[7] == 1.0f && aw[6] == 0.0f && aw[0] == ambient[0] && aw[2] == ambient[2],
              "%s: a cone outside the volume sees the environment (%g %g %g, %g samples)", c.name,
              aw[0], aw[1], aw[2], aw[6]);
        /* A wide cone (30 degrees) through the wall's middle: directional
         * bricks keep it opaque seen along its normal. */
        const float wide[8] = {0.2f, 0.5f, 0.5f, 0.577f, 1.0f, 0.0f, 0.0f, INFINITY};
        float wide_out[8];
        trace(&c, ambient, wide, 1, wide_out);
        printf("%-28s thin cones stopped, wide cone across it: opacity %.3f\n", c.name,
               wide_out[3]);
        if (directional)
            CHECK(wide_out[3] >= 0.9f, "%s: a wide cone sees through the wall (opacity %g)", c.name,
                  wide_out[3]);
        /* A wide cone (30 degrees) running along the wall, 3 voxels off its
         * lit face: the wall hides the part of it that heads its way, half
         * of it at most, however many of its samples take the wall in, and
         * not nothing. */
        const float along[8] = {
            0.5f - 3.0f / 32.0f, 0.03f, 0.5f, 0.577f, 0.0f, 1.0f, 0.0f, INFINITY};
        float along_out[8];
        trace(&c, ambient, along, 1, along_out);
        printf("%-28s wide cone along it, 3 voxels off: opacity %.3f\n", c.name, along_out[3]);
        CHECK(along_out[3] > 0.1f && along_out[3] < 0.6f,
              "%s: a wide cone along the wall, 3 voxels off: opacity %g", c.name, along_out[3]);
        /* Lit on its x < 0.5 face only: cones from behind it, narrow and
         * wide, head-on and at 45 degrees, see its dark face; from before
         * it, its lit face. */
        enum { SIDED = 8 };
        float sided[8 * SIDED], sided_out[8 * SIDED];
        for (int i = 0; i < SIDED; ++i) {
            const int lit_side = i < SIDED / 2;
            const float slant = (i & 1) ? 0.70710678f : 0.0f, ahead = (i & 1) ? 0.70710678f : 1.0f;
            const float q[8] = {lit_side ? 0.3f : 0.7f,
                                0.5f - 0.1f * slant,
                                0.5f,
                                (i & 2) ? 0.577f : 0.05f,
                                lit_side ? ahead : -ahead,
                                slant,
                                0.0f,
                                INFINITY};
            memcpy(sided + 8 * i, q, sizeof q);
        }
        const float none[3] = {0, 0, 0};
        trace(&c, none, sided, SIDED, sided_out);
        float seen_lit = INFINITY, seen_dark = 0.0f;
        for (int i = 0; i < SIDED; ++i) {
            const float y = sided_out[8 * i + 1];
            if (i < SIDED / 2)
                seen_lit = fminf(seen_lit, y);
            else
                seen_dark = fmaxf(seen_dark, y);
        }
        printf("%-28s seen from its lit side at least %.4f, from behind at most %.5f\n", c.name,
               seen_lit, seen_dark);
        CHECK(seen_lit > 0.0f && seen_dark <= 0.01f * seen_lit,
              "%s: lit on one face, seen from behind %g against %g from before: light leaks "
              "through",
              c.name, seen_dark, seen_lit);
        case_free(&c);
    }
    /* A lit wall in the last voxel layer of the volume, on its face: wide
     * cones (steps of a diameter, up to 0.7 of the volume) towards it must
     * not step over it and out. */
    const float face_wall[12] = {0.99f, 0.01f, 0.01f, 0.99f, 0.99f, 0.01f,
                                 0.99f, 0.99f, 0.99f, 0.99f, 0.01f, 0.99f};
    for (int directional = 0; directional < 2; ++directional) {
        brick_case c =
            lit_wall_case(face_wall, 0.5f, directional,
                          directional ? "face wall, directional" : "face wall, isotropic");
        enum { WIDE = 12 };
        float cones[8 * WIDE], out[8 * WIDE];
        for (int i = 0; i < WIDE; ++i) {
            const float from = 0.05f + 0.075f * (float)i;
            const float q[8] = {from, 0.5f, 0.5f, 0.577f, 1.0f, 0.0f, 0.0f, INFINITY};
            memcpy(cones + 8 * i, q, sizeof q);
        }
        trace(&c, ambient, cones, WIDE, out);
        float least = 1.0f;
        for (int i = 0; i < WIDE; ++i)
            least = fminf(least, out[8 * i + 3]);
        printf("%-28s wide cones towards it: least opacity %.3f\n", c.name, least);
        /* Isotropic bricks average the wall with the empty space beside it
         * (see above); directional ones keep it opaque along its normal. */
        if (directional)
            CHECK(least >= 0.9f,
                  "%s: a wide cone stepped over the wall on the volume's face (opacity %g)", c.name,
                  least);
        case_free(&c);
    }
    (void)err;
}

/* The light where the ray from `from` along d meets the scene
 * (kernels/conetrace/inject_bounce.cl): the finest level's sample there,
 * seen from a tenth of a voxel off `from` along n, un-premultiplied; none
 * where the ray meets nothing. */
static void ref_ray_light(const brick_case *c, const ref_pyramid *p, const double from[3],
                          const double n[3], const double d[3], double light[3]) {
    const double side = c->info.side, voxel = side / c->info.resolution;
    double border;
    light[0] = light[1] = light[2] = 0.0;
    const double t = ref_closest(c->scene, from, d, INFINITY, &border);
    if (t < 0.0)
        return;
    double at[3], o[4] = {0, 0, 0, -1.0}, v[4], coherence;
    for (int k = 0; k < 3; ++k) {
        at[k] = fmin(fmax((from[k] + t * d[k] - c->info.origin[k]) / side, 0.0), 0.99999);
        o[k] = (from[k] + 0.1 * voxel * n[k] - c->info.origin[k]) / side - 0.5;
    }
    ref_level_sample_coherence(c, p, 1, p->levels - 1, at, d, o, v, &coherence);
    for (int k = 0; k < 3; ++k)
        light[k] = v[3] > 1e-3 ? v[k] / v[3] : 0.0;
}

static uint32_t lowbias32(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

enum { RAYS_SIDE = 3 };

/* A face parallel to the plane (normals within 25 degrees) that the ray
 * from `from` along n meets within `reach`: `from` moves just past it (the
 * plane of a closed object thinner than a voxel lies inside it). */
static void past_parallel_face(const vct_scene *s, double from[3], const double n[3], double reach,
                               double lift) {
    double border;
    uint32_t tri = 0;
    const double t = ref_closest_tri(s, from, n, reach, &border, &tri);
    if (t < 0.0)
        return;
    const uint32_t *corner = s->triangles + 3 * tri;
    const v3 a = v3_of(s->positions + 3 * corner[0]);
    const v3 normal = cross(sub(v3_of(s->positions + 3 * corner[1]), a),
                            sub(v3_of(s->positions + 3 * corner[2]), a));
    const double len = sqrt(dot(normal, normal));
    if (!(len > 0.0) || fabs(dot(normal, v(n[0], n[1], n[2]))) / len <= 0.9)
        return;
    for (int k = 0; k < 3; ++k)
        from[k] += n[k] * (t + lift);
}

/* The mean light of the bounce's rays from voxel `cell` on the side of
 * unit n: a 3 x 3 grid over the unit square at an offset hashed from the
 * key and the side, mapped onto the cosine-weighted hemisphere (Malley) in
 * the voxel's turned frame; from the point of the voxel's plane (normal n,
 * offset h) nearest its centre, just off it, or from its centre lifted the
 * cone offset where it has no normal; past a parallel face within a voxel
 * along n. The scene has no ambient light. */
static void gather_side(const brick_case *c, const ref_pyramid *p, const vct_cone_settings *s,
                        uint32_t key, const uint32_t cell[3], const double n[3], int has_normal,
                        double h, double gathered[3]) {
    const double side = c->info.side, voxel = side / c->info.resolution;
    /* the frame of bsdf.h's basis_of (Duff et al. 2017) about the normal's
     * axis (its largest component made positive), turned about it by the
     * angle 2 pi hash(key) / 2^32 (cone_frame.h) */
    const double ax = fabs(n[0]), ay = fabs(n[1]), az = fabs(n[2]);
    const double major = ax >= ay && ax >= az ? n[0] : (ay >= az ? n[1] : n[2]);
    const double m[3] = {major < 0 ? -n[0] : n[0], major < 0 ? -n[1] : n[1],
                         major < 0 ? -n[2] : n[2]};
    const double sg = m[2] >= 0 ? 1.0 : -1.0, a = -1.0 / (sg + m[2]), bb = m[0] * m[1] * a;
    const double t0[3] = {1.0 + sg * m[0] * m[0] * a, sg * bb, -sg * m[0]};
    const double b0[3] = {bb, sg + m[1] * m[1] * a, -m[1]};
    const double angle = 6.283185307179586 * (double)(lowbias32(key) >> 8) / 16777216.0;
    double t[3], b[3];
    for (int k = 0; k < 3; ++k) {
        t[k] = cos(angle) * t0[k] + sin(angle) * b0[k];
        b[k] = cos(angle) * b0[k] - sin(angle) * t0[k];
    }
    double from[3], unit[3], along = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double centre = c->info.origin[k] + (cell[k] + 0.5) * voxel;
        unit[k] = (centre - c->info.origin[k]) / side - 0.5;
        along += n[k] * unit[k];
        from[k] = centre + n[k] * s->offset * voxel;
        gathered[k] = 0.0;
    }
    for (int k = 0; k < 3 && has_normal; ++k)
        from[k] =
            c->info.origin[k] + (unit[k] - (along - h) * n[k] + 0.5) * side + n[k] * 1e-5 * side;
    if (has_normal)
        past_parallel_face(c->scene, from, n, voxel, 1e-5 * side);
    const uint32_t hashed =
        lowbias32(key ^ (n[0] + 2.0 * n[1] + 4.0 * n[2] > 0.0 ? 0x9e3779b9u : 0u));
    const double jitter[2] = {(double)(hashed >> 8) / 16777216.0,
                              (double)(lowbias32(hashed) >> 8) / 16777216.0};
    for (int i = 0; i < RAYS_SIDE * RAYS_SIDE; ++i) {
        const double u = (i % RAYS_SIDE + jitter[0]) / RAYS_SIDE;
        const double w = (i / RAYS_SIDE + jitter[1]) / RAYS_SIDE;
        const double r = sqrt(u), phi = 6.283185307179586 * w, up = sqrt(fmax(1.0 - u, 0.0));
        double d[3], dl = 0.0, light[3];
        for (int k = 0; k < 3; ++k) {
            d[k] = r * cos(phi) * t[k] + r * sin(phi) * b[k] + up * n[k];
            dl += d[k] * d[k];
        }
        for (int k = 0; k < 3; ++k)
            d[k] /= sqrt(dl);
        ref_ray_light(c, p, from, n, d, light);
        for (int k = 0; k < 3; ++k)
            gathered[k] += light[k] / (RAYS_SIDE * RAYS_SIDE);
    }
}

static double luminance(const double c[3]) {
    return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
}

/* Checks one bounce: each side of every checked voxel (vct_voxels_read_sides)
 * must be its direct light plus albedo times the mean light its rays meet
 * on that side of its plane, read from pyramid p (the light the bounce
 * read); the brighter side becomes its radiance `after`,
 * the difference its shade in `after_sides`. With `kept` (the sides before a
 * bounce after the first), the side `kept`'s plane faces does instead, the
 * plane stays and k is the larger of kept's and the difference's luminance.
 * A voxel without a normal gathers on both sides of z and sends the brighter
 * both ways. One in `gain_share` of the voxels at least must gain light
 * over `direct`. */
static void check_bounce(const char *what, const brick_case *c, const ref_pyramid *p,
                         const float *direct, const float *direct_sides, const float *kept,
                         const float *after, const float *after_sides, uint32_t gain_share) {
    const uint32_t nv = c->info.voxels;
    uint32_t *keys = malloc(4ull * nv);
    vct_error err = {0};
    const vct_cone_settings s = vct_cone_settings_default();
    REQUIRE_OK(vct_voxels_read(ctx, c->voxels, keys, NULL, NULL, NULL, &err), err);
    uint32_t off = 0, checked = 0, brighter = 0, two_sided = 0;
    for (uint32_t v = 0; v < nv; v += 7, ++checked) {
        uint32_t cell[3];
        decode(keys[v], cell);
        const float *plane = direct_sides + 8 * v + 4;
        const int has_normal = plane[0] != 0.0f || plane[1] != 0.0f || plane[2] != 0.0f;
        double n[3] = {has_normal ? plane[0] : 0.0, has_normal ? plane[1] : 0.0,
                       has_normal ? plane[2] : 1.0};
        double front[3], back[3], toward[3], away[3];
        gather_side(c, p, &s, keys[v], cell, n, has_normal, plane[3], front);
        for (int k = 0; k < 3; ++k)
            n[k] = -n[k];
        /* the same plane seen from its other side: normal -n, offset -h */
        gather_side(c, p, &s, keys[v], cell, n, has_normal, -plane[3], back);
        const int front_more = luminance(front) >= luminance(back);
        for (int k = 0; k < 3; ++k) {
            const double lit = direct[4 * v + k], rho = c->albedo[4 * v + k];
            const double more = front_more ? front[k] : back[k];
            toward[k] = lit + rho * (has_normal ? front[k] : more);
            away[k] = lit - (has_normal ? direct_sides[8 * v + k] : 0.0) +
                      rho * (has_normal ? back[k] : more);
        }
        const float *up = kept ? kept + 8 * v + 4 : NULL;
        const int flip =
            up ? (double)up[0] * plane[0] + (double)up[1] * plane[1] + (double)up[2] * plane[2] <
                     0.0
               : luminance(away) > luminance(toward);
        double e = 0.0, diff[3];
        for (int k = 0; k < 3; ++k) {
            const double bright = flip ? away[k] : toward[k], dark = flip ? toward[k] : away[k];
            diff[k] = bright - dark;
            e = fmax(e, fabs(after[4 * v + k] - bright) / (1.0 + fabs(bright)));
            e = fmax(e, fabs(after_sides[8 * v + k] - diff[k]) / (1.0 + fabs(bright)));
        }
        if (up) {
            const double k_want = fmax(kept[8 * v + 3], fabs(luminance(diff)));
            e = fmax(e, fabs(after_sides[8 * v + 3] - k_want) / (1.0 + k_want));
            for (int k = 0; k < 4; ++k)
                e = after_sides[8 * v + 4 + k] == up[k] ? e : fmax(e, 1.0);
        }
        two_sided += !has_normal;
        brighter += after[4 * v] > direct[4 * v] + 1e-4f;
        if (!(e <= 2e-3) && off++ < 3)
            fprintf(stderr, "%s: voxel %u off by %g\n", what, v, e);
    }
    CHECK(off <= checked / 100 && brighter > checked / gain_share,
          "%s: %u of %u voxels differ from the reference, %u gained light", what, off, checked,
          brighter);
    printf("%s 32^3: %u voxels checked (%u without a normal), %u off, %u gained light\n", what,
           checked, two_sided, off, brighter);
    free(keys);
}

/* One bounce on c's voxels, checked against the reference pyramid of
 * `reads` and `reads_sides` (the light the bounce gathers): the result lands
 * in `after` and `after_sides`. */
static void bounce_against_reference(const char *what, brick_case *c, const vct_scene *scene,
                                     const vct_cone_settings *s, const float *reads,
                                     const float *reads_sides, const float *direct,
                                     const float *direct_sides, int keeps, float *after,
                                     float *after_sides, uint32_t gain_share) {
    vct_error err = {0};
    memmove(c->radiance, reads, 16ull * c->info.voxels);
    memmove(c->sides, reads_sides, 32ull * c->info.voxels);
    float *kept = keeps ? malloc(32ull * c->info.voxels) : NULL;
    if (kept)
        memcpy(kept, reads_sides, 32ull * c->info.voxels);
    ref_pyramid p = pyramid_of(c, 1);
    REQUIRE_OK(vct_voxels_inject_bounce(ctx, scene, c->accel, c->voxels, s, &err), err);
    REQUIRE_OK(vct_voxels_read_radiance(ctx, c->voxels, after, &err), err);
    REQUIRE_OK(vct_voxels_read_sides(ctx, c->voxels, after_sides, &err), err);
    check_bounce(what, c, &p, direct, direct_sides, kept, after, after_sides, gain_share);
    free(kept);
    pyramid_free(&p);
}

/* A case's light before a bounce (direct: injection's) and after it, its
 * radiance and sides as vct_voxels_read_* give them. */
typedef struct bounce_light {
    float *direct, *after, *direct_sides, *after_sides;
} bounce_light;

static bounce_light bounce_light_of(const brick_case *c) {
    const uint32_t nv = c->info.voxels;
    bounce_light l = {malloc(16ull * nv), malloc(16ull * nv), malloc(32ull * nv),
                      malloc(32ull * nv)};
    memcpy(l.direct, c->radiance, 16ull * nv);
    memcpy(l.direct_sides, c->sides, 32ull * nv);
    return l;
}

static void bounce_light_free(bounce_light *l) {
    free(l->direct);
    free(l->after);
    free(l->direct_sides);
    free(l->after_sides);
}

/* Bounces (vct_voxels_inject_bounce): the second bounce gathers the direct
 * light's bricks; the third gathers the bricks of the second's radiance and
 * still adds to the direct light alone, so that the light of the second
 * bounce is not counted twice, on the sides the second decided. Each is
 * checked against the reference marcher on the bricks it read. */
static void bounces(void) {
    vct_material mats[4];
    for (int i = 0; i < 4; ++i)
        mats[i] = soup_material(i);
    test_mesh m = mesh_soup(300, 0.0f, 77);
    vct_scene *scene = scene_of(&m, mats, 4);
    mesh_free(&m);
    add_point_light(scene, 0.3f, 0.8f, 0.6f, 0.5f);
    const vct_brick_options opt = {VCT_BRICKS_BUFFER, 1, 0};
    brick_case c = make_case("bounces 32^3", scene, 32, 1.0f, &opt);
    bounce_light l = bounce_light_of(&c);
    vct_error err = {0};
    const vct_cone_settings s = vct_cone_settings_default();
    bounce_against_reference("second bounce", &c, scene, &s, l.direct, l.direct_sides, l.direct,
                             l.direct_sides, 0, l.after, l.after_sides, 4);
    /* The third bounce reads the second's radiance. */
    bounce_against_reference("third bounce", &c, scene, &s, l.after, l.after_sides, l.direct,
                             l.direct_sides, 1, l.after, l.after_sides, 4);
    /* Light injection starts over: one bounce after it is the second again. */
    REQUIRE_OK(vct_voxels_inject_light(ctx, scene, c.accel, c.voxels, &err), err);
    bounce_against_reference("second bounce again", &c, scene, &s, l.direct, l.direct_sides,
                             l.direct, l.direct_sides, 0, l.after, l.after_sides, 4);
    bounce_light_free(&l);
    case_free(&c);
}

/* A closed slab a quarter voxel thick (a slat, a table top) over a floor
 * lit from above: its voxels' plane runs inside it, between its faces, and
 * the rays of its underside must leave from below its lower face to gather
 * the floor's light. Checked against the reference, and against the floor:
 * the underside, which no light reaches directly, sends back at least a
 * fifth of its albedo times the floor's light (from inside, nothing). */
static void thin_slab_bounce(void) {
    const float y0 = 0.5f, y1 = 0.508f, lo = 0.35f, hi = 0.65f;
    const float quads[7][12] = {
        /* the floor, the slab's top and underside, then its four sides */
        {0.02f, 0.1f, 0.02f, 0.98f, 0.1f, 0.02f, 0.98f, 0.1f, 0.98f, 0.02f, 0.1f, 0.98f},
        {lo, y1, lo, hi, y1, lo, hi, y1, hi, lo, y1, hi},
        {lo, y0, lo, lo, y0, hi, hi, y0, hi, hi, y0, lo},
        {lo, y0, lo, hi, y0, lo, hi, y1, lo, lo, y1, lo},
        {lo, y0, hi, lo, y1, hi, hi, y1, hi, hi, y0, hi},
        {lo, y0, lo, lo, y1, lo, lo, y1, hi, lo, y0, hi},
        {hi, y0, lo, hi, y0, hi, hi, y1, hi, hi, y1, lo}};
    vct_scene *scene = quads_scene(&quads[0][0], 7);
    add_point_light(scene, 0.1f, 0.9f, 0.1f, 0.5f);
    const vct_brick_options opt = {VCT_BRICKS_BUFFER, 1, 0};
    brick_case c = make_case("thin slab 32^3", scene, 32, 1.0f, &opt);
    const uint32_t nv = c.info.voxels;
    bounce_light l = bounce_light_of(&c);
    uint32_t *keys = malloc(4ull * nv);
    const vct_cone_settings s = vct_cone_settings_default();
    /* only the slab's voxels gain light: the floor sees its dark underside */
    bounce_against_reference("thin slab", &c, scene, &s, l.direct, l.direct_sides, l.direct,
                             l.direct_sides, 0, l.after, l.after_sides, 10);
    vct_error err = {0};
    REQUIRE_OK(vct_voxels_read(ctx, c.voxels, keys, NULL, NULL, NULL, &err), err);
    /* the floor's light (its voxels' brighter side) and the slab's
     * underside, away from its rim */
    double floor_light = 0.0, under = 0.0, rho = 0.0;
    uint32_t floor_voxels = 0, under_voxels = 0;
    for (uint32_t v = 0; v < nv; ++v) {
        uint32_t cell[3];
        decode(keys[v], cell);
        if (cell[1] == 3) {
            floor_light += luminance(
                (const double[3]){l.direct[4 * v], l.direct[4 * v + 1], l.direct[4 * v + 2]});
            ++floor_voxels;
        }
        if (cell[1] == 16 && cell[0] >= 12 && cell[0] <= 19 && cell[2] >= 12 && cell[2] <= 19) {
            const float *plane = l.after_sides + 8 * v + 4;
            double side[3];
            for (int k = 0; k < 3; ++k) /* the side facing down */
                side[k] = l.after[4 * v + k] - (plane[1] < 0.0f ? 0.0f : l.after_sides[8 * v + k]);
            under += luminance(side);
            rho += luminance(
                (const double[3]){c.albedo[4 * v], c.albedo[4 * v + 1], c.albedo[4 * v + 2]});
            ++under_voxels;
        }
    }
    floor_light /= floor_voxels ? floor_voxels : 1;
    under /= under_voxels ? under_voxels : 1;
    rho /= under_voxels ? under_voxels : 1;
    CHECK(under_voxels == 64 && under > 0.2 * rho * floor_light,
          "thin slab: its underside sends %g (%u voxels), the floor %g, albedo %g", under,
          under_voxels, floor_light, rho);
    printf("thin slab: underside %.4f = %.2f of albedo times the floor's light\n", under,
           under / (rho * floor_light));
    free(keys);
    bounce_light_free(&l);
    case_free(&c);
}

int main(void) {
    ctx = check_context();
    presets();
    random_volumes();
    hard_cases();
    bounces();
    thin_slab_bounce();
    vct_context_release(ctx);
    return check_exit("test_cone");
}
