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

#ifdef VCT_PACKETS
/* camera_ray_dir for 16 points of the image in vector lanes, with its
 * operations (normalize's as the library does them for lengths in the
 * normal range; any other lane is normalized by itself). */
inline void camera_ray_dir16(const vct_camera_desc *cam, float16 px, float16 py, float16 *dx,
                             float16 *dy, float16 *dz) {
    const float tan_half = cam->position.w, aspect = cam->forward.w;
    const uint height = cam->size.w ? cam->size.w : cam->size.y;
    const float16 sx = (2.0f * px / (float)cam->size.x - 1.0f) * tan_half * aspect;
    const float16 sy = (1.0f - 2.0f * py / (float)height) * tan_half;
    const float16 x = cam->forward.x + sx * cam->right.x + sy * cam->up.x,
                  y = cam->forward.y + sx * cam->right.y + sy * cam->up.y,
                  z = cam->forward.z + sx * cam->right.z + sy * cam->up.z;
    const float16 xx = x * x, yy = y * y, zz = z * z;
    const float16 xy = xx + yy;
    const float16 d = xy + zz;
    const float16 inv = 1.0f / sqrt(d);
    *dx = x * inv;
    *dy = y * inv;
    *dz = z * inv;
    const int16 odd = d < 0x1p-126f || d == INFINITY || (x == 0.0f && y == 0.0f && z == 0.0f);
    if (any(odd)) {
        float ax[16], ay[16], az[16], ox[16], oy[16], oz[16];
        int at[16];
        vstore16(x, 0, ax);
        vstore16(y, 0, ay);
        vstore16(z, 0, az);
        vstore16(*dx, 0, ox);
        vstore16(*dy, 0, oy);
        vstore16(*dz, 0, oz);
        vstore16(odd, 0, at);
        for (uint k = 0; k < 16u; ++k)
            if (at[k]) {
                const float3 v = normalize((float3)(ax[k], ay[k], az[k]));
                ox[k] = v.x;
                oy[k] = v.y;
                oz[k] = v.z;
            }
        *dx = vload16(0, ox);
        *dy = vload16(0, oy);
        *dz = vload16(0, oz);
    }
}
#endif

#endif
