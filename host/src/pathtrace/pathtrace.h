/* The path tracer in three steps, for callers that hand out samples
 * themselves (a device group): begin (inputs and running sums), run
 * (samples [first, first + count) into the sums) and end (the frame). */
#ifndef VCT_RENDER_PATHTRACE_H
#define VCT_RENDER_PATHTRACE_H

#include "runtime/runtime.h"
#include "light/emitters.h"
#include "scene/scene_device.h"
#include "vct/partial.h"

/* Per pixel: exact sums of red, green, blue, the count of samples kept and
 * the squares of their luminance, then of the direct part's (red, green,
 * blue, squared luminance) and the indirect part's squared luminance
 * (kernels/render/pathtrace.cl, exact_sum.h), 16 bytes each. */
#define VCT_PT_ACCUM_BYTES VCT_SAMPLE_SUM_BYTES

typedef struct vct_pt_session {
    vct_context *ctx;
    const vct_pathtrace_options *opt;
    vct_accumulation *acc; /* the running sums this session adds to */
    cl_program program;
    cl_kernel kernel;
    vct_scene_buffers sb;
    vct_emitters eb;
} vct_pt_session;

/* Drops the path tracer's running sums in acc. */
void vct_pt_sums_release(vct_context *ctx, vct_accumulation *acc);
/* Opens the stage; the running sums are kept when opt->resume allows. */
int vct_pt_begin(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                 const vct_pathtrace_options *opt, vct_pt_session *pt, vct_error *err);
/* Queues samples [first, first + count), opt->samples_per_pass per launch;
 * wait: also waits for them. */
int vct_pt_run(vct_pt_session *pt, uint32_t first, uint32_t count, int wait, vct_error *err);
/* The session's running sums (VCT_PT_ACCUM_BYTES per pixel) and the count
 * of samples it dropped, read into host memory. */
int vct_pt_sums_read(vct_pt_session *pt, void *sums, uint32_t *discarded, vct_error *err);
/* Resolves `sums` (NULL: the session's own; else a buffer of the same
 * layout) into the frame and delivers it into `image` (NULL: neither), then
 * closes the stage. rc: how the samples went; on failure the running sums
 * are dropped. */
int vct_pt_end(vct_pt_session *pt, int rc, cl_mem sums, vct_image *image,
               vct_pathtrace_result *result, vct_error *err);

#endif
