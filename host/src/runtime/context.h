/* The context: one device, its queue, program cache, stage statistics and
 * the state renderers keep between calls. */
#ifndef VCT_RUNTIME_CONTEXT_H
#define VCT_RUNTIME_CONTEXT_H

#include "runtime/error.h"

#define VCT_MAX_STAGES 32
#define VCT_MAX_PROGRAMS 128
#define VCT_MAX_KERNEL_NAMES 64
#define VCT_MAX_PENDING_EVENTS 256
#define VCT_MAX_RELEASE_HOOKS 8

typedef struct vct_program {
    char key[64];
    cl_program program;
} vct_program;

typedef vct_kernel_stat vct_kernel_count;
typedef void (*vct_release_hook)(vct_context *ctx);

/* What the progressive methods add to across resumed calls: the path
 * tracer's exact sums (pathtrace/) and photon mapping's per-pixel
 * statistics (photon/sppm.c), each dropped when it no longer describes the
 * scene. */
typedef struct vct_accumulation {
    cl_mem pt_sums, pt_discarded;
    int pt_size[2];
    uint32_t pt_done;   /* samples in pt_sums */
    int pt_colour_only; /* pt_sums hold no moments (vct_pathtrace_options) */
    void *pm_state;
} vct_accumulation;

struct vct_context {
    cl_platform_id platform;
    cl_device_id device;
    cl_context context;
    cl_command_queue queue;
    /* 0 when the caller's handles were wrapped (vct_context_wrap): they are
     * theirs to release. */
    int owns_handles;
    /* 0 when the queue has no profiling: stages then report host time only. */
    int profiling;
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
    double bytes_live;            /* device bytes currently allocated through vct_buffer */
    double bytes_stage_peak;      /* most bytes live during the current stage */
    vct_transfer_stats transfers; /* host <-> device copies through vct_buffer */
    /* The device scenes committed on this context (scene/scene_resident.h):
     * stages take their scene's buffers from them instead of uploading. */
    struct vct_resident *resident;
    /* Tuning chosen from the device type (see parallel/primitives.c). */
    size_t scan_group_size;
    size_t scan_groups;
    int radix_bits;
    /* The frame every renderer writes (frame/frame.c). */
    cl_mem frame;
    int frame_size[2];
    int frame_device_only; /* renders return no host copy */
    int gl_shared;         /* created with an OpenGL context (frame/gl_share.c) */
    /* The running sums of scenes rendered without a device scene (a
     * committed scene keeps its own: scene/scene_resident.h). */
    vct_accumulation accumulation;
    /* The band of a taller image the current render draws (vct_render_job
     * band): its first row and the whole image's height, 0 for none. */
    int band_first, band_height;
    /* Photon mapping in bands: the largest radii of pass `pass` (float
     * bits, per map) in, the whole image's out; non-zero when the other
     * bands stopped. NULL: the band stands alone. */
    int (*band_sync)(void *user, uint32_t pass, uint32_t radius_bits[2]);
    void *band_sync_user;
    long launch_count; /* kernels launched on this context (runtime/launch.c) */
    /* What higher stages keep in the context, released with it: each stage
     * registers its own release, so the runtime calls up into none of them. */
    vct_release_hook release_hooks[VCT_MAX_RELEASE_HOOKS];
    int release_hook_count;
    /* Program cache statistics, for reporting cold/warm starts. */
    int cache_hits, cache_misses;
    double build_ms;
    vct_log_fn log;
    void *log_user;
};

/* Opens a context on the device `selector` picks (as vct_context_create),
 * with `extra` context properties (0-terminated pairs, may be NULL); fails
 * when the device lacks `required_extension` (may be NULL). */
vct_context *vct_context_open(const char *selector, const cl_context_properties *extra,
                              const char *required_extension, vct_error *err);
/* The device `selector` names (as vct_context_create): its index, or -1
 * with err filled. */
int vct_device_pick(const char *selector, cl_platform_id *platform, cl_device_id *device,
                    vct_error *err);
/* Fills `info` (index -1 when the device is not in the platform list). */
void vct_device_describe(cl_platform_id platform, cl_device_id device, int index,
                         vct_device_info *info);
/* The index of `device` in vct_list_devices' order, or -1. */
int vct_device_index(cl_device_id device);
/* Registers `hook` (once) to run when the context is destroyed. */
void vct_context_on_release(vct_context *ctx, vct_release_hook hook);

#endif
