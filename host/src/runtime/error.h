/* Errors: messages that name the stage, the call and what to do. */
#ifndef VCT_RUNTIME_ERROR_H
#define VCT_RUNTIME_ERROR_H

#define CL_TARGET_OPENCL_VERSION 120
#include <CL/cl.h>

#include "vct/vct.h"

#define VCT_PI_F 3.14159265358979f

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

#endif
