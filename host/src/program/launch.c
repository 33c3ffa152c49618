/* Kernel arguments and launches, each recorded in the current stage. */
#include <stdarg.h>
#include <stdio.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "program/arg_check.h"
#include "program/launch.h"
#include "program/program.h"

/* Switches that make a device misbehave, to test how a device group copes:
 * VCT_FAIL_LAUNCH=D:N fails every launch of device D (its index in `vct
 * devices`) from its N-th on, as a lost device would; VCT_SLOW_LAUNCH=D:F
 * makes device D F times slower: each launch is awaited, then the host
 * waits F - 1 times as long again. */
static int launch_switches(vct_context *ctx, const char *stage, double *slow_factor,
                           vct_error *err) {
    ++ctx->launch_count;
    *slow_factor = 0.0;
    int device = -1;
    long at = 0;
    const char *fail = getenv("VCT_FAIL_LAUNCH");
    if (fail && sscanf(fail, "%d:%ld", &device, &at) == 2 && device == ctx->info.index &&
        ctx->launch_count >= at)
        return vct_fail(err, VCT_ERR_OPENCL,
                        "%s: clEnqueueNDRangeKernel failed on %s (device %d) with "
                        "CL_OUT_OF_RESOURCES, injected by VCT_FAIL_LAUNCH from launch %ld",
                        stage, ctx->info.name, device, at);
    double factor = 0.0;
    const char *slow = getenv("VCT_SLOW_LAUNCH");
    if (slow && sscanf(slow, "%d:%lf", &device, &factor) == 2 && device == ctx->info.index &&
        factor > 1.0)
        *slow_factor = factor;
    return VCT_OK;
}

/* VCT_SLOW_LAUNCH's wait, after launch `ev` queued at host time start_ms:
 * its own run time from the event where the queue profiles (a device that
 * shares its cores with another would count the other's work too). */
static void launch_slowdown(vct_context *ctx, cl_event ev, double factor, double start_ms) {
    if (!(factor > 1.0) || !ev)
        return;
    clWaitForEvents(1, &ev);
    double run_ms = vct_now_ms() - start_ms;
    cl_ulong t0 = 0, t1 = 0;
    if (ctx->profiling &&
        clGetEventProfilingInfo(ev, CL_PROFILING_COMMAND_START, sizeof t0, &t0, NULL) ==
            CL_SUCCESS &&
        clGetEventProfilingInfo(ev, CL_PROFILING_COMMAND_END, sizeof t1, &t1, NULL) == CL_SUCCESS &&
        t1 >= t0)
        run_ms = (double)(t1 - t0) * 1e-6;
    const double wait_ms = run_ms * (factor - 1.0);
    const struct timespec pause = {(time_t)(wait_ms / 1e3), (long)(fmod(wait_ms, 1e3) * 1e6)};
    nanosleep(&pause, NULL);
}

#define DEFAULT_LOCAL_SIZE 64

static int kernel_name_of(cl_kernel kernel, char *name, size_t size) {
    name[0] = '\0';
    return clGetKernelInfo(kernel, CL_KERNEL_FUNCTION_NAME, size, name, NULL);
}

/* The enqueue both launch shapes end in: the fault switches, the launch,
 * the slowdown a test asked for, and the event recorded for the stage. */
static int enqueue(vct_context *ctx, cl_kernel kernel, const char *name, cl_uint dims,
                   const size_t *global, const size_t *local, vct_error *err) {
    cl_event ev = NULL;
    const char *stage = ctx->current_stage >= 0 ? ctx->stages[ctx->current_stage].name : name;
    double slow = 0.0;
    if (launch_switches(ctx, stage, &slow, err) != VCT_OK)
        return err->status;
    const double start_ms = vct_now_ms();
    VCT_CL(err, stage,
           clEnqueueNDRangeKernel(ctx->queue, kernel, dims, NULL, global, local, 0, NULL, &ev));
    launch_slowdown(ctx, ev, slow, start_ms);
    return vct_record_event(ctx, ev, name, err);
}

int vct_launch(vct_context *ctx, cl_kernel kernel, size_t global, size_t local, vct_error *err) {
    char name[64];
    kernel_name_of(kernel, name, sizeof name);
    if (global == 0)
        return VCT_OK; /* nothing to do; zero-sized NDRanges are invalid in OpenCL 1.2 */
    if (!local) {
        /* A fixed work-group rather than the driver's pick: drivers that
         * compile per work-group size (PoCL) would build a new one for every
         * new count. Kernels check their bounds. */
        size_t most = 0;
        local = DEFAULT_LOCAL_SIZE;
        if (clGetKernelWorkGroupInfo(kernel, ctx->device, CL_KERNEL_WORK_GROUP_SIZE, sizeof most,
                                     &most, NULL) == CL_SUCCESS &&
            most > 0 && most < local)
            local = most;
    }
    global = (global + local - 1) / local * local;
    return enqueue(ctx, kernel, name, 1, &global, local ? &local : NULL, err);
}

int vct_launch_2d(vct_context *ctx, cl_kernel kernel, const size_t global_in[2],
                  const size_t local[2], vct_error *err) {
    char name[64];
    kernel_name_of(kernel, name, sizeof name);
    size_t global[2] = {global_in[0], global_in[1]};
    if (global[0] == 0 || global[1] == 0)
        return VCT_OK;
    for (int i = 0; local && i < 2; ++i)
        global[i] = (global[i] + local[i] - 1) / local[i] * local[i];
    return enqueue(ctx, kernel, name, 2, global, local, err);
}

static int set_args_v(vct_error *err, const char *stage, cl_kernel kernel, int first, int count,
                      va_list ap) {
    int rc = VCT_OK;
    for (int i = 0; i < count && rc == VCT_OK; ++i) {
        size_t size = va_arg(ap, size_t);
        const void *value = va_arg(ap, const void *);
        const char *expression = va_arg(ap, const char *);
        rc = vct_check_arg(err, stage, kernel, (cl_uint)(first + i), expression);
        if (rc == VCT_OK)
            rc = vct_cl_check(err, clSetKernelArg(kernel, (cl_uint)(first + i), size, value), stage,
                              "clSetKernelArg");
    }
    return rc;
}

int vct_set_args(vct_error *err, const char *stage, cl_kernel kernel, int first, int count, ...) {
    va_list ap;
    va_start(ap, count);
    int rc = set_args_v(err, stage, kernel, first, count, ap);
    va_end(ap);
    return rc;
}

static int run_kernel_v(vct_context *ctx, cl_program program, const char *name, const char *stage,
                        size_t global, size_t local, vct_error *err, int count, va_list ap) {
    if (global == 0)
        return VCT_OK;
    cl_kernel k = vct_kernel_create(ctx, program, name, err);
    if (!k)
        return err->status;
    int rc = set_args_v(err, stage, k, 0, count, ap);
    if (rc == VCT_OK)
        rc = vct_launch(ctx, k, global, local, err);
    clReleaseKernel(k);
    return rc;
}

int vct_run_kernel(vct_context *ctx, cl_program program, const char *name, const char *stage,
                   size_t global, vct_error *err, int count, ...) {
    va_list ap;
    va_start(ap, count);
    const int rc = run_kernel_v(ctx, program, name, stage, global, 0, err, count, ap);
    va_end(ap);
    return rc;
}

int vct_run_kernel_grouped(vct_context *ctx, cl_program program, const char *name,
                           const char *stage, size_t global, size_t local, vct_error *err,
                           int count, ...) {
    va_list ap;
    va_start(ap, count);
    const int rc = run_kernel_v(ctx, program, name, stage, global, local, err, count, ap);
    va_end(ap);
    return rc;
}
