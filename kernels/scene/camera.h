/* Pinhole camera: primary ray through the centre of pixel (x, y), y down. */
#ifndef VCT_CAMERA_H
#define VCT_CAMERA_H

#include "vct_types.h"

inline float3 camera_ray_dir(const vct_camera_desc *cam, float px, float py) {
    const float tan_half = cam->position.w, aspect = cam->forward.w;
    const float sx = (2.0f * px / (float)cam->size.x - 1.0f) * tan_half * aspect;
    const float sy = (1.0f - 2.0f * py / (float)cam->size.y) * tan_half;
    return normalize(cam->forward.xyz + sx * cam->right.xyz + sy * cam->up.xyz);
}

#endif
