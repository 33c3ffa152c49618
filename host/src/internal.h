/* Library-internal declarations shared by host/src files. */
#ifndef VCT_INTERNAL_H
#define VCT_INTERNAL_H

#define CL_TARGET_OPENCL_VERSION 120
#include <CL/cl.h>

#include "vct/vct.h"

#define VCT_PI_F 3.14159265358979f
#define VCT_MAX_STAGES 32
#define VCT_MAX_PROGRAMS 32
#define VCT_MAX_KERNEL_NAMES 64
#define VCT_MAX_PENDING_EVENTS 256

/* ---- errors ---- */
const char *vct_cl_error_name(cl_int code);
/* Formats the message, sets err->status; returns status (for `return vct_fail(...)`). */
int vct_fail(vct_error *err, vct_status status, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* Checks an OpenCL result: on failure fills err with stage, call, name and a hint. */
int vct_cl_check(vct_error *err, cl_int code, const char *stage, const char *call);
#define VCT_CL(err, stage, call)                                                                   \
    do {                                                                                           \
        cl_int vct_cl_rc_ = (call);                                                                \
        if (vct_cl_rc_ != CL_SUCCESS)                                                              \
            return vct_cl_check((err), vct_cl_rc_, (stage), #call);                                \
    } while (0)

/* ---- contexts ---- */
/* Opens a context on the device `selector` picks (as vct_context_create),
 * with `extra` context properties (0-terminated pairs, may be NULL); fails
 * when the device lacks `required_extension` (may be NULL). */
vct_context *vct_context_open(const char *selector, const cl_context_properties *extra,
                              const char *required_extension, vct_error *err);

/* ---- the frame (frame.c) ---- */
/* The context's frame at this size (reallocated when it changes). */
cl_mem vct_frame_get(vct_context *ctx, const char *stage, int width, int height, vct_error *err);
/* Hands the frame to a renderer's caller: a host copy, or only its size
 * when host copies are off. */
int vct_frame_deliver(vct_context *ctx, const char *stage, vct_image *image, vct_error *err);
void vct_frame_release(vct_context *ctx);
void vct_pathtrace_release(vct_context *ctx);

/* ---- programs ---- */
typedef struct vct_program {
    char key[64];
    cl_program program;
} vct_program;

typedef vct_kernel_stat vct_kernel_count;

struct vct_context {
    cl_platform_id platform;
    cl_device_id device;
    cl_context context;
    cl_command_queue queue;
    vct_device_info info;
    vct_program programs[VCT_MAX_PROGRAMS];
    int program_count;
    vct_stage_stat stages[VCT_MAX_STAGES];
    int stage_count;
    int current_stage;
    double stage_host_start;
    cl_event pending[VCT_MAX_PENDING_EVENTS];
    int pending_kernel[VCT_MAX_PENDING_EVENTS]; /* index into kernel_counts */
    int pending_count;
    vct_kernel_count kernel_counts[VCT_MAX_KERNEL_NAMES];
    int kernel_count_n;
    double bytes_live;       /* device bytes currently allocated through vct_buffer */
    double bytes_stage_peak; /* most bytes live during the current stage */
    /* Tuning chosen from the device type (see primitives.c). */
    size_t scan_group_size;
    size_t scan_groups;
    int radix_bits;
    /* The frame every renderer writes (frame.c), and the path tracer's
     * running sums, which a resumed call adds to (pathtrace.c). */
    cl_mem frame;
    int frame_size[2];
    int frame_device_only; /* renders return no host copy */
    int gl_shared;         /* created with an OpenGL context (gl_share.c) */
    cl_mem pt_accum, pt_discarded;
    int pt_size[2];
    uint32_t pt_done;
    /* Program cache statistics, for reporting cold/warm starts. */
    int cache_hits, cache_misses;
    double build_ms;
};

/* Builds (or loads from the disk cache) kernels/<file> with options. */
int vct_program_get(vct_context *ctx, const char *file, const char *options, cl_program *out,
                    vct_error *err);
cl_kernel vct_kernel_create(vct_context *ctx, cl_program program, const char *name, vct_error *err);
/* Expands #include "x" against the kernel directory or the embedded copies. */
char *vct_kernel_source_expand(const char *file, vct_error *err);
/* Path of the kernel-binary cache directory (created on demand). */
const char *vct_cache_dir(void);

/* ---- buffers ---- */
cl_mem vct_buffer_create(vct_context *ctx, const char *stage, const char *what, size_t bytes,
                         cl_mem_flags flags, const void *host, vct_error *err);
/* A read-only image of 8-byte texels (half RGBA), counted like a buffer;
 * vct_buffer_release releases it. */
cl_mem vct_image3d_create(vct_context *ctx, const char *stage, const char *what,
                          const cl_image_format *format, const cl_image_desc *desc, vct_error *err);
void vct_buffer_release(vct_context *ctx, cl_mem mem);
int vct_buffer_read(vct_context *ctx, const char *stage, cl_mem mem, size_t offset, size_t bytes,
                    void *dst, vct_error *err);
int vct_buffer_write(vct_context *ctx, const char *stage, cl_mem mem, size_t offset, size_t bytes,
                     const void *src, vct_error *err);
int vct_buffer_fill_u32(vct_context *ctx, const char *stage, cl_mem mem, uint32_t value,
                        size_t count, vct_error *err);

/* ---- launches and statistics ---- */
void vct_stage_begin(vct_context *ctx, const char *name);
void vct_stage_end(vct_context *ctx);
/* Enqueues a 1D kernel over `global` work-items rounded up to `local`
 * (local 0 = let the runtime choose), records the event in the current stage. */
int vct_launch(vct_context *ctx, cl_kernel kernel, size_t global, size_t local, vct_error *err);
int vct_launch_2d(vct_context *ctx, cl_kernel kernel, const size_t global[2], const size_t local[2],
                  vct_error *err);
int vct_record_event(vct_context *ctx, cl_event event, const char *kernel_name, vct_error *err);
int vct_finish(vct_context *ctx, const char *stage, vct_error *err);
double vct_now_ms(void);

/* Sets `count` kernel arguments from index `first`, given as (size_t size,
 * const void *value) pairs, most easily written VCT_ARG_OF(variable). */
int vct_set_args(vct_error *err, const char *stage, cl_kernel kernel, int first, int count, ...);
#define VCT_ARG_OF(x) sizeof(x), (const void *)&(x)
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

/* Sort key bits that tell `count` values apart (1 to 32). */
int vct_key_bits_for(uint64_t count);

/* Reads a device image of width x height float4 pixels into `image`. */
int vct_image_read_device(vct_context *ctx, const char *stage, cl_mem mem, int width, int height,
                          vct_image *image, vct_error *err);

/* Whole file into a NUL-terminated buffer (size optional); NULL if unreadable. */
char *vct_read_file(const char *path, size_t *size);

/* ---- grid internals used by renderers ---- */
struct vct_grid {
    cl_mem cell_ranges, cell_bits, tri_ids;
    cl_mem tri_vertices; /* 3 float4 per triangle */
    uint32_t res[3];
    float origin[3], cell_size[3];
    float scene_extent;
    float tolerance; /* distance below which positions are not told apart */
    uint32_t references;
    uint32_t triangle_count;
    vct_context *ctx;
};

/* Grid description passed to kernels (vct_grid_desc in kernels/vct_types.h). */
void vct_grid_kernel_args(const vct_grid *grid, void *out_desc);
/* Arguments 0-4 of every kernel that traverses the grid (GRID_ARGS in the kernels). */
int vct_grid_set_args(cl_kernel k, const vct_grid *grid, const char *stage, vct_error *err);

#endif
