/* Pinhole camera: primary ray through the centre of pixel (x, y), y down.
 * A camera may render a band of a taller image: size.z is the band's first
 * row in that image and size.w its height (0: the band is the image). Rays
 * and random streams follow the row in the whole image, so that a band's
 * pixels equal the whole image's, bit for bit. */
#ifndef VCT_CAMERA_H
#define VCT_CAMERA_H

#include "vct_types.h"

/* Row y of the band in the whole image. */
inline uint camera_row(const vct_camera_desc *cam, uint y) {
    return y + cam->size.z;
}

/* Pixel (x, y) of the band as an index into the whole image: the key of its
 * random stream. */
inline uint camera_pixel_id(const vct_camera_desc *cam, uint x, uint y) {
    return camera_row(cam, y) * cam->size.x + x;
}

/* (px, py) in the whole image's pixel coordinates. */
inline float3 camera_ray_dir(const vct_camera_desc *cam, float px, float py) {
    const float tan_half = cam->position.w, aspect = cam->forward.w;
    const uint height = cam->size.w ? cam->size.w : cam->size.y;
    const float sx = (2.0f * px / (float)cam->size.x - 1.0f) * tan_half * aspect;
    const float sy = (1.0f - 2.0f * py / (float)height) * tan_half;
    return normalize(cam->forward.xyz + sx * cam->right.xyz + sy * cam->up.xyz);
}

#endif
