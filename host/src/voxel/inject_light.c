/* Direct light into the voxels (kernels/voxel/inject_light.cl). */
#include <math.h>

#include "runtime/runtime.h"
#include "accel/accel.h"
#include "light/emitters.h"
#include "light/light_bins_host.h"
#include "scene/scene_device.h"
#include "vct_types.h"
#include "voxel/voxels.h"

#define STAGE "light injection"

vct_status vct_voxels_inject_light(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                                   vct_voxels *v, vct_error *err) {
    return vct_voxels_inject_light_with(ctx, s, g, v, NULL, err);
}

static int inject(vct_context *ctx, const vct_scene *s, const vct_accel *g, vct_voxels *v,
                  const vct_light_bins_options *bins_options, int refresh, vct_voxel_carry *carry,
                  vct_error *err);

int vct_voxels_inject_light_with(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                                 vct_voxels *v, const vct_light_bins_options *bins_options,
                                 vct_error *err) {
    return inject(ctx, s, g, v, bins_options, 1, NULL, err);
}

int vct_voxels_inject_light_kept(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                                 vct_voxels *v, vct_error *err) {
    return inject(ctx, s, g, v, NULL, 0, NULL, err);
}

int vct_voxels_inject_light_carried(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                                    vct_voxels *v, vct_voxel_carry *carry, vct_error *err) {
    /* few voxels are lit anew: their shadow rays through the BVH cost less
     * than binning every triangle again (the same light either way) */
    const vct_light_bins_options no_bins = {0, 0, 0};
    return inject(ctx, s, g, v, &no_bins, 1, carry, err);
}

/* The box around the scene's emissive triangles (lo.w 1 if any) and the
 * radius of the ball around it (hi.w). */
static void emitter_bounds(const vct_scene *s, cl_float4 *lo, cl_float4 *hi) {
    for (int k = 0; k < 3; ++k)
        lo->s[k] = INFINITY, hi->s[k] = -INFINITY;
    lo->s[3] = hi->s[3] = 0.0f;
    for (uint32_t t = 0; t < s->triangle_count; ++t) {
        const float *e = s->materials[s->triangle_material[t]].emission;
        if (!(e[0] > 0.0f || e[1] > 0.0f || e[2] > 0.0f))
            continue;
        lo->s[3] = 1.0f;
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 3; ++k) {
                const float x = s->positions[3ull * s->triangles[3ull * t + i] + k];
                lo->s[k] = fminf(lo->s[k], x);
                hi->s[k] = fmaxf(hi->s[k], x);
            }
    }
    double r2 = 0.0;
    for (int k = 0; lo->s[3] > 0.0f && k < 3; ++k)
        r2 += 0.25 * ((double)hi->s[k] - lo->s[k]) * ((double)hi->s[k] - lo->s[k]);
    hi->s[3] = (float)(sqrt(r2) * (1.0 + 1e-6)) + 1e-6f; /* rounded up */
}

/* carry_direct: each new voxel's voxel before, and its direct light kept
 * where nothing that moved reaches it. */
static int carry_direct(vct_context *ctx, cl_program p, const vct_scene *s, vct_voxels *v,
                        vct_voxel_carry *c, const vct_scene_buffers *sb, vct_error *err) {
    const vct_voxels *before = c->before;
    const uint32_t n = v->info.voxels;
    c->carried_from =
        vct_buffer_create(ctx, STAGE, "carried voxels", 4ull * n, CL_MEM_READ_WRITE, NULL, err);
    cl_mem boxes = c->carried_from ? vct_buffer_create(ctx, STAGE, "moved boxes", sizeof c->boxes,
                                                       CL_MEM_READ_ONLY, c->boxes, err)
                                   : NULL;
    if (!boxes)
        return err->status;
    /* the direct part of the light before: kept aside once bounces were added */
    const int bounced = before->bounces > 0 && before->direct_radiance;
    cl_mem before_radiance = bounced ? before->direct_radiance : before->radiance;
    cl_mem before_side = bounced ? before->direct_side : before->side;
    cl_float4 emit_lo, emit_hi;
    emitter_bounds(s, &emit_lo, &emit_hi);
    if (v->emitters_by_cones)
        emit_lo.s[3] = 0.0f; /* emitters light no voxel directly */
    vct_volume_desc vol;
    vct_voxels_volume_desc(v, &vol);
    int rc =
        vct_run_kernel(ctx, p, "carry_direct", STAGE, n, err, 16, VCT_ARG_OF(vol),
                       VCT_ARG_OF(v->keys), VCT_ARG(voxels, n), VCT_ARG(before_keys, before->keys),
                       VCT_ARG(before_voxels, before->info.voxels), VCT_ARG_OF(before_radiance),
                       VCT_ARG_OF(before_side), VCT_ARG_OF(boxes), VCT_ARG(box_count, c->box_count),
                       VCT_ARG_OF(sb->lights), VCT_ARG_OF(sb->light_count), VCT_ARG_OF(emit_lo),
                       VCT_ARG_OF(emit_hi), VCT_ARG_OF(c->carried_from), VCT_ARG_OF(v->radiance),
                       VCT_ARG_OF(v->side));
    vct_buffer_release(ctx, boxes);
    return rc;
}

/* refresh 0: the bricks keep the light they held (the light of the frame
 * before, which the next bounce gathers). */
static int inject(vct_context *ctx, const vct_scene *s, const vct_accel *g, vct_voxels *v,
                  const vct_light_bins_options *bins_options, int refresh, vct_voxel_carry *carry,
                  vct_error *err) {
    const uint32_t n = v->info.voxels;
    vct_stage_begin(ctx, STAGE);
    cl_program p;
    int rc = vct_program_get(ctx, "voxel/inject_light.cl", vct_accel_program_options(g), &p, err);
    if (rc == VCT_OK && !v->radiance) {
        v->radiance = vct_buffer_create(ctx, STAGE, "voxel radiance", 16ull * n, CL_MEM_READ_WRITE,
                                        NULL, err);
        rc = v->radiance ? VCT_OK : (int)err->status;
    }
    if (rc == VCT_OK && !v->side) {
        v->side = vct_buffer_create(ctx, STAGE, "voxel sides", 16ull * VCT_VOXEL_SIDE_FLOAT4S * n,
                                    CL_MEM_READ_WRITE, NULL, err);
        rc = v->side ? VCT_OK : (int)err->status;
    }
    vct_scene_buffers sb = {0};
    if (rc == VCT_OK)
        rc = vct_scene_buffers_make(ctx, s, STAGE, &sb, err);
    if (rc == VCT_OK && carry && n)
        rc = carry_direct(ctx, p, s, v, carry, &sb, err);
    vct_emitters em = {0}; /* none: the voxels keep their emission for the cones */
    if (rc == VCT_OK && !v->emitters_by_cones)
        rc = vct_emitters_build(ctx, s, VCT_EMITTERS_BY_POWER, STAGE, &em, err);
    vct_light_bins bins = {0};
    if (rc == VCT_OK && n)
        rc = vct_light_bins_build(ctx, s, g, bins_options, STAGE, &bins, err);
    vct_volume_desc vol;
    vct_voxels_volume_desc(v, &vol);
    cl_kernel k = rc == VCT_OK && n ? vct_kernel_create(ctx, p, "inject_direct", err) : NULL;
    if (rc == VCT_OK && n && !k)
        rc = err->status;
    if (k)
        rc = vct_accel_set_args(k, g, STAGE, err);
    if (k && rc == VCT_OK)
        rc = vct_light_bins_set_args(k, 5, &bins, STAGE, err);
    if (k && rc == VCT_OK)
        rc = vct_set_args(err, STAGE, k, 9, 12, VCT_ARG_OF(vol), VCT_ARG_OF(v->keys),
                          VCT_ARG(voxels, n), VCT_ARG(voxel_start, v->fragment_start),
                          VCT_ARG_OF(v->fragment_tri), VCT_ARG_OF(v->info.fragments),
                          VCT_ARG_OF(sb.materials), VCT_ARG_OF(sb.tri_material),
                          VCT_ARG_OF(v->albedo), VCT_ARG_OF(v->emission), VCT_ARG_OF(sb.lights),
                          VCT_ARG_OF(sb.light_count));
    if (k && rc == VCT_OK)
        rc = vct_emitters_set_args(k, 21, &em, VCT_EMITTER_INJECT_SAMPLES, STAGE, err);
    if (k && rc == VCT_OK)
        rc = vct_scene_texture_args(k, 26, &sb, STAGE, err);
    /* without carried light the flag is 0 and the buffer never read */
    cl_mem carried_from = carry ? carry->carried_from : v->radiance;
    const cl_uint carry_on = carry != NULL;
    if (k && rc == VCT_OK)
        rc = vct_set_args(err, STAGE, k, 29, 5, VCT_ARG_OF(v->radiance), VCT_ARG_OF(v->normal),
                          VCT_ARG_OF(v->side), VCT_ARG_OF(carried_from), VCT_ARG(carry, carry_on));
    if (k && rc == VCT_OK)
        rc = vct_launch(ctx, k, n, 64, err);
    if (rc == VCT_OK)
        rc = vct_finish(ctx, STAGE, err);
    if (k)
        clReleaseKernel(k);
    vct_light_bins_release(ctx, &bins);
    vct_emitters_release(ctx, &em);
    vct_scene_buffers_release(ctx, &sb);
    vct_stage_end(ctx);
    v->bounces = 0; /* the radiance is direct light again */
    v->bounces_measured = 0;
    v->radiance_stale = !refresh;
    for (int c = 0; c < 3; ++c)
        v->bounce_ratio[c] = 0.0;
    if (rc == VCT_OK && refresh)
        rc = vct_bricks_refresh_radiance(ctx, v, err);
    return rc;
}

vct_status vct_voxels_read_sides(vct_context *ctx, const vct_voxels *v, float *sides,
                                 vct_error *err) {
    if (!v->side)
        return vct_fail(err, VCT_ERR_INPUT,
                        "voxel sides: inject light first (vct_voxels_inject_light)");
    return vct_buffer_read(ctx, "voxel read", v->side, 0,
                           16ull * VCT_VOXEL_SIDE_FLOAT4S * v->info.voxels, sides, err);
}

vct_status vct_voxels_read_radiance(vct_context *ctx, const vct_voxels *v, float *radiance,
                                    vct_error *err) {
    if (!v->radiance)
        return vct_fail(err, VCT_ERR_INPUT,
                        "voxel radiance: inject light first (vct_voxels_inject_light)");
    return vct_buffer_read(ctx, "voxel read", v->radiance, 0, 16ull * v->info.voxels, radiance,
                           err);
}
