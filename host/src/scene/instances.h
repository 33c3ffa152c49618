/* Meshes and their instances (vct/scene.h): the node tree a file's flat
 * arrays were made from, kept so that an instance can move alone and an
 * acceleration structure can hold a shared mesh once. */
#ifndef VCT_SCENE_INSTANCES_H
#define VCT_SCENE_INSTANCES_H

#include "runtime/runtime.h"

/* The scene's file, or "(arrays)", for messages. */
const char *vct_scene_name(const vct_scene *s);
/* world = m * (p, 1), in double and rounded once: the loader's arithmetic,
 * so that moving an instance back gives the positions loading gave. */
void vct_instance_transform_point(const float m[12], const float *p, float *out);
/* Checks every instance against its mesh and the flat arrays. */
int vct_instances_validate(const vct_scene *s, vct_error *err);
/* Whether some mesh is placed more than once (a two-level structure then
 * holds it once). */
int vct_instances_shared(const vct_scene *s);
/* Instance `instance` at `transform`, its vertices in the flat arrays
 * rewritten; nothing changes when a value is not finite. The scene's bounds
 * wait for vct_scene_validate (scene/placing.c). */
vct_status vct_instance_place(vct_scene *s, uint32_t instance, const float transform[12],
                              vct_error *err);
/* Whether every instance's vertices in the flat arrays are its mesh's
 * through its transform, bit for bit (not where a host edited the flat
 * positions alone): what a two-level structure, which holds the meshes,
 * needs in order to report the hits of the flat triangles. */
int vct_instances_consistent(const vct_scene *s);
/* One mesh made of the flat arrays and one instance of it, untransformed. */
int vct_instances_identity(vct_scene *s, vct_error *err);
void vct_instances_release(vct_scene *s);

#endif
