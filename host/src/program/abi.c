/* The kernel interface as the host sees it: the shared structs' layouts,
 * checked at compile time against the table in kernels/vct_types.h, and
 * the versions. */
#include <stddef.h>

#include "program/abi.h"
#include "vct_types.h"

#define CHECK_SIZE(T, size) _Static_assert(sizeof(T) == (size), "layout of " #T " changed");
#define CHECK_FIELD(T, f, offset)                                                                  \
    _Static_assert(offsetof(T, f) == (offset), "offset of " #T "." #f " changed");
VCT_ABI_LAYOUT(CHECK_SIZE, CHECK_FIELD)

#define COUNT_ENTRY(T, x) +1
#define COUNT_FIELD(T, f, offset) +1
enum { ABI_ENTRIES = 0 VCT_ABI_LAYOUT(COUNT_ENTRY, COUNT_FIELD) };

int vct_abi_layout_count(void) {
    return 1 + ABI_ENTRIES;
}

int vct_abi_layout_host(uint32_t *out, int max) {
    int n = 0;
#define HOST_SIZE(T, size)                                                                         \
    if (n < max)                                                                                   \
        out[n] = (uint32_t)sizeof(T);                                                              \
    ++n;
#define HOST_FIELD(T, f, offset)                                                                   \
    if (n < max)                                                                                   \
        out[n] = (uint32_t)offsetof(T, f);                                                         \
    ++n;
    if (n < max)
        out[n] = VCT_KERNEL_ABI_VERSION;
    ++n;
    VCT_ABI_LAYOUT(HOST_SIZE, HOST_FIELD)
    return n;
}

const char *vct_abi_layout_name(int index) {
    static const char *names[] = {"VCT_KERNEL_ABI_VERSION",
#define NAME_SIZE(T, size) "sizeof(" #T ")",
#define NAME_FIELD(T, f, offset) "offsetof(" #T ", " #f ")",
                                  VCT_ABI_LAYOUT(NAME_SIZE, NAME_FIELD)};
    return index >= 0 && index < (int)(sizeof names / sizeof names[0]) ? names[index] : "?";
}

const char *vct_version(void) {
    return VCT_VERSION_STRING;
}

int vct_kernel_abi_version(void) {
    return VCT_KERNEL_ABI_VERSION;
}
