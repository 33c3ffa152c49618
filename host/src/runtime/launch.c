/* Kernel arguments and launches, each recorded in the current stage. */
#include <stdarg.h>
#include <stdio.h>

#include "runtime/launch.h"
#include "runtime/program.h"

static int kernel_name_of(cl_kernel kernel, char *name, size_t size) {
    name[0] = '\0';
    return clGetKernelInfo(kernel, CL_KERNEL_FUNCTION_NAME, size, name, NULL);
}

int vct_launch(vct_context *ctx, cl_kernel kernel, size_t global, size_t local, vct_error *err) {
    char name[64];
    kernel_name_of(kernel, name, sizeof name);
    if (global == 0)
        return VCT_OK; /* nothing to do; zero-sized NDRanges are invalid in OpenCL 1.2 */
    if (local)
        global = (global + local - 1) / local * local;
    cl_event ev = NULL;
    const char *stage = ctx->current_stage >= 0 ? ctx->stages[ctx->current_stage].name : name;
    VCT_CL(err, stage,
           clEnqueueNDRangeKernel(ctx->queue, kernel, 1, NULL, &global, local ? &local : NULL, 0,
                                  NULL, &ev));
    return vct_record_event(ctx, ev, name, err);
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
    cl_event ev = NULL;
    const char *stage = ctx->current_stage >= 0 ? ctx->stages[ctx->current_stage].name : name;
    VCT_CL(err, stage,
           clEnqueueNDRangeKernel(ctx->queue, kernel, 2, NULL, global, local, 0, NULL, &ev));
    return vct_record_event(ctx, ev, name, err);
}

static int set_args_v(vct_error *err, const char *stage, cl_kernel kernel, int first, int count,
                      va_list ap) {
    int rc = VCT_OK;
    for (int i = 0; i < count && rc == VCT_OK; ++i) {
        size_t size = va_arg(ap, size_t);
        const void *value = va_arg(ap, const void *);
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
