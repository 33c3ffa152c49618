/* Base-colour textures of a loaded scene: found through assimp (glTF
 * baseColorTexture, OBJ map_Kd), read with stb_image from a file beside the
 * model or from the data embedded in it, decoded from sRGB to linear, one
 * copy per distinct image. Texture coordinates come with the meshes
 * (scene_load.c). */
#include <assimp/material.h>
#include <assimp/scene.h>
#include <assimp/texture.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <stb/stb_image.h>

#include "runtime/runtime.h"
#include "load/scene_path.h"
#include "load/scene_textures.h"

/* Textures larger than this per side are refused: a broken or hostile file
 * should not make the engine allocate gigabytes. */
#define MAX_TEXTURE_SIDE 16384

static float srgb_to_linear(unsigned char c) {
    const float s = (float)c / 255.0f;
    return s <= 0.04045f ? s / 12.92f : powf((s + 0.055f) / 1.055f, 2.4f);
}

static int decode(const char *model, const char *name, unsigned char *px, int w, int h,
                  vct_texture *t, vct_error *err) {
    if (!px)
        return vct_fail(err, VCT_ERR_INPUT, "scene %s: texture \"%s\" cannot be decoded: %s", model,
                        name, stbi_failure_reason());
    if (w <= 0 || h <= 0 || w > MAX_TEXTURE_SIDE || h > MAX_TEXTURE_SIDE) {
        stbi_image_free(px);
        return vct_fail(err, VCT_ERR_INPUT,
                        "scene %s: texture \"%s\" is %dx%d: vct takes 1 to %d texels a side", model,
                        name, w, h, MAX_TEXTURE_SIDE);
    }
    t->rgba = malloc(16ull * w * h);
    if (!t->rgba) {
        stbi_image_free(px);
        return vct_fail(err, VCT_ERR_MEMORY, "scene %s: out of host memory for texture \"%s\"",
                        model, name);
    }
    for (size_t i = 0; i < (size_t)w * h; ++i) {
        for (int c = 0; c < 3; ++c)
            t->rgba[4 * i + c] = srgb_to_linear(px[4 * i + c]);
        t->rgba[4 * i + 3] = (float)px[4 * i + 3] / 255.0f;
    }
    stbi_image_free(px);
    t->width = w;
    t->height = h;
    snprintf(t->name, sizeof t->name, "%s", name);
    return VCT_OK;
}

/* Reads texture `name` ("*N" for embedded image N) into t. */
static int load_texture(const struct aiScene *sc, const char *model, const char *name,
                        vct_texture *t, vct_error *err) {
    int w = 0, h = 0, n = 0;
    if (name[0] == '*') {
        const unsigned idx = (unsigned)strtoul(name + 1, NULL, 10);
        if (idx >= sc->mNumTextures)
            return vct_fail(err, VCT_ERR_INPUT,
                            "scene %s: texture \"%s\" names embedded image %u of %u", model, name,
                            idx, sc->mNumTextures);
        const struct aiTexture *at = sc->mTextures[idx];
        if (at->mHeight == 0) { /* compressed: mWidth bytes of a PNG or JPEG */
            unsigned char *px = stbi_load_from_memory((const unsigned char *)at->pcData,
                                                      (int)at->mWidth, &w, &h, &n, 4);
            return decode(model, name, px, w, h, t, err);
        }
        return vct_fail(err, VCT_ERR_INPUT,
                        "scene %s: texture \"%s\" is stored as raw texels, which vct does not "
                        "read: store it as PNG or JPEG",
                        model, name);
    }
    char path[2048];
    vct_path_beside(model, name, path, sizeof path);
    unsigned char *px = stbi_load(path, &w, &h, &n, 4);
    return decode(model, name, px, w, h, t, err);
}

int vct_scene_load_textures(const struct aiScene *sc, const char *model, vct_scene *s,
                            vct_error *err) {
    for (unsigned i = 0; i < sc->mNumMaterials && i < s->material_count; ++i) {
        const struct aiMaterial *am = sc->mMaterials[i];
        enum aiTextureType type = aiTextureType_BASE_COLOR;
        if (aiGetMaterialTextureCount(am, type) == 0)
            type = aiTextureType_DIFFUSE;
        struct aiString name;
        enum aiTextureMapMode wrap[3] = {aiTextureMapMode_Wrap, aiTextureMapMode_Wrap,
                                         aiTextureMapMode_Wrap};
        if (aiGetMaterialTextureCount(am, type) == 0 ||
            aiGetMaterialTexture(am, type, 0, &name, NULL, NULL, NULL, NULL, wrap, NULL) !=
                aiReturn_SUCCESS)
            continue;
        uint32_t found = 0;
        for (uint32_t t = 0; t < s->texture_count && !found; ++t)
            if (strcmp(s->textures[t].name, name.data) == 0)
                found = t + 1;
        if (!found) {
            vct_texture *grown = realloc(s->textures, sizeof *grown * (s->texture_count + 1));
            if (!grown)
                return vct_fail(err, VCT_ERR_MEMORY, "scene %s: out of host memory", model);
            s->textures = grown;
            memset(&s->textures[s->texture_count], 0, sizeof *grown);
            const int rc = load_texture(sc, model, name.data, &s->textures[s->texture_count], err);
            if (rc)
                return rc;
            found = ++s->texture_count;
        }
        vct_material *m = &s->materials[i];
        m->albedo_texture = found;
        m->texture_wrap = (wrap[0] == aiTextureMapMode_Clamp ? VCT_WRAP_CLAMP_S : 0u) |
                          (wrap[1] == aiTextureMapMode_Clamp ? VCT_WRAP_CLAMP_T : 0u);
    }
    return VCT_OK;
}
