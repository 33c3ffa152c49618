/* Host scene: flat arrays, validation, bounds and a default camera. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "runtime/runtime.h"
#include "scene/instances.h"

vct_material vct_material_default(void) {
    vct_material m;
    memset(&m, 0, sizeof m);
    snprintf(m.name, sizeof m.name, "default");
    m.albedo[0] = m.albedo[1] = m.albedo[2] = 0.8f;
    m.roughness = 1.0f;
    m.ior = 1.5f;
    m.alpha = 1.0f;
    return m;
}

void vct_scene_release(vct_scene *scene) {
    if (!scene)
        return;
    free(scene->positions);
    free(scene->triangles);
    free(scene->triangle_material);
    free(scene->materials);
    free(scene->lights);
    free(scene->uvs);
    for (uint32_t t = 0; t < scene->texture_count; ++t)
        free(scene->textures[t].rgba);
    free(scene->textures);
    vct_instances_release(scene);
    for (uint32_t a = 0; scene->animations && a < scene->animation_count; ++a) {
        vct_animation_info *an = &scene->animations[a];
        for (uint32_t c = 0; an->channel && c < an->channels; ++c) {
            vct_animation_channel *ch = &an->channel[c];
            free(ch->translation_times);
            free(ch->translations);
            free(ch->rotation_times);
            free(ch->rotations);
            free(ch->scale_times);
            free(ch->scales);
            free(ch->translation_tangents);
            free(ch->rotation_tangents);
            free(ch->scale_tangents);
        }
        free(an->channel);
    }
    free(scene->animations);
    free(scene->nodes);
    free(scene->light_attachments);
    free(scene);
}

static int finite3(const float *v) {
    return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]);
}

static int check_light(const char *src, uint32_t index, const vct_light *l, vct_error *err) {
    if (!finite3(l->position) || !finite3(l->direction) || !finite3(l->color) ||
        !isfinite(l->radius))
        return vct_fail(err, VCT_ERR_INPUT, "scene %s: light %u has a non-finite value", src,
                        index);
    const int directional = l->type == VCT_LIGHT_DIRECTIONAL;
    if (!(l->radius >= 0.0f && l->radius < (directional ? 1.0f : FLT_MAX)))
        return vct_fail(err, VCT_ERR_INPUT,
                        "scene %s: light %u has radius %g: give 0 (a point) or more%s", src, index,
                        l->radius, directional ? ", below 1 radian for a directional light" : "");
    return VCT_OK;
}

vct_status vct_scene_validate(vct_scene *s, vct_error *err) {
    const char *src = s->source[0] ? s->source : "(arrays)";
    if (s->triangle_count == 0)
        return vct_fail(err, VCT_ERR_INPUT,
                        "scene %s: no triangles to render (an empty scene, or only points and "
                        "lines)",
                        src);
    if (s->material_count == 0)
        return vct_fail(err, VCT_ERR_INPUT, "scene %s: no materials", src);
    for (uint32_t i = 0; i < s->vertex_count; ++i)
        if (!finite3(&s->positions[3 * i]))
            return vct_fail(err, VCT_ERR_INPUT,
                            "scene %s: vertex %u is not finite (%g, %g, %g): fix the file", src, i,
                            s->positions[3 * i], s->positions[3 * i + 1], s->positions[3 * i + 2]);
    s->degenerate_triangles = 0;
    float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (uint32_t t = 0; t < s->triangle_count; ++t) {
        const uint32_t *tri = &s->triangles[3 * t];
        for (int k = 0; k < 3; ++k)
            if (tri[k] >= s->vertex_count)
                return vct_fail(err, VCT_ERR_INPUT,
                                "scene %s: triangle %u uses vertex %u but there are only %u "
                                "vertices",
                                src, t, tri[k], s->vertex_count);
        if (s->triangle_material[t] >= s->material_count)
            return vct_fail(err, VCT_ERR_INPUT,
                            "scene %s: triangle %u uses material %u but there are only %u", src, t,
                            s->triangle_material[t], s->material_count);
        const float *a = &s->positions[3 * tri[0]], *b = &s->positions[3 * tri[1]],
                    *c = &s->positions[3 * tri[2]];
        double e1[3], e2[3];
        for (int k = 0; k < 3; ++k) {
            e1[k] = (double)b[k] - a[k];
            e2[k] = (double)c[k] - a[k];
            lo[k] = fminf(lo[k], fminf(a[k], fminf(b[k], c[k])));
            hi[k] = fmaxf(hi[k], fmaxf(a[k], fmaxf(b[k], c[k])));
        }
        double cx = e1[1] * e2[2] - e1[2] * e2[1], cy = e1[2] * e2[0] - e1[0] * e2[2],
               cz = e1[0] * e2[1] - e1[1] * e2[0];
        if (cx == 0.0 && cy == 0.0 && cz == 0.0)
            s->degenerate_triangles++;
    }
    for (uint32_t m = 0; m < s->material_count; ++m) {
        const vct_material *mat = &s->materials[m];
        if (!finite3(mat->albedo) || !finite3(mat->emission) || !finite3(mat->specular) ||
            !isfinite(mat->roughness) || !isfinite(mat->ior))
            return vct_fail(err, VCT_ERR_INPUT, "scene %s: material %u (%s) has a non-finite value",
                            src, m, mat->name);
        if (!(mat->alpha_cutoff >= 0.0f && mat->alpha_cutoff <= 1.0f) ||
            (mat->alpha_cutoff > 0.0f && !(mat->alpha >= 0.0f && mat->alpha <= 1.0f)))
            return vct_fail(err, VCT_ERR_INPUT,
                            "scene %s: material %u (%s) has alpha %g and alpha cutoff %g: give "
                            "both in [0, 1]",
                            src, m, mat->name, mat->alpha, mat->alpha_cutoff);
        if (mat->albedo_texture > s->texture_count)
            return vct_fail(err, VCT_ERR_INPUT,
                            "scene %s: material %u (%s) uses texture %u but there are only %u", src,
                            m, mat->name, mat->albedo_texture - 1, s->texture_count);
    }
    for (uint32_t i = 0; s->uvs && i < 2 * s->vertex_count; ++i)
        if (!isfinite(s->uvs[i]))
            return vct_fail(err, VCT_ERR_INPUT,
                            "scene %s: vertex %u has a non-finite texture coordinate", src, i / 2);
    for (uint32_t l = 0; l < s->light_count; ++l) {
        int rc = check_light(src, l, &s->lights[l], err);
        if (rc)
            return rc;
    }
    if (!finite3(s->ambient) || s->ambient[0] < 0 || s->ambient[1] < 0 || s->ambient[2] < 0)
        return vct_fail(err, VCT_ERR_INPUT,
                        "scene %s: ambient radiance (%g %g %g) must be finite and not negative",
                        src, s->ambient[0], s->ambient[1], s->ambient[2]);
    for (int k = 0; k < 3; ++k) {
        s->bounds_min[k] = lo[k];
        s->bounds_max[k] = hi[k];
    }
    return vct_instances_validate(s, err);
}

vct_scene *vct_scene_from_arrays(const float *positions, uint32_t vertex_count,
                                 const uint32_t *triangles, uint32_t triangle_count,
                                 const uint32_t *triangle_material, const vct_material *materials,
                                 uint32_t material_count, vct_error *err) {
    vct_scene *s = calloc(1, sizeof *s);
    if (!s) {
        vct_fail(err, VCT_ERR_MEMORY, "scene: out of host memory");
        return NULL;
    }
    s->vertex_count = vertex_count;
    s->triangle_count = triangle_count;
    s->material_count = material_count ? material_count : 1;
    s->positions = malloc(3ull * vertex_count * sizeof(float) + 16);
    s->triangles = malloc(3ull * triangle_count * sizeof(uint32_t) + 16);
    s->triangle_material = calloc(triangle_count + 1ull, sizeof(uint32_t));
    s->materials = malloc(s->material_count * sizeof(vct_material));
    if (!s->positions || !s->triangles || !s->triangle_material || !s->materials) {
        vct_scene_release(s);
        vct_fail(err, VCT_ERR_MEMORY, "scene: out of host memory for %u triangles", triangle_count);
        return NULL;
    }
    memcpy(s->positions, positions, 3ull * vertex_count * sizeof(float));
    memcpy(s->triangles, triangles, 3ull * triangle_count * sizeof(uint32_t));
    if (triangle_material)
        memcpy(s->triangle_material, triangle_material, triangle_count * sizeof(uint32_t));
    if (materials && material_count)
        memcpy(s->materials, materials, material_count * sizeof(vct_material));
    else
        s->materials[0] = vct_material_default();
    if (vct_scene_validate(s, err) != VCT_OK || vct_instances_identity(s, err) != VCT_OK) {
        vct_scene_release(s);
        return NULL;
    }
    vct_scene_default_camera(s, &s->camera);
    return s;
}

vct_status vct_scene_add_light(vct_scene *s, const vct_light *light, vct_error *err) {
    int rc = check_light(s->source[0] ? s->source : "(arrays)", s->light_count, light, err);
    if (rc)
        return rc;
    vct_light *grown = realloc(s->lights, (s->light_count + 1) * sizeof *grown);
    if (!grown)
        return vct_fail(err, VCT_ERR_MEMORY, "scene: out of host memory for lights");
    s->lights = grown;
    s->lights[s->light_count++] = *light;
    return VCT_OK;
}

void vct_scene_default_camera(const vct_scene *s, vct_camera *cam) {
    float center[3], radius = 0.0f;
    for (int k = 0; k < 3; ++k) {
        center[k] = 0.5f * (s->bounds_min[k] + s->bounds_max[k]);
        float h = 0.5f * (s->bounds_max[k] - s->bounds_min[k]);
        radius += h * h;
    }
    radius = sqrtf(radius);
    if (!(radius > 0.0f))
        radius = 1.0f;
    cam->fov_y_deg = 40.0f;
    float dist = radius / sinf(0.5f * cam->fov_y_deg * VCT_PI_F / 180.0f);
    for (int k = 0; k < 3; ++k) {
        cam->look_at[k] = center[k];
        cam->position[k] = center[k];
        cam->up[k] = 0.0f;
    }
    cam->position[2] += dist;
    cam->up[1] = 1.0f;
}
