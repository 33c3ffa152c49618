/* Digests of the host scene's parts (XXH3, 64 bits): a commit's cost is
 * reading the scene once, far below any upload it saves. */
#include <string.h>
#include <xxhash.h>

#include "device_scene/scene_digest.h"
#include "scene/scene_resident.h"

static void add(XXH3_state_t *h, const void *data, size_t bytes) {
    if (data && bytes)
        XXH3_64bits_update(h, data, bytes);
}

static void add_u32(XXH3_state_t *h, uint32_t value) {
    XXH3_64bits_update(h, &value, sizeof value);
}

static uint64_t geometry(XXH3_state_t *h, const vct_scene *s) {
    XXH3_64bits_reset(h);
    add_u32(h, s->vertex_count);
    add_u32(h, s->triangle_count);
    add(h, s->triangles, 12ull * s->triangle_count);
    add(h, s->triangle_material, 4ull * s->triangle_count);
    add_u32(h, s->uvs != NULL);
    add(h, s->uvs, 8ull * s->vertex_count);
    add_u32(h, s->mesh_count);
    for (uint32_t m = 0; m < s->mesh_count; ++m) {
        const vct_mesh *x = &s->meshes[m];
        add_u32(h, x->vertex_count);
        add_u32(h, x->triangle_count);
        add(h, x->positions, 12ull * x->vertex_count);
        add(h, x->triangles, 12ull * x->triangle_count);
    }
    add_u32(h, s->instance_count);
    for (uint32_t i = 0; i < s->instance_count; ++i) {
        add_u32(h, s->instances[i].mesh);
        add_u32(h, s->instances[i].first_triangle);
        add_u32(h, s->instances[i].first_vertex);
    }
    return XXH3_64bits_digest(h);
}

static uint64_t positions(XXH3_state_t *h, const vct_scene *s) {
    XXH3_64bits_reset(h);
    add(h, s->positions, 12ull * s->vertex_count);
    for (uint32_t i = 0; i < s->instance_count; ++i)
        add(h, s->instances[i].transform, sizeof s->instances[i].transform);
    return XXH3_64bits_digest(h);
}

static uint64_t textures(XXH3_state_t *h, const vct_scene *s) {
    XXH3_64bits_reset(h);
    add_u32(h, s->texture_count);
    for (uint32_t t = 0; t < s->texture_count; ++t) {
        const vct_texture *x = &s->textures[t];
        add_u32(h, (uint32_t)x->width);
        add_u32(h, (uint32_t)x->height);
        add(h, x->rgba, 16ull * x->width * x->height);
    }
    return XXH3_64bits_digest(h);
}

/* The fields the acceleration structure's alpha masks read; the texels
 * count only when some material is masked. */
static uint64_t masks(XXH3_state_t *h, const vct_scene *s, uint64_t texels) {
    XXH3_64bits_reset(h);
    int masked = 0;
    for (uint32_t m = 0; m < s->material_count; ++m) {
        const vct_material *x = &s->materials[m];
        add(h, &x->alpha, sizeof x->alpha);
        add(h, &x->alpha_cutoff, sizeof x->alpha_cutoff);
        add_u32(h, x->albedo_texture);
        add_u32(h, x->texture_wrap);
        masked |= x->alpha_cutoff > 0.0f;
    }
    if (masked)
        add(h, &texels, sizeof texels);
    return XXH3_64bits_digest(h);
}

void vct_scene_digest_make(const vct_scene *s, vct_scene_digest *d) {
    XXH3_state_t *h = XXH3_createState();
    memset(d, 0, sizeof *d);
    if (!h) /* no memory: digests that never match, so everything is rebuilt */
        return;
    d->geometry = geometry(h, s);
    d->positions = positions(h, s);
    d->textures = textures(h, s);
    d->materials = XXH3_64bits(s->materials, sizeof *s->materials * s->material_count);
    d->masks = masks(h, s, d->textures);
    XXH3_64bits_reset(h);
    add_u32(h, s->light_count);
    add(h, s->lights, sizeof *s->lights * s->light_count);
    add(h, s->ambient, sizeof s->ambient);
    d->lights = XXH3_64bits_digest(h);
    XXH3_64bits_reset(h);
    add(h, &s->camera, sizeof s->camera);
    add_u32(h, (uint32_t)s->has_camera);
    d->camera = XXH3_64bits_digest(h);
    XXH3_freeState(h);
}

unsigned vct_scene_digest_changes(const vct_scene_digest *a, const vct_scene_digest *b) {
    if (!a->geometry || !b->geometry)
        return VCT_CHANGED_ALL;
    return (a->geometry != b->geometry ? VCT_CHANGED_GEOMETRY : 0u) |
           (a->materials != b->materials ? VCT_CHANGED_MATERIALS : 0u) |
           (a->textures != b->textures ? VCT_CHANGED_TEXTURES : 0u) |
           (a->lights != b->lights ? VCT_CHANGED_LIGHTS : 0u) |
           (a->positions != b->positions ? VCT_CHANGED_POSITIONS : 0u) |
           (a->camera != b->camera ? VCT_CHANGED_CAMERA : 0u);
}
