/* Base-colour textures of a scene loaded through assimp (scene_textures.c). */
#ifndef VCT_SCENE_TEXTURES_H
#define VCT_SCENE_TEXTURES_H

#include "vct/scene.h"
#include "vct/error.h"

struct aiScene;

/* Reads each material's base-colour texture (and its wrap modes) into s,
 * decoded to linear; refuses one that is missing or cannot be decoded. */
int vct_scene_load_textures(const struct aiScene *sc, const char *model, vct_scene *s,
                            vct_error *err);

#endif
