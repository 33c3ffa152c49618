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

#endif
