/* Triangle / axis-aligned box overlap by the separating axis theorem
 * (13 axes: 3 box normals, the triangle normal, 9 edge cross products).
 * Closed boxes: touching counts as overlap. A degenerate triangle (zero
 * normal, zero cross products) is never separated by a zero axis, so the test
 * stays conservative and NaN-free. Plain C99 and OpenCL C. */
#ifndef VCT_TRI_BOX_H
#define VCT_TRI_BOX_H

#ifndef __OPENCL_VERSION__
#include <math.h>
#define TB_FMIN fminf
#define TB_FMAX fmaxf
#define TB_FABS fabsf
#else
#define TB_FMIN fmin
#define TB_FMAX fmax
#define TB_FABS fabs
#endif

/* Projects the triangle (a, b, c, relative to the box centre) and the box of
 * half-size (hx, hy, hz) onto axis (x, y, z); 1 if the projections overlap. */
static inline int tb_axis_overlaps(float x, float y, float z, const float *a, const float *b,
                                   const float *c, float hx, float hy, float hz) {
    float pa = x * a[0] + y * a[1] + z * a[2];
    float pb = x * b[0] + y * b[1] + z * b[2];
    float pc = x * c[0] + y * c[1] + z * c[2];
    float r = hx * TB_FABS(x) + hy * TB_FABS(y) + hz * TB_FABS(z);
    float lo = TB_FMIN(pa, TB_FMIN(pb, pc)), hi = TB_FMAX(pa, TB_FMAX(pb, pc));
    return !(lo > r || hi < -r);
}

/* v0..v2: triangle vertices; centre and half_size: the box (half-size per axis). */
static inline int tri_box_overlap(const float *v0, const float *v1, const float *v2,
                                  const float *centre, const float *half_size) {
    float a[3], b[3], c[3];
    for (int k = 0; k < 3; ++k) {
        a[k] = v0[k] - centre[k];
        b[k] = v1[k] - centre[k];
        c[k] = v2[k] - centre[k];
    }
    /* Box normals: the triangle's bounding box against the box. */
    for (int k = 0; k < 3; ++k) {
        float lo = TB_FMIN(a[k], TB_FMIN(b[k], c[k])), hi = TB_FMAX(a[k], TB_FMAX(b[k], c[k]));
        if (lo > half_size[k] || hi < -half_size[k])
            return 0;
    }
    float e0[3], e1[3], e2[3];
    for (int k = 0; k < 3; ++k) {
        e0[k] = b[k] - a[k];
        e1[k] = c[k] - b[k];
        e2[k] = a[k] - c[k];
    }
    /* Triangle normal. */
    float nx = e0[1] * e1[2] - e0[2] * e1[1];
    float ny = e0[2] * e1[0] - e0[0] * e1[2];
    float nz = e0[0] * e1[1] - e0[1] * e1[0];
    if (!tb_axis_overlaps(nx, ny, nz, a, b, c, half_size[0], half_size[1], half_size[2]))
        return 0;
    /* Edge x box-axis cross products. */
    const float *edges[3] = {e0, e1, e2};
    for (int i = 0; i < 3; ++i) {
        const float *e = edges[i];
        if (!tb_axis_overlaps(0.0f, -e[2], e[1], a, b, c, half_size[0], half_size[1],
                              half_size[2]) ||
            !tb_axis_overlaps(e[2], 0.0f, -e[0], a, b, c, half_size[0], half_size[1],
                              half_size[2]) ||
            !tb_axis_overlaps(-e[1], e[0], 0.0f, a, b, c, half_size[0], half_size[1], half_size[2]))
            return 0;
    }
    return 1;
}

#endif
