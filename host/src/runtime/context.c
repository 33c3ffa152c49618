/* Contexts: on a device the engine opens, or on the caller's own OpenCL
 * objects; the device's tuning; release of what the context holds. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "runtime/runtime.h"

/* GPUs: wide work-groups over a few tiles each; CPUs: one work-item per
 * group walking a contiguous chunk, which keeps scans at memory speed. */
static void choose_tuning(vct_context *ctx) {
    if (ctx->info.is_gpu) {
        ctx->scan_group_size = 256;
        ctx->scan_groups = ctx->info.compute_units * 4;
        ctx->radix_bits = 4;
    } else {
        ctx->scan_group_size = 1;
        ctx->scan_groups = ctx->info.compute_units * 4;
        ctx->radix_bits = 8;
    }
    /* VCT_TUNING=gpu|cpu forces one shape, so both are tested on any device. */
    const char *tuning = getenv("VCT_TUNING");
    if (tuning && strcmp(tuning, "gpu") == 0) {
        ctx->scan_group_size = 256;
        ctx->radix_bits = 4;
    } else if (tuning && strcmp(tuning, "cpu") == 0) {
        ctx->scan_group_size = 1;
        ctx->radix_bits = 8;
    }
    const char *bits = getenv("VCT_RADIX_BITS");
    if (bits && atoi(bits) >= 1 && atoi(bits) <= 12)
        ctx->radix_bits = atoi(bits);
    /* VCT_MAX_ALLOC_MIB=M (every device) or D:M (device D only) lowers the
     * per-buffer limit, to see how a smaller device would fail without one
     * at hand. */
    const char *limit = getenv("VCT_MAX_ALLOC_MIB");
    int only = -1;
    double mib = 0.0;
    if (limit && sscanf(limit, "%d:%lf", &only, &mib) != 2) {
        only = -1;
        mib = atof(limit);
    }
    if (mib > 0.0 && (only < 0 || only == ctx->info.index) &&
        mib * 1048576.0 < (double)ctx->info.max_alloc)
        ctx->info.max_alloc = (uint64_t)(mib * 1048576.0);
    if (ctx->scan_groups < 4)
        ctx->scan_groups = 4;
    if (ctx->scan_groups > 1024)
        ctx->scan_groups = 1024;
    if (ctx->scan_group_size > ctx->info.max_work_group)
        ctx->scan_group_size = ctx->info.max_work_group;
}

static vct_context *context_new(cl_platform_id platform, cl_device_id device, int index,
                                vct_error *err) {
    vct_context *ctx = calloc(1, sizeof *ctx);
    if (!ctx) {
        vct_fail(err, VCT_ERR_MEMORY, "context: out of host memory");
        return NULL;
    }
    ctx->platform = platform;
    ctx->device = device;
    vct_device_describe(platform, device, index, &ctx->info);
    ctx->current_stage = -1;
    return ctx;
}

vct_context *vct_context_open(const char *selector, const cl_context_properties *extra,
                              const char *required_extension, vct_error *err) {
    cl_platform_id platform = NULL;
    cl_device_id device = NULL;
    const int pick = vct_device_pick(selector, &platform, &device, err);
    if (pick < 0)
        return NULL;
    vct_context *ctx = context_new(platform, device, pick, err);
    if (!ctx)
        return NULL;
    if (required_extension && !strstr(ctx->info.extensions, required_extension)) {
        vct_fail(err, VCT_ERR_OPENCL, "context: %s (%s) has no %s", ctx->info.name,
                 ctx->info.platform, required_extension);
        free(ctx);
        return NULL;
    }

    cl_int rc = CL_SUCCESS;
    cl_context_properties props[16] = {CL_CONTEXT_PLATFORM, (cl_context_properties)platform};
    int count = 2;
    for (int i = 0; extra && extra[i] && count < 14; i += 2) {
        props[count++] = extra[i];
        props[count++] = extra[i + 1];
    }
    props[count] = 0;
    ctx->context = clCreateContext(props, 1, &ctx->device, NULL, NULL, &rc);
    if (rc != CL_SUCCESS) {
        vct_cl_check(err, rc, "context", "clCreateContext");
        free(ctx);
        return NULL;
    }
    ctx->queue = clCreateCommandQueue(ctx->context, ctx->device, CL_QUEUE_PROFILING_ENABLE, &rc);
    if (rc != CL_SUCCESS) {
        vct_cl_check(err, rc, "context", "clCreateCommandQueue");
        clReleaseContext(ctx->context);
        free(ctx);
        return NULL;
    }
    ctx->owns_handles = 1;
    ctx->profiling = 1;
    choose_tuning(ctx);
    return ctx;
}

vct_context *vct_context_create(const char *selector, vct_error *err) {
    return vct_context_open(selector, NULL, NULL, err);
}

/* Whether `device` is one of `context`'s devices. */
static int context_has_device(cl_context context, cl_device_id device, vct_error *err) {
    cl_uint n = 0;
    VCT_CL(err, "context wrap",
           clGetContextInfo(context, CL_CONTEXT_NUM_DEVICES, sizeof n, &n, NULL));
    cl_device_id *devices = calloc(n ? n : 1, sizeof *devices);
    if (!devices)
        return vct_fail(err, VCT_ERR_MEMORY, "context wrap: out of host memory");
    cl_int rc = clGetContextInfo(context, CL_CONTEXT_DEVICES, n * sizeof *devices, devices, NULL);
    int found = 0;
    for (cl_uint i = 0; rc == CL_SUCCESS && i < n; ++i)
        found |= devices[i] == device;
    free(devices);
    if (rc != CL_SUCCESS)
        return vct_cl_check(err, rc, "context wrap", "clGetContextInfo(CL_CONTEXT_DEVICES)");
    if (!found)
        return vct_fail(err, VCT_ERR_INPUT,
                        "context wrap: the device is not one of the context's devices: pass "
                        "a device the context was created with");
    return VCT_OK;
}

/* The queue must belong to this context and device. */
static int queue_matches(cl_command_queue queue, cl_context context, cl_device_id device,
                         int *profiling, vct_error *err) {
    cl_context queue_context = NULL;
    cl_device_id queue_device = NULL;
    cl_command_queue_properties props = 0;
    VCT_CL(
        err, "context wrap",
        clGetCommandQueueInfo(queue, CL_QUEUE_CONTEXT, sizeof queue_context, &queue_context, NULL));
    VCT_CL(err, "context wrap",
           clGetCommandQueueInfo(queue, CL_QUEUE_DEVICE, sizeof queue_device, &queue_device, NULL));
    VCT_CL(err, "context wrap",
           clGetCommandQueueInfo(queue, CL_QUEUE_PROPERTIES, sizeof props, &props, NULL));
    if (queue_context != context)
        return vct_fail(err, VCT_ERR_INPUT,
                        "context wrap: the queue belongs to another OpenCL context: pass a "
                        "queue created on this context");
    if (queue_device != device)
        return vct_fail(err, VCT_ERR_INPUT,
                        "context wrap: the queue is on another device: pass a queue created "
                        "for this device");
    if (props & CL_QUEUE_OUT_OF_ORDER_EXEC_MODE_ENABLE)
        return vct_fail(err, VCT_ERR_INPUT,
                        "context wrap: the queue executes out of order; the engine's stages "
                        "rely on in-order execution: pass an in-order queue");
    *profiling = (props & CL_QUEUE_PROFILING_ENABLE) != 0;
    return VCT_OK;
}

vct_context *vct_context_wrap(cl_context context, cl_device_id device, cl_command_queue queue,
                              vct_error *err) {
    if (!context || !device || !queue) {
        vct_fail(err, VCT_ERR_INPUT,
                 "context wrap: a NULL %s: pass the cl_context, the cl_device_id and the "
                 "cl_command_queue to run on",
                 !context  ? "context"
                 : !device ? "device"
                           : "queue");
        return NULL;
    }
    cl_platform_id platform = NULL;
    int profiling = 0;
    cl_int rc = clGetDeviceInfo(device, CL_DEVICE_PLATFORM, sizeof platform, &platform, NULL);
    if (rc != CL_SUCCESS) {
        vct_cl_check(err, rc, "context wrap", "clGetDeviceInfo(CL_DEVICE_PLATFORM)");
        return NULL;
    }
    if (context_has_device(context, device, err) != VCT_OK ||
        queue_matches(queue, context, device, &profiling, err) != VCT_OK)
        return NULL;
    vct_context *ctx = context_new(platform, device, vct_device_index(device), err);
    if (!ctx)
        return NULL;
    ctx->context = context;
    ctx->queue = queue;
    ctx->owns_handles = 0;
    ctx->profiling = profiling;
    choose_tuning(ctx);
    return ctx;
}

void vct_context_on_release(vct_context *ctx, vct_release_hook hook) {
    for (int i = 0; i < ctx->release_hook_count; ++i)
        if (ctx->release_hooks[i] == hook)
            return;
    if (ctx->release_hook_count < VCT_MAX_RELEASE_HOOKS)
        ctx->release_hooks[ctx->release_hook_count++] = hook;
}

void vct_context_release(vct_context *ctx) {
    if (!ctx)
        return;
    vct_stage_end(ctx);
    for (int i = ctx->release_hook_count - 1; i >= 0; --i)
        ctx->release_hooks[i](ctx);
    for (int i = 0; i < ctx->program_count; ++i)
        clReleaseProgram(ctx->programs[i].program);
    if (ctx->owns_handles) {
        clReleaseCommandQueue(ctx->queue);
        clReleaseContext(ctx->context);
    }
    free(ctx);
}

const vct_device_info *vct_context_device(const vct_context *ctx) {
    return &ctx->info;
}

cl_context vct_context_cl_context(const vct_context *ctx) {
    return ctx->context;
}

cl_device_id vct_context_cl_device(const vct_context *ctx) {
    return ctx->device;
}

cl_command_queue vct_context_cl_queue(const vct_context *ctx) {
    return ctx->queue;
}
