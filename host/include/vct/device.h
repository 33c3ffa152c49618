/* vct: devices, contexts and their statistics.
 *
 * A context is one OpenCL device with its queue, program cache and stage
 * statistics: one the engine opens (vct_context_create), or the caller's own
 * (vct_context_wrap). Independent contexts are independent and may be used
 * from different threads at once; calls on one context must be serialised
 * by the caller. */
#ifndef VCT_API_DEVICE_H
#define VCT_API_DEVICE_H

#include "vct/export.h"

#include <stddef.h>
#include <stdint.h>

#include "vct/error.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct vct_device_info {
    int index; /* global index over all platforms, as used by --device N */
    char platform[128];
    char name[256];
    char version[128];
    char driver[128];
    int is_gpu;
    unsigned compute_units;
    uint64_t global_mem;
    uint64_t max_alloc;
    size_t max_work_group;
    int image_support;
    int fp64;
    int gl_sharing;
    char extensions[4096];
} vct_device_info;

/* Lists every device of every platform. Returns the count (at most max). */
VCT_API int vct_list_devices(vct_device_info *out, int max, vct_error *err);

typedef struct vct_context vct_context;

/* selector: NULL or "" = $VCT_DEVICE, else first GPU, else first CPU;
 * a number = global device index; otherwise a case-insensitive substring of
 * the device or platform name. */
VCT_API vct_context *vct_context_create(const char *selector, vct_error *err);
VCT_API void vct_context_release(vct_context *ctx);
VCT_API const vct_device_info *vct_context_device(const vct_context *ctx);

/* Messages about work a call does beyond what it was asked, as it does it:
 * today, compiling a kernel program that is not in the on-disk cache (the
 * first use of a kernel variant on a device takes seconds; later uses load
 * it). The library prints nothing itself; without a callback messages are
 * dropped. Called on the thread that uses the context. */
typedef void (*vct_log_fn)(void *user, const char *message);
VCT_API void vct_context_set_log(vct_context *ctx, vct_log_fn log, void *user);

/* Kernel programs this context compiled from source and loaded from the
 * on-disk cache, and the wall time both took. */
typedef struct vct_program_stats {
    int compiled, cached;
    double ms;
} vct_program_stats;
VCT_API void vct_context_program_stats(const vct_context *ctx, vct_program_stats *stats);

/* Bytes this context has copied from the host to the device and back since
 * it was made: scene data, parameters and read-backs alike. */
typedef struct vct_transfer_stats {
    uint64_t uploaded, downloaded;
} vct_transfer_stats;
VCT_API void vct_context_transfer_stats(const vct_context *ctx, vct_transfer_stats *stats);

/* ---- statistics ----------------------------------------------------------- */

typedef struct vct_stage_stat {
    char name[48];
    double device_ms; /* sum of kernel/copy event durations */
    double host_ms;   /* wall time the host spent in the stage */
    double mib;       /* peak device memory allocated through vct while the stage ran */
    int launches;
} vct_stage_stat;

VCT_API int vct_stats(const vct_context *ctx, const vct_stage_stat **stages);
VCT_API void vct_stats_reset(vct_context *ctx);

typedef struct vct_kernel_stat {
    char name[64];
    int launches;
    double device_ms; /* summed over the launches made inside a stage */
} vct_kernel_stat;

/* Per-kernel launches and device time since the last reset. */
VCT_API int vct_kernel_stats(const vct_context *ctx, const vct_kernel_stat **kernels);

#ifdef __cplusplus
}
#endif
#endif
