/* The device's own layout of the shared structs (vct_types.h), written back
 * so that a host can compare it with its own: out[0] = VCT_KERNEL_ABI_VERSION,
 * then, in VCT_ABI_LAYOUT's order, each struct's size and each field's
 * offset in bytes. One work-item; out holds 1 + VCT_ABI_LAYOUT's entries. */
#include "vct_types.h"

#define ABI_SIZE(T, size) out[n++] = (uint)sizeof(T);
#define ABI_FIELD(T, f, offset)                                                                    \
    {                                                                                              \
        T probe;                                                                                   \
        out[n++] = (uint)((__private char *)&probe.f - (__private char *)&probe);                  \
    }

__kernel void vct_abi_layout(__global uint *out) {
    if (get_global_id(0) != 0)
        return;
    uint n = 0;
    out[n++] = VCT_KERNEL_ABI_VERSION;
    VCT_ABI_LAYOUT(ABI_SIZE, ABI_FIELD)
}
