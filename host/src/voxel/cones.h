/* Cone kernels' shared host side (host/src/cones.c). */
#ifndef VCT_CONES_H
#define VCT_CONES_H

#include "runtime/runtime.h"

int vct_cone_settings_check(const vct_cone_settings *settings, vct_error *err);
/* vct_cone_desc (kernels/vct_types.h) for these voxels and settings. */
void vct_cone_desc_make(const vct_voxels *voxels, const vct_cone_settings *settings,
                        const float *ambient, void *out_desc);
/* -D options for the voxels' brick pool kind and the settings' level choice
 * (each after a space). */
void vct_cone_options(const vct_voxels *voxels, const vct_cone_settings *settings, char *out,
                      size_t size);
/* Sets CONE_POOLS, the octree's child pointers and the cone description as
 * a cone kernel's arguments from index *next on (0: its first); *next
 * receives the index after them. */
int vct_cone_set_args(cl_kernel kernel, const vct_voxels *voxels, const void *desc,
                      const char *stage, int *next, vct_error *err);

#endif
