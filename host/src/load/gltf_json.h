/* What vct reads of a glTF file's JSON itself, beside assimp (gltf_json.c). */
#ifndef VCT_GLTF_JSON_H
#define VCT_GLTF_JSON_H

#include "runtime/runtime.h"

/* Checks, before assimp parses `path`, what assimp 5.2 mishandles: a .glb
 * without its binary header (read by content as another format), JSON that
 * does not parse, embedded buffers whose data URI is not base64 (assimp
 * leaks memory on those), and cubic-spline samplers without three values a
 * key (assimp reads beyond them). Nothing for other formats. */
int vct_gltf_precheck(const char *path, vct_error *err);
/* Applies to s, loaded from `path` by assimp, what the file's glTF material
 * extensions say and assimp left out; nothing for other formats. */
int vct_gltf_extensions_apply(const char *path, vct_scene *s, vct_error *err);

/* What assimp 5.2 reads of glTF animation samplers without saying how they
 * interpolate: marks the channel parts whose samplers step (STEP), and
 * reads the tangents of cubic splines (CUBICSPLINE) from the file's
 * buffers, refusing ones that are missing or not finite. node_names: each
 * of s's nodes' names as assimp gave them (a glTF node without a name is
 * "nodes[N]"). Nothing for other formats. */
int vct_gltf_sampler_modes(const char *path, vct_scene *s, const char *const *node_names,
                           vct_error *err);

#endif
