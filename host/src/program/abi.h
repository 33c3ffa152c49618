/* The kernel interface's layout table (kernels/vct_types.h) on the host,
 * in the order kernels/runtime/abi_layout.cl writes the device's. */
#ifndef VCT_RUNTIME_ABI_H
#define VCT_RUNTIME_ABI_H

#include <stdint.h>

#include "vct/version.h"

/* Entries in the table: the version, then each size and offset. */
int vct_abi_layout_count(void);
/* The host's values (up to max); returns the count. */
int vct_abi_layout_host(uint32_t *out, int max);
/* What entry `index` is, for messages. */
const char *vct_abi_layout_name(int index);

#endif
