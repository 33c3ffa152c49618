/* The frame: one device image (float4 per pixel, rows top to bottom) that
 * every renderer writes, kept in the context between calls. A display takes
 * it on the device (vct_frame_to_gl_buffer); offline callers get a host copy. */
#include <stdlib.h>
#include <string.h>

#include "runtime/runtime.h"
#include "frame/frame.h"
#include "scene/scene_device.h"

static void frame_release(vct_context *ctx);

cl_mem vct_frame_get(vct_context *ctx, const char *stage, int width, int height, vct_error *err) {
    if (ctx->frame && ctx->frame_size[0] == width && ctx->frame_size[1] == height)
        return ctx->frame;
    vct_buffer_release(ctx, ctx->frame);
    vct_context_on_release(ctx, frame_release);
    ctx->frame = vct_buffer_create(ctx, stage, "image", 16 * (size_t)width * (size_t)height,
                                   CL_MEM_READ_WRITE, NULL, err);
    ctx->frame_size[0] = ctx->frame ? width : 0;
    ctx->frame_size[1] = ctx->frame ? height : 0;
    return ctx->frame;
}

int vct_frame_camera(const vct_context *ctx, const vct_camera *camera, int width, int height,
                     vct_camera_desc *cam, vct_error *err) {
    const int whole = ctx->band_height ? ctx->band_height : height;
    int rc = vct_camera_desc_make(camera, width, whole, cam, err);
    if (rc != VCT_OK || !ctx->band_height)
        return rc;
    if (ctx->band_first < 0 || height < 1 || ctx->band_first + height > ctx->band_height)
        return vct_fail(err, VCT_ERR_INPUT,
                        "render: rows %d to %d are not a band of an image %d rows tall",
                        ctx->band_first, ctx->band_first + height - 1, ctx->band_height);
    /* The aspect stays the whole image's: the band's rays are its rows' rays. */
    cam->size.s[1] = (cl_uint)height;
    cam->size.s[2] = (cl_uint)ctx->band_first;
    cam->size.s[3] = (cl_uint)ctx->band_height;
    return VCT_OK;
}

int vct_frame_deliver(vct_context *ctx, const char *stage, vct_image *image, vct_error *err) {
    if (!ctx->frame)
        return vct_fail(err, VCT_ERR_INPUT, "%s: no frame has been rendered", stage);
    if (ctx->frame_device_only) {
        image->width = ctx->frame_size[0];
        image->height = ctx->frame_size[1];
        image->rgba = NULL;
        return VCT_OK;
    }
    return vct_image_read_device(ctx, stage, ctx->frame, ctx->frame_size[0], ctx->frame_size[1],
                                 image, err);
}

void vct_frame_host_copy(vct_context *ctx, int on) {
    ctx->frame_device_only = !on;
}

void vct_frame_size(const vct_context *ctx, int *width, int *height) {
    *width = ctx->frame_size[0];
    *height = ctx->frame_size[1];
}

vct_status vct_frame_read(vct_context *ctx, float *rgba, size_t floats, vct_error *err) {
    if (!ctx->frame)
        return vct_fail(err, VCT_ERR_INPUT, "frame: nothing has been rendered yet");
    const size_t need = 4 * (size_t)ctx->frame_size[0] * (size_t)ctx->frame_size[1];
    if (floats < need)
        return vct_fail(err, VCT_ERR_INPUT, "frame: %zu floats given, the %dx%d frame has %zu",
                        floats, ctx->frame_size[0], ctx->frame_size[1], need);
    return vct_buffer_read(ctx, "frame", ctx->frame, 0, 4 * need, rgba, err);
}

static void frame_release(vct_context *ctx) {
    vct_buffer_release(ctx, ctx->frame);
    ctx->frame = NULL;
    ctx->frame_size[0] = ctx->frame_size[1] = 0;
}

int vct_image_read_device(vct_context *ctx, const char *stage, cl_mem mem, int width, int height,
                          vct_image *image, vct_error *err) {
    const size_t bytes = 16 * (size_t)width * (size_t)height;
    image->width = width;
    image->height = height;
    image->rgba = malloc(bytes);
    if (!image->rgba)
        return vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory", stage);
    return vct_buffer_read(ctx, stage, mem, 0, bytes, image->rgba, err);
}
