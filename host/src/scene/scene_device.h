/* Conversions from the public scene structs to the kernels' layouts. */
#ifndef VCT_SCENE_DEVICE_H
#define VCT_SCENE_DEVICE_H

#include "runtime/runtime.h"
#include "vct_types.h"

int vct_camera_desc_make(const vct_camera *cam, int width, int height, vct_camera_desc *d,
                         vct_error *err);
void vct_light_desc_make(const vct_light *l, vct_light_desc *d);
void vct_material_desc_make(const vct_material *m, vct_material_desc *d);

/* Materials, per-triangle material ids and lights on the device, and the
 * textures (kernels/scene/texture.h): every texture's linear texels in one
 * float4 buffer, a table of (first texel, width, height, 0) per texture, and
 * each triangle's three texture coordinates in two float4. Without textures,
 * one-element buffers. */
typedef struct vct_scene_buffers {
    cl_mem materials, tri_material, lights;
    cl_mem texels, texture_table, tri_uvs;
    cl_uint light_count;
    int borrowed; /* 1: a committed scene's (scene_resident.h); release leaves them */
} vct_scene_buffers;

/* The three texture buffers' kernel arguments (TEXTURE_ARGS) from `first`. */
int vct_scene_texture_args(cl_kernel k, int first, const vct_scene_buffers *b, const char *stage,
                           vct_error *err);

/* The scene's buffers: a committed scene's resident ones (borrowed), else
 * uploaded for this call. */
int vct_scene_buffers_make(vct_context *ctx, const vct_scene *s, const char *stage,
                           vct_scene_buffers *b, vct_error *err);
void vct_scene_buffers_release(vct_context *ctx, vct_scene_buffers *b);

#endif
