/* Benchmark helpers: device time and peak memory of a stage, from the statistics. */
#ifndef VCT_BENCH_UTIL_H
#define VCT_BENCH_UTIL_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "runtime/runtime.h"

/* The statistics of stage `name`, or NULL if it has not run. */
static inline const vct_stage_stat *stage_stat(const vct_context *ctx, const char *name) {
    const vct_stage_stat *st;
    int n = vct_stats(ctx, &st);
    for (int i = 0; i < n; ++i)
        if (strcmp(st[i].name, name) == 0)
            return &st[i];
    return NULL;
}

static inline double stage_device_ms(const vct_context *ctx, const char *name) {
    const vct_stage_stat *st = stage_stat(ctx, name);
    return st ? st->device_ms : 0.0;
}

static inline double stage_peak_mib(const vct_context *ctx, const char *name) {
    const vct_stage_stat *st = stage_stat(ctx, name);
    return st ? st->mib : 0.0;
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
