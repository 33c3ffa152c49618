/* Kernel arguments checked against the kernel's parameter names. */
#include <ctype.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "program/arg_check.h"

int vct_args_checked(void) {
    const char *v = getenv("VCT_CHECK_ARGS");
    return v && v[0] == '1';
}

/* The last identifier before " at " ("b->nodes at f.c:3" binds nodes). */
static void bound_name(const char *bound, char *out, size_t size) {
    const char *at = strstr(bound, " at ");
    const char *end = at ? at : bound + strlen(bound), *start = end;
    while (start > bound && (isalnum((unsigned char)start[-1]) || start[-1] == '_'))
        --start;
    snprintf(out, size, "%.*s", (int)(end - start), start);
}

/* With $VCT_ARG_LOG naming a file, each kernel whose arguments were checked
 * is appended to it once per process: tools/arg_coverage.py compares the
 * suite's log with every kernel the sources define. */
static void log_checked(cl_kernel kernel) {
    static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
    static char seen[256][64];
    static int seen_count;
    const char *path = getenv("VCT_ARG_LOG");
    char name[64] = "";
    if (!path || !path[0] ||
        clGetKernelInfo(kernel, CL_KERNEL_FUNCTION_NAME, sizeof name, name, NULL) != CL_SUCCESS)
        return;
    pthread_mutex_lock(&lock);
    int known = 0;
    for (int i = 0; i < seen_count && !known; ++i)
        known = strcmp(seen[i], name) == 0;
    if (!known && seen_count < 256) {
        snprintf(seen[seen_count++], sizeof seen[0], "%s", name);
        FILE *f = fopen(path, "a");
        if (f) {
            fprintf(f, "%s\n", name);
            fclose(f);
        }
    }
    pthread_mutex_unlock(&lock);
}

int vct_check_arg(vct_error *err, const char *stage, cl_kernel kernel, cl_uint index,
                  const char *bound) {
    if (!bound[0] || !vct_args_checked())
        return VCT_OK;
    char param[128] = "", name[128], kernel_name[64] = "?";
    if (clGetKernelArgInfo(kernel, index, CL_KERNEL_ARG_NAME, sizeof param, param, NULL) !=
        CL_SUCCESS)
        return vct_fail(err, VCT_ERR_OPENCL,
                        "%s: argument %u's name is not known: the program was built without "
                        "-cl-kernel-arg-info",
                        stage, index);
    bound_name(bound, name, sizeof name);
    /* some compilers prefix names that are also built-in functions (step) */
    const char *p = strncmp(param, "_cl_", 4) == 0 ? param + 4 : param;
    if (strcmp(p, name) == 0) {
        log_checked(kernel);
        return VCT_OK;
    }
    clGetKernelInfo(kernel, CL_KERNEL_FUNCTION_NAME, sizeof kernel_name, kernel_name, NULL);
    return vct_fail(err, VCT_ERR_INPUT,
                    "%s: kernel %s's argument %u is \"%s\" but the host binds %s there: the "
                    "host's arguments have drifted from the kernel's",
                    stage, kernel_name, index, p, bound);
}
