/* The angle between two directions from its sine and cosine, as atan2(s, c)
 * for s >= 0, in [0, pi]. The library's atan2 handles every sign, infinity
 * and NaN and costs more than the rest of Lambert's formula on some CPU
 * drivers (a fifth of the cone tracer's primary pass with emitters in view,
 * on PoCL). Here the ratio of the smaller magnitude to the larger, in [0, 1],
 * goes through an odd polynomial fitted to atan's relative error (at most
 * 1.6e-7 in float, about an ulp), and the octant puts it back. */
#ifndef VCT_ANGLE_H
#define VCT_ANGLE_H

#define ANGLE_HALF_PI 1.57079632679489662f
#define ANGLE_PI 3.14159265358979324f

/* atan(a) for a in [0, 1]. */
inline float atan_unit(float a) {
    const float a2 = a * a;
    const float p =
        1.0f + a2 * (-0.3333307206630707f +
                     a2 * (0.1999262273311615f +
                           a2 * (-0.14203663170337677f +
                                 a2 * (0.106409952044487f +
                                       a2 * (-0.07504408806562424f +
                                             a2 * (0.04269274324178696f +
                                                   a2 * (-0.01606932282447815f +
                                                         a2 * 0.002850051736459136f)))))));
    return a * p;
}

/* atan2(s, c) for s >= 0 (0 where both are 0). */
inline float angle_of(float s, float c) {
    const float ac = fabs(c), hi = fmax(s, ac), lo = fmin(s, ac);
    const float a = hi > 0.0f ? atan_unit(lo / hi) : 0.0f;
    const float first = s > ac ? ANGLE_HALF_PI - a : a; /* from the +c axis, for c >= 0 */
    return c < 0.0f ? ANGLE_PI - first : first;
}

#endif
