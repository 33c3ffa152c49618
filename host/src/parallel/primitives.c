/* Host side of the parallel primitives: scan, compaction, radix sort and
 * segmented sum. Buffers are the caller's; temporaries live for one call. */
#include <stdio.h>
#include <string.h>

#include "runtime/runtime.h"
#include "parallel/parallel.h"

#define STAGE "primitives"

static size_t scan_item_span(const vct_context *ctx) {
    return ctx->scan_group_size == 1 ? 1024 : 8;
}

static int scan_program(vct_context *ctx, cl_program *p, vct_error *err) {
    char opts[128];
    snprintf(opts, sizeof opts, "-D WG=%zu -D ITEM_SPAN=%zu", ctx->scan_group_size,
             scan_item_span(ctx));
    return vct_program_get(ctx, "parallel/scan.cl", opts, p, err);
}

/* Splits n elements into at most ctx->scan_groups spans aligned to `tile`. */
static void split(const vct_context *ctx, uint32_t n, size_t tile, uint32_t *span,
                  uint32_t *groups) {
    uint64_t per = ((uint64_t)n + ctx->scan_groups - 1) / ctx->scan_groups;
    per = (per + tile - 1) / tile * tile;
    if (per == 0)
        per = tile;
    *span = (uint32_t)per;
    *groups = (uint32_t)(((uint64_t)n + per - 1) / per);
    if (*groups == 0)
        *groups = 1;
}

static int scan_impl(vct_context *ctx, cl_mem in, cl_mem out, uint32_t n, int inclusive,
                     int as_flags, uint64_t *total_out, vct_error *err) {
    if (n == 0) {
        if (total_out)
            *total_out = 0;
        return VCT_OK;
    }
    cl_program p;
    int rc = scan_program(ctx, &p, err);
    if (rc)
        return rc;
    const size_t wg = ctx->scan_group_size;
    uint32_t span, groups;
    split(ctx, n, wg * scan_item_span(ctx), &span, &groups);
    cl_mem sums = vct_buffer_create(ctx, STAGE, "scan group sums", (groups + 1) * sizeof(cl_ulong),
                                    CL_MEM_READ_WRITE, NULL, err);
    if (!sums)
        return err->status;
    cl_kernel reduce = vct_kernel_create(ctx, p, "scan_reduce", err);
    cl_kernel offsets = reduce ? vct_kernel_create(ctx, p, "scan_group_offsets", err) : NULL;
    cl_kernel down = offsets ? vct_kernel_create(ctx, p, "scan_downsweep", err) : NULL;
    rc = down ? VCT_OK : (int)err->status;
    cl_uint flags = (cl_uint)as_flags, incl = (cl_uint)inclusive;
#define TRY(x)                                                                                     \
    do {                                                                                           \
        if (rc == VCT_OK)                                                                          \
            rc = (x);                                                                              \
    } while (0)
    TRY(vct_set_args(err, STAGE, reduce, 0, 5, VCT_ARG_OF(in), VCT_ARG_OF(n), VCT_ARG_OF(span),
                     VCT_ARG(as_flags, flags), VCT_ARG(group_sums, sums)));
    TRY(vct_launch(ctx, reduce, groups * wg, wg, err));
    TRY(vct_set_args(err, STAGE, offsets, 0, 2, VCT_ARG_OF(sums), VCT_ARG_OF(groups)));
    TRY(vct_launch(ctx, offsets, 1, 1, err));
    TRY(vct_set_args(err, STAGE, down, 0, 7, VCT_ARG_OF(in), VCT_ARG_OF(out), VCT_ARG_OF(n),
                     VCT_ARG_OF(span), VCT_ARG(as_flags, flags), VCT_ARG(inclusive, incl),
                     VCT_ARG(group_offsets, sums)));
    TRY(vct_launch(ctx, down, groups * wg, wg, err));
    /* The total costs a blocking read: only callers that need it (to size
     * an output, or because it may overflow) pass total_out. */
    cl_ulong total = 0;
    if (total_out)
        TRY(vct_buffer_read(ctx, STAGE, sums, groups * sizeof(cl_ulong), sizeof total, &total,
                            err));
#undef TRY
    if (reduce)
        clReleaseKernel(reduce);
    if (offsets)
        clReleaseKernel(offsets);
    if (down)
        clReleaseKernel(down);
    vct_buffer_release(ctx, sums);
    if (rc)
        return rc;
    if (total_out)
        *total_out = total;
    if (total > UINT32_MAX)
        return vct_fail(err, VCT_ERR_OVERFLOW,
                        "scan: the total %llu of %u values exceeds 32 bits, so offsets would "
                        "wrap: split the input or lower the resolution",
                        (unsigned long long)total, n);
    return VCT_OK;
}

vct_status vct_scan_u32(vct_context *ctx, void *in_mem, void *out_mem, uint32_t n, int inclusive,
                        uint64_t *total, vct_error *err) {
    uint64_t sum = 0; /* always read: overflow must be reported */
    int rc = scan_impl(ctx, (cl_mem)in_mem, (cl_mem)out_mem, n, inclusive, 0, &sum, err);
    if (total)
        *total = sum;
    return rc;
}

vct_status vct_compact_u32(vct_context *ctx, void *in_mem, void *flags_mem, void *out_mem,
                           uint32_t n, uint32_t *count, vct_error *err) {
    *count = 0;
    if (n == 0)
        return VCT_OK;
    cl_mem offsets = vct_buffer_create(ctx, STAGE, "compaction offsets", (size_t)n * 4,
                                       CL_MEM_READ_WRITE, NULL, err);
    if (!offsets)
        return err->status;
    uint64_t total = 0;
    int rc = scan_impl(ctx, (cl_mem)flags_mem, offsets, n, 0, 1, &total, err);
    cl_program p;
    if (rc == VCT_OK)
        rc = scan_program(ctx, &p, err);
    cl_kernel k = rc == VCT_OK ? vct_kernel_create(ctx, p, "compact_scatter", err) : NULL;
    if (rc == VCT_OK && !k)
        rc = err->status;
    if (rc == VCT_OK) {
        cl_mem in = in_mem, flags = flags_mem, out = out_mem;
        rc = vct_set_args(err, STAGE, k, 0, 5, VCT_ARG_OF(in), VCT_ARG_OF(flags),
                          VCT_ARG_OF(offsets), VCT_ARG_OF(n), VCT_ARG_OF(out));
        if (rc == VCT_OK)
            rc = vct_launch(ctx, k, n, 0, err);
    }
    if (k)
        clReleaseKernel(k);
    vct_buffer_release(ctx, offsets);
    *count = (uint32_t)total;
    return rc;
}

static int sort_impl(vct_context *ctx, cl_mem keys, cl_mem values, uint32_t n, int key_bits,
                     int key64, vct_error *err) {
    const int max_bits = key64 ? 64 : 32;
    if (key_bits <= 0 || key_bits > max_bits)
        key_bits = max_bits;
    if (n <= 1)
        return VCT_OK;
    const size_t key_size = key64 ? 8 : 4;
    const size_t wg = ctx->scan_group_size;
    const int bits = ctx->radix_bits;
    const uint32_t radix = 1u << bits;
    char opts[128];
    snprintf(opts, sizeof opts, "-D KEY_T=%s -D RADIX_BITS=%d -D WG=%zu", key64 ? "ulong" : "uint",
             bits, wg);
    cl_program p;
    int rc = vct_program_get(ctx, "parallel/radix_sort.cl", opts, &p, err);
    if (rc)
        return rc;
    uint32_t span, groups;
    split(ctx, n, wg, &span, &groups);
    const uint32_t hist_n = radix * groups;
    cl_mem keys_tmp =
        vct_buffer_create(ctx, STAGE, "sort keys", n * key_size, CL_MEM_READ_WRITE, NULL, err);
    cl_mem values_tmp = keys_tmp ? vct_buffer_create(ctx, STAGE, "sort values", n * 4ull,
                                                     CL_MEM_READ_WRITE, NULL, err)
                                 : NULL;
    cl_mem hist = values_tmp ? vct_buffer_create(ctx, STAGE, "sort histogram", hist_n * 4ull,
                                                 CL_MEM_READ_WRITE, NULL, err)
                             : NULL;
    cl_kernel histogram = hist ? vct_kernel_create(ctx, p, "radix_histogram", err) : NULL;
    cl_kernel scatter = histogram ? vct_kernel_create(ctx, p, "radix_scatter", err) : NULL;
    rc = scatter ? VCT_OK : (int)err->status;
    cl_mem src_k = keys, src_v = values, dst_k = keys_tmp, dst_v = values_tmp;
    for (int shift = 0; rc == VCT_OK && shift < key_bits; shift += bits) {
        cl_uint sh = (cl_uint)shift;
        rc = vct_set_args(err, STAGE, histogram, 0, 6, VCT_ARG(keys, src_k), VCT_ARG_OF(n),
                          VCT_ARG_OF(span), VCT_ARG(shift, sh), VCT_ARG_OF(groups),
                          VCT_ARG_OF(hist));
        if (rc == VCT_OK)
            rc = vct_launch(ctx, histogram, groups * wg, wg, err);
        if (rc == VCT_OK)
            rc = scan_impl(ctx, hist, hist, hist_n, 0, 0, NULL, err); /* total is n */
        if (rc != VCT_OK)
            break;
        rc = vct_set_args(err, STAGE, scatter, 0, 9, VCT_ARG(keys_in, src_k),
                          VCT_ARG(values_in, src_v), VCT_ARG_OF(n), VCT_ARG_OF(span),
                          VCT_ARG(shift, sh), VCT_ARG_OF(groups), VCT_ARG(offsets, hist),
                          VCT_ARG(keys_out, dst_k), VCT_ARG(values_out, dst_v));
        if (rc == VCT_OK)
            rc = vct_launch(ctx, scatter, groups * wg, wg, err);
        cl_mem t = src_k;
        src_k = dst_k;
        dst_k = t;
        t = src_v;
        src_v = dst_v;
        dst_v = t;
    }
    if (rc == VCT_OK && src_k != keys) {
        cl_event e1 = NULL, e2 = NULL;
        rc = vct_cl_check(
            err, clEnqueueCopyBuffer(ctx->queue, src_k, keys, 0, 0, n * key_size, 0, NULL, &e1),
            STAGE, "clEnqueueCopyBuffer");
        if (rc == VCT_OK)
            rc = vct_record_event(ctx, e1, "copy", err);
        if (rc == VCT_OK)
            rc = vct_cl_check(
                err, clEnqueueCopyBuffer(ctx->queue, src_v, values, 0, 0, n * 4ull, 0, NULL, &e2),
                STAGE, "clEnqueueCopyBuffer");
        if (rc == VCT_OK)
            rc = vct_record_event(ctx, e2, "copy", err);
    }
    if (histogram)
        clReleaseKernel(histogram);
    if (scatter)
        clReleaseKernel(scatter);
    vct_buffer_release(ctx, hist);
    vct_buffer_release(ctx, values_tmp);
    vct_buffer_release(ctx, keys_tmp);
    return rc;
}

int vct_key_bits_for(uint64_t count) {
    int b = 1;
    while (b < 32 && (1ull << b) < count)
        ++b;
    return b;
}

vct_status vct_sort_pairs_u32(vct_context *ctx, void *keys_mem, void *values_mem, uint32_t n,
                              int key_bits, vct_error *err) {
    return sort_impl(ctx, (cl_mem)keys_mem, (cl_mem)values_mem, n, key_bits, 0, err);
}

vct_status vct_sort_pairs_u64(vct_context *ctx, void *keys_mem, void *values_mem, uint32_t n,
                              int key_bits, vct_error *err) {
    return sort_impl(ctx, (cl_mem)keys_mem, (cl_mem)values_mem, n, key_bits, 1, err);
}

vct_status vct_segmented_sum_f4(vct_context *ctx, void *keys_mem, void *values_mem, uint32_t n,
                                void *out_keys_mem, void *out_sums_mem, uint32_t *runs,
                                vct_error *err) {
    *runs = 0;
    if (n == 0)
        return VCT_OK;
    cl_program p;
    int rc = vct_program_get(ctx, "parallel/segmented_reduce.cl", "-D KEY_T=uint", &p, err);
    if (rc)
        return rc;
    cl_mem heads =
        vct_buffer_create(ctx, STAGE, "segment heads", n * 4ull, CL_MEM_READ_WRITE, NULL, err);
    cl_mem index = heads ? vct_buffer_create(ctx, STAGE, "segment index", n * 4ull,
                                             CL_MEM_READ_WRITE, NULL, err)
                         : NULL;
    cl_kernel k_heads = index ? vct_kernel_create(ctx, p, "segment_heads", err) : NULL;
    cl_kernel k_starts = k_heads ? vct_kernel_create(ctx, p, "segment_starts", err) : NULL;
    cl_kernel k_sum = k_starts ? vct_kernel_create(ctx, p, "segment_sum_f4", err) : NULL;
    rc = k_sum ? VCT_OK : (int)err->status;
    cl_mem keys = keys_mem, values = values_mem, out_keys = out_keys_mem, sums = out_sums_mem;
    uint64_t total = 0;
    if (rc == VCT_OK)
        rc = vct_set_args(err, STAGE, k_heads, 0, 3, VCT_ARG_OF(keys), VCT_ARG_OF(n),
                          VCT_ARG_OF(heads));
    if (rc == VCT_OK)
        rc = vct_launch(ctx, k_heads, n, 0, err);
    if (rc == VCT_OK)
        rc = scan_impl(ctx, heads, index, n, 0, 0, &total, err);
    cl_mem starts = NULL;
    if (rc == VCT_OK) {
        starts = vct_buffer_create(ctx, STAGE, "segment starts", total * 4ull, CL_MEM_READ_WRITE,
                                   NULL, err);
        rc = starts ? VCT_OK : (int)err->status;
    }
    if (rc == VCT_OK)
        rc = vct_set_args(err, STAGE, k_starts, 0, 6, VCT_ARG_OF(keys), VCT_ARG_OF(heads),
                          VCT_ARG(run_index, index), VCT_ARG_OF(n), VCT_ARG_OF(starts),
                          VCT_ARG(run_keys, out_keys));
    if (rc == VCT_OK)
        rc = vct_launch(ctx, k_starts, n, 0, err);
    cl_uint run_count = (cl_uint)total;
    if (rc == VCT_OK)
        rc = vct_set_args(err, STAGE, k_sum, 0, 5, VCT_ARG_OF(values), VCT_ARG_OF(starts),
                          VCT_ARG(runs, run_count), VCT_ARG_OF(n), VCT_ARG_OF(sums));
    if (rc == VCT_OK)
        rc = vct_launch(ctx, k_sum, run_count, 0, err);
    if (rc == VCT_OK)
        rc = vct_finish(ctx, STAGE, err);
    if (k_heads)
        clReleaseKernel(k_heads);
    if (k_starts)
        clReleaseKernel(k_starts);
    if (k_sum)
        clReleaseKernel(k_sum);
    vct_buffer_release(ctx, starts);
    vct_buffer_release(ctx, index);
    vct_buffer_release(ctx, heads);
    *runs = run_count;
    return rc;
}
