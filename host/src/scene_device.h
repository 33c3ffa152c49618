/* Conversions from the public scene structs to the kernels' layouts. */
#ifndef VCT_SCENE_DEVICE_H
#define VCT_SCENE_DEVICE_H

#include "vct/vct.h"
#include "vct_types.h"

int vct_camera_desc_make(const vct_camera *cam, int width, int height, vct_camera_desc *d,
                         vct_error *err);
void vct_light_desc_make(const vct_light *l, vct_light_desc *d);
void vct_material_desc_make(const vct_material *m, vct_material_desc *d);

#endif
