/* A glTF file's binary data, read through its accessors: what vct reads of
 * the file itself where assimp 5.2 drops it (cubic-spline tangents). */
#ifndef VCT_GLTF_BUFFERS_H
#define VCT_GLTF_BUFFERS_H

#include <cjson/cJSON.h>

#include "runtime/runtime.h"

typedef struct vct_gltf_buffers vct_gltf_buffers;

/* The buffers of the glTF file at `path` whose JSON is `root` (kept by the
 * caller), each read at its first use: a base64 data URI, a file beside
 * `path`, or a .glb's binary chunk. NULL when out of memory. */
vct_gltf_buffers *vct_gltf_buffers_open(const char *path, const cJSON *root);
void vct_gltf_buffers_close(vct_gltf_buffers *b);

/* Accessor `index` as floats: *count elements of `components` each (its
 * type must have that many), floats as they are and normalised integers
 * scaled as glTF says. *values is the caller's to free. Fails, naming the
 * file and the accessor, on anything out of range or missing. */
int vct_gltf_accessor_floats(vct_gltf_buffers *b, int index, int components, float **values,
                             uint32_t *count, vct_error *err);

#endif
