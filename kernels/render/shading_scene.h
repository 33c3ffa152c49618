/* What a camera ray's shading reads: the acceleration structure, the
 * textures, the emitters, the materials, the lights and the sky. Built in a
 * kernel from its own arguments by SHADING_SCENE() (ACCEL_ARGS,
 * TEXTURE_ARGS, EMITTER_ARGS, materials, tri_material, lights, light_count
 * and a float4 ambient under those names). */
#ifndef VCT_SHADING_SCENE_H
#define VCT_SHADING_SCENE_H

#include "accel/accel.h"
#include "light/emitters.h"
#include "scene/texture.h"
#include "vct_types.h"

typedef struct shading_scene {
    accel_view g;
    texture_view tv;
    emitter_view e;
    __global const vct_material_desc *materials;
    __global const uint *tri_material;
    __global const vct_light_desc *lights;
    uint light_count;
    float3 ambient;
} shading_scene;

#define SHADING_SCENE()                                                                            \
    ((shading_scene){ACCEL_VIEW(), TEXTURE_VIEW(), EMITTER_VIEW(), materials, tri_material,        \
                     lights, light_count, ambient.xyz})

#endif
