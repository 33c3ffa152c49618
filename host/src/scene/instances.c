/* Meshes and instances: validation, consistency with the flat arrays, the
 * identity instance of a scene built from arrays. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "scene/instances.h"

void vct_instance_transform_point(const float m[12], const float *p, float *out) {
    for (int r = 0; r < 3; ++r)
        out[r] = (float)((double)m[4 * r] * p[0] + (double)m[4 * r + 1] * p[1] +
                         (double)m[4 * r + 2] * p[2] + m[4 * r + 3]);
}

const char *vct_scene_name(const vct_scene *s) {
    return s->source[0] ? s->source : "(arrays)";
}

int vct_instances_validate(const vct_scene *s, vct_error *err) {
    for (uint32_t i = 0; i < s->instance_count; ++i) {
        const vct_instance *in = &s->instances[i];
        if (in->mesh >= s->mesh_count)
            return vct_fail(err, VCT_ERR_INPUT, "scene %s: instance %u places mesh %u of %u",
                            vct_scene_name(s), i, in->mesh, s->mesh_count);
        const vct_mesh *m = &s->meshes[in->mesh];
        if ((uint64_t)in->first_triangle + m->triangle_count > s->triangle_count ||
            (uint64_t)in->first_vertex + m->vertex_count > s->vertex_count)
            return vct_fail(err, VCT_ERR_INPUT,
                            "scene %s: instance %u's triangles or vertices lie past the scene's",
                            vct_scene_name(s), i);
        for (int k = 0; k < 12; ++k)
            if (!isfinite(in->transform[k]))
                return vct_fail(err, VCT_ERR_INPUT,
                                "scene %s: instance %u's transform has a value that is not finite",
                                vct_scene_name(s), i);
        for (uint32_t t = 0; t < m->triangle_count; ++t)
            for (int k = 0; k < 3; ++k)
                if (m->triangles[3 * t + k] >= m->vertex_count ||
                    s->triangles[3 * (in->first_triangle + t) + k] !=
                        in->first_vertex + m->triangles[3 * t + k])
                    return vct_fail(err, VCT_ERR_INPUT,
                                    "scene %s: instance %u's triangle %u is not its mesh's",
                                    vct_scene_name(s), i, t);
    }
    return VCT_OK;
}

int vct_instances_consistent(const vct_scene *s) {
    for (uint32_t i = 0; i < s->instance_count; ++i) {
        const vct_instance *in = &s->instances[i];
        const vct_mesh *m = &s->meshes[in->mesh];
        for (uint32_t v = 0; v < m->vertex_count; ++v) {
            float p[3];
            vct_instance_transform_point(in->transform, &m->positions[3 * v], p);
            if (memcmp(p, &s->positions[3ull * (in->first_vertex + v)], sizeof p) != 0)
                return 0;
        }
    }
    return 1;
}

int vct_instances_shared(const vct_scene *s) {
    uint8_t *seen = calloc(s->mesh_count + 1, 1);
    int shared = 0;
    for (uint32_t i = 0; seen && i < s->instance_count && !shared; ++i)
        shared = seen[s->instances[i].mesh]++ != 0;
    free(seen);
    return shared;
}

int vct_instances_identity(vct_scene *s, vct_error *err) {
    s->meshes = calloc(1, sizeof *s->meshes);
    s->instances = calloc(1, sizeof *s->instances);
    vct_mesh *m = s->meshes;
    if (m) {
        m->positions = malloc(12ull * s->vertex_count + 16);
        m->triangles = malloc(12ull * s->triangle_count + 16);
    }
    if (!m || !s->instances || !m->positions || !m->triangles) {
        vct_instances_release(s);
        return vct_fail(err, VCT_ERR_MEMORY, "scene: out of host memory");
    }
    m->vertex_count = s->vertex_count;
    m->triangle_count = s->triangle_count;
    memcpy(m->positions, s->positions, 12ull * s->vertex_count);
    memcpy(m->triangles, s->triangles, 12ull * s->triangle_count);
    s->mesh_count = s->instance_count = 1;
    s->instances[0].node = VCT_NO_NODE;
    static const float identity[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    memcpy(s->instances[0].transform, identity, sizeof identity);
    return VCT_OK;
}

void vct_instances_release(vct_scene *s) {
    for (uint32_t m = 0; s->meshes && m < s->mesh_count; ++m) {
        free(s->meshes[m].positions);
        free(s->meshes[m].triangles);
    }
    free(s->meshes);
    free(s->instances);
    s->meshes = NULL;
    s->instances = NULL;
    s->mesh_count = s->instance_count = 0;
}
