/* Benchmark helpers: best-of-N device time of a stage, from profiling events. */
#ifndef VCT_BENCH_UTIL_H
#define VCT_BENCH_UTIL_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "internal.h"

static inline double stage_device_ms(const vct_context *ctx, const char *name) {
    const vct_stage_stat *st;
    int n = vct_stats(ctx, &st);
    for (int i = 0; i < n; ++i)
        if (strcmp(st[i].name, name) == 0)
            return st[i].device_ms;
    return 0.0;
}

static inline int bench_repeats(void) {
    const char *r = getenv("VCT_BENCH_REPEATS");
    int n = r ? atoi(r) : 5;
    return n > 0 ? n : 5;
}

static inline void bench_die(const vct_error *err) {
    fprintf(stderr, "bench: %s\n", err->message);
    exit(1);
}

#endif
