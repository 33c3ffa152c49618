/* The objects a subsampling square could miss: connected pieces of the mesh
 * (triangles that share vertices) whose projection is smaller than twice the
 * first squares' size (sub_fill splits a square while such an object is
 * less than twice the square's size). The map gives each pixel the projected size of the smallest
 * such object whose screen box (one pixel wider each way) covers it. */
#ifndef VCT_RENDER_SMALL_OBJECTS_H
#define VCT_RENDER_SMALL_OBJECTS_H

#include <stdint.h>

#include "vct/vct.h"
#include "vct_types.h"

#define VCT_NO_SMALL_OBJECT 0xFFFFu

/* map: width x height, set to VCT_NO_SMALL_OBJECT where no object smaller
 * than 2 x `size` pixels lies. Returns the number of such objects, or -1 when
 * out of host memory. */
int64_t vct_small_object_map(const vct_scene *s, const vct_camera_desc *cam, uint32_t size,
                             uint16_t *map);

#endif
