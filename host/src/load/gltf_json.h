/* What vct reads of a glTF file's JSON itself, beside assimp (gltf_json.c). */
#ifndef VCT_GLTF_JSON_H
#define VCT_GLTF_JSON_H

#include "runtime/runtime.h"

/* Checks, before assimp parses `path`, what assimp 5.2 mishandles: a .glb
 * without its binary header (read by content as another format), JSON that
 * does not parse, and embedded buffers whose data URI is not base64 (assimp
 * leaks memory on those). Nothing for other formats. */
int vct_gltf_precheck(const char *path, vct_error *err);
/* Applies to s, loaded from `path` by assimp, what the file's glTF material
 * extensions say and assimp left out; nothing for other formats. */
int vct_gltf_extensions_apply(const char *path, vct_scene *s, vct_error *err);

/* Marks the channels of s's animations whose glTF samplers step (STEP),
 * which assimp 5.2 reads as keys without saying how they interpolate.
 * node_names: each of s's nodes' names as assimp gave them (a glTF node
 * without a name is "nodes[N]"). Nothing for other formats. */
void vct_gltf_sampler_steps(const char *path, vct_scene *s, const char *const *node_names);

#endif
