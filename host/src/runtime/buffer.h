/* Device buffers, counted per stage for the memory statistics. */
#ifndef VCT_RUNTIME_BUFFER_H
#define VCT_RUNTIME_BUFFER_H

#include <stddef.h>
#include <stdint.h>

#include "runtime/context.h"

cl_mem vct_buffer_create(vct_context *ctx, const char *stage, const char *what, size_t bytes,
                         cl_mem_flags flags, const void *host, vct_error *err);
/* A read-only image of 8-byte texels (half RGBA), counted like a buffer;
 * vct_buffer_release releases it. */
cl_mem vct_image3d_create(vct_context *ctx, const char *stage, const char *what,
                          const cl_image_format *format, const cl_image_desc *desc, vct_error *err);
void vct_buffer_release(vct_context *ctx, cl_mem mem);
/* A device copy of `bytes` of `from` into *to, which is created (read and
 * write, named `what`) the first time. */
int vct_buffer_copy_into(vct_context *ctx, const char *stage, const char *what, cl_mem from,
                         cl_mem *to, size_t bytes, vct_error *err);
int vct_buffer_read(vct_context *ctx, const char *stage, cl_mem mem, size_t offset, size_t bytes,
                    void *dst, vct_error *err);
int vct_buffer_write(vct_context *ctx, const char *stage, cl_mem mem, size_t offset, size_t bytes,
                     const void *src, vct_error *err);
int vct_buffer_fill_u32(vct_context *ctx, const char *stage, cl_mem mem, uint32_t value,
                        size_t count, vct_error *err);

#endif
