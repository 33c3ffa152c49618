/* Kernel arguments bound by name: with $VCT_CHECK_ARGS=1 (every test runs
 * with it) programs keep their parameter names (-cl-kernel-arg-info) and
 * each argument the host sets is checked against the kernel's parameter at
 * that position, so that host and kernel cannot drift apart unseen. */
#ifndef VCT_RUNTIME_ARG_CHECK_H
#define VCT_RUNTIME_ARG_CHECK_H

#include "runtime/error.h"

int vct_args_checked(void);
/* `bound` is what VCT_ARG_OF or VCT_ARG wrote: the host expression (or the
 * parameter's name), " at ", the file and line. Its last identifier must be
 * parameter `index`'s name; "" is not checked. */
int vct_check_arg(vct_error *err, const char *stage, cl_kernel kernel, cl_uint index,
                  const char *bound);

#endif
