/* vct: errors: every call reports failure through a vct_error the caller owns. */
#ifndef VCT_API_ERROR_H
#define VCT_API_ERROR_H

#include "vct/export.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum vct_status {
    VCT_OK = 0,
    VCT_ERR_OPENCL,   /* an OpenCL call failed */
    VCT_ERR_INPUT,    /* the scene or an option is invalid */
    VCT_ERR_MEMORY,   /* a buffer would not fit the device or host */
    VCT_ERR_IO,       /* a file could not be read or written */
    VCT_ERR_OVERFLOW, /* a count exceeded what the structure can index */
} vct_status;

typedef struct vct_error {
    vct_status status;
    char message[2048];
} vct_error;

/* The status's name ("VCT_ERR_INPUT"), or "unknown status" for a value
 * outside the enum; the message in vct_error says what happened. */
VCT_API const char *vct_status_string(vct_status status);

#ifdef __cplusplus
}
#endif
#endif
