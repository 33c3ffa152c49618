/* Double-precision vectors and the pinhole camera for tests that compute
 * their references independently of the kernels. */
#ifndef VCT_TEST_VEC3D_H
#define VCT_TEST_VEC3D_H

#include <math.h>

typedef struct v3 {
    double x, y, z;
} v3;

static inline v3 v(double x, double y, double z) {
    return (v3){x, y, z};
}
static inline v3 sub(v3 a, v3 b) {
    return v(a.x - b.x, a.y - b.y, a.z - b.z);
}
static inline v3 add(v3 a, v3 b) {
    return v(a.x + b.x, a.y + b.y, a.z + b.z);
}
static inline v3 mul(v3 a, double s) {
    return v(a.x * s, a.y * s, a.z * s);
}
static inline double dot(v3 a, v3 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
static inline v3 cross(v3 a, v3 b) {
    return v(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline v3 norm(v3 a) {
    return mul(a, 1.0 / sqrt(dot(a, a)));
}
static inline v3 v3_of(const float *f) {
    return v(f[0], f[1], f[2]);
}

/* Direction of the ray through the centre of pixel (x, y) of a w x h image
 * (row 0 at the top) for a camera at eye looking at `at`, vertical field of
 * view fov_deg. */
static inline v3 camera_ray(v3 eye, v3 at, v3 up, double fov_deg, int w, int h, int x, int y) {
    const v3 f = norm(sub(at, eye)), r = norm(cross(f, up)), u = cross(r, f);
    const double th = tan(fov_deg * 3.14159265358979323846 / 360.0), aspect = (double)w / h;
    const double sx = (2.0 * (x + 0.5) / w - 1.0) * th * aspect;
    const double sy = (1.0 - 2.0 * (y + 0.5) / h) * th;
    return norm(add(f, add(mul(r, sx), mul(u, sy))));
}

#endif
