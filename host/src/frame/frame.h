/* The frame every renderer writes, kept in the context between calls. */
#ifndef VCT_RENDER_FRAME_H
#define VCT_RENDER_FRAME_H

#include "runtime/runtime.h"
#include "vct_types.h"

/* The context's frame at this size (reallocated when it changes). */
cl_mem vct_frame_get(vct_context *ctx, const char *stage, int width, int height, vct_error *err);
/* The camera of a width x height render: of the whole image, or of the
 * band of a taller image the context is drawing (vct_render_job band). */
int vct_frame_camera(const vct_context *ctx, const vct_camera *camera, int width, int height,
                     vct_camera_desc *cam, vct_error *err);
/* Hands the frame to a renderer's caller: a host copy, or only its size
 * when host copies are off. */
int vct_frame_deliver(vct_context *ctx, const char *stage, vct_image *image, vct_error *err);
/* Reads a device buffer of width x height float4 pixels into `image`. */
int vct_image_read_device(vct_context *ctx, const char *stage, cl_mem mem, int width, int height,
                          vct_image *image, vct_error *err);

#endif
