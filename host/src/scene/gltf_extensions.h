/* glTF material extensions read beside assimp (gltf_extensions.c). */
#ifndef VCT_GLTF_EXTENSIONS_H
#define VCT_GLTF_EXTENSIONS_H

#include "runtime/runtime.h"

/* Applies to s, loaded from `path` by assimp, what the file's glTF material
 * extensions say and assimp left out; nothing for other formats. */
int vct_gltf_extensions_apply(const char *path, vct_scene *s, vct_error *err);

#endif
