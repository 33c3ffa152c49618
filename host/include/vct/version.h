/* vct: the library's version and the kernel interface's. */
#ifndef VCT_API_VERSION_H
#define VCT_API_VERSION_H

#include "vct/export.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The library: major changes break the C API, minor ones add to it. */
#define VCT_VERSION_MAJOR 0
#define VCT_VERSION_MINOR 2
#define VCT_VERSION_PATCH 0
#define VCT_VERSION_STRING "0.2.0"

/* "major.minor.patch" of the library linked, which may differ from the
 * header's VCT_VERSION_STRING when a shared library was replaced. */
VCT_API const char *vct_version(void);
/* The kernel interface (kernels/README.md): VCT_KERNEL_ABI_VERSION of the
 * kernel sources this library was built with. */
VCT_API int vct_kernel_abi_version(void);
/* Where kernel sources are read from: a directory, or "(embedded)". */
VCT_API const char *vct_kernel_source_dir(void);

#ifdef __cplusplus
}
#endif
#endif
