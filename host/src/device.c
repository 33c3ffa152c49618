/* Platforms and devices: listing, selection and context creation. */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "internal.h"

#define MAX_PLATFORMS 16
#define MAX_DEVICES 64

typedef struct device_ref {
    cl_platform_id platform;
    cl_device_id device;
} device_ref;

static int enumerate(device_ref *refs, int max, vct_error *err) {
    cl_platform_id platforms[MAX_PLATFORMS];
    cl_uint platform_count = 0;
    cl_int rc = clGetPlatformIDs(MAX_PLATFORMS, platforms, &platform_count);
    if (rc == -1001 || platform_count == 0) {
        vct_fail(err, VCT_ERR_OPENCL,
                 "devices: no OpenCL platform found: install an ICD such as "
                 "pocl-opencl-icd (CPU) or your GPU vendor's OpenCL driver");
        return -1;
    }
    if (rc != CL_SUCCESS) {
        vct_cl_check(err, rc, "devices", "clGetPlatformIDs");
        return -1;
    }
    int count = 0;
    for (cl_uint p = 0; p < platform_count && p < MAX_PLATFORMS; ++p) {
        cl_device_id devices[MAX_DEVICES];
        cl_uint n = 0;
        rc = clGetDeviceIDs(platforms[p], CL_DEVICE_TYPE_ALL, MAX_DEVICES, devices, &n);
        if (rc == CL_DEVICE_NOT_FOUND)
            continue;
        if (rc != CL_SUCCESS) {
            vct_cl_check(err, rc, "devices", "clGetDeviceIDs");
            return -1;
        }
        for (cl_uint d = 0; d < n && count < max; ++d) {
            refs[count].platform = platforms[p];
            refs[count].device = devices[d];
            ++count;
        }
    }
    return count;
}

static void describe(const device_ref *ref, int index, vct_device_info *info) {
    memset(info, 0, sizeof *info);
    info->index = index;
    clGetPlatformInfo(ref->platform, CL_PLATFORM_NAME, sizeof info->platform, info->platform, NULL);
    clGetDeviceInfo(ref->device, CL_DEVICE_NAME, sizeof info->name, info->name, NULL);
    clGetDeviceInfo(ref->device, CL_DEVICE_VERSION, sizeof info->version, info->version, NULL);
    clGetDeviceInfo(ref->device, CL_DRIVER_VERSION, sizeof info->driver, info->driver, NULL);
    cl_device_type type = 0;
    clGetDeviceInfo(ref->device, CL_DEVICE_TYPE, sizeof type, &type, NULL);
    info->is_gpu = (type & CL_DEVICE_TYPE_GPU) != 0;
    cl_uint cu = 0;
    clGetDeviceInfo(ref->device, CL_DEVICE_MAX_COMPUTE_UNITS, sizeof cu, &cu, NULL);
    info->compute_units = cu;
    cl_ulong mem = 0;
    clGetDeviceInfo(ref->device, CL_DEVICE_GLOBAL_MEM_SIZE, sizeof mem, &mem, NULL);
    info->global_mem = mem;
    clGetDeviceInfo(ref->device, CL_DEVICE_MAX_MEM_ALLOC_SIZE, sizeof mem, &mem, NULL);
    info->max_alloc = mem;
    size_t wg = 0;
    clGetDeviceInfo(ref->device, CL_DEVICE_MAX_WORK_GROUP_SIZE, sizeof wg, &wg, NULL);
    info->max_work_group = wg;
    cl_bool images = CL_FALSE;
    clGetDeviceInfo(ref->device, CL_DEVICE_IMAGE_SUPPORT, sizeof images, &images, NULL);
    info->image_support = images == CL_TRUE;
    clGetDeviceInfo(ref->device, CL_DEVICE_EXTENSIONS, sizeof info->extensions, info->extensions,
                    NULL);
    info->extensions[sizeof info->extensions - 1] = '\0';
    info->fp64 = strstr(info->extensions, "cl_khr_fp64") != NULL;
    info->gl_sharing = strstr(info->extensions, "cl_khr_gl_sharing") != NULL;
}

int vct_list_devices(vct_device_info *out, int max, vct_error *err) {
    device_ref refs[MAX_DEVICES];
    int n = enumerate(refs, MAX_DEVICES, err);
    if (n < 0)
        return -1;
    for (int i = 0; i < n && i < max; ++i)
        describe(&refs[i], i, &out[i]);
    return n < max ? n : max;
}

static int contains_nocase(const char *hay, const char *needle) {
    size_t n = strlen(needle);
    for (; *hay; ++hay) {
        size_t i = 0;
        while (i < n && hay[i] &&
               tolower((unsigned char)hay[i]) == tolower((unsigned char)needle[i]))
            ++i;
        if (i == n)
            return 1;
    }
    return n == 0;
}

static int choose(const device_ref *refs, int n, const char *selector, vct_error *err) {
    vct_device_info info;
    if (selector && *selector) {
        char *end = NULL;
        long index = strtol(selector, &end, 10);
        if (end && *end == '\0') {
            if (index < 0 || index >= n) {
                vct_fail(err, VCT_ERR_INPUT,
                         "devices: device %ld does not exist (there are %d): see `vct devices`",
                         index, n);
                return -1;
            }
            return (int)index;
        }
        for (int i = 0; i < n; ++i) {
            describe(&refs[i], i, &info);
            if (contains_nocase(info.name, selector) || contains_nocase(info.platform, selector))
                return i;
        }
        vct_fail(err, VCT_ERR_INPUT, "devices: no device matches \"%s\": see `vct devices`",
                 selector);
        return -1;
    }
    for (int i = 0; i < n; ++i) {
        describe(&refs[i], i, &info);
        if (info.is_gpu)
            return i;
    }
    return 0;
}

vct_context *vct_context_open(const char *selector, const cl_context_properties *extra,
                              const char *required_extension, vct_error *err) {
    device_ref refs[MAX_DEVICES];
    int n = enumerate(refs, MAX_DEVICES, err);
    if (n < 0)
        return NULL;
    if (n == 0) {
        vct_fail(err, VCT_ERR_OPENCL,
                 "devices: OpenCL platforms exist but have no devices: install a driver");
        return NULL;
    }
    if (!selector || !*selector)
        selector = getenv("VCT_DEVICE");
    int pick = choose(refs, n, selector, err);
    if (pick < 0)
        return NULL;

    vct_context *ctx = calloc(1, sizeof *ctx);
    if (!ctx) {
        vct_fail(err, VCT_ERR_MEMORY, "context: out of host memory");
        return NULL;
    }
    ctx->platform = refs[pick].platform;
    ctx->device = refs[pick].device;
    describe(&refs[pick], pick, &ctx->info);
    ctx->current_stage = -1;
    if (required_extension && !strstr(ctx->info.extensions, required_extension)) {
        vct_fail(err, VCT_ERR_OPENCL, "context: %s (%s) has no %s", ctx->info.name,
                 ctx->info.platform, required_extension);
        free(ctx);
        return NULL;
    }

    cl_int rc = CL_SUCCESS;
    cl_context_properties props[16] = {CL_CONTEXT_PLATFORM, (cl_context_properties)ctx->platform};
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
    /* GPUs: wide work-groups over a few tiles each; CPUs: one work-item per
     * group walking a contiguous chunk, which keeps scans at memory speed. */
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
    /* VCT_MAX_ALLOC_MIB lowers the per-buffer limit, to see how a smaller
     * device would fail without one at hand. */
    const char *limit = getenv("VCT_MAX_ALLOC_MIB");
    if (limit && atof(limit) > 0.0 && atof(limit) * 1048576.0 < (double)ctx->info.max_alloc)
        ctx->info.max_alloc = (uint64_t)(atof(limit) * 1048576.0);
    if (ctx->scan_groups < 4)
        ctx->scan_groups = 4;
    if (ctx->scan_groups > 1024)
        ctx->scan_groups = 1024;
    if (ctx->scan_group_size > ctx->info.max_work_group)
        ctx->scan_group_size = ctx->info.max_work_group;
    return ctx;
}

vct_context *vct_context_create(const char *selector, vct_error *err) {
    return vct_context_open(selector, NULL, NULL, err);
}

void vct_context_destroy(vct_context *ctx) {
    if (!ctx)
        return;
    vct_stage_end(ctx);
    vct_frame_release(ctx);
    vct_pathtrace_release(ctx);
    for (int i = 0; i < ctx->program_count; ++i)
        clReleaseProgram(ctx->programs[i].program);
    clReleaseCommandQueue(ctx->queue);
    clReleaseContext(ctx->context);
    free(ctx);
}

const vct_device_info *vct_context_device(const vct_context *ctx) {
    return &ctx->info;
}
