/* Per-stage statistics: launches, device time from profiling events, host time, memory. */
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "runtime/stats.h"
#include "vct/debug.h"

double vct_now_ms(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

static int drain_events(vct_context *ctx, vct_error *err);

void vct_stage_begin(vct_context *ctx, const char *name) {
    if (ctx->current_stage >= 0)
        vct_stage_end(ctx);
    int i = 0;
    for (; i < ctx->stage_count; ++i)
        if (strcmp(ctx->stages[i].name, name) == 0)
            break;
    if (i == ctx->stage_count) {
        if (ctx->stage_count == VCT_MAX_STAGES)
            i = VCT_MAX_STAGES - 1; /* fold overflow into the last row */
        else
            ctx->stage_count++;
        memset(&ctx->stages[i], 0, sizeof ctx->stages[i]);
        snprintf(ctx->stages[i].name, sizeof ctx->stages[i].name, "%s", name);
    }
    ctx->current_stage = i;
    ctx->stage_host_start = vct_now_ms();
    ctx->bytes_stage_peak = ctx->bytes_live;
}

void vct_stage_end(vct_context *ctx) {
    if (ctx->current_stage < 0)
        return;
    clFinish(ctx->queue);
    drain_events(ctx, NULL);
    vct_stage_stat *s = &ctx->stages[ctx->current_stage];
    s->host_ms += vct_now_ms() - ctx->stage_host_start;
    const double mib = ctx->bytes_stage_peak / (1024.0 * 1024.0);
    if (mib > s->mib)
        s->mib = mib;
    ctx->current_stage = -1;
}

/* The counter of kernel `name`, made on first use (the last one when full). */
static int count_kernel(vct_context *ctx, const char *name) {
    for (int i = 0; i < ctx->kernel_count_n; ++i) {
        if (strcmp(ctx->kernel_counts[i].name, name) == 0) {
            ctx->kernel_counts[i].launches++;
            return i;
        }
    }
    if (ctx->kernel_count_n == VCT_MAX_KERNEL_NAMES)
        return VCT_MAX_KERNEL_NAMES - 1;
    vct_kernel_count *k = &ctx->kernel_counts[ctx->kernel_count_n];
    snprintf(k->name, sizeof k->name, "%s", name);
    k->launches = 1;
    k->device_ms = 0.0;
    return ctx->kernel_count_n++;
}

/* Events are kept until the stage ends, so launches stay asynchronous; their
 * device times are summed then. */
static int drain_events(vct_context *ctx, vct_error *err) {
    int rc = VCT_OK;
    if (ctx->pending_count == 0)
        return rc;
    cl_int wait = clWaitForEvents((cl_uint)ctx->pending_count, ctx->pending);
    if (wait != CL_SUCCESS)
        rc = vct_cl_check(err, wait, "statistics", "clWaitForEvents");
    for (int i = 0; i < ctx->pending_count; ++i) {
        cl_ulong start = 0, end = 0;
        if (rc == VCT_OK && ctx->profiling && ctx->current_stage >= 0 &&
            clGetEventProfilingInfo(ctx->pending[i], CL_PROFILING_COMMAND_START, sizeof start,
                                    &start, NULL) == CL_SUCCESS &&
            clGetEventProfilingInfo(ctx->pending[i], CL_PROFILING_COMMAND_END, sizeof end, &end,
                                    NULL) == CL_SUCCESS &&
            end >= start) {
            ctx->stages[ctx->current_stage].device_ms += (double)(end - start) * 1e-6;
            ctx->kernel_counts[ctx->pending_kernel[i]].device_ms += (double)(end - start) * 1e-6;
        }
        clReleaseEvent(ctx->pending[i]);
    }
    ctx->pending_count = 0;
    return rc;
}

int vct_record_event(vct_context *ctx, cl_event event, const char *kernel_name, vct_error *err) {
    if (!event)
        return VCT_OK;
    const int counter = count_kernel(ctx, kernel_name);
    if (ctx->current_stage < 0) {
        clReleaseEvent(event);
        return VCT_OK;
    }
    ctx->stages[ctx->current_stage].launches++;
    if (ctx->pending_count == VCT_MAX_PENDING_EVENTS) {
        int rc = drain_events(ctx, err);
        if (rc != VCT_OK) {
            clReleaseEvent(event);
            return rc;
        }
    }
    ctx->pending_kernel[ctx->pending_count] = counter;
    ctx->pending[ctx->pending_count++] = event;
    return VCT_OK;
}

int vct_finish(vct_context *ctx, const char *stage, vct_error *err) {
    VCT_CL(err, stage, clFinish(ctx->queue));
    return VCT_OK;
}

int vct_stats(const vct_context *ctx, const vct_stage_stat **stages) {
    *stages = ctx->stages;
    return ctx->stage_count;
}

void vct_stats_reset(vct_context *ctx) {
    ctx->stage_count = 0;
    ctx->current_stage = -1;
    ctx->kernel_count_n = 0;
}

int vct_kernel_stats(const vct_context *ctx, const vct_kernel_stat **kernels) {
    *kernels = ctx->kernel_counts;
    return ctx->kernel_count_n;
}

int vct_kernel_launches(const vct_context *ctx, const char *kernel_name) {
    for (int i = 0; i < ctx->kernel_count_n; ++i)
        if (strcmp(ctx->kernel_counts[i].name, kernel_name) == 0)
            return ctx->kernel_counts[i].launches;
    return 0;
}
