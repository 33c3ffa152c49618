/* Test meshes: a closed icosphere with shared vertices and a triangle soup
 * with slivers and degenerate triangles. Callers free the arrays. */
#ifndef VCT_MESH_GEN_H
#define VCT_MESH_GEN_H

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

typedef struct test_mesh {
    float *pos;
    uint32_t *tri;
    uint32_t nv, nt;
} test_mesh;

static inline uint32_t mesh_midpoint(test_mesh *m, uint32_t a, uint32_t b, uint32_t *cache_a,
                                     uint32_t *cache_b, uint32_t *cache_v, uint32_t *ncache) {
    uint32_t lo = a < b ? a : b, hi = a < b ? b : a;
    for (uint32_t i = 0; i < *ncache; ++i)
        if (cache_a[i] == lo && cache_b[i] == hi)
            return cache_v[i];
    float p[3];
    for (int k = 0; k < 3; ++k)
        p[k] = 0.5f * (m->pos[3 * a + k] + m->pos[3 * b + k]);
    float len = sqrtf(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    for (int k = 0; k < 3; ++k)
        m->pos[3 * m->nv + k] = p[k] / len;
    cache_a[*ncache] = lo;
    cache_b[*ncache] = hi;
    cache_v[*ncache] = m->nv;
    ++*ncache;
    return m->nv++;
}

/* Unit icosphere, `levels` subdivisions, scaled and moved to centre. */
static inline test_mesh mesh_icosphere(int levels, float radius, const float centre[3]) {
    const float t = (1.0f + sqrtf(5.0f)) / 2.0f;
    const float base[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                               {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                               {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    const uint32_t faces[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                   {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                   {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                   {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    uint32_t max_t = 20u << (2 * levels), max_v = 12 + max_t * 3 / 2;
    test_mesh m = {malloc(12ull * max_v), malloc(12ull * max_t), 12, 20};
    for (int i = 0; i < 12; ++i) {
        float len =
            sqrtf(base[i][0] * base[i][0] + base[i][1] * base[i][1] + base[i][2] * base[i][2]);
        for (int k = 0; k < 3; ++k)
            m.pos[3 * i + k] = base[i][k] / len;
    }
    memcpy(m.tri, faces, sizeof faces);
    for (int l = 0; l < levels; ++l) {
        uint32_t *next = malloc(12ull * m.nt * 4);
        uint32_t *ca = malloc(4ull * m.nt * 3), *cb = malloc(4ull * m.nt * 3),
                 *cv = malloc(4ull * m.nt * 3), nc = 0;
        for (uint32_t f = 0; f < m.nt; ++f) {
            uint32_t a = m.tri[3 * f], b = m.tri[3 * f + 1], c = m.tri[3 * f + 2];
            uint32_t ab = mesh_midpoint(&m, a, b, ca, cb, cv, &nc);
            uint32_t bc = mesh_midpoint(&m, b, c, ca, cb, cv, &nc);
            uint32_t caa = mesh_midpoint(&m, c, a, ca, cb, cv, &nc);
            uint32_t out[12] = {a, ab, caa, b, bc, ab, c, caa, bc, ab, bc, caa};
            memcpy(&next[12 * f], out, sizeof out);
        }
        free(m.tri);
        free(ca);
        free(cb);
        free(cv);
        m.tri = next;
        m.nt *= 4;
    }
    for (uint32_t i = 0; i < m.nv; ++i)
        for (int k = 0; k < 3; ++k)
            m.pos[3 * i + k] = m.pos[3 * i + k] * radius + centre[k];
    return m;
}

/* n triangles in [offset, offset + 1]^3: mostly small, some large, every 50th
 * a sliver (aspect ~1e6), every 97th degenerate (a repeated vertex). */
static inline test_mesh mesh_soup(uint32_t n, float offset, uint64_t seed) {
    test_mesh m = {malloc(36ull * n), malloc(12ull * n), 3 * n, n};
    for (uint32_t t = 0; t < n; ++t) {
        float c[3], size = (t % 10 == 0) ? 0.5f : 0.05f;
        for (int k = 0; k < 3; ++k)
            c[k] = check_randf(&seed);
        for (int v = 0; v < 3; ++v)
            for (int k = 0; k < 3; ++k) {
                float x = c[k] + (check_randf(&seed) - 0.5f) * size;
                m.pos[9 * t + 3 * v + k] = fminf(fmaxf(x, 0.0f), 1.0f) + offset;
            }
        if (t % 50 == 1) /* sliver: third vertex a hair off the first edge */
            for (int k = 0; k < 3; ++k)
                m.pos[9 * t + 6 + k] =
                    0.5f * (m.pos[9 * t + k] + m.pos[9 * t + 3 + k]) + (k == 1 ? 1e-7f : 0.0f);
        if (t % 97 == 2)
            for (int k = 0; k < 3; ++k)
                m.pos[9 * t + 6 + k] = m.pos[9 * t + k];
        for (int v = 0; v < 3; ++v)
            m.tri[3 * t + v] = 3 * t + v;
    }
    return m;
}

/* count quads of 4 corners each (12 floats), each as two triangles. */
static inline test_mesh mesh_quads(const float *quads, uint32_t count) {
    test_mesh m = {malloc(48ull * count), malloc(24ull * count), 4 * count, 2 * count};
    memcpy(m.pos, quads, 48ull * count);
    for (uint32_t q = 0; q < count; ++q) {
        const uint32_t t[6] = {0, 1, 2, 0, 2, 3};
        for (int k = 0; k < 6; ++k)
            m.tri[6 * q + k] = 4 * q + t[k];
    }
    return m;
}

static inline void mesh_free(test_mesh *m) {
    free(m->pos);
    free(m->tri);
}

#endif
