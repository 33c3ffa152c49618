/* Cones: diffuse presets, march settings, and the arguments every cone
 * kernel takes (kernels/conetrace/cone_trace.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "voxel/cones.h"
#include "vct_types.h"
#include "voxel/voxels.h"

vct_cone_settings vct_cone_settings_default(void) {
    const vct_cone_settings s = {1.0f, 4.0f, 0.125f, 0.99f, 0};
    return s;
}

int vct_cone_settings_check(const vct_cone_settings *s, vct_error *err) {
    if (!(s->step > 0.0f && s->step <= 4.0f))
        return vct_fail(err, VCT_ERR_INPUT,
                        "cone step %g: give a fraction of the diameter in (0, 4]", s->step);
    if (!(s->offset >= 0.0f && s->offset <= 64.0f))
        return vct_fail(err, VCT_ERR_INPUT, "cone offset %g: give 0 to 64 voxels", s->offset);
    if (!(s->ao_distance > 0.0f && s->ao_distance <= 2.0f))
        return vct_fail(err, VCT_ERR_INPUT,
                        "AO distance %g: give a fraction of the volume's side in (0, 2]",
                        s->ao_distance);
    if (!(s->stop_alpha > 0.0f && s->stop_alpha <= 1.0f))
        return vct_fail(err, VCT_ERR_INPUT, "cone stop opacity %g: give a value in (0, 1]",
                        s->stop_alpha);
    if (s->nearest_level != 0 && s->nearest_level != 1)
        return vct_fail(err, VCT_ERR_INPUT, "cone levels %d: give 0 (blend) or 1 (nearest)",
                        s->nearest_level);
    return VCT_OK;
}

/* Rings of cones around the normal: how many on each, from the pole out.
 * Nine cones are two rings of 3 and 6, not one along the normal and a ring
 * of 8: under the 20-degree cap the ring of 8 sits at 48 degrees and leaves
 * a band from 19.5 to 28 degrees off the normal (11 % of the cosine-weighted
 * hemisphere) between it and the pole cone, where a bright source such as a
 * spot-lit statue under a ceiling was read at two thirds of its light. The
 * suite at 128x128, NRMSE: mean 0.1045 -> 0.0993, 11 of 12 scenes better
 * (spot_gallery 0.127 -> 0.115, window_room 0.078 -> 0.064, dense_hall
 * 0.091 -> 0.093 the one worse); 3 + 6 beat 4 + 5 (0.1005). */
typedef struct preset_rings {
    uint32_t count;
    uint32_t ring[3];
} preset_rings;

static const preset_rings presets[] = {
    {1, {1, 0, 0}}, {5, {1, 4, 0}}, {6, {1, 5, 0}}, {9, {3, 6, 0}}, {16, {1, 5, 10}}};

#define PI 3.14159265358979323846
/* A cone is as wide as its cell up to this half angle; a cone narrower
 * than its cell still stands for the whole cell through its weight. Nine
 * cones' cells are 21.6 (inner ring) and 29 to 30 degrees (outer). Wider
 * cones read coarser levels, whose samples mix a room's walls with their
 * lit outer faces: at 27.5 a closed room under a sky lets in 1.3 % of the
 * outside's light (test_vct; 0.8 % at 20), the atrium's shaded column
 * faces take in the sunlit ones beside them (0.061 -> 0.066), and 60
 * degrees gave the Cornell box twice the error. What the wider cones
 * gained over the suite was their open rest's wider spread, which the rest
 * now has at every cap (below). */
#define MAX_HALF_ANGLE (20.0 * PI / 180.0)
/* The rays that look past a cone where it leaves the volume (its open
 * rest, for a caller that marches the preset's cones) spread over a cone of its cell's
 * solid angle, uncapped: the sky and the walls between 20 degrees and a
 * cell's edge are its own, and rays kept within the cone's aperture missed
 * them (the suite's mean NRMSE at 128^2 0.0783 -> 0.0759: the Cornell box
 * 0.052 -> 0.049, the spot gallery 0.091 -> 0.082; the march's levels, and
 * with them its leaks, stay as they were). One cone's cell is the whole
 * hemisphere: its rays stop at 45 degrees, well above the surface. */
#define MAX_REST_HALF_ANGLE (45.0 * PI / 180.0)

vct_status vct_cone_preset(uint32_t count, float *dirs, float *tan_half, float *cell_tan,
                           vct_error *err) {
    const preset_rings *p = NULL;
    for (size_t i = 0; i < sizeof presets / sizeof presets[0]; ++i)
        if (presets[i].count == count)
            p = &presets[i];
    if (!p)
        return vct_fail(err, VCT_ERR_INPUT, "%u diffuse cones: the presets are 1, 5, 6, 9 and 16",
                        count);
    /* Directions: each ring sits in the middle (in cosine-weighted measure,
     * sin^2 of the tilt) of the band its share of cones would cover. */
    double d[16][3];
    uint32_t n = 0, before = 0;
    for (int r = 0; r < 3 && p->ring[r]; ++r) {
        const uint32_t k = p->ring[r];
        const double mid = (before + 0.5 * k) / count;
        const double tilt = k == 1 ? 0.0 : asin(sqrt(mid));
        for (uint32_t j = 0; j < k; ++j, ++n) {
            const double phi = 2.0 * PI * (j + 0.5 * (r % 2 == 0)) / k;
            d[n][0] = sin(tilt) * cos(phi);
            d[n][1] = sin(tilt) * sin(phi);
            d[n][2] = cos(tilt);
        }
        before += k;
    }
    /* Weights and solid angles of each cone's cell (the directions nearest
     * it), on a grid uniform in cosine-weighted measure: u = sin^2 tilt. */
    enum { NU = 256, NPHI = 512 };
    double weight[16] = {0}, solid[16] = {0};
    for (int i = 0; i < NU; ++i) {
        const double u = (i + 0.5) / NU, s = sqrt(u), c = sqrt(1.0 - u);
        /* a grid cell's solid angle, exactly: its band of cos(tilt) times
         * its share of the turn (du / 2c diverges at the horizon) */
        const double band = sqrt(1.0 - (double)i / NU) - sqrt(1.0 - (i + 1.0) / NU);
        for (int j = 0; j < NPHI; ++j) {
            const double phi = 2.0 * PI * (j + 0.5) / NPHI;
            const double w[3] = {s * cos(phi), s * sin(phi), c};
            uint32_t best = 0;
            double best_dot = -2.0;
            for (uint32_t k = 0; k < n; ++k) {
                const double dot = w[0] * d[k][0] + w[1] * d[k][1] + w[2] * d[k][2];
                if (dot > best_dot) {
                    best_dot = dot;
                    best = k;
                }
            }
            weight[best] += 1.0;
            solid[best] += band * (2.0 * PI / NPHI);
        }
    }
    double total = 0.0;
    for (uint32_t k = 0; k < n; ++k)
        total += weight[k];
    for (uint32_t k = 0; k < n; ++k) {
        for (int a = 0; a < 3; ++a)
            dirs[4 * k + a] = (float)d[k][a];
        dirs[4 * k + 3] = (float)(weight[k] / total);
        /* a cone of the same solid angle as its cell */
        const double cell = acos(fmax(1.0 - solid[k] / (2.0 * PI), -1.0));
        tan_half[k] = (float)tan(fmin(cell, MAX_HALF_ANGLE));
        if (cell_tan)
            cell_tan[k] = (float)tan(fmin(cell, MAX_REST_HALF_ANGLE));
    }
    return VCT_OK;
}

void vct_cone_desc_make(const vct_voxels *v, const vct_cone_settings *s, const float *ambient,
                        void *out) {
    vct_cone_desc *d = out;
    memset(d, 0, sizeof *d);
    for (int k = 0; k < 3; ++k) {
        d->volume.s[k] = (float)v->info.origin[k];
        d->ambient.s[k] = ambient ? ambient[k] : 0.0f;
    }
    d->volume.s[3] = (float)v->info.side;
    d->ambient.s[3] = (float)(1.0 / v->info.side);
    d->res.s[0] = v->info.resolution;
    d->res.s[1] = v->info.levels;
    d->res.s[2] = v->brick_info.pool[0];
    d->res.s[3] = v->brick_info.pool[1];
    d->march.s[0] = s->step;
    d->march.s[1] = s->offset;
    d->march.s[2] = (float)(s->ao_distance * v->info.side);
    d->march.s[3] = s->stop_alpha;
}

void vct_cone_options(const vct_voxels *v, const vct_cone_settings *s, char *out, size_t size) {
    const vct_brick_info *b = &v->brick_info;
    snprintf(out, size, "%s%s%s", b->image ? " -DVCT_BRICK_IMAGE" : "",
             b->anisotropic ? " -DVCT_ANISOTROPIC" : "",
             s->nearest_level ? " -DVCT_CONE_NEAREST_LEVEL" : "");
}

int vct_cone_set_args(cl_kernel k, const vct_voxels *v, const void *desc, const char *stage,
                      int *next, vct_error *err) {
    const vct_brick_info *b = &v->brick_info;
    if (vct_bricks_radiance_check(v, stage, err))
        return err->status;
    /* radiance, its shade and plane, then the directions of both sides */
    const int pools = b->anisotropic ? 15 : 3, first = *next;
    static const char *const pool_names[15] = {
        "radiance", "shade_pool", "plane_pool", "dir0",  "dir1",  "dir2",  "dir3", "dir4",
        "dir5",     "dark0",      "dark1",      "dark2", "dark3", "dark4", "dark5"};
    for (int i = 0; i < pools; ++i) {
        const int c = VCT_BRICK_RADIANCE + i;
        cl_mem m = b->image ? v->brick_image[c] : v->brick_buffer[c];
        int rc =
            vct_set_args(err, stage, k, first + i, 1, sizeof m, (const void *)&m, pool_names[i]);
        if (rc)
            return rc;
    }
    int rc = vct_set_args(err, stage, k, first + pools, 2, VCT_ARG_OF(v->child),
                          sizeof(vct_cone_desc), desc, "cd");
    *next = first + pools + 2;
    return rc;
}

vct_status vct_cone_trace(vct_context *ctx, const vct_voxels *v, const vct_cone_settings *s,
                          const float *ambient, const float *cones, uint32_t n, float *out,
                          vct_error *err) {
    const char *stage = "cone trace";
    if (!v->has_bricks)
        return vct_fail(err, VCT_ERR_INPUT, "%s: build the bricks first (vct_bricks_build)", stage);
    int rc = vct_cone_settings_check(s, err);
    if (rc || n == 0)
        return rc;
    cl_program p;
    char options[128] = "-DVCT_CONE_PROBE";
    vct_cone_options(v, s, options + strlen(options), sizeof options - strlen(options));
    rc = vct_program_get(ctx, "render/vct_render.cl", options, &p, err);
    cl_mem in = rc == VCT_OK ? vct_buffer_create(ctx, stage, "cones", 32ull * n, CL_MEM_READ_ONLY,
                                                 (void *)cones, err)
                             : NULL;
    cl_mem dst =
        in ? vct_buffer_create(ctx, stage, "cone results", 32ull * n, CL_MEM_WRITE_ONLY, NULL, err)
           : NULL;
    cl_kernel k = dst ? vct_kernel_create(ctx, p, "cone_probe", err) : NULL;
    vct_cone_desc desc;
    vct_cone_desc_make(v, s, ambient, &desc);
    int next = 0;
    rc = k ? vct_cone_set_args(k, v, &desc, stage, &next, err) : (int)err->status;
    if (rc == VCT_OK)
        rc = vct_set_args(err, stage, k, next, 3, VCT_ARG(cones, in), VCT_ARG_OF(n),
                          VCT_ARG(out, dst));
    if (rc == VCT_OK) {
        vct_stage_begin(ctx, stage);
        rc = vct_launch(ctx, k, n, 64, err);
        vct_stage_end(ctx);
    }
    if (rc == VCT_OK)
        rc = vct_buffer_read(ctx, stage, dst, 0, 32ull * n, out, err);
    if (k)
        clReleaseKernel(k);
    vct_buffer_release(ctx, dst);
    vct_buffer_release(ctx, in);
    return rc;
}
