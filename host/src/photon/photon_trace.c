/* Photon tracing: slots and the launch. */
#include <string.h>

#include "photon/photon_trace.h"

uint64_t vct_photon_slot_bytes(uint32_t paths, uint32_t depth) {
    return (uint64_t)paths * depth * (VCT_PHOTON_BYTES + 4u);
}

int vct_photon_slots_make(vct_context *ctx, const char *stage, uint32_t paths, uint32_t depth,
                          vct_photon_slots *slots, vct_error *err) {
    memset(slots, 0, sizeof *slots);
    const uint64_t n = (uint64_t)paths * depth;
    if (n == 0 || n > 0xffffffffull / 3u)
        return vct_fail(err, VCT_ERR_INPUT,
                        "%s: %u photons per pass x %u bounces is %s: give between 1 and %llu "
                        "photons per pass (--photons) or fewer bounces (--max-depth)",
                        stage, paths, depth, n ? "too many slots" : "no slots",
                        (unsigned long long)(0xffffffffull / 3u / (depth ? depth : 1)));
    const uint64_t bytes = n * VCT_PHOTON_BYTES;
    if (bytes > ctx->info.max_alloc)
        return vct_fail(err, VCT_ERR_MEMORY,
                        "%s: %u photons per pass x %u bounces need %.1f MiB of photon slots, "
                        "more than %s allocates at once (%.1f MiB): lower --photons or "
                        "--max-depth",
                        stage, paths, depth, bytes / 1048576.0, ctx->info.name,
                        ctx->info.max_alloc / 1048576.0);
    slots->records =
        vct_buffer_create(ctx, stage, "photon slots", bytes, CL_MEM_READ_WRITE, NULL, err);
    slots->kinds = slots->records ? vct_buffer_create(ctx, stage, "photon slot kinds", 4 * n,
                                                      CL_MEM_READ_WRITE, NULL, err)
                                  : NULL;
    if (!slots->kinds) {
        vct_photon_slots_release(ctx, slots);
        return err->status;
    }
    slots->paths = paths;
    slots->depth = depth;
    return VCT_OK;
}

void vct_photon_slots_release(vct_context *ctx, vct_photon_slots *slots) {
    vct_buffer_release(ctx, slots->records);
    vct_buffer_release(ctx, slots->kinds);
    slots->records = slots->kinds = NULL;
}

int vct_photon_trace(vct_context *ctx, const char *stage, const vct_photon_trace_job *job,
                     vct_photon_slots *slots, vct_error *err) {
    cl_program p;
    int rc = vct_program_get(ctx, "photon/photon_trace.cl", vct_accel_program_options(job->accel),
                             &p, err);
    cl_kernel k = rc == VCT_OK ? vct_kernel_create(ctx, p, "photon_trace", err) : NULL;
    if (rc == VCT_OK && !k)
        rc = err->status;
    const vct_scene_buffers *sb = job->buffers;
    const vct_photon_sources *src = job->sources;
    if (rc == VCT_OK)
        rc = vct_accel_set_args(k, job->accel, stage, err);
    if (rc == VCT_OK)
        rc = vct_set_args(err, stage, k, 5, 2, VCT_ARG_OF(sb->materials),
                          VCT_ARG_OF(sb->tri_material));
    if (rc == VCT_OK)
        rc = vct_scene_texture_args(k, 7, sb, stage, err);
    if (rc == VCT_OK)
        rc = vct_set_args(
            err, stage, k, 10, 16, VCT_ARG_OF(sb->lights), VCT_ARG(sources, src->table),
            VCT_ARG(source_count, src->count), VCT_ARG(emitter_tris, src->emitters.tris),
            VCT_ARG(emitter_cdf, src->emitters.cdf), VCT_ARG(emitter_scale, src->emitters.scale),
            VCT_ARG(emitter_count, src->emitters.count), VCT_ARG_OF(src->bounds),
            VCT_ARG_OF(src->ambient), VCT_ARG_OF(job->seed), VCT_ARG_OF(job->pass),
            VCT_ARG_OF(slots->paths), VCT_ARG(max_depth, slots->depth), VCT_ARG_OF(job->store_mask),
            VCT_ARG_OF(slots->records), VCT_ARG_OF(slots->kinds));
    if (rc == VCT_OK)
        rc = vct_launch(ctx, k, slots->paths, 64, err);
    if (k)
        clReleaseKernel(k);
    return rc;
}
