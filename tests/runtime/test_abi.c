/* The kernel interface: the device's layout of every shared struct (written
 * back by kernels/runtime/abi_layout.cl) equals the host's, field by field,
 * and the kernels carry the ABI version the library reports. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "program/abi.h"
#include "runtime/runtime.h"

int main(void) {
    vct_error err = {0};
    vct_context *ctx = check_context();
    const int n = vct_abi_layout_count();
    CHECK(n > 30, "the layout table has %d entries", n);
    uint32_t *host = calloc((size_t)n, sizeof *host);
    uint32_t *device = calloc((size_t)n, sizeof *device);
    CHECK(vct_abi_layout_host(host, n) == n, "host table size");

    cl_program program;
    REQUIRE_OK(vct_program_get(ctx, "runtime/abi_layout.cl", "", &program, &err), err);
    cl_mem out = vct_buffer_create(ctx, "abi", "layout", sizeof *device * (size_t)n,
                                   CL_MEM_READ_WRITE, NULL, &err);
    REQUIRE_OK(out ? VCT_OK : err.status, err);
    REQUIRE_OK(vct_buffer_fill_u32(ctx, "abi", out, 0xdeadbeefu, (size_t)n, &err), err);
    REQUIRE_OK(vct_run_kernel(ctx, program, "vct_abi_layout", "abi", 1, &err, 1, VCT_ARG_OF(out)),
               err);
    REQUIRE_OK(vct_buffer_read(ctx, "abi", out, 0, sizeof *device * (size_t)n, device, &err), err);
    for (int i = 0; i < n; ++i)
        CHECK(device[i] == host[i], "%s: device %u, host %u", vct_abi_layout_name(i), device[i],
              host[i]);
    CHECK(device[0] == (uint32_t)vct_kernel_abi_version(), "kernel ABI %u, library reports %d",
          device[0], vct_kernel_abi_version());

    /* The library's version is the header's. */
    CHECK(strcmp(vct_version(), VCT_VERSION_STRING) == 0, "vct_version %s, header %s",
          vct_version(), VCT_VERSION_STRING);
    vct_buffer_release(ctx, out);
    vct_context_release(ctx);
    free(host);
    free(device);
    return check_exit("test_abi");
}
