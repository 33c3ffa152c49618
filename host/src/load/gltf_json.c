/* What vct reads of a glTF file's own JSON, with cJSON: checks before
 * assimp parses it, and the material extensions that assimp 5.2 leaves out:
 * KHR_materials_emissive_strength (the factor on emissiveFactor, which the
 * core format limits to 1). Materials are matched by index, as assimp
 * imports them in order, and by name where the names disagree. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include <cjson/cJSON.h>

#include "load/gltf_buffers.h"
#include "load/gltf_json.h"

/* The file's JSON: a whole .gltf, or a .glb's first chunk. NULL if neither. */
static char *read_json(const char *path) {
    const char *dot = strrchr(path, '.');
    const int glb = dot && strcasecmp(dot, ".glb") == 0;
    if (!dot || (!glb && strcasecmp(dot, ".gltf") != 0))
        return NULL;
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    char *text = NULL;
    long size = 0;
    if (glb) {
        unsigned char head[20];
        if (fread(head, 1, 20, f) == 20 && memcmp(head, "glTF", 4) == 0 &&
            memcmp(head + 16, "JSON", 4) == 0) {
            size =
                (long)(head[12] | head[13] << 8 | head[14] << 16 | (unsigned long)head[15] << 24);
        }
    } else if (fseek(f, 0, SEEK_END) == 0) {
        size = ftell(f);
        rewind(f);
    }
    if (size > 0 && size < (1L << 30) && (text = malloc((size_t)size + 1)) != NULL) {
        if (fread(text, 1, (size_t)size, f) == (size_t)size)
            text[size] = '\0';
        else {
            free(text);
            text = NULL;
        }
    }
    fclose(f);
    return text;
}

/* The material of `s` that glTF material i became. */
static vct_material *material_for(vct_scene *s, uint32_t i, const char *name) {
    if (i < s->material_count && (!name || strcmp(s->materials[i].name, name) == 0))
        return &s->materials[i];
    for (uint32_t m = 0; name && m < s->material_count; ++m)
        if (strcmp(s->materials[m].name, name) == 0)
            return &s->materials[m];
    return NULL;
}

/* 1 if the data URI is base64, every character of its payload after
 * "base64," of the alphabet (padding only at the end). */
static int base64_payload_ok(const char *uri) {
    const char *p = strstr(uri, ";base64,");
    if (!p)
        return 0;                             /* glTF's data URIs are base64 */
    for (const char *m = uri + 5; m < p; ++m) /* the media type */
        if (!((*m >= 'a' && *m <= 'z') || (*m >= 'A' && *m <= 'Z') || (*m >= '0' && *m <= '9') ||
              *m == '/' || *m == '+' || *m == '-' || *m == '.'))
            return 0;
    p += 8;
    size_t n = 0, pad = 0;
    for (; *p; ++p, ++n) {
        const char c = *p;
        const int alpha = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') ||
                          (c >= '0' && c <= '9') || c == '+' || c == '/';
        if (c == '=')
            ++pad;
        else if (!alpha || pad)
            return 0;
    }
    return pad <= 2 && n % 4 == 0;
}

/* 1 if `path` names a .glb file that does not start with a binary glTF
 * header and JSON chunk (assimp would read it by its content as another
 * format instead). */
static int glb_without_header(const char *path) {
    const char *dot = strrchr(path, '.');
    if (!dot || strcasecmp(dot, ".glb") != 0)
        return 0;
    FILE *f = fopen(path, "rb");
    if (!f)
        return 0;
    unsigned char head[20];
    const int ok = fread(head, 1, 20, f) == 20 && memcmp(head, "glTF", 4) == 0 &&
                   memcmp(head + 16, "JSON", 4) == 0;
    fclose(f);
    return !ok;
}

static int accessor_count(const cJSON *root, const cJSON *index) {
    const cJSON *acc = cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(root, "accessors"),
                                          cJSON_IsNumber(index) ? index->valueint : -1);
    const cJSON *count = cJSON_GetObjectItemCaseSensitive(acc, "count");
    return cJSON_IsNumber(count) ? count->valueint : -1;
}

/* A CUBICSPLINE sampler's output holds three values a key; assimp 5.2
 * reads that many whatever the accessor holds. */
static int check_cubic_samplers(const char *path, const cJSON *root, vct_error *err) {
    const cJSON *an;
    cJSON_ArrayForEach(an, cJSON_GetObjectItemCaseSensitive(root, "animations")) {
        const cJSON *name = cJSON_GetObjectItemCaseSensitive(an, "name"), *sampler;
        int i = 0;
        cJSON_ArrayForEach(sampler, cJSON_GetObjectItemCaseSensitive(an, "samplers")) {
            const cJSON *mode = cJSON_GetObjectItemCaseSensitive(sampler, "interpolation");
            const int keys =
                accessor_count(root, cJSON_GetObjectItemCaseSensitive(sampler, "input"));
            const int values =
                accessor_count(root, cJSON_GetObjectItemCaseSensitive(sampler, "output"));
            if (cJSON_IsString(mode) && strcmp(mode->valuestring, "CUBICSPLINE") == 0 &&
                (keys < 0 || values != 3 * keys))
                return vct_fail(err, VCT_ERR_INPUT,
                                "scene %s: animation \"%s\", sampler %d: %d values for %d keys: a "
                                "cubic spline has 3 a key (in-tangent, value, out-tangent)",
                                path, cJSON_IsString(name) ? name->valuestring : "", i, values,
                                keys);
            ++i;
        }
    }
    return VCT_OK;
}

int vct_gltf_precheck(const char *path, vct_error *err) {
    if (glb_without_header(path))
        return vct_fail(err, VCT_ERR_INPUT,
                        "scene %s: not a binary glTF file (no glTF header and JSON chunk)", path);
    char *text = read_json(path);
    if (!text)
        return VCT_OK; /* not glTF, or unreadable: assimp says which */
    cJSON *root = cJSON_Parse(text);
    free(text);
    if (!root)
        return vct_fail(err, VCT_ERR_INPUT, "scene %s: its glTF JSON does not parse", path);
    int rc = VCT_OK;
    static const char *const lists[] = {"buffers", "images"}, *items[] = {"buffer", "image"};
    for (int l = 0; l < 2 && rc == VCT_OK; ++l) {
        uint32_t i = 0;
        const cJSON *b;
        cJSON_ArrayForEach(b, cJSON_GetObjectItemCaseSensitive(root, lists[l])) {
            const cJSON *uri = cJSON_GetObjectItemCaseSensitive(b, "uri");
            if (cJSON_IsString(uri) && strncmp(uri->valuestring, "data:", 5) == 0 &&
                !base64_payload_ok(uri->valuestring)) {
                rc = vct_fail(err, VCT_ERR_INPUT,
                              "scene %s: %s %u: its data URI is not valid base64", path, items[l],
                              i);
                break;
            }
            ++i;
        }
    }
    if (rc == VCT_OK)
        rc = check_cubic_samplers(path, root, err);
    cJSON_Delete(root);
    return rc;
}

int vct_gltf_extensions_apply(const char *path, vct_scene *s, vct_error *err) {
    char *text = read_json(path);
    if (!text)
        return VCT_OK; /* not glTF: nothing to add */
    cJSON *root = cJSON_Parse(text);
    free(text);
    if (!root)
        return VCT_OK; /* assimp read it; what it could not, we leave */
    const cJSON *materials = cJSON_GetObjectItemCaseSensitive(root, "materials");
    int rc = VCT_OK;
    uint32_t i = 0;
    const cJSON *m;
    cJSON_ArrayForEach(m, materials) {
        const cJSON *name = cJSON_GetObjectItemCaseSensitive(m, "name");
        const cJSON *ext = cJSON_GetObjectItemCaseSensitive(m, "extensions");
        const cJSON *strength = cJSON_GetObjectItemCaseSensitive(
            cJSON_GetObjectItemCaseSensitive(ext, "KHR_materials_emissive_strength"),
            "emissiveStrength");
        vct_material *mat = material_for(s, i, cJSON_IsString(name) ? name->valuestring : NULL);
        if (cJSON_IsNumber(strength) && mat) {
            const double k = strength->valuedouble;
            if (!(k >= 0.0) || k > 1e30) {
                rc = vct_fail(err, VCT_ERR_INPUT,
                              "scene %s: material %u \"%s\": emissiveStrength %g is not a "
                              "finite non-negative number",
                              path, i, mat->name, k);
                break;
            }
            for (int c = 0; c < 3; ++c)
                mat->emission[c] *= (float)k;
        }
        ++i;
    }
    cJSON_Delete(root);
    return rc;
}

/* The name assimp gives glTF node n: its own, or "nodes[n]". */
static void gltf_node_name(const cJSON *nodes, int n, char *out, size_t size) {
    const cJSON *name = cJSON_GetObjectItemCaseSensitive(cJSON_GetArrayItem(nodes, n), "name");
    if (cJSON_IsString(name) && name->valuestring[0])
        snprintf(out, size, "%s", name->valuestring);
    else
        snprintf(out, size, "nodes[%d]", n);
}

/* The in- and out-tangents of a CUBICSPLINE sampler whose output accessor
 * holds (in-tangent, value, out-tangent) for each of `keys` keys. */
static int read_tangents(vct_gltf_buffers *buffers, const cJSON *sampler, uint32_t keys, int n,
                         float **tangents, vct_error *err) {
    float *triples = NULL;
    uint32_t count = 0;
    const cJSON *output = cJSON_GetObjectItemCaseSensitive(sampler, "output");
    int rc = vct_gltf_accessor_floats(buffers, cJSON_IsNumber(output) ? output->valueint : -1, n,
                                      &triples, &count, err);
    if (rc != VCT_OK)
        return rc;
    if (count != 3 * keys) {
        free(triples);
        return vct_fail(err, VCT_ERR_INPUT,
                        "%u values for %u keys: a cubic spline has 3 a key (in-tangent, value, "
                        "out-tangent)",
                        count, keys);
    }
    free(*tangents);
    *tangents = malloc(sizeof(float) * 2 * n * (keys + 1));
    if (!*tangents) {
        free(triples);
        return vct_fail(err, VCT_ERR_MEMORY, "out of host memory");
    }
    for (uint32_t k = 0; k < keys; ++k)
        for (int c = 0; c < n; ++c) {
            const float in = triples[(3 * k) * n + c], out = triples[(3 * k + 2) * n + c];
            if (!isfinite(in) || !isfinite(out)) {
                free(triples);
                return vct_fail(err, VCT_ERR_INPUT, "key %u: a tangent is not finite", k);
            }
            (*tangents)[2 * n * k + c] = in;
            (*tangents)[2 * n * k + n + c] = out;
        }
    free(triples);
    return VCT_OK;
}

/* The glTF sampler of one channel of one part of `mine`, as its mode says. */
static int apply_sampler(vct_gltf_buffers *buffers, const cJSON *sampler, const char *part,
                         vct_animation_channel *mine, vct_error *err) {
    const cJSON *mode = cJSON_GetObjectItemCaseSensitive(sampler, "interpolation");
    const int step = cJSON_IsString(mode) && strcmp(mode->valuestring, "STEP") == 0;
    const int cubic = cJSON_IsString(mode) && strcmp(mode->valuestring, "CUBICSPLINE") == 0;
    if (strcmp(part, "translation") == 0) {
        mine->translation_step = (uint8_t)step;
        if (cubic)
            return read_tangents(buffers, sampler, mine->translation_keys, 3,
                                 &mine->translation_tangents, err);
    } else if (strcmp(part, "rotation") == 0) {
        mine->rotation_step = (uint8_t)step;
        if (cubic)
            return read_tangents(buffers, sampler, mine->rotation_keys, 4, &mine->rotation_tangents,
                                 err);
    } else if (strcmp(part, "scale") == 0) {
        mine->scale_step = (uint8_t)step;
        if (cubic)
            return read_tangents(buffers, sampler, mine->scale_keys, 3, &mine->scale_tangents, err);
    }
    return VCT_OK;
}

int vct_gltf_sampler_modes(const char *path, vct_scene *s, const char *const *node_names,
                           vct_error *err) {
    char *text = read_json(path);
    cJSON *root = text ? cJSON_Parse(text) : NULL;
    free(text);
    if (!root)
        return VCT_OK;
    vct_gltf_buffers *buffers = vct_gltf_buffers_open(path, root);
    int rc = buffers ? VCT_OK : vct_fail(err, VCT_ERR_MEMORY, "scene %s: out of host memory", path);
    const cJSON *nodes = cJSON_GetObjectItemCaseSensitive(root, "nodes");
    const cJSON *animations = cJSON_GetObjectItemCaseSensitive(root, "animations");
    /* assimp keeps the file's animations in order */
    for (uint32_t a = 0; rc == VCT_OK && a < s->animation_count; ++a) {
        const cJSON *an = cJSON_GetArrayItem(animations, (int)a);
        const cJSON *samplers = cJSON_GetObjectItemCaseSensitive(an, "samplers");
        const cJSON *ch;
        cJSON_ArrayForEach(ch, cJSON_GetObjectItemCaseSensitive(an, "channels")) {
            const cJSON *index = cJSON_GetObjectItemCaseSensitive(ch, "sampler");
            const cJSON *sampler =
                cJSON_IsNumber(index) ? cJSON_GetArrayItem(samplers, index->valueint) : NULL;
            const cJSON *target = cJSON_GetObjectItemCaseSensitive(ch, "target");
            const cJSON *node = cJSON_GetObjectItemCaseSensitive(target, "node");
            const cJSON *part = cJSON_GetObjectItemCaseSensitive(target, "path");
            if (!sampler || !cJSON_IsNumber(node) || !cJSON_IsString(part))
                continue;
            char name[256];
            gltf_node_name(nodes, node->valueint, name, sizeof name);
            for (uint32_t c = 0; rc == VCT_OK && c < s->animations[a].channels; ++c) {
                vct_animation_channel *mine = &s->animations[a].channel[c];
                if (mine->node >= s->node_count || strcmp(node_names[mine->node], name) != 0)
                    continue;
                rc = apply_sampler(buffers, sampler, part->valuestring, mine, err);
                if (rc != VCT_OK) {
                    char why[sizeof err->message];
                    snprintf(why, sizeof why, "%s", err->message);
                    rc = vct_fail(err, rc,
                                  "scene %s: animation \"%s\", the %s channel of node \"%s\": %s",
                                  path, s->animations[a].name, part->valuestring, name, why);
                }
            }
            if (rc != VCT_OK)
                break;
        }
    }
    vct_gltf_buffers_close(buffers);
    cJSON_Delete(root);
    return rc;
}
