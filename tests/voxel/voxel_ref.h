/* Plain-C reference voxelizer for the tests: quantises as vct.h documents,
 * then tests every voxel in each triangle's bounding box with exact 128-bit
 * integer arithmetic (box-centred separating axes for the conservative mode,
 * Schwarz & Seidel's 6-separating test for the thin mode). */
#ifndef VCT_VOXEL_REF_H
#define VCT_VOXEL_REF_H

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "vct/vct.h"

typedef __int128 ref_int;

typedef struct ref_fragment {
    uint32_t key, tri;
} ref_fragment;

typedef struct ref_voxels {
    ref_fragment *frags;
    size_t count, cap;
    uint32_t *keys;  /* unique, ascending */
    uint32_t *first; /* first fragment of each voxel; first[voxels] = count */
    uint32_t voxels;
} ref_voxels;

static inline uint32_t ref_morton(uint32_t x, uint32_t y, uint32_t z) {
    uint32_t key = 0;
    for (int b = 0; b < 10; ++b)
        key |= ((x >> b) & 1u) << (3 * b) | ((y >> b) & 1u) << (3 * b + 1) |
               ((z >> b) & 1u) << (3 * b + 2);
    return key;
}

static inline int64_t ref_floor_div(int64_t a, int64_t q) {
    return a >= 0 ? a / q : -((-a + q - 1) / q);
}

static inline ref_int ref_abs(ref_int v) {
    return v < 0 ? -v : v;
}

static inline ref_int ref_max(ref_int a, ref_int b) {
    return a > b ? a : b;
}

static inline ref_int ref_min(ref_int a, ref_int b) {
    return a < b ? a : b;
}

/* Separating axis (x, y, z) for the triangle t (relative to the box centre,
 * doubled) and the box of half-size h: 1 when it separates. */
static inline int ref_separates(const ref_int t[3][3], ref_int x, ref_int y, ref_int z, ref_int h) {
    ref_int p[3];
    for (int i = 0; i < 3; ++i)
        p[i] = x * t[i][0] + y * t[i][1] + z * t[i][2];
    const ref_int r = h * (ref_abs(x) + ref_abs(y) + ref_abs(z));
    return ref_min(p[0], ref_min(p[1], p[2])) > r || ref_max(p[0], ref_max(p[1], p[2])) < -r;
}

/* 26-separating: all 13 axes, in coordinates doubled about the voxel centre. */
static inline int ref_conservative(const int64_t v[3][3], const int64_t cell[3], int64_t q) {
    ref_int t[3][3];
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k)
            t[i][k] = 2 * (ref_int)v[i][k] - (2 * (ref_int)cell[k] + 1) * q;
    for (int k = 0; k < 3; ++k) {
        ref_int axis[3] = {0, 0, 0};
        axis[k] = 1;
        if (ref_separates(t, axis[0], axis[1], axis[2], q))
            return 0;
    }
    ref_int e[3][3];
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k)
            e[i][k] = t[(i + 1) % 3][k] - t[i][k];
    const ref_int n[3] = {e[0][1] * e[1][2] - e[0][2] * e[1][1],
                          e[0][2] * e[1][0] - e[0][0] * e[1][2],
                          e[0][0] * e[1][1] - e[0][1] * e[1][0]};
    if (ref_separates(t, n[0], n[1], n[2], q))
        return 0;
    for (int i = 0; i < 3; ++i) {
        if (ref_separates(t, 0, -e[i][2], e[i][1], q) ||
            ref_separates(t, e[i][2], 0, -e[i][0], q) || ref_separates(t, -e[i][1], e[i][0], 0, q))
            return 0;
    }
    return 1;
}

/* 6-separating (Schwarz & Seidel 2010), voxel size q, min corner p = cell * q. */
static inline int ref_thin(const int64_t v[3][3], const int64_t cell[3], int64_t q) {
    ref_int e[3][3], n[3];
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k)
            e[i][k] = (ref_int)v[(i + 1) % 3][k] - v[i][k];
    n[0] = e[0][1] * e[1][2] - e[0][2] * e[1][1];
    n[1] = e[0][2] * e[1][0] - e[0][0] * e[1][2];
    n[2] = e[0][0] * e[1][1] - e[0][1] * e[1][0];
    /* Plane: |n . (centre - v0)| <= q/2 * max |n_i|, doubled. */
    ref_int dist2 = 0;
    for (int k = 0; k < 3; ++k)
        dist2 += n[k] * ((2 * (ref_int)cell[k] + 1) * q - 2 * (ref_int)v[0][k]);
    const ref_int nmax = ref_max(ref_abs(n[0]), ref_max(ref_abs(n[1]), ref_abs(n[2])));
    if (ref_abs(dist2) > q * nmax)
        return 0;
    /* Projections onto the yz, zx and xy planes (axes a, b; normal along c). */
    for (int c = 0; c < 3; ++c) {
        const int a = (c + 1) % 3, b = (c + 2) % 3;
        const ref_int sign = n[c] < 0 ? -1 : 1;
        for (int i = 0; i < 3; ++i) {
            const ref_int na = -e[i][b] * sign, nb = e[i][a] * sign;
            const ref_int f = na * ((2 * (ref_int)cell[a] + 1) * q - 2 * (ref_int)v[i][a]) +
                              nb * ((2 * (ref_int)cell[b] + 1) * q - 2 * (ref_int)v[i][b]) +
                              q * ref_max(ref_abs(na), ref_abs(nb));
            if (f < 0)
                return 0;
        }
    }
    return 1;
}

static inline void ref_push(ref_voxels *r, uint32_t key, uint32_t tri) {
    if (r->count == r->cap) {
        r->cap = r->cap ? 2 * r->cap : 1024;
        r->frags = realloc(r->frags, r->cap * sizeof *r->frags);
    }
    r->frags[r->count].key = key;
    r->frags[r->count].tri = tri;
    r->count++;
}

static inline int ref_fragment_order(const void *a, const void *b) {
    const ref_fragment *x = a, *y = b;
    if (x->key != y->key)
        return x->key < y->key ? -1 : 1;
    return x->tri < y->tri ? -1 : (x->tri > y->tri);
}

/* Quantised vertices of triangle t: round to nearest (ties to even) of
 * (p - origin) * units / side, in double. */
static inline void ref_quantise(const vct_scene *s, const vct_voxel_info *info, uint32_t t,
                                int64_t v[3][3]) {
    const double scale = info->units / info->side;
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k)
            v[i][k] = (int64_t)nearbyint(
                ((double)s->positions[3 * s->triangles[3 * t + i] + k] - info->origin[k]) * scale);
}

/* Every voxel of every triangle's bounding box, tested exactly. */
static inline ref_voxels ref_voxelize(const vct_scene *s, const vct_voxel_info *info, int thin) {
    ref_voxels r;
    memset(&r, 0, sizeof r);
    const int64_t q = info->units / info->resolution, last = info->resolution - 1;
    for (uint32_t t = 0; t < s->triangle_count; ++t) {
        int64_t v[3][3], lo[3], hi[3];
        ref_quantise(s, info, t, v);
        const int64_t e0[3] = {v[1][0] - v[0][0], v[1][1] - v[0][1], v[1][2] - v[0][2]};
        const int64_t e1[3] = {v[2][0] - v[0][0], v[2][1] - v[0][1], v[2][2] - v[0][2]};
        if (e0[1] * e1[2] - e0[2] * e1[1] == 0 && e0[2] * e1[0] - e0[0] * e1[2] == 0 &&
            e0[0] * e1[1] - e0[1] * e1[0] == 0)
            continue; /* zero area: no surface, no voxels */
        int empty = 0;
        for (int k = 0; k < 3; ++k) {
            int64_t mn = v[0][k], mx = v[0][k];
            for (int i = 1; i < 3; ++i) {
                mn = v[i][k] < mn ? v[i][k] : mn;
                mx = v[i][k] > mx ? v[i][k] : mx;
            }
            lo[k] = ref_floor_div(mn - 1, q);
            hi[k] = ref_floor_div(mx, q);
            lo[k] = lo[k] < 0 ? 0 : lo[k];
            hi[k] = hi[k] > last ? last : hi[k];
            empty |= lo[k] > hi[k];
        }
        if (empty)
            continue;
        int64_t c[3];
        for (c[2] = lo[2]; c[2] <= hi[2]; ++c[2])
            for (c[1] = lo[1]; c[1] <= hi[1]; ++c[1])
                for (c[0] = lo[0]; c[0] <= hi[0]; ++c[0])
                    if (thin ? ref_thin(v, c, q) : ref_conservative(v, c, q))
                        ref_push(&r, ref_morton((uint32_t)c[0], (uint32_t)c[1], (uint32_t)c[2]), t);
    }
    if (r.count)
        qsort(r.frags, r.count, sizeof *r.frags, ref_fragment_order);
    r.keys = malloc(4 * (r.count + 1));
    r.first = malloc(4 * (r.count + 2));
    for (size_t i = 0; i < r.count; ++i)
        if (i == 0 || r.frags[i].key != r.frags[i - 1].key) {
            r.keys[r.voxels] = r.frags[i].key;
            r.first[r.voxels++] = (uint32_t)i;
        }
    r.first[r.voxels] = (uint32_t)r.count;
    return r;
}

/* The cell (x, y, z) of a Morton key. */
static inline void ref_unmorton(uint32_t key, int64_t cell[3]) {
    cell[0] = cell[1] = cell[2] = 0;
    for (int b = 0; b < 10; ++b)
        for (int k = 0; k < 3; ++k)
            cell[k] |= (int64_t)((key >> (3 * b + k)) & 1u) << b;
}

/* Area of triangle v (quantised) inside the voxel `cell` of side q, in
 * units of the voxel's face: the triangle cut by one face plane at a time,
 * keeping the part on the voxel's side, in double. */
static inline double ref_area_in_voxel(const int64_t v[3][3], const int64_t cell[3], int64_t q) {
    double poly[16][3], cut[16][3];
    int n = 3;
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k)
            poly[i][k] = ((double)v[i][k] - ((double)cell[k] + 0.5) * (double)q) / (double)q;
    for (int face = 0; face < 6 && n > 0; ++face) {
        const int k = face / 2;
        const double sign = face % 2 ? -1.0 : 1.0;
        int m = 0;
        for (int i = 0; i < n; ++i) {
            const double *p = poly[i], *r = poly[(i + 1) % n];
            const double dp = sign * p[k] - 0.5, dr = sign * r[k] - 0.5;
            if (dp <= 0.0) {
                memcpy(cut[m++], p, sizeof cut[0]);
            }
            if ((dp < 0.0) != (dr < 0.0) && dp != 0.0 && dr != 0.0) {
                const double w = dp / (dp - dr);
                for (int j = 0; j < 3; ++j)
                    cut[m][j] = p[j] + w * (r[j] - p[j]);
                ++m;
            }
        }
        memcpy(poly, cut, sizeof poly);
        n = m;
    }
    double sum[3] = {0, 0, 0};
    for (int i = 1; i + 1 < n; ++i) {
        double a[3], b[3];
        for (int j = 0; j < 3; ++j) {
            a[j] = poly[i][j] - poly[0][j];
            b[j] = poly[i + 1][j] - poly[0][j];
        }
        sum[0] += a[1] * b[2] - a[2] * b[1];
        sum[1] += a[2] * b[0] - a[0] * b[2];
        sum[2] += a[0] * b[1] - a[1] * b[0];
    }
    return 0.5 * sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]);
}

static inline void ref_free(ref_voxels *r) {
    free(r->frags);
    free(r->keys);
    free(r->first);
}

#endif
