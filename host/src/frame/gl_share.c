/* OpenGL interop (cl_khr_gl_sharing on GLX): a context that shares objects
 * with the caller's GL context, and the frame copied into a GL buffer object
 * on the device, between acquire and release. */
#include <CL/cl_gl.h>

#include "runtime/runtime.h"

#define STAGE "display"

vct_context *vct_context_create_gl(const char *selector, void *glx_context, void *x_display,
                                   vct_error *err) {
    if (!glx_context || !x_display) {
        vct_fail(err, VCT_ERR_INPUT, "context: OpenGL sharing needs a GLX context and display");
        return NULL;
    }
    const cl_context_properties gl[] = {CL_GL_CONTEXT_KHR, (cl_context_properties)glx_context,
                                        CL_GLX_DISPLAY_KHR, (cl_context_properties)x_display, 0};
    vct_context *ctx = vct_context_open(selector, gl, "cl_khr_gl_sharing", err);
    if (ctx)
        ctx->gl_shared = 1;
    return ctx;
}

int vct_context_shares_gl(const vct_context *ctx) {
    return ctx->gl_shared;
}

vct_status vct_frame_to_gl_buffer(vct_context *ctx, unsigned gl_buffer, vct_error *err) {
    if (!ctx->gl_shared)
        return vct_fail(err, VCT_ERR_INPUT,
                        "%s: this context shares nothing with OpenGL (vct_context_create_gl)",
                        STAGE);
    if (!ctx->frame)
        return vct_fail(err, VCT_ERR_INPUT, "%s: nothing has been rendered yet", STAGE);
    const size_t bytes = 16 * (size_t)ctx->frame_size[0] * (size_t)ctx->frame_size[1];
    cl_int rc = CL_SUCCESS;
    cl_mem shared = clCreateFromGLBuffer(ctx->context, CL_MEM_WRITE_ONLY, gl_buffer, &rc);
    if (rc != CL_SUCCESS)
        return vct_cl_check(err, rc, STAGE, "clCreateFromGLBuffer");
    size_t size = 0;
    rc = clGetMemObjectInfo(shared, CL_MEM_SIZE, sizeof size, &size, NULL);
    int status = vct_cl_check(err, rc, STAGE, "clGetMemObjectInfo");
    if (status == VCT_OK && size < bytes)
        status = vct_fail(err, VCT_ERR_INPUT,
                          "%s: the GL buffer holds %zu bytes, the %dx%d frame needs %zu", STAGE,
                          size, ctx->frame_size[0], ctx->frame_size[1], bytes);
    /* GL is done with the buffer (the caller's glFinish); CL owns it from
     * acquire to release, and clFinish hands it back complete. */
    if (status == VCT_OK)
        status = vct_cl_check(err, clEnqueueAcquireGLObjects(ctx->queue, 1, &shared, 0, NULL, NULL),
                              STAGE, "clEnqueueAcquireGLObjects");
    if (status == VCT_OK) {
        status = vct_cl_check(
            err, clEnqueueCopyBuffer(ctx->queue, ctx->frame, shared, 0, 0, bytes, 0, NULL, NULL),
            STAGE, "clEnqueueCopyBuffer");
        const int released =
            vct_cl_check(status == VCT_OK ? err : NULL,
                         clEnqueueReleaseGLObjects(ctx->queue, 1, &shared, 0, NULL, NULL), STAGE,
                         "clEnqueueReleaseGLObjects");
        if (status == VCT_OK)
            status = released;
    }
    const int finished =
        vct_cl_check(status == VCT_OK ? err : NULL, clFinish(ctx->queue), STAGE, "clFinish");
    if (status == VCT_OK)
        status = finished;
    clReleaseMemObject(shared);
    return status;
}
