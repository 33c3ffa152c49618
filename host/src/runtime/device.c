/* Platforms and devices: listing and selection. */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "runtime/runtime.h"

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
    vct_device_describe(ref->platform, ref->device, index, info);
}

void vct_device_describe(cl_platform_id platform, cl_device_id device, int index,
                         vct_device_info *info) {
    memset(info, 0, sizeof *info);
    info->index = index;
    clGetPlatformInfo(platform, CL_PLATFORM_NAME, sizeof info->platform, info->platform, NULL);
    clGetDeviceInfo(device, CL_DEVICE_NAME, sizeof info->name, info->name, NULL);
    clGetDeviceInfo(device, CL_DEVICE_VERSION, sizeof info->version, info->version, NULL);
    clGetDeviceInfo(device, CL_DRIVER_VERSION, sizeof info->driver, info->driver, NULL);
    cl_device_type type = 0;
    clGetDeviceInfo(device, CL_DEVICE_TYPE, sizeof type, &type, NULL);
    info->is_gpu = (type & CL_DEVICE_TYPE_GPU) != 0;
    cl_uint cu = 0;
    clGetDeviceInfo(device, CL_DEVICE_MAX_COMPUTE_UNITS, sizeof cu, &cu, NULL);
    info->compute_units = cu;
    cl_ulong mem = 0;
    clGetDeviceInfo(device, CL_DEVICE_GLOBAL_MEM_SIZE, sizeof mem, &mem, NULL);
    info->global_mem = mem;
    clGetDeviceInfo(device, CL_DEVICE_MAX_MEM_ALLOC_SIZE, sizeof mem, &mem, NULL);
    info->max_alloc = mem;
    size_t wg = 0;
    clGetDeviceInfo(device, CL_DEVICE_MAX_WORK_GROUP_SIZE, sizeof wg, &wg, NULL);
    info->max_work_group = wg;
    cl_bool images = CL_FALSE;
    clGetDeviceInfo(device, CL_DEVICE_IMAGE_SUPPORT, sizeof images, &images, NULL);
    info->image_support = images == CL_TRUE;
    clGetDeviceInfo(device, CL_DEVICE_EXTENSIONS, sizeof info->extensions, info->extensions, NULL);
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

int vct_device_pick(const char *selector, cl_platform_id *platform, cl_device_id *device,
                    vct_error *err) {
    device_ref refs[MAX_DEVICES];
    int n = enumerate(refs, MAX_DEVICES, err);
    if (n < 0)
        return -1;
    if (n == 0) {
        vct_fail(err, VCT_ERR_OPENCL,
                 "devices: OpenCL platforms exist but have no devices: install a driver");
        return -1;
    }
    if (!selector || !*selector)
        selector = getenv("VCT_DEVICE");
    int pick = choose(refs, n, selector, err);
    if (pick >= 0) {
        *platform = refs[pick].platform;
        *device = refs[pick].device;
    }
    return pick;
}

int vct_device_index(cl_device_id device) {
    device_ref refs[MAX_DEVICES];
    int n = enumerate(refs, MAX_DEVICES, NULL);
    for (int i = 0; i < n; ++i)
        if (refs[i].device == device)
            return i;
    return -1;
}
