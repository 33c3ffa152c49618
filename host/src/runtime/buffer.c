/* Device buffers: every allocation is checked against the device's limits
 * before it is made, so a failure says what to lower instead of crashing. */
#include <stdio.h>
#include <string.h>

#include "runtime/runtime.h"

#define MIB (1.0 / (1024.0 * 1024.0))

/* Whether `bytes` more still fit in the device's memory; else fails with `lower`. */
static int fits_in_memory(vct_context *ctx, const char *stage, const char *what, size_t bytes,
                          const char *lower, vct_error *err) {
    if (ctx->bytes_live + (double)bytes <= (double)ctx->info.global_mem)
        return 1;
    vct_fail(err, VCT_ERR_MEMORY,
             "%s: %s needs %.1f MiB with %.1f MiB already in use, beyond the %.1f MiB of %s: %s",
             stage, what, bytes * MIB, ctx->bytes_live * MIB, ctx->info.global_mem * MIB,
             ctx->info.name, lower);
    return 0;
}

static void count_allocation(vct_context *ctx, size_t bytes) {
    ctx->bytes_live += (double)bytes;
    if (ctx->bytes_live > ctx->bytes_stage_peak)
        ctx->bytes_stage_peak = ctx->bytes_live;
}

cl_mem vct_buffer_create(vct_context *ctx, const char *stage, const char *what, size_t bytes,
                         cl_mem_flags flags, const void *host, vct_error *err) {
    if (bytes == 0)
        bytes = 16; /* OpenCL forbids empty buffers; empty inputs still get a handle */
    const double mib = MIB;
    if ((uint64_t)bytes > ctx->info.max_alloc) {
        vct_fail(err, VCT_ERR_MEMORY,
                 "%s: %s needs %.1f MiB but %s allows at most %.1f MiB per buffer: lower the "
                 "resolution (--grid-res, --size) or the scene size",
                 stage, what, bytes * mib, ctx->info.name, ctx->info.max_alloc * mib);
        return NULL;
    }
    if (!fits_in_memory(ctx, stage, what, bytes,
                        "lower the resolution (--grid-res, --size) or the scene size", err))
        return NULL;
    cl_int rc = CL_SUCCESS;
    if (host)
        flags |= CL_MEM_COPY_HOST_PTR;
    cl_mem mem = clCreateBuffer(ctx->context, flags, bytes, (void *)host, &rc);
    if (rc != CL_SUCCESS) {
        vct_cl_check(err, rc, stage, "clCreateBuffer");
        size_t len = strlen(err->message);
        snprintf(err->message + len, sizeof err->message - len, " (%s, %.1f MiB)", what,
                 bytes * mib);
        return NULL;
    }
    count_allocation(ctx, bytes);
    if (host)
        ctx->transfers.uploaded += bytes;
    return mem;
}

cl_mem vct_image3d_create(vct_context *ctx, const char *stage, const char *what,
                          const cl_image_format *format, const cl_image_desc *desc,
                          vct_error *err) {
    const size_t bytes = desc->image_width * desc->image_height * desc->image_depth * 8;
    if (!fits_in_memory(ctx, stage, what, bytes, "lower the voxel resolution (--voxel-res)", err))
        return NULL;
    cl_int rc = CL_SUCCESS;
    cl_mem mem = clCreateImage(ctx->context, CL_MEM_READ_ONLY, format, desc, NULL, &rc);
    if (rc != CL_SUCCESS) {
        vct_cl_check(err, rc, stage, "clCreateImage");
        size_t len = strlen(err->message);
        snprintf(err->message + len, sizeof err->message - len,
                 " (%s, %zux%zux%zu texels): use a buffer pool (--bricks buffer)", what,
                 desc->image_width, desc->image_height, desc->image_depth);
        return NULL;
    }
    count_allocation(ctx, bytes);
    return mem;
}

void vct_buffer_release(vct_context *ctx, cl_mem mem) {
    if (!mem)
        return;
    size_t bytes = 0;
    if (clGetMemObjectInfo(mem, CL_MEM_SIZE, sizeof bytes, &bytes, NULL) == CL_SUCCESS)
        ctx->bytes_live -= (double)bytes;
    clReleaseMemObject(mem);
}

int vct_buffer_copy_into(vct_context *ctx, const char *stage, const char *what, cl_mem from,
                         cl_mem *to, size_t bytes, vct_error *err) {
    if (!*to)
        *to = vct_buffer_create(ctx, stage, what, bytes, CL_MEM_READ_WRITE, NULL, err);
    if (!*to)
        return err->status;
    return vct_cl_check(err, clEnqueueCopyBuffer(ctx->queue, from, *to, 0, 0, bytes, 0, NULL, NULL),
                        stage, "clEnqueueCopyBuffer");
}

int vct_buffer_read(vct_context *ctx, const char *stage, cl_mem mem, size_t offset, size_t bytes,
                    void *dst, vct_error *err) {
    if (bytes == 0)
        return VCT_OK;
    cl_event ev = NULL;
    VCT_CL(err, stage,
           clEnqueueReadBuffer(ctx->queue, mem, CL_TRUE, offset, bytes, dst, 0, NULL, &ev));
    ctx->transfers.downloaded += bytes;
    return vct_record_event(ctx, ev, "read", err);
}

int vct_buffer_write(vct_context *ctx, const char *stage, cl_mem mem, size_t offset, size_t bytes,
                     const void *src, vct_error *err) {
    if (bytes == 0)
        return VCT_OK;
    cl_event ev = NULL;
    VCT_CL(err, stage,
           clEnqueueWriteBuffer(ctx->queue, mem, CL_TRUE, offset, bytes, src, 0, NULL, &ev));
    ctx->transfers.uploaded += bytes;
    return vct_record_event(ctx, ev, "write", err);
}

int vct_buffer_fill_u32(vct_context *ctx, const char *stage, cl_mem mem, uint32_t value,
                        size_t count, vct_error *err) {
    if (count == 0)
        return VCT_OK;
    cl_event ev = NULL;
    VCT_CL(err, stage,
           clEnqueueFillBuffer(ctx->queue, mem, &value, sizeof value, 0, count * sizeof value, 0,
                               NULL, &ev));
    return vct_record_event(ctx, ev, "fill", err);
}
