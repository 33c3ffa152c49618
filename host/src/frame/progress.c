/* Progress bar: the share done, the rate and the time left. */
#include <math.h>
#include <stdio.h>

#include "frame/progress.h"

void vct_progress_line(uint32_t done, uint32_t total, double elapsed_s, double limit_s,
                       const char *unit) {
    const int width = 30;
    double frac = total ? (double)done / total : 0.0;
    if (limit_s > 0.0)
        frac = fmax(frac, fmin(elapsed_s / limit_s, 1.0));
    int filled = (int)(frac * width + 0.5);
    double rate = elapsed_s > 0.0 ? done / elapsed_s : 0.0;
    double left = frac > 0.0 ? elapsed_s * (1.0 - frac) / frac : 0.0;
    fprintf(stderr, "\r[%.*s%*s] %u %s, %.1f %s/s, %.0f s left ", filled,
            "##############################", width - filled, "", done, unit, rate, unit, left);
    fflush(stderr);
}
