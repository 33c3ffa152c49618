/* Stages: launches, device time from profiling events, host time, memory. */
#ifndef VCT_RUNTIME_STATS_H
#define VCT_RUNTIME_STATS_H

#include "runtime/context.h"

/* A monotonic clock for host-side timings. */
double vct_now_ms(void);

void vct_stage_begin(vct_context *ctx, const char *name);
void vct_stage_end(vct_context *ctx);
/* Counts a launch of `kernel_name` in the current stage and keeps its event
 * (released here) until the stage ends, when its device time is summed. */
int vct_record_event(vct_context *ctx, cl_event event, const char *kernel_name, vct_error *err);
int vct_finish(vct_context *ctx, const char *stage, vct_error *err);

#endif
