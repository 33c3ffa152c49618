/* The diffuse gather's picks: leaf voxels weighed by the luminance of
 * their direct light, those at least PICK_HOT times the mean, where they
 * hold at least PICK_HOT_SHARE of the voxels' light. */
#include "conetrace/gather_picks.h"

#include "vct/parallel.h"
#include "vct_types.h"

/* A voxel is hot at PICK_HOT times the voxels' mean luminance: over the
 * scene suite at 128^3 the voxels that bright hold 10 to 53 % of the light
 * in the scenes lit by a point light under a ceiling, small emissive panels
 * or spot lights, and none in those lit by a sun, a sky, a point light
 * well below the ceiling or large emitters, whose gathers the cosine's rays
 * do well (picking every lit voxel there raised the Cornell box's NRMSE,
 * 0.0252 -> 0.0263, and a quarter more gather time). */
#define PICK_HOT 32.0
#define PICK_HOT_SHARE 0.05
/* A voxel brighter than PICK_CAP times the mean weighs that much: the
 * weights' sum stays within 32 bits for up to 2^32 / PICK_CAP voxels. */
#define PICK_CAP 1024.0

/* The weights of the n voxels of `direct`: luminance l at least floor_l
 * weighs min(l scale, cap) unit, rounded; their running sum in `weights`
 * and their sum in *total. */
static int pick_weights(vct_context *ctx, cl_program program, const char *stage, cl_mem direct,
                        cl_uint n, float scale, float floor_l, float cap, cl_uint unit,
                        cl_mem weights, uint64_t *total, vct_error *err) {
    int rc =
        vct_run_kernel(ctx, program, "gather_pick_weights", stage, n, err, 7, VCT_ARG_OF(direct),
                       VCT_ARG(voxels, n), VCT_ARG_OF(scale), VCT_ARG_OF(floor_l), VCT_ARG_OF(cap),
                       VCT_ARG_OF(unit), VCT_ARG_OF(weights));
    if (rc == VCT_OK)
        rc = vct_scan_u32(ctx, weights, weights, n, 1, total, err);
    return rc;
}

int vct_gather_picks_build(vct_context *ctx, cl_program program, const vct_voxels *v,
                           const char *stage, vct_gather_picks *picks, vct_error *err) {
    picks->cdf = NULL;
    picks->count = picks->total = 0;
    const cl_uint n = (cl_uint)v->info.voxels;
    const cl_mem direct = v->bounces > 0 && v->direct_radiance ? v->direct_radiance : v->radiance;
    const cl_uint hot_unit = (cl_uint)(4294967295.0 / ((double)n * PICK_CAP));
    if (n == 0 || hot_unit == 0)
        return VCT_OK;
    cl_mem peak = vct_buffer_create(ctx, stage, "pick peak", 4, CL_MEM_READ_WRITE, NULL, err);
    picks->cdf = peak ? vct_buffer_create(ctx, stage, "pick weights", 4 * (size_t)n,
                                          CL_MEM_READ_WRITE, NULL, err)
                      : NULL;
    int rc = picks->cdf ? vct_buffer_fill_u32(ctx, stage, peak, 0, 1, err) : (int)err->status;
    if (rc == VCT_OK)
        rc = vct_run_kernel(ctx, program, "gather_pick_peak", stage,
                            (n + VCT_PICK_SPAN - 1) / VCT_PICK_SPAN, err, 3, VCT_ARG_OF(direct),
                            VCT_ARG(voxels, n), VCT_ARG_OF(peak));
    float brightest = 0.0f;
    if (rc == VCT_OK)
        rc = vct_buffer_read(ctx, stage, peak, 0, 4, &brightest, err);
    /* the mean, exactly from integer weights against the brightest: one
     * voxel's light moves it by its share alone, as it moves the sum */
    const cl_uint mean_unit = 4294967295u / n;
    uint64_t sum = 0, total = 0;
    if (rc == VCT_OK && brightest > 0.0f)
        rc = pick_weights(ctx, program, stage, direct, n, 1.0f / brightest, 0.0f, 1.0f, mean_unit,
                          picks->cdf, &sum, err);
    const double mean = (double)brightest * (double)sum / ((double)n * mean_unit);
    if (rc == VCT_OK && mean > 0.0)
        rc = pick_weights(ctx, program, stage, direct, n, (float)(1.0 / mean),
                          (float)(PICK_HOT * mean), (float)PICK_CAP, hot_unit, picks->cdf, &total,
                          err);
    vct_buffer_release(ctx, peak);
    /* the hot voxels' share of the light: their weights over n unit, what
     * every voxel's (uncapped) would sum to */
    if (rc == VCT_OK && (double)total >= PICK_HOT_SHARE * (double)n * hot_unit) {
        picks->count = n;
        picks->total = (cl_uint)total;
        return VCT_OK;
    }
    vct_buffer_release(ctx, picks->cdf);
    picks->cdf = NULL;
    return rc;
}
