/* Scan and radix sort throughput, each as a ratio to a device buffer copy of
 * the same bytes measured in the same run (device time from profiling
 * events, best of VCT_BENCH_REPEATS runs). */
#include "bench_util.h"

static double copy_ms(vct_context *ctx, cl_mem a, cl_mem b, size_t bytes) {
    double best = 1e30;
    for (int r = 0; r < bench_repeats(); ++r) {
        vct_stats_reset(ctx);
        vct_stage_begin(ctx, "copy");
        cl_event ev;
        vct_error err = {0};
        if (clEnqueueCopyBuffer(ctx->queue, a, b, 0, 0, bytes, 0, NULL, &ev) != CL_SUCCESS)
            exit(1);
        vct_record_event(ctx, ev, "copy", &err);
        vct_stage_end(ctx);
        double ms = stage_device_ms(ctx, "copy");
        best = ms < best ? ms : best;
    }
    return best;
}

static cl_mem random_buffer(vct_context *ctx, size_t words, uint64_t seed) {
    uint32_t *h = malloc(words * 4);
    for (size_t i = 0; i < words; ++i) {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        h[i] = (uint32_t)seed & 0x7fffffffu;
    }
    vct_error err = {0};
    cl_mem m = vct_buffer_create(ctx, "bench", "input", words * 4, CL_MEM_READ_WRITE, h, &err);
    free(h);
    if (!m)
        bench_die(&err);
    return m;
}

int main(void) {
    vct_error err = {0};
    vct_context *ctx = vct_context_create(NULL, &err);
    if (!ctx)
        bench_die(&err);
    printf("device: %s, %u compute units\n\n", ctx->info.name, ctx->info.compute_units);
    printf("| operation | elements | MiB | time ms | copy of same bytes ms | ratio |\n");
    printf("|---|---:|---:|---:|---:|---:|\n");

    const uint32_t scan_n = 1u << 24;
    cl_mem in = random_buffer(ctx, scan_n, 1), out = random_buffer(ctx, scan_n, 2);
    /* Keep the sum inside 32 bits: values below 2^8. */
    {
        uint32_t *h = malloc(scan_n * 4ull);
        for (uint32_t i = 0; i < scan_n; ++i)
            h[i] = (i * 2654435761u) >> 24;
        vct_buffer_write(ctx, "bench", in, 0, scan_n * 4ull, h, &err);
        free(h);
    }
    double copy = copy_ms(ctx, in, out, scan_n * 4ull), best = 1e30;
    for (int r = 0; r < bench_repeats(); ++r) {
        vct_stats_reset(ctx);
        vct_stage_begin(ctx, "scan");
        uint64_t total;
        if (vct_scan_u32(ctx, in, out, scan_n, 0, &total, &err))
            bench_die(&err);
        vct_stage_end(ctx);
        double ms = stage_device_ms(ctx, "scan");
        best = ms < best ? ms : best;
    }
    printf("| exclusive scan u32 | 2^24 | %.0f | %.2f | %.2f | %.2f |\n", scan_n * 4.0 / 1048576,
           best, copy, best / copy);
    vct_buffer_release(ctx, in);
    vct_buffer_release(ctx, out);

    const uint32_t sort_n = 1u << 22;
    for (int wide = 0; wide < 2; ++wide) {
        size_t key_bytes = wide ? 8 : 4, bytes = sort_n * (key_bytes + 4);
        cl_mem k0 = random_buffer(ctx, sort_n * key_bytes / 4, 3);
        cl_mem v0 = random_buffer(ctx, sort_n, 4);
        cl_mem k = random_buffer(ctx, sort_n * key_bytes / 4, 5);
        cl_mem v = random_buffer(ctx, sort_n, 6);
        cl_mem c0 = random_buffer(ctx, bytes / 4, 7), c1 = random_buffer(ctx, bytes / 4, 8);
        copy = copy_ms(ctx, c0, c1, bytes);
        best = 1e30;
        for (int r = 0; r < bench_repeats(); ++r) {
            clEnqueueCopyBuffer(ctx->queue, k0, k, 0, 0, sort_n * key_bytes, 0, NULL, NULL);
            clEnqueueCopyBuffer(ctx->queue, v0, v, 0, 0, sort_n * 4ull, 0, NULL, NULL);
            clFinish(ctx->queue);
            vct_stats_reset(ctx);
            vct_stage_begin(ctx, "sort");
            int rc = wide ? vct_sort_pairs_u64(ctx, k, v, sort_n, 64, &err)
                          : vct_sort_pairs_u32(ctx, k, v, sort_n, 32, &err);
            if (rc)
                bench_die(&err);
            vct_stage_end(ctx);
            double ms = stage_device_ms(ctx, "sort");
            best = ms < best ? ms : best;
        }
        printf("| radix sort (%s key, u32 value) | 2^22 | %.0f | %.2f | %.2f | %.2f |\n",
               wide ? "u64" : "u32", bytes / 1048576.0, best, copy, best / copy);
        cl_mem all[] = {k0, v0, k, v, c0, c1};
        for (int i = 0; i < 6; ++i)
            vct_buffer_release(ctx, all[i]);
    }
    vct_context_release(ctx);
    return 0;
}
