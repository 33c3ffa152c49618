/* The frame every renderer writes, kept in the context between calls. */
#ifndef VCT_RENDER_FRAME_H
#define VCT_RENDER_FRAME_H

#include "runtime/runtime.h"

/* The context's frame at this size (reallocated when it changes). */
cl_mem vct_frame_get(vct_context *ctx, const char *stage, int width, int height, vct_error *err);
/* Hands the frame to a renderer's caller: a host copy, or only its size
 * when host copies are off. */
int vct_frame_deliver(vct_context *ctx, const char *stage, vct_image *image, vct_error *err);
/* Reads a device buffer of width x height float4 pixels into `image`. */
int vct_image_read_device(vct_context *ctx, const char *stage, cl_mem mem, int width, int height,
                          vct_image *image, vct_error *err);

#endif
