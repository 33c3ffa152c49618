/* A committed scene's resident copy on a context (device_scene/ makes and
 * owns it): the stages below take their scene's buffers from it instead of
 * uploading them on every call. */
#ifndef VCT_SCENE_RESIDENT_H
#define VCT_SCENE_RESIDENT_H

#include "scene/scene_device.h"

/* What changed in a scene since its last commit (VCT_CHANGED_* bits). */
#define VCT_CHANGED_GEOMETRY 1u  /* triangles, uvs, triangle materials, meshes, instances */
#define VCT_CHANGED_MATERIALS 2u /* the material table */
#define VCT_CHANGED_TEXTURES 4u  /* texels */
#define VCT_CHANGED_LIGHTS 8u    /* the light list and the ambient light */
#define VCT_CHANGED_CAMERA 16u
#define VCT_CHANGED_POSITIONS 32u /* where the vertices are: instances moved */
#define VCT_CHANGED_ALL 63u

struct vct_emitters;

typedef struct vct_resident {
    const vct_scene *scene;
    vct_scene_buffers buffers; /* valid when has_buffers */
    int has_buffers;
    /* The emitter tables by area and by power (light/emitters.h), built on
     * first need; NULL until then. */
    struct vct_emitters *emitters[2];
    uint64_t scene_bytes; /* scene data uploaded into this copy so far */
    /* The running sums of this scene's progressive renders, dropped (by
     * device_scene/) when a commit changes the scene. */
    vct_accumulation accumulation;
    struct vct_resident *next;
} vct_resident;

/* ctx's resident copy of s, or NULL when s is not committed on ctx. */
vct_resident *vct_resident_find(vct_context *ctx, const vct_scene *s);
/* Where renders of s on ctx accumulate: its committed copy's sums, or the
 * context's own for a scene not committed there. */
vct_accumulation *vct_accumulation_of(vct_context *ctx, const vct_scene *s);
/* Brings the buffers up to date with `changed`: rewritten in place where
 * their size allows, else made again at next use. */
int vct_resident_update(vct_context *ctx, vct_resident *r, unsigned changed, vct_error *err);
/* Releases the buffers (not the emitters, which their stage releases). */
void vct_resident_release_buffers(vct_context *ctx, vct_resident *r);

#endif
