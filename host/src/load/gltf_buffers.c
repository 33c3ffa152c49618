/* glTF accessors read from the file's own buffers (gltf_buffers.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include <b64/cdecode.h>

#include "load/gltf_buffers.h"

struct vct_gltf_buffers {
    const char *path;
    const cJSON *root;
    int count;
    unsigned char **data; /* NULL until read */
    size_t *size;
};

vct_gltf_buffers *vct_gltf_buffers_open(const char *path, const cJSON *root) {
    vct_gltf_buffers *b = calloc(1, sizeof *b);
    if (!b)
        return NULL;
    b->path = path;
    b->root = root;
    b->count = cJSON_GetArraySize(cJSON_GetObjectItemCaseSensitive(root, "buffers"));
    b->data = calloc((size_t)b->count + 1, sizeof *b->data);
    b->size = calloc((size_t)b->count + 1, sizeof *b->size);
    if (!b->data || !b->size) {
        vct_gltf_buffers_close(b);
        return NULL;
    }
    return b;
}

void vct_gltf_buffers_close(vct_gltf_buffers *b) {
    if (!b)
        return;
    for (int i = 0; b->data && i < b->count; ++i)
        free(b->data[i]);
    free(b->data);
    free(b->size);
    free(b);
}

/* `size` bytes of `f` from `offset`; NULL if it has fewer. */
static unsigned char *read_bytes(FILE *f, long offset, size_t size) {
    unsigned char *out = malloc(size + 1);
    if (out && (fseek(f, offset, SEEK_SET) != 0 || fread(out, 1, size, f) != size)) {
        free(out);
        out = NULL;
    }
    return out;
}

static uint32_t le32(const unsigned char *p) {
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* A .glb's binary chunk, the one that follows its JSON chunk. */
static unsigned char *glb_binary_chunk(const char *path, size_t *size) {
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    unsigned char head[20], chunk[8];
    unsigned char *out = NULL;
    if (fread(head, 1, 20, f) == 20) {
        const long json_end = 20 + (long)le32(head + 12);
        if (fseek(f, json_end, SEEK_SET) == 0 && fread(chunk, 1, 8, f) == 8 &&
            memcmp(chunk + 4, "BIN", 4) == 0) {
            *size = le32(chunk);
            out = read_bytes(f, json_end + 8, *size);
        }
    }
    fclose(f);
    return out;
}

/* A buffer's bytes from its URI: base64 data, or a file beside the glTF's. */
static unsigned char *uri_bytes(const char *path, const char *uri, size_t *size) {
    if (strncmp(uri, "data:", 5) == 0) {
        const char *payload = strstr(uri, ";base64,");
        if (!payload)
            return NULL;
        payload += 8;
        const size_t n = strlen(payload);
        unsigned char *out = malloc(n / 4 * 3 + 4);
        if (!out)
            return NULL;
        base64_decodestate state;
        base64_init_decodestate(&state);
        *size = (size_t)base64_decode_block(payload, (int)n, (char *)out, &state);
        return out;
    }
    if (strchr(uri, ':') || strstr(uri, "%")) /* other schemes; escaped names */
        return NULL;
    const char *slash = strrchr(path, '/');
    const int dir = slash ? (int)(slash - path + 1) : 0;
    char *file = malloc((size_t)dir + strlen(uri) + 1);
    if (!file)
        return NULL;
    sprintf(file, "%.*s%s", dir, path, uri);
    FILE *f = fopen(file, "rb");
    free(file);
    unsigned char *out = NULL;
    if (f && fseek(f, 0, SEEK_END) == 0) {
        const long end = ftell(f);
        if (end >= 0) {
            *size = (size_t)end;
            out = read_bytes(f, 0, *size);
        }
    }
    if (f)
        fclose(f);
    return out;
}

static const unsigned char *buffer_bytes(vct_gltf_buffers *b, int i, size_t *size) {
    if (i < 0 || i >= b->count)
        return NULL;
    if (!b->data[i]) {
        const cJSON *buf =
            cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(b->root, "buffers"), i);
        const cJSON *uri = cJSON_GetObjectItemCaseSensitive(buf, "uri");
        const char *dot = strrchr(b->path, '.');
        if (cJSON_IsString(uri))
            b->data[i] = uri_bytes(b->path, uri->valuestring, &b->size[i]);
        else if (i == 0 && dot && strcasecmp(dot, ".glb") == 0)
            b->data[i] = glb_binary_chunk(b->path, &b->size[i]);
    }
    *size = b->size[i];
    return b->data[i];
}

static int json_int(const cJSON *object, const char *name, int fallback) {
    const cJSON *item = cJSON_GetObjectItemCaseSensitive(object, name);
    return cJSON_IsNumber(item) ? item->valueint : fallback;
}

static int type_components(const char *type) {
    static const char *const names[] = {"SCALAR", "VEC2", "VEC3", "VEC4"};
    for (int i = 0; i < 4; ++i)
        if (strcmp(type, names[i]) == 0)
            return i + 1;
    return 0;
}

/* Component bytes, and how an integer one is normalised (glTF 2.0 3.11). */
static int component_bytes(int type) {
    switch (type) {
    case 5120: /* BYTE */
    case 5121: /* UNSIGNED_BYTE */
        return 1;
    case 5122: /* SHORT */
    case 5123: /* UNSIGNED_SHORT */
        return 2;
    case 5126: /* FLOAT */
        return 4;
    default:
        return 0;
    }
}

static float component_value(const unsigned char *p, int type) {
    switch (type) {
    case 5120:
        return fmaxf((float)(signed char)p[0] / 127.0f, -1.0f);
    case 5121:
        return (float)p[0] / 255.0f;
    case 5122:
        return fmaxf((float)(int16_t)(p[0] | p[1] << 8) / 32767.0f, -1.0f);
    case 5123:
        return (float)(p[0] | p[1] << 8) / 65535.0f;
    default: {
        const uint32_t bits = le32(p);
        float f;
        memcpy(&f, &bits, sizeof f);
        return f;
    }
    }
}

int vct_gltf_accessor_floats(vct_gltf_buffers *b, int index, int components, float **values,
                             uint32_t *count, vct_error *err) {
    *values = NULL;
    *count = 0;
    const cJSON *acc =
        cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(b->root, "accessors"), index);
    const cJSON *type = cJSON_GetObjectItemCaseSensitive(acc, "type");
    const int ctype = json_int(acc, "componentType", 0),
              view_index = json_int(acc, "bufferView", -1);
    const int n = json_int(acc, "count", -1), bytes = component_bytes(ctype);
    const cJSON *normalized = cJSON_GetObjectItemCaseSensitive(acc, "normalized");
    const char *why = NULL;
    if (!acc)
        why = "the file has no such accessor";
    else if (!cJSON_IsString(type) || type_components(type->valuestring) != components)
        why = "its type has the wrong number of components";
    else if (!bytes || (ctype != 5126 && !cJSON_IsTrue(normalized)))
        why = "its components are neither floats nor normalised integers";
    else if (n < 0 || view_index < 0 || cJSON_GetObjectItemCaseSensitive(acc, "sparse"))
        why = "it has no count or no buffer view (or is sparse)";
    const cJSON *view =
        cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(b->root, "bufferViews"), view_index);
    const long long element = (long long)bytes * components;
    const long long stride =
        json_int(view, "byteStride", 0) ? json_int(view, "byteStride", 0) : element;
    const long long start =
        (long long)json_int(view, "byteOffset", 0) + json_int(acc, "byteOffset", 0);
    const long long view_end =
        (long long)json_int(view, "byteOffset", 0) + json_int(view, "byteLength", 0);
    size_t size = 0;
    const unsigned char *data = NULL;
    if (!why && !view)
        why = "its buffer view is missing";
    if (!why && !(data = buffer_bytes(b, json_int(view, "buffer", -1), &size)))
        why = "its buffer cannot be read";
    if (!why && n > 0 &&
        (stride < element || start + stride * (n - 1) + element > view_end ||
         view_end > (long long)size))
        why = "it reaches beyond its buffer view or its buffer";
    float *out = why ? NULL : malloc(sizeof(float) * ((size_t)n * components + 1));
    if (!why && !out)
        return vct_fail(err, VCT_ERR_MEMORY, "scene %s: out of host memory", b->path);
    if (why)
        return vct_fail(err, VCT_ERR_INPUT, "scene %s: accessor %d: %s", b->path, index, why);
    for (int e = 0; e < n; ++e)
        for (int c = 0; c < components; ++c)
            out[(size_t)e * components + c] =
                component_value(data + start + stride * e + bytes * c, ctype);
    *values = out;
    *count = (uint32_t)n;
    return VCT_OK;
}
