/* A monotonic clock for host-side timings. */
#ifndef VCT_RUNTIME_CLOCK_H
#define VCT_RUNTIME_CLOCK_H

double vct_now_ms(void);

#endif
