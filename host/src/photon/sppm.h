/* Photon mapping's per-pixel statistics, kept in a vct_accumulation
 * between resumed calls (the renderer itself is vct_render_pm). */
#ifndef VCT_PHOTON_SPPM_H
#define VCT_PHOTON_SPPM_H

#include "runtime/runtime.h"

/* Drops the statistics in acc: the next call starts over. */
void vct_pm_state_release(vct_context *ctx, vct_accumulation *acc);

#endif
