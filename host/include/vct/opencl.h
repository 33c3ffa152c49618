/* vct: running on the caller's own OpenCL objects.
 *
 * For hosts that already have a context and a queue: the engine enqueues
 * its work on that queue and creates no context or queue of its own. Every
 * buffer, program and kernel it creates it releases in vct_context_release;
 * it never releases the handles given here, which must outlive the
 * vct_context. */
#ifndef VCT_API_OPENCL_H
#define VCT_API_OPENCL_H

#include "vct/export.h"

#ifndef CL_TARGET_OPENCL_VERSION
#define CL_TARGET_OPENCL_VERSION 120
#endif
#include <CL/cl.h>

#include "vct/device.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A context on `device` of `context`, enqueueing on `queue`, which must be
 * an in-order queue of that context and device (profiling enabled for
 * device times in the statistics; without it stages report host time).
 * NULL handles, a device outside the context or a queue of another context
 * or device are refused with VCT_ERR_INPUT and a message saying which. */
VCT_API vct_context *vct_context_wrap(cl_context context, cl_device_id device,
                                      cl_command_queue queue, vct_error *err);
/* The OpenCL objects a context runs on (its own, or those it wraps). */
VCT_API cl_context vct_context_cl_context(const vct_context *ctx);
VCT_API cl_device_id vct_context_cl_device(const vct_context *ctx);
VCT_API cl_command_queue vct_context_cl_queue(const vct_context *ctx);

#ifdef __cplusplus
}
#endif
#endif
