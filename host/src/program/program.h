/* Kernel programs: sources found on disk or embedded, built once per
 * (source, device, driver, options) and cached on disk. */
#ifndef VCT_RUNTIME_PROGRAM_H
#define VCT_RUNTIME_PROGRAM_H

#include <stddef.h>

#include "runtime/context.h"

/* Builds (or loads from the disk cache) kernels/<file> with options. */
int vct_program_get(vct_context *ctx, const char *file, const char *options, cl_program *out,
                    vct_error *err);
cl_kernel vct_kernel_create(vct_context *ctx, cl_program program, const char *name, vct_error *err);
/* Expands #include "x" against the kernel directory or the embedded copies. */
char *vct_kernel_source_expand(const char *file, vct_error *err);
/* A build log whose "<name>:LINE:" locations (compilers that ignore #line,
 * as NVIDIA's does, count lines of the expanded source) name the kernel file
 * and its line instead (not the compiler's "<built-in>" and the like); NULL
 * if out of memory. */
char *vct_kernel_log_locate(const char *log, const char *source);
/* Path of the kernel-binary cache directory (created on demand). */
const char *vct_cache_dir(void);
/* Whole file into a NUL-terminated buffer (size optional); NULL if unreadable. */
char *vct_read_file(const char *path, size_t *size);

#endif
