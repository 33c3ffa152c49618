/* The progress bar of the progressive renderers, on stderr. */
#ifndef VCT_RENDER_PROGRESS_H
#define VCT_RENDER_PROGRESS_H

#include <stdint.h>

/* done of total units (total 0: timed by limit_s) after elapsed_s. */
void vct_progress_line(uint32_t done, uint32_t total, double elapsed_s, double limit_s,
                       const char *unit);

#endif
