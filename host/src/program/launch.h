/* Kernel arguments and launches, recorded in the current stage. */
#ifndef VCT_RUNTIME_LAUNCH_H
#define VCT_RUNTIME_LAUNCH_H

#include <stddef.h>

#include "runtime/stats.h"

/* Enqueues a 1D kernel over `global` work-items rounded up to `local`
 * (local 0: 64, or the kernel's largest work-group when smaller; never the
 * driver's pick, which some compile anew per size), records the event in the
 * current stage. */
int vct_launch(vct_context *ctx, cl_kernel kernel, size_t global, size_t local, vct_error *err);
int vct_launch_2d(vct_context *ctx, cl_kernel kernel, const size_t global[2], const size_t local[2],
                  vct_error *err);

/* Sets `count` kernel arguments from index `first`, given as (size_t size,
 * const void *value) pairs, most easily written VCT_ARG_OF(variable). */
int vct_set_args(vct_error *err, const char *stage, cl_kernel kernel, int first, int count, ...);

#define VCT_ARG_OF(x)                                                                              \
    sizeof(x), (const void *)&(x), #x " at " __FILE__ ":" VCT_LINE_STRING(__LINE__)
/* The same where the kernel names the parameter otherwise than the host
 * expression's last identifier. */
#define VCT_ARG(param, x)                                                                          \
    sizeof(x), (const void *)&(x), #param " at " __FILE__ ":" VCT_LINE_STRING(__LINE__)
#define VCT_LINE_STRING(n) VCT_LINE_STRING_(n)
#define VCT_LINE_STRING_(n) #n
/* Creates kernel `name`, sets its `count` arguments (as vct_set_args) and
 * launches it over `global` work-items (none when global is 0). */
int vct_run_kernel(vct_context *ctx, cl_program program, const char *name, const char *stage,
                   size_t global, vct_error *err, int count, ...);
/* The same in work-groups of `local` (global rounded up to a multiple; the
 * kernel must ignore the extra work-items). For kernels with kilobytes of
 * private arrays per work-item: left to choose, PoCL runs thousands of
 * work-items per group, whose private memory overflows its threads' stacks. */
int vct_run_kernel_grouped(vct_context *ctx, cl_program program, const char *name,
                           const char *stage, size_t global, size_t local, vct_error *err,
                           int count, ...);

#endif
