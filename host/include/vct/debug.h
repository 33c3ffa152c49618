/* vct: hooks for tests and tools that look inside the engine: read-backs
 * of internal structures and counts of what ran. Not part of rendering;
 * vct/vct.h does not include this header. */
#ifndef VCT_API_DEBUG_H
#define VCT_API_DEBUG_H

#include "vct/export.h"

#include <stdint.h>

#include "vct/accel.h"
#include "vct/device.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The grid's cell ranges (start, end per cell into tri_ids) and its sorted
 * triangle list, read back. */
VCT_API vct_status vct_grid_read(vct_context *ctx, const vct_grid *grid, uint32_t *cell_start,
                                 uint32_t *cell_end, uint32_t *tri_ids, vct_error *err);
/* Launches of the kernel named kernel_name on ctx since it was made (what
 * the effect plan's tests count). */
VCT_API int vct_kernel_launches(const vct_context *ctx, const char *kernel_name);

#ifdef __cplusplus
}
#endif
#endif
