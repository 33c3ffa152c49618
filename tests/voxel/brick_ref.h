/* Plain-C reference for the bricks: dense sample lattices, no octree.
 *
 * Level l's lattice has 2^(l+1) + 1 points per axis, at the corners of the
 * level-(l+1) cells. The finest (level L-1) point is the mean of (value *
 * opacity, opacity) over the voxels with geometry among the 8 around it; a
 * coarser point is the 27-point Gaussian of the finer lattice around it,
 * written as one direct sum (the kernel filters separably). Directional
 * lattices composite each 3-point column along the axis instead. Every
 * lattice is rounded to half floats, as the pool stores it. */
#ifndef VCT_BRICK_REF_H
#define VCT_BRICK_REF_H

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

typedef struct ref_lattice {
    uint32_t n; /* points per axis */
    float *v;   /* n^3 float4, x fastest */
} ref_lattice;

static inline float ref_half(float x) {
    return (float)(_Float16)x;
}

static inline float *ref_at(const ref_lattice *l, int64_t x, int64_t y, int64_t z) {
    const int64_t n = l->n;
    if (x < 0 || y < 0 || z < 0 || x >= n || y >= n || z >= n)
        return NULL;
    return l->v + 4 * ((z * n + y) * n + x);
}

static inline ref_lattice ref_lattice_new(uint32_t n) {
    ref_lattice l = {n, calloc(4ull * n * n * n, sizeof(float))};
    return l;
}

/* voxel_of[(z * res + y) * res + x]: voxel index or -1. A point is the mean
 * of value4 (4 doubles per voxel, premultiplied) over the voxels with
 * geometry among the 8 around it. */
static inline ref_lattice ref_leaf_lattice4(uint32_t res, const int32_t *voxel_of,
                                            const double *value4) {
    ref_lattice l = ref_lattice_new(res + 1);
    for (int64_t z = 0; z <= res; ++z)
        for (int64_t y = 0; y <= res; ++y)
            for (int64_t x = 0; x <= res; ++x) {
                double sum[4] = {0, 0, 0, 0};
                int found = 0;
                for (int64_t vz = z - 1; vz <= z; ++vz)
                    for (int64_t vy = y - 1; vy <= y; ++vy)
                        for (int64_t vx = x - 1; vx <= x; ++vx) {
                            if (vx < 0 || vy < 0 || vz < 0 || vx >= res || vy >= res || vz >= res)
                                continue;
                            const int32_t v = voxel_of[(vz * res + vy) * res + vx];
                            if (v < 0)
                                continue;
                            for (int k = 0; k < 4; ++k)
                                sum[k] += value4[4 * v + k];
                            ++found;
                        }
                float *p = ref_at(&l, x, y, z);
                for (int k = 0; k < 4 && found; ++k)
                    p[k] = ref_half((float)(sum[k] / found));
            }
    return l;
}

/* The same of value (per voxel xyz, not premultiplied; NULL: 0) times
 * opacity, with the opacity in w. */
static inline ref_lattice ref_leaf_lattice(uint32_t res, const int32_t *voxel_of,
                                           const float *value, const float *opacity) {
    size_t voxels = 0;
    for (size_t i = 0; i < (size_t)res * res * res; ++i)
        if (voxel_of[i] >= 0 && (size_t)voxel_of[i] + 1 > voxels)
            voxels = (size_t)voxel_of[i] + 1;
    double *value4 = malloc(32 * (voxels ? voxels : 1));
    for (size_t v = 0; v < voxels; ++v) {
        const double a = opacity[v];
        for (int k = 0; k < 3; ++k)
            value4[4 * v + k] = a * (value ? value[4 * v + k] : 0.0f);
        value4[4 * v + 3] = a;
    }
    ref_lattice l = ref_leaf_lattice4(res, voxel_of, value4);
    free(value4);
    return l;
}

/* The darker sides of a leaf lattice: radiance less shade, opacity kept
 * (not rounded again: the kernel composites them as loaded). */
static inline ref_lattice ref_dark_lattice(const ref_lattice *radiance, const ref_lattice *shade) {
    ref_lattice d = ref_lattice_new(radiance->n);
    const size_t points = (size_t)d.n * d.n * d.n;
    for (size_t i = 0; i < points; ++i) {
        for (int k = 0; k < 3; ++k)
            d.v[4 * i + k] = radiance->v[4 * i + k] - shade->v[4 * i + k];
        d.v[4 * i + 3] = radiance->v[4 * i + 3];
    }
    return d;
}

static inline double ref_weight(int d) {
    return d == 0 ? 0.5 : 0.25;
}

static inline ref_lattice ref_filter(const ref_lattice *fine) {
    ref_lattice c = ref_lattice_new((fine->n - 1) / 2 + 1);
    for (int64_t z = 0; z < c.n; ++z)
        for (int64_t y = 0; y < c.n; ++y)
            for (int64_t x = 0; x < c.n; ++x) {
                double sum[4] = {0, 0, 0, 0};
                for (int dz = -1; dz <= 1; ++dz)
                    for (int dy = -1; dy <= 1; ++dy)
                        for (int dx = -1; dx <= 1; ++dx) {
                            const float *f = ref_at(fine, 2 * x + dx, 2 * y + dy, 2 * z + dz);
                            const double w = ref_weight(dx) * ref_weight(dy) * ref_weight(dz);
                            for (int k = 0; k < 4 && f; ++k)
                                sum[k] += w * f[k];
                        }
                float *p = ref_at(&c, x, y, z);
                for (int k = 0; k < 4; ++k)
                    p[k] = ref_half((float)sum[k]);
            }
    return c;
}

/* Direction dir (0..5: +x, +y, +z, -x, -y, -z, the way light travels). A
 * sample at the column's ends stands for half a fine sample's thickness:
 * opacity 1 - (1 - a)^(1/2), its colour kept. */
static inline ref_lattice ref_filter_dir(const ref_lattice *fine, int dir) {
    ref_lattice c = ref_lattice_new((fine->n - 1) / 2 + 1);
    const int axis = dir % 3, sign = dir < 3 ? 1 : -1;
    const int u_axis = (axis + 1) % 3, v_axis = (axis + 2) % 3;
    for (int64_t z = 0; z < c.n; ++z)
        for (int64_t y = 0; y < c.n; ++y)
            for (int64_t x = 0; x < c.n; ++x) {
                const int64_t centre[3] = {2 * x, 2 * y, 2 * z};
                double sum[4] = {0, 0, 0, 0};
                for (int dv = -1; dv <= 1; ++dv)
                    for (int du = -1; du <= 1; ++du) {
                        double colour[3] = {0, 0, 0}, alpha = 0;
                        for (int step = -1; step <= 1; ++step) {
                            int64_t p[3] = {centre[0], centre[1], centre[2]};
                            p[axis] += sign * step;
                            p[u_axis] += du;
                            p[v_axis] += dv;
                            const float *f = ref_at(fine, p[0], p[1], p[2]);
                            if (!f)
                                continue;
                            double a = f[3], scale = 1.0;
                            if (step != 0 && a > 0) {
                                const double thin = 1.0 - sqrt(1.0 - fmin(a, 1.0));
                                scale = thin / a;
                                a = thin;
                            }
                            for (int k = 0; k < 3; ++k)
                                colour[k] += (1.0 - alpha) * scale * f[k];
                            alpha += (1.0 - alpha) * a;
                        }
                        const double w = ref_weight(du) * ref_weight(dv);
                        for (int k = 0; k < 3; ++k)
                            sum[k] += w * colour[k];
                        sum[3] += w * alpha;
                    }
                float *p = ref_at(&c, x, y, z);
                for (int k = 0; k < 4; ++k)
                    p[k] = ref_half((float)sum[k]);
            }
    return c;
}

#endif
