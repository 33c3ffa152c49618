/* A monotonic clock for host-side timings. */
#include <time.h>

#include "runtime/clock.h"

double vct_now_ms(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}
