/* Parallel primitives' host-side helpers (the primitives are public, vct/parallel.h). */
#ifndef VCT_PARALLEL_PARALLEL_H
#define VCT_PARALLEL_PARALLEL_H

#include <stdint.h>

/* Sort key bits that tell `count` values apart (1 to 32). */
int vct_key_bits_for(uint64_t count);

#endif
