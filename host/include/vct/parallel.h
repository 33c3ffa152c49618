/* vct: parallel primitives on device buffers (cl_mem passed as void*). */
#ifndef VCT_API_PARALLEL_H
#define VCT_API_PARALLEL_H

#include "vct/export.h"

#include <stdint.h>

#include "vct/device.h"

#ifdef __cplusplus
extern "C" {
#endif

/* out[i] = sum of in[0..i) (exclusive) or in[0..i] (inclusive); n may be 0.
 * total receives the sum of all n inputs; a total above UINT32_MAX fails with
 * VCT_ERR_OVERFLOW instead of wrapping. in and out may be the same buffer. */
VCT_API vct_status vct_scan_u32(vct_context *ctx, void *in_mem, void *out_mem, uint32_t n,
                                int inclusive, uint64_t *total, vct_error *err);
/* out receives in[i] for every i with flags[i] != 0, in order; count returned. */
VCT_API vct_status vct_compact_u32(vct_context *ctx, void *in_mem, void *flags_mem, void *out_mem,
                                   uint32_t n, uint32_t *count, vct_error *err);
/* Stable LSD radix sort of (key, value) pairs on the low key_bits bits. */
VCT_API vct_status vct_sort_pairs_u32(vct_context *ctx, void *keys_mem, void *values_mem,
                                      uint32_t n, int key_bits, vct_error *err);
VCT_API vct_status vct_sort_pairs_u64(vct_context *ctx, void *keys_mem, void *values_mem,
                                      uint32_t n, int key_bits, vct_error *err);
/* keys sorted; sums float4 values of equal-key runs in input order.
 * Writes unique keys and their sums; returns the number of runs. */
VCT_API vct_status vct_segmented_sum_f4(vct_context *ctx, void *keys_mem, void *values_mem,
                                        uint32_t n, void *out_keys_mem, void *out_sums_mem,
                                        uint32_t *runs, vct_error *err);

#ifdef __cplusplus
}
#endif
#endif
