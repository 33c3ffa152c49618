/* Placing instances: a new one, or a new transform for one, rewriting its
 * vertices in the flat arrays as loading made them. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "scene/instances.h"

vct_status vct_instance_place(vct_scene *s, uint32_t instance, const float transform[12],
                              vct_error *err) {
    if (instance >= s->instance_count)
        return vct_fail(err, VCT_ERR_INPUT, "scene %s: no instance %u (the scene has %u)",
                        vct_scene_name(s), instance, s->instance_count);
    for (int k = 0; k < 12; ++k)
        if (!isfinite(transform[k]))
            return vct_fail(err, VCT_ERR_INPUT,
                            "scene %s: instance %u: transform value %d is %g, not finite",
                            vct_scene_name(s), instance, k, transform[k]);
    vct_instance *in = &s->instances[instance];
    const vct_mesh *m = &s->meshes[in->mesh];
    float *moved = malloc(12ull * (m->vertex_count ? m->vertex_count : 1));
    if (!moved)
        return vct_fail(err, VCT_ERR_MEMORY, "scene: out of host memory");
    for (uint32_t v = 0; v < m->vertex_count; ++v) {
        vct_instance_transform_point(transform, &m->positions[3 * v], &moved[3 * v]);
        if (!isfinite(moved[3 * v]) || !isfinite(moved[3 * v + 1]) || !isfinite(moved[3 * v + 2])) {
            free(moved);
            return vct_fail(err, VCT_ERR_INPUT,
                            "scene %s: instance %u: the transform takes vertex %u beyond float "
                            "range",
                            vct_scene_name(s), instance, v);
        }
    }
    memcpy(&s->positions[3ull * in->first_vertex], moved, 12ull * m->vertex_count);
    memcpy(in->transform, transform, sizeof in->transform);
    free(moved);
    return VCT_OK;
}

vct_status vct_scene_set_instance_transform(vct_scene *s, uint32_t instance,
                                            const float transform[12], vct_error *err) {
    const vct_status rc = vct_instance_place(s, instance, transform, err);
    return rc == VCT_OK ? vct_scene_validate(s, err) : rc;
}

/* Grows *p to hold `count` elements of `size` bytes. */
static int grow_to(void **p, size_t count, size_t size) {
    void *q = realloc(*p, count * size + 16);
    if (!q)
        return 0;
    *p = q;
    return 1;
}

vct_status vct_scene_add_instance(vct_scene *s, uint32_t mesh, const float transform[12],
                                  vct_error *err) {
    const vct_instance *model = NULL;
    for (uint32_t i = 0; i < s->instance_count && !model; ++i)
        if (s->instances[i].mesh == mesh)
            model = &s->instances[i];
    if (mesh >= s->mesh_count || !model)
        return vct_fail(err, VCT_ERR_INPUT, "scene %s: no placed mesh %u (the scene has %u)",
                        vct_scene_name(s), mesh, s->mesh_count);
    const vct_mesh *m = &s->meshes[mesh];
    const uint64_t vertices = (uint64_t)s->vertex_count + m->vertex_count,
                   triangles = (uint64_t)s->triangle_count + m->triangle_count;
    if (vertices > UINT32_MAX / 2 || triangles > UINT32_MAX / 4)
        return vct_fail(err, VCT_ERR_INPUT, "scene %s: more triangles than vct indexes",
                        vct_scene_name(s));
    const vct_instance placed = *model; /* the arrays below may move it */
    if (!grow_to((void **)&s->positions, vertices, 12) ||
        !grow_to((void **)&s->triangles, triangles, 12) ||
        !grow_to((void **)&s->triangle_material, triangles, 4) ||
        (s->uvs && !grow_to((void **)&s->uvs, vertices, 8)) ||
        !grow_to((void **)&s->instances, s->instance_count + 1ull, sizeof(vct_instance)))
        return vct_fail(err, VCT_ERR_MEMORY, "scene: out of host memory");
    vct_instance *in = &s->instances[s->instance_count];
    memset(in, 0, sizeof *in);
    in->mesh = mesh;
    in->node = VCT_NO_NODE; /* placed by the host, not by the file's tree */
    in->first_triangle = s->triangle_count;
    in->first_vertex = s->vertex_count;
    memcpy(in->transform, placed.transform, sizeof in->transform);
    memcpy(&s->positions[3ull * in->first_vertex], &s->positions[3ull * placed.first_vertex],
           12ull * m->vertex_count);
    if (s->uvs)
        memcpy(&s->uvs[2ull * in->first_vertex], &s->uvs[2ull * placed.first_vertex],
               8ull * m->vertex_count);
    for (uint32_t t = 0; t < m->triangle_count; ++t) {
        for (int k = 0; k < 3; ++k)
            s->triangles[3ull * (in->first_triangle + t) + k] =
                in->first_vertex + m->triangles[3 * t + k];
        s->triangle_material[in->first_triangle + t] =
            s->triangle_material[placed.first_triangle + t];
    }
    s->vertex_count = (uint32_t)vertices;
    s->triangle_count = (uint32_t)triangles;
    s->instance_count++;
    const int rc = vct_scene_set_instance_transform(s, s->instance_count - 1, transform, err);
    if (rc != VCT_OK) { /* take it back */
        s->instance_count--;
        s->vertex_count = in->first_vertex;
        s->triangle_count = in->first_triangle;
    }
    return rc;
}
