/* Ray against triangle in double precision (Möller-Trumbore): the
 * independent reference that ray queries and the cones' near rays are
 * checked against. */
#ifndef VCT_TEST_RAY_REF_H
#define VCT_TEST_RAY_REF_H

#include <math.h>

#include "vct/vct.h"

/* Möller-Trumbore in double: the independent reference. Returns t or -1, and
 * the distance of the hit to the triangle's border in barycentric units. */
static double ref_intersect(const double o[3], const double d[3], const float *a, const float *b,
                            const float *c, double *border) {
    double e1[3], e2[3], p[3], s[3], q[3];
    for (int k = 0; k < 3; ++k) {
        e1[k] = (double)b[k] - a[k];
        e2[k] = (double)c[k] - a[k];
        s[k] = o[k] - a[k];
    }
    p[0] = d[1] * e2[2] - d[2] * e2[1];
    p[1] = d[2] * e2[0] - d[0] * e2[2];
    p[2] = d[0] * e2[1] - d[1] * e2[0];
    double det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
    if (det == 0.0)
        return -1;
    double inv = 1.0 / det;
    double u = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) * inv;
    q[0] = s[1] * e1[2] - s[2] * e1[1];
    q[1] = s[2] * e1[0] - s[0] * e1[2];
    q[2] = s[0] * e1[1] - s[1] * e1[0];
    double v = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) * inv;
    double t = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) * inv;
    *border = fmin(fmin(u, v), 1.0 - u - v);
    if (u < 0 || v < 0 || u + v > 1 || t <= 0)
        return -1;
    return t;
}

/* The nearest hit in (0, reach] of the ray from o along d over the scene's
 * triangles, by brute force; -1 where none. *border: the hit's distance to
 * its triangle's border in barycentric units; *tri: the triangle hit. */
static inline double ref_closest_tri(const vct_scene *s, const double o[3], const double d[3],
                                     double reach, double *border, uint32_t *tri) {
    double best = -1.0;
    for (uint32_t i = 0; i < s->triangle_count; ++i) {
        const uint32_t *t = s->triangles + 3 * i;
        double b;
        const double hit = ref_intersect(o, d, s->positions + 3 * t[0], s->positions + 3 * t[1],
                                         s->positions + 3 * t[2], &b);
        if (hit > 0.0 && hit <= reach && (best < 0.0 || hit < best)) {
            best = hit;
            *border = b;
            *tri = i;
        }
    }
    return best;
}

/* ref_closest_tri without the triangle. */
static inline double ref_closest(const vct_scene *s, const double o[3], const double d[3],
                                 double reach, double *border) {
    uint32_t tri = 0;
    return ref_closest_tri(s, o, d, reach, border, &tri);
}

#endif
