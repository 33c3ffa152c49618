/* Scene data in the kernels' layout: camera, lights and materials. */
#include <cglm/vec3.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "runtime/runtime.h"
#include "scene/scene_device.h"
#include "scene/scene_resident.h"

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
    d->extra.s[1] = (float)m->albedo_texture; /* exact: far below 2^24 */
    d->extra.s[2] = (float)m->texture_wrap;
    /* masked where alpha * texture alpha < cutoff, that is texture alpha < cutoff / alpha */
    if (m->alpha_cutoff > 0.0f)
        d->extra.s[3] = m->alpha > 0.0f ? m->alpha_cutoff / m->alpha : INFINITY;
}

static size_t buffer_bytes(cl_mem mem) {
    size_t bytes = 0;
    clGetMemObjectInfo(mem, CL_MEM_SIZE, sizeof bytes, &bytes, NULL);
    return bytes;
}

/* The texture buffers of b (see scene_device.h). */
static int texture_buffers_make(vct_context *ctx, const vct_scene *s, const char *stage,
                                vct_scene_buffers *b, vct_error *err) {
    size_t texels = 0;
    for (uint32_t t = 0; t < s->texture_count; ++t)
        texels += (size_t)s->textures[t].width * s->textures[t].height;
    /* materials name textures by index: with any texture, every table entry
     * and every triangle's coordinates exist (0 where the file has none) */
    const int textured = s->texture_count > 0;
    const size_t n_texels = textured ? texels : 1, n_table = textured ? s->texture_count : 1,
                 n_uvs = textured ? 2ull * s->triangle_count : 2;
    float *tx = calloc(n_texels, 16), *uv = calloc(n_uvs, 16);
    cl_uint *table = calloc(n_table, 16);
    int rc =
        tx && uv && table ? VCT_OK : vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory", stage);
    size_t at = 0;
    for (uint32_t t = 0; rc == VCT_OK && textured && t < s->texture_count; ++t) {
        const vct_texture *x = &s->textures[t];
        memcpy(tx + 4 * at, x->rgba, 16ull * x->width * x->height);
        table[4 * t] = (cl_uint)at;
        table[4 * t + 1] = (cl_uint)x->width;
        table[4 * t + 2] = (cl_uint)x->height;
        at += (size_t)x->width * x->height;
    }
    for (uint32_t t = 0; rc == VCT_OK && textured && s->uvs && t < s->triangle_count; ++t)
        for (int k = 0; k < 3; ++k)
            memcpy(uv + 8ull * t + 2 * k, &s->uvs[2 * s->triangles[3 * t + k]], 8);
    if (rc == VCT_OK && texels > UINT32_MAX)
        rc = vct_fail(err, VCT_ERR_INPUT, "%s: the textures hold %zu texels, over 2^32", stage,
                      texels);
    if (rc == VCT_OK)
        b->texels = vct_buffer_create(ctx, stage, "texture texels", 16ull * n_texels,
                                      CL_MEM_READ_ONLY, tx, err);
    if (b->texels)
        b->texture_table = vct_buffer_create(ctx, stage, "texture table", 16ull * n_table,
                                             CL_MEM_READ_ONLY, table, err);
    if (b->texture_table)
        b->tri_uvs = vct_buffer_create(ctx, stage, "triangle texture coordinates", 16ull * n_uvs,
                                       CL_MEM_READ_ONLY, uv, err);
    if (rc == VCT_OK && !b->tri_uvs)
        rc = err->status;
    free(tx);
    free(uv);
    free(table);
    return rc;
}

int vct_scene_texture_args(cl_kernel k, int first, const vct_scene_buffers *b, const char *stage,
                           vct_error *err) {
    return vct_set_args(err, stage, k, first, 3, VCT_ARG_OF(b->texels),
                        VCT_ARG_OF(b->texture_table), VCT_ARG_OF(b->tri_uvs));
}

void vct_scene_buffers_release(vct_context *ctx, vct_scene_buffers *b) {
    if (b->borrowed)
        return;
    vct_buffer_release(ctx, b->materials);
    vct_buffer_release(ctx, b->tri_material);
    vct_buffer_release(ctx, b->lights);
    vct_buffer_release(ctx, b->texels);
    vct_buffer_release(ctx, b->texture_table);
    vct_buffer_release(ctx, b->tri_uvs);
}

/* The kernels' material table and light list of s (lights: one more
 * element, so that a scene without lights still has a buffer). */
static int descs_make(const vct_scene *s, const char *stage, vct_material_desc **mats,
                      vct_light_desc **lights, vct_error *err) {
    *mats = calloc(s->material_count + 1, sizeof **mats);
    *lights = calloc(s->light_count + 1, sizeof **lights);
    if (!*mats || !*lights) {
        free(*mats);
        free(*lights);
        return vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory", stage);
    }
    for (uint32_t i = 0; i < s->material_count; ++i)
        vct_material_desc_make(&s->materials[i], &(*mats)[i]);
    for (uint32_t i = 0; i < s->light_count; ++i)
        vct_light_desc_make(&s->lights[i], &(*lights)[i]);
    return VCT_OK;
}

static int upload(vct_context *ctx, const vct_scene *s, const char *stage, vct_scene_buffers *b,
                  vct_error *err) {
    memset(b, 0, sizeof *b);
    vct_material_desc *mats;
    vct_light_desc *lights;
    if (descs_make(s, stage, &mats, &lights, err) != VCT_OK)
        return err->status;
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
    const int rc = b->lights ? texture_buffers_make(ctx, s, stage, b, err) : (int)err->status;
    if (rc != VCT_OK)
        vct_scene_buffers_release(ctx, b);
    return rc;
}

int vct_scene_buffers_make(vct_context *ctx, const vct_scene *s, const char *stage,
                           vct_scene_buffers *b, vct_error *err) {
    vct_resident *r = vct_resident_find(ctx, s);
    if (!r)
        return upload(ctx, s, stage, b, err);
    if (!r->has_buffers) {
        const uint64_t before = ctx->transfers.uploaded;
        if (upload(ctx, s, stage, &r->buffers, err) != VCT_OK)
            return err->status;
        r->has_buffers = 1;
        r->scene_bytes += ctx->transfers.uploaded - before;
    }
    *b = r->buffers;
    b->borrowed = 1;
    return VCT_OK;
}

vct_resident *vct_resident_find(vct_context *ctx, const vct_scene *s) {
    for (vct_resident *r = ctx->resident; r; r = r->next)
        if (r->scene == s)
            return r;
    return NULL;
}

vct_accumulation *vct_accumulation_of(vct_context *ctx, const vct_scene *s) {
    vct_resident *r = vct_resident_find(ctx, s);
    return r ? &r->accumulation : &ctx->accumulation;
}

void vct_resident_release_buffers(vct_context *ctx, vct_resident *r) {
    if (r->has_buffers)
        vct_scene_buffers_release(ctx, &r->buffers);
    memset(&r->buffers, 0, sizeof r->buffers);
    r->has_buffers = 0;
}

int vct_resident_update(vct_context *ctx, vct_resident *r, unsigned changed, vct_error *err) {
    static const char *const stage = "scene update";
    const vct_scene *s = r->scene;
    if (!r->has_buffers)
        return VCT_OK; /* made at first use, from the scene as it is then */
    if ((changed & (VCT_CHANGED_GEOMETRY | VCT_CHANGED_TEXTURES)) ||
        s->material_count * sizeof(vct_material_desc) != buffer_bytes(r->buffers.materials) ||
        s->light_count != r->buffers.light_count) {
        vct_resident_release_buffers(ctx, r);
        return VCT_OK;
    }
    if (!(changed & (VCT_CHANGED_MATERIALS | VCT_CHANGED_LIGHTS)))
        return VCT_OK;
    vct_material_desc *mats;
    vct_light_desc *lights;
    if (descs_make(s, stage, &mats, &lights, err) != VCT_OK)
        return err->status;
    const uint64_t before = ctx->transfers.uploaded;
    int rc = VCT_OK;
    if (changed & VCT_CHANGED_MATERIALS)
        rc = vct_buffer_write(ctx, stage, r->buffers.materials, 0, sizeof *mats * s->material_count,
                              mats, err);
    if (rc == VCT_OK && (changed & VCT_CHANGED_LIGHTS))
        rc = vct_buffer_write(ctx, stage, r->buffers.lights, 0, sizeof *lights * s->light_count,
                              lights, err);
    r->scene_bytes += ctx->transfers.uploaded - before;
    free(mats);
    free(lights);
    return rc;
}
