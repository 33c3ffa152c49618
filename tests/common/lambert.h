/* Lambert's formula in double precision, the tests' analytic answer for an
 * emitter: the irradiance at p (unit normal n) from a uniform planar polygon
 * of radiance le that lies wholly on n's side, E = le / 2 * |sum over edges
 * of the edge's angle at p times the cosine between n and the plane through
 * p and the edge|. */
#ifndef VCT_TEST_LAMBERT_H
#define VCT_TEST_LAMBERT_H

#include <math.h>

static inline double lambert_irradiance(const double p[3], const double n[3],
                                        const double (*polygon)[3], int corners, double le) {
    double sum = 0.0;
    for (int i = 0; i < corners; ++i) {
        double a[3], b[3], c[3];
        for (int k = 0; k < 3; ++k) {
            a[k] = polygon[i][k] - p[k];
            b[k] = polygon[(i + 1) % corners][k] - p[k];
        }
        const double la = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        const double lb = sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
        const double cosg = (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / (la * lb);
        const double angle = acos(fmax(-1.0, fmin(1.0, cosg)));
        c[0] = a[1] * b[2] - a[2] * b[1];
        c[1] = a[2] * b[0] - a[0] * b[2];
        c[2] = a[0] * b[1] - a[1] * b[0];
        const double lc = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
        sum += angle * (c[0] * n[0] + c[1] * n[1] + c[2] * n[2]) / lc;
    }
    return le / 2.0 * fabs(sum);
}

#endif
