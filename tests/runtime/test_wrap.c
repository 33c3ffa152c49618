/* vct_context_wrap: the engine on the caller's own context and queue. It
 * renders what a context of its own renders, bit for bit; it releases none
 * of the caller's handles; NULL and mismatched handles are refused with a
 * message, never a crash. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "check.h"

static vct_image render(vct_context *ctx, const vct_scene *s) {
    vct_error err = {0};
    vct_accel *g = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    vct_render_job job = vct_render_job_default(VCT_METHOD_RAYCAST, 96, 64);
    job.scene = s;
    job.accel = g;
    vct_image im;
    REQUIRE_OK(vct_render(ctx, &job, &im, NULL, &err), err);
    vct_accel_release(g);
    return im;
}

static cl_uint ref_count_queue(cl_command_queue q) {
    cl_uint n = 0;
    clGetCommandQueueInfo(q, CL_QUEUE_REFERENCE_COUNT, sizeof n, &n, NULL);
    return n;
}

/* A queue's reference count is a snapshot: the platform may still hold one
 * for a command it is retiring on its own threads (seen on PoCL under load).
 * Waits up to a second for the count to come back to `want`. */
static void settle_refs(cl_command_queue q, cl_uint want) {
    clFinish(q);
    for (int i = 0; i < 1000 && ref_count_queue(q) != want; ++i)
        nanosleep(&(struct timespec){0, 1000000}, NULL);
}

static cl_uint ref_count_context(cl_context c) {
    cl_uint n = 0;
    clGetContextInfo(c, CL_CONTEXT_REFERENCE_COUNT, sizeof n, &n, NULL);
    return n;
}

static void expect_refused(vct_context *ctx, const vct_error *err, const char *words,
                           const char *what) {
    CHECK(ctx == NULL, "%s: accepted", what);
    CHECK(err->status == VCT_ERR_INPUT, "%s: status %d", what, (int)err->status);
    CHECK(strstr(err->message, words) != NULL, "%s: message \"%s\" lacks \"%s\"", what,
          err->message, words);
    vct_context_release(ctx);
}

int main(void) {
    vct_error err = {0};
    vct_scene *s = check_cornell_box();
    vct_context *own = check_context();
    const vct_image reference = render(own, s);
    cl_device_id device = vct_context_cl_device(own);
    cl_int rc = CL_SUCCESS;
    cl_context context = clCreateContext(NULL, 1, &device, NULL, NULL, &rc);
    CHECK(rc == CL_SUCCESS, "clCreateContext: %d", rc);
    cl_command_queue queue = clCreateCommandQueue(context, device, CL_QUEUE_PROFILING_ENABLE, &rc);
    CHECK(rc == CL_SUCCESS, "clCreateCommandQueue: %d", rc);
    const cl_uint queue_refs = ref_count_queue(queue), context_refs = ref_count_context(context);

    vct_context *wrapped = vct_context_wrap(context, device, queue, &err);
    REQUIRE_OK(wrapped ? VCT_OK : err.status, err);
    CHECK(vct_context_cl_queue(wrapped) == queue && vct_context_cl_context(wrapped) == context,
          "the wrapped context runs on other handles");
    CHECK(strcmp(vct_context_device(wrapped)->name, vct_context_device(own)->name) == 0,
          "device described as %s", vct_context_device(wrapped)->name);
    vct_image im = render(wrapped, s);
    CHECK(im.width == reference.width && im.height == reference.height &&
              memcmp(im.rgba, reference.rgba, 16ull * im.width * im.height) == 0,
          "the wrapped context's image differs from the engine's own context's");
    vct_image_release(&im);
    vct_context_release(wrapped);
    settle_refs(queue, queue_refs);
    CHECK(ref_count_queue(queue) == queue_refs, "queue references %u, were %u",
          ref_count_queue(queue), queue_refs);
    CHECK(ref_count_context(context) == context_refs, "context references %u, were %u",
          ref_count_context(context), context_refs);
    /* The caller's queue still works after the engine is gone. */
    CHECK(clFinish(queue) == CL_SUCCESS, "the caller's queue no longer works");

    /* A queue without profiling: the same image; stages have host time only. */
    cl_command_queue plain = clCreateCommandQueue(context, device, 0, &rc);
    wrapped = vct_context_wrap(context, device, plain, &err);
    REQUIRE_OK(wrapped ? VCT_OK : err.status, err);
    im = render(wrapped, s);
    CHECK(memcmp(im.rgba, reference.rgba, 16ull * im.width * im.height) == 0,
          "image without profiling differs");
    const vct_stage_stat *st;
    const int stages = vct_stats(wrapped, &st);
    double device_ms = 0, host_ms = 0;
    for (int i = 0; i < stages; ++i)
        device_ms += st[i].device_ms, host_ms += st[i].host_ms;
    CHECK(stages > 0 && device_ms == 0.0 && host_ms > 0.0,
          "%d stages, %g device ms, %g host ms without profiling", stages, device_ms, host_ms);
    vct_image_release(&im);
    vct_context_release(wrapped);

    /* Refused handles. */
    err = (vct_error){0};
    expect_refused(vct_context_wrap(NULL, device, queue, &err), &err, "NULL context", "no context");
    err = (vct_error){0};
    expect_refused(vct_context_wrap(context, NULL, queue, &err), &err, "NULL device", "no device");
    err = (vct_error){0};
    expect_refused(vct_context_wrap(context, device, NULL, &err), &err, "NULL queue", "no queue");
    cl_context other = clCreateContext(NULL, 1, &device, NULL, NULL, &rc);
    err = (vct_error){0};
    expect_refused(vct_context_wrap(other, device, queue, &err), &err, "another OpenCL context",
                   "a queue of another context");
    cl_command_queue ooo =
        clCreateCommandQueue(context, device, CL_QUEUE_OUT_OF_ORDER_EXEC_MODE_ENABLE, &rc);
    if (rc == CL_SUCCESS) {
        err = (vct_error){0};
        expect_refused(vct_context_wrap(context, device, ooo, &err), &err, "out of order",
                       "an out-of-order queue");
        clReleaseCommandQueue(ooo);
    } else {
        printf("test_wrap: this device has no out-of-order queues; that refusal is not tried\n");
    }

    clReleaseContext(other);
    clReleaseCommandQueue(plain);
    clReleaseCommandQueue(queue);
    clReleaseContext(context);
    vct_image_release((vct_image *)&reference);
    vct_context_release(own);
    vct_scene_release(s);
    return check_exit("test_wrap");
}
