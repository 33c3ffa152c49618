/* Scene data in the kernels' layout: camera, lights and materials. */
#include <cglm/vec3.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "runtime/runtime.h"
#include "scene/scene_device.h"

int vct_camera_desc_make(const vct_camera *cam, int width, int height, vct_camera_desc *d,
                         vct_error *err) {
    vec3 f, r, u, up = {cam->up[0], cam->up[1], cam->up[2]};
    vec3 eye = {cam->position[0], cam->position[1], cam->position[2]};
    vec3 at = {cam->look_at[0], cam->look_at[1], cam->look_at[2]};
    glm_vec3_sub(at, eye, f);
    glm_vec3_normalize(f);
    glm_vec3_crossn(f, up, r);
    glm_vec3_cross(r, f, u);
    float rl = glm_vec3_norm2(r), fl = glm_vec3_norm2(f);
    if (!(fl > 0.5f) || !(rl > 0.5f))
        return vct_fail(err, VCT_ERR_INPUT,
                        "camera: position, look-at and up do not define a view (look-at equals "
                        "the position, or up is parallel to the view direction)");
    if (!(cam->fov_y_deg > 0.0f && cam->fov_y_deg < 179.0f))
        return vct_fail(err, VCT_ERR_INPUT, "camera: field of view %g degrees is outside (0, 179)",
                        cam->fov_y_deg);
    if (width <= 0 || height <= 0 || width > 32768 || height > 32768)
        return vct_fail(err, VCT_ERR_INPUT, "camera: image size %dx%d is outside 1..32768", width,
                        height);
    memset(d, 0, sizeof *d);
    for (int k = 0; k < 3; ++k) {
        d->position.s[k] = cam->position[k];
        d->forward.s[k] = f[k];
        d->right.s[k] = r[k];
        d->up.s[k] = u[k];
    }
    d->position.s[3] = tanf(0.5f * cam->fov_y_deg * VCT_PI_F / 180.0f);
    d->forward.s[3] = (float)width / (float)height;
    d->size.s[0] = (cl_uint)width;
    d->size.s[1] = (cl_uint)height;
    return VCT_OK;
}

void vct_light_desc_make(const vct_light *l, vct_light_desc *d) {
    memset(d, 0, sizeof *d);
    vec3 dir = {l->direction[0], l->direction[1], l->direction[2]};
    glm_vec3_normalize(dir);
    for (int k = 0; k < 3; ++k) {
        d->position.s[k] = l->position[k];
        d->direction.s[k] = dir[k];
        d->color.s[k] = l->color[k];
    }
    d->position.s[3] = (float)l->type;
    d->direction.s[3] = cosf(l->outer_cone);
    d->color.s[3] = cosf(l->inner_cone < l->outer_cone ? l->inner_cone : l->outer_cone);
    d->shape.s[0] = l->type == VCT_LIGHT_DIRECTIONAL ? tanf(l->radius) : l->radius;
}

void vct_material_desc_make(const vct_material *m, vct_material_desc *d) {
    memset(d, 0, sizeof *d);
    for (int k = 0; k < 3; ++k) {
        d->albedo.s[k] = m->albedo[k];
        d->emission.s[k] = m->emission[k];
        d->specular.s[k] = m->specular[k];
    }
    d->albedo.s[3] = m->metallic;
    d->emission.s[3] = m->roughness;
    d->specular.s[3] = m->transmission;
    d->extra.s[0] = m->ior;
}

void vct_scene_buffers_release(vct_context *ctx, vct_scene_buffers *b) {
    vct_buffer_release(ctx, b->materials);
    vct_buffer_release(ctx, b->tri_material);
    vct_buffer_release(ctx, b->lights);
}

int vct_scene_buffers_make(vct_context *ctx, const vct_scene *s, const char *stage,
                           vct_scene_buffers *b, vct_error *err) {
    memset(b, 0, sizeof *b);
    vct_material_desc *mats = calloc(s->material_count, sizeof *mats);
    vct_light_desc *lights = calloc(s->light_count + 1, sizeof *lights);
    if (!mats || !lights) {
        free(mats);
        free(lights);
        return vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory", stage);
    }
    for (uint32_t i = 0; i < s->material_count; ++i)
        vct_material_desc_make(&s->materials[i], &mats[i]);
    for (uint32_t i = 0; i < s->light_count; ++i)
        vct_light_desc_make(&s->lights[i], &lights[i]);
    b->light_count = s->light_count;
    b->materials = vct_buffer_create(ctx, stage, "materials", sizeof *mats * s->material_count,
                                     CL_MEM_READ_ONLY, mats, err);
    b->tri_material =
        b->materials ? vct_buffer_create(ctx, stage, "triangle materials", 4ull * s->triangle_count,
                                         CL_MEM_READ_ONLY, s->triangle_material, err)
                     : NULL;
    b->lights = b->tri_material
                    ? vct_buffer_create(ctx, stage, "lights", sizeof *lights * (s->light_count + 1),
                                        CL_MEM_READ_ONLY, lights, err)
                    : NULL;
    free(mats);
    free(lights);
    if (!b->lights) {
        vct_scene_buffers_release(ctx, b);
        return err->status;
    }
    return VCT_OK;
}
