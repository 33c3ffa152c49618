/* What a commit compares: a digest of each part of the host scene, so that
 * a change made through any field is seen, whatever wrote it. */
#ifndef VCT_DEVICE_SCENE_DIGEST_H
#define VCT_DEVICE_SCENE_DIGEST_H

#include <stdint.h>

#include "vct/scene.h"

typedef struct vct_scene_digest {
    uint64_t geometry;  /* triangles, texture coordinates, triangle materials; the meshes and
                           which mesh each instance places where in the flat arrays */
    uint64_t positions; /* the flat positions and the instances' transforms */
    uint64_t materials; /* the material table */
    uint64_t masks;     /* what the alpha masks read: mask fields, and texels when masked */
    uint64_t textures;  /* every texture's size and texels */
    uint64_t lights;    /* lights and the ambient light */
    uint64_t camera;
} vct_scene_digest;

void vct_scene_digest_make(const vct_scene *s, vct_scene_digest *d);
/* VCT_CHANGED_* bits (scene/scene_resident.h) where a and b differ. */
unsigned vct_scene_digest_changes(const vct_scene_digest *a, const vct_scene_digest *b);

#endif
