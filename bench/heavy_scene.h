/* A heavy procedural scene for benchmarks: the Cornell box with 80
 * icospheres of 1280 triangles each (102,430 triangles), and its light. */
#ifndef VCT_HEAVY_SCENE_H
#define VCT_HEAVY_SCENE_H

#include "mesh_gen.h"

static vct_scene *heavy_scene_load(const char *source_dir, vct_error *err) {
    char path[1024];
    snprintf(path, sizeof path, "%s/scenes/cornell_box.gltf", source_dir);
    vct_scene *box = vct_scene_load(path, err);
    if (!box)
        return NULL;
    const int nx = 5, ny = 4, nz = 4, level = 3;
    const uint32_t per = 20u << (2 * level);
    uint32_t nt = box->triangle_count + (uint32_t)(nx * ny * nz) * per;
    uint32_t nv = box->vertex_count;
    float *pos = NULL;
    uint32_t *tri = malloc(12ull * nt), *mat = malloc(4ull * nt);
    memcpy(tri, box->triangles, 12ull * box->triangle_count);
    memcpy(mat, box->triangle_material, 4ull * box->triangle_count);
    pos = malloc(12ull * box->vertex_count);
    memcpy(pos, box->positions, 12ull * box->vertex_count);
    uint32_t t = box->triangle_count;
    for (int i = 0; i < nx * ny * nz; ++i) {
        float c[3] = {70.0f + 104.0f * (float)(i % nx), 70.0f + 130.0f * (float)((i / nx) % ny),
                      80.0f + 130.0f * (float)(i / (nx * ny))};
        test_mesh m = mesh_icosphere(level, 38.0f, c);
        pos = realloc(pos, 12ull * (nv + m.nv));
        memcpy(pos + 3ull * nv, m.pos, 12ull * m.nv);
        for (uint32_t f = 0; f < m.nt; ++f, ++t) {
            for (int k = 0; k < 3; ++k)
                tri[3 * t + k] = nv + m.tri[3 * f + k];
            mat[t] = (uint32_t)i % box->material_count;
        }
        nv += m.nv;
        mesh_free(&m);
    }
    vct_scene *s =
        vct_scene_from_arrays(pos, nv, tri, nt, mat, box->materials, box->material_count, err);
    if (s) {
        s->camera = box->camera;
        for (uint32_t l = 0; l < box->light_count; ++l)
            vct_scene_add_light(s, &box->lights[l], err);
    }
    free(pos);
    free(tri);
    free(mat);
    vct_scene_release(box);
    return s;
}

#endif
