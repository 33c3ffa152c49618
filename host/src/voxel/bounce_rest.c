/* The rest of the bounces: the light each bounce added, measured, and the
 * geometric series of their ratio added after the last one. */
#include <math.h>
#include <stdlib.h>

#include "vct_types.h"
#include "voxel/bounce_rest.h"

#define STAGE "light bounce rest"
#define GROUP 64 /* BOUNCE_GROUP in bounce_rest.cl */

int vct_bounce_rest_keep(vct_context *ctx, vct_voxels *v, vct_error *err) {
    const size_t n = v->info.voxels;
    if (!v->bounce_rest || n == 0)
        return VCT_OK;
    int rc = vct_buffer_copy_into(ctx, STAGE, "voxel radiance before a bounce", v->radiance,
                                  &v->before_radiance, 16 * n, err);
    return rc ? rc
              : vct_buffer_copy_into(ctx, STAGE, "voxel sides before a bounce", v->side,
                                     &v->before_side, 16 * VCT_VOXEL_SIDE_FLOAT4S * n, err);
}

int vct_bounce_rest_measure(vct_context *ctx, vct_voxels *v, vct_error *err) {
    const uint32_t n = v->info.voxels;
    if (!v->bounce_rest || n == 0)
        return VCT_OK;
    const size_t groups = (n + GROUP - 1) / GROUP;
    cl_float4 *sums = malloc(sizeof(cl_float4) * groups);
    if (!sums)
        return vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory (%zu group sums)", STAGE,
                        groups);
    cl_program p;
    int rc = vct_program_get(ctx, "voxel/bounce_rest.cl", "", &p, err);
    cl_mem out = rc == VCT_OK
                     ? vct_buffer_create(ctx, STAGE, "bounce light per group",
                                         sizeof(cl_float4) * groups, CL_MEM_WRITE_ONLY, NULL, err)
                     : NULL;
    if (rc == VCT_OK && !out)
        rc = err->status;
    if (rc == VCT_OK)
        rc = vct_run_kernel_grouped(
            ctx, p, "bounce_energy", STAGE, n, GROUP, err, 7, VCT_ARG_OF(v->radiance),
            VCT_ARG_OF(v->side), VCT_ARG(before, v->before_radiance), VCT_ARG_OF(v->before_side),
            VCT_ARG_OF(v->direct_side), VCT_ARG(voxels, n), VCT_ARG(group_sums, out));
    if (rc == VCT_OK)
        rc = vct_buffer_read(ctx, STAGE, out, 0, sizeof(cl_float4) * groups, sums, err);
    if (rc == VCT_OK) {
        for (int c = 0; c < 3; ++c) {
            double total = 0.0; /* in group order: the same sum on every device */
            for (size_t g = 0; g < groups; ++g)
                total += sums[g].s[c];
            v->bounce_light[0][c] = v->bounce_light[1][c];
            v->bounce_light[1][c] = total;
        }
        ++v->bounces_measured;
    }
    vct_buffer_release(ctx, out);
    free(sums);
    return rc;
}

void vct_voxels_bounce_ratios(const vct_voxels *v, double ratio[3]) {
    for (int c = 0; c < 3; ++c)
        ratio[c] = v ? v->bounce_ratio[c] : 0.0;
}

double vct_voxels_bounce_ratio(const vct_voxels *v) {
    double r[3];
    vct_voxels_bounce_ratios(v, r);
    return fmax(r[0], fmax(r[1], r[2]));
}

vct_status vct_voxels_bounce_rest(vct_context *ctx, vct_voxels *v, vct_error *err) {
    cl_float4 rest = {{0.0f, 0.0f, 0.0f, 0.0f}};
    int any = 0;
    for (int c = 0; c < 3; ++c) {
        v->bounce_ratio[c] = 0.0;
        if (!v->bounce_rest || v->bounces_measured < 2 || !(v->bounce_light[0][c] > 0.0))
            continue;
        /* A ratio near 1 would make the rest unbounded: no surface keeps
         * 90 % of what reaches it, bounce after bounce, in a scene we render;
         * nor more than the channel's brightest albedo. After a few bounces
         * light entering by a slit can still be spreading (the ratio of the
         * first bounces above the series' own): the bound keeps the rest
         * finite. */
        const double most = v->albedo_max[c] > 0.0 && v->albedo_max[c] < VCT_BOUNCE_RATIO_MAX
                                ? v->albedo_max[c]
                                : VCT_BOUNCE_RATIO_MAX;
        double r = v->bounce_light[1][c] / v->bounce_light[0][c];
        r = r < 0.0 ? 0.0 : (r > most ? most : r);
        v->bounce_ratio[c] = r;
        rest.s[c] = (float)(r / (1.0 - r));
        any |= rest.s[c] > 0.0f;
    }
    const uint32_t n = v->info.voxels;
    int rc = VCT_OK;
    if (any && n > 0) {
        vct_stage_begin(ctx, STAGE);
        cl_program p;
        rc = vct_program_get(ctx, "voxel/bounce_rest.cl", "", &p, err);
        if (rc == VCT_OK)
            rc = vct_run_kernel(ctx, p, "bounce_rest", STAGE, n, err, 7, VCT_ARG_OF(v->radiance),
                                VCT_ARG_OF(v->side), VCT_ARG(before, v->before_radiance),
                                VCT_ARG_OF(v->before_side), VCT_ARG_OF(v->direct_side),
                                VCT_ARG(voxels, n), VCT_ARG_OF(rest));
        if (rc == VCT_OK)
            rc = vct_finish(ctx, STAGE, err);
        vct_stage_end(ctx);
    }
    if (rc != VCT_OK || (!any && !v->radiance_stale))
        return rc;
    v->radiance_stale = 0;
    return vct_bricks_refresh_radiance(ctx, v, err);
}
