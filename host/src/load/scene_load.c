/* Scene files through assimp: the node tree is flattened with its transforms
 * into flat arrays; materials, cameras and punctual lights are converted to
 * the engine's conventions (linear radiance, W/sr, irradiance). */
#include <assimp/GltfMaterial.h>
#include <assimp/cimport.h>
#include <assimp/light.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#include "runtime/runtime.h"
#include "load/gltf_json.h"
#include "load/obj_check.h"
#include "load/scene_path.h"
#include "load/scene_textures.h"

typedef struct builder {
    vct_scene *s;
    uint32_t vertex_cap, triangle_cap, uv_cap, instance_cap;
    const char *path;
    vct_error *err;
    int32_t *mesh_of; /* assimp mesh -> the scene's mesh, -1 before its first use */
    uint32_t node_cap, current_node;
    const char **node_names; /* while loading: each node's name, for the animations */
} builder;

static int grow(void **p, uint32_t *cap, uint32_t need, size_t elem) {
    if (need <= *cap)
        return 1;
    uint32_t c = *cap ? *cap : 1024;
    while (c < need)
        c = c > UINT32_MAX / 2 ? need : c * 2;
    void *q = realloc(*p, (size_t)c * elem);
    if (!q)
        return 0;
    *p = q;
    *cap = c;
    return 1;
}

/* The scene's mesh of an assimp mesh, in its own space, made at its first
 * use: its vertices and its triangles (faces of 3 vertices). */
static int mesh_index(builder *b, const struct aiScene *sc, unsigned mi, uint32_t *out) {
    vct_scene *s = b->s;
    if (b->mesh_of[mi] >= 0) {
        *out = (uint32_t)b->mesh_of[mi];
        return VCT_OK;
    }
    const struct aiMesh *mesh = sc->mMeshes[mi];
    vct_mesh *grown = realloc(s->meshes, (s->mesh_count + 1) * sizeof *grown);
    if (!grown)
        return vct_fail(b->err, VCT_ERR_MEMORY, "scene %s: out of host memory", b->path);
    s->meshes = grown;
    vct_mesh *m = &s->meshes[s->mesh_count];
    memset(m, 0, sizeof *m);
    m->positions = malloc(12ull * mesh->mNumVertices + 16);
    m->triangles = malloc(12ull * mesh->mNumFaces + 16);
    *out = s->mesh_count++;
    b->mesh_of[mi] = (int32_t)*out;
    if (!m->positions || !m->triangles)
        return vct_fail(b->err, VCT_ERR_MEMORY, "scene %s: out of host memory", b->path);
    m->vertex_count = mesh->mNumVertices;
    for (unsigned i = 0; i < mesh->mNumVertices; ++i) {
        m->positions[3 * i] = mesh->mVertices[i].x;
        m->positions[3 * i + 1] = mesh->mVertices[i].y;
        m->positions[3 * i + 2] = mesh->mVertices[i].z;
    }
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
        const struct aiFace *face = &mesh->mFaces[f];
        if (face->mNumIndices != 3)
            continue;
        for (int k = 0; k < 3; ++k)
            m->triangles[3 * m->triangle_count + k] = face->mIndices[k];
        m->triangle_count++;
    }
    return VCT_OK;
}

/* An instance of mesh `mesh` at `world`, whose triangles come next. */
static int add_instance(builder *b, uint32_t mesh, const struct aiMatrix4x4 *world) {
    vct_scene *s = b->s;
    if (!grow((void **)&s->instances, &b->instance_cap, s->instance_count + 1,
              sizeof(vct_instance)))
        return vct_fail(b->err, VCT_ERR_MEMORY, "scene %s: out of host memory", b->path);
    vct_instance *in = &s->instances[s->instance_count++];
    memset(in, 0, sizeof *in);
    in->mesh = mesh;
    in->node = b->current_node;
    memcpy(in->transform, &world->a1, sizeof in->transform); /* rows a, b, c */
    in->first_triangle = s->triangle_count;
    in->first_vertex = s->vertex_count;
    return VCT_OK;
}

static int add_mesh(builder *b, const struct aiMesh *mesh, const struct aiMatrix4x4 *m) {
    vct_scene *s = b->s;
    uint64_t verts = (uint64_t)s->vertex_count + mesh->mNumVertices;
    if (verts > UINT32_MAX / 2)
        return vct_fail(b->err, VCT_ERR_INPUT, "scene %s: more vertices than vct indexes", b->path);
    uint32_t vcap = b->vertex_cap;
    if (!grow((void **)&s->positions, &vcap, (uint32_t)verts, 3 * sizeof(float)))
        return vct_fail(b->err, VCT_ERR_MEMORY, "scene %s: out of host memory", b->path);
    b->vertex_cap = vcap;
    const uint32_t base = s->vertex_count;
    for (unsigned i = 0; i < mesh->mNumVertices; ++i) {
        struct aiVector3D v = mesh->mVertices[i];
        float *out = &s->positions[3 * (base + i)];
        /* Row-major affine transform, in double so large offsets stay exact. */
        out[0] = (float)((double)m->a1 * v.x + (double)m->a2 * v.y + (double)m->a3 * v.z + m->a4);
        out[1] = (float)((double)m->b1 * v.x + (double)m->b2 * v.y + (double)m->b3 * v.z + m->b4);
        out[2] = (float)((double)m->c1 * v.x + (double)m->c2 * v.y + (double)m->c3 * v.z + m->c4);
        if (!isfinite(v.x) || !isfinite(v.y) || !isfinite(v.z) || !isfinite(out[0]) ||
            !isfinite(out[1]) || !isfinite(out[2]))
            return vct_fail(b->err, VCT_ERR_INPUT,
                            "scene %s: mesh \"%s\" vertex %u is not finite (%g, %g, %g)", b->path,
                            mesh->mName.data, i, v.x, v.y, v.z);
    }
    /* Texture coordinates: channel 0, or 0 for a mesh without; the array
     * appears with the first mesh that has them. */
    if (mesh->mTextureCoords[0] || s->uvs) {
        uint32_t ucap = b->uv_cap;
        const int first = !s->uvs;
        if (!grow((void **)&s->uvs, &ucap, (uint32_t)verts, 2 * sizeof(float)))
            return vct_fail(b->err, VCT_ERR_MEMORY, "scene %s: out of host memory", b->path);
        b->uv_cap = ucap;
        if (first)
            memset(s->uvs, 0, 2 * sizeof(float) * base);
        for (unsigned i = 0; i < mesh->mNumVertices; ++i) {
            const struct aiVector3D *uv =
                mesh->mTextureCoords[0] ? &mesh->mTextureCoords[0][i] : NULL;
            s->uvs[2 * (base + i)] = uv ? uv->x : 0.0f;
            /* glTF's v runs down the image as rows do; assimp flips it up */
            s->uvs[2 * (base + i) + 1] = uv ? 1.0f - uv->y : 0.0f;
        }
    }
    s->vertex_count = (uint32_t)verts;
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
        const struct aiFace *face = &mesh->mFaces[f];
        if (face->mNumIndices != 3)
            continue; /* points and lines carry no surface */
        uint32_t tcap = b->triangle_cap, tcap2 = b->triangle_cap;
        if (!grow((void **)&s->triangles, &tcap, s->triangle_count + 1, 3 * sizeof(uint32_t)) ||
            !grow((void **)&s->triangle_material, &tcap2, s->triangle_count + 1, sizeof(uint32_t)))
            return vct_fail(b->err, VCT_ERR_MEMORY, "scene %s: out of host memory", b->path);
        b->triangle_cap = tcap;
        for (int k = 0; k < 3; ++k) {
            if (face->mIndices[k] >= mesh->mNumVertices)
                return vct_fail(b->err, VCT_ERR_INPUT,
                                "scene %s: mesh \"%s\" face %u uses vertex %u of %u", b->path,
                                mesh->mName.data, f, face->mIndices[k], mesh->mNumVertices);
            s->triangles[3 * s->triangle_count + k] = base + face->mIndices[k];
        }
        s->triangle_material[s->triangle_count] = mesh->mMaterialIndex;
        s->triangle_count++;
    }
    return VCT_OK;
}

static void mat_mul(const struct aiMatrix4x4 *a, const struct aiMatrix4x4 *b,
                    struct aiMatrix4x4 *out) {
    const float *x = &a->a1, *y = &b->a1;
    float r[16];
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            r[4 * i + j] = x[4 * i] * y[j] + x[4 * i + 1] * y[4 + j] + x[4 * i + 2] * y[8 + j] +
                           x[4 * i + 3] * y[12 + j];
    memcpy(&out->a1, r, sizeof r);
}

/* The node as the scene keeps it: its parent, its rest transform and that
 * transform as translation, rotation and scale. */
static int add_node(builder *b, const struct aiNode *node, uint32_t parent) {
    vct_scene *s = b->s;
    if (!grow((void **)&s->nodes, &b->node_cap, s->node_count + 1, sizeof(vct_node)) ||
        !(b->node_names = realloc(b->node_names, sizeof(char *) * b->node_cap)))
        return vct_fail(b->err, VCT_ERR_MEMORY, "scene %s: out of host memory", b->path);
    vct_node *n = &s->nodes[s->node_count];
    memset(n, 0, sizeof *n);
    n->parent = parent;
    memcpy(n->rest, &node->mTransformation.a1, sizeof n->rest); /* rows a, b, c */
    struct aiVector3D scaling, position;
    struct aiQuaternion rotation;
    aiDecomposeMatrix(&node->mTransformation, &scaling, &rotation, &position);
    const float t[3] = {position.x, position.y, position.z},
                q[4] = {rotation.x, rotation.y, rotation.z, rotation.w},
                sc[3] = {scaling.x, scaling.y, scaling.z};
    memcpy(n->translation, t, sizeof t);
    memcpy(n->rotation, q, sizeof q);
    memcpy(n->scale, sc, sizeof sc);
    b->node_names[s->node_count] = node->mName.data;
    b->current_node = s->node_count++;
    return VCT_OK;
}

static int walk(builder *b, const struct aiScene *sc, const struct aiNode *node,
                const struct aiMatrix4x4 *parent, uint32_t parent_node) {
    struct aiMatrix4x4 world;
    mat_mul(parent, &node->mTransformation, &world);
    const int added = add_node(b, node, parent_node);
    if (added != VCT_OK)
        return added;
    const uint32_t self = b->current_node;
    for (unsigned i = 0; i < node->mNumMeshes; ++i) {
        unsigned mi = node->mMeshes[i];
        if (mi >= sc->mNumMeshes)
            return vct_fail(b->err, VCT_ERR_INPUT, "scene %s: node \"%s\" names mesh %u of %u",
                            b->path, node->mName.data, mi, sc->mNumMeshes);
        uint32_t mesh = 0;
        int rc = mesh_index(b, sc, mi, &mesh);
        if (rc == VCT_OK)
            rc = add_instance(b, mesh, &world);
        if (rc == VCT_OK)
            rc = add_mesh(b, sc->mMeshes[mi], &world);
        if (rc)
            return rc;
    }
    for (unsigned c = 0; c < node->mNumChildren; ++c) {
        int rc = walk(b, sc, node->mChildren[c], &world, self);
        if (rc)
            return rc;
    }
    return VCT_OK;
}

static const struct aiNode *find_node(const struct aiNode *n, const char *name,
                                      const struct aiMatrix4x4 *parent, struct aiMatrix4x4 *out) {
    struct aiMatrix4x4 world;
    mat_mul(parent, &n->mTransformation, &world);
    if (strcmp(n->mName.data, name) == 0) {
        *out = world;
        return n;
    }
    for (unsigned c = 0; c < n->mNumChildren; ++c) {
        const struct aiNode *r = find_node(n->mChildren[c], name, &world, out);
        if (r)
            return r;
    }
    return NULL;
}

static void xform_point(const struct aiMatrix4x4 *m, const struct aiVector3D *v, float *out) {
    out[0] = m->a1 * v->x + m->a2 * v->y + m->a3 * v->z + m->a4;
    out[1] = m->b1 * v->x + m->b2 * v->y + m->b3 * v->z + m->b4;
    out[2] = m->c1 * v->x + m->c2 * v->y + m->c3 * v->z + m->c4;
}

static void xform_dir(const struct aiMatrix4x4 *m, const struct aiVector3D *v, float *out) {
    out[0] = m->a1 * v->x + m->a2 * v->y + m->a3 * v->z;
    out[1] = m->b1 * v->x + m->b2 * v->y + m->b3 * v->z;
    out[2] = m->c1 * v->x + m->c2 * v->y + m->c3 * v->z;
    float len = sqrtf(out[0] * out[0] + out[1] * out[1] + out[2] * out[2]);
    if (len > 0.0f)
        for (int k = 0; k < 3; ++k)
            out[k] /= len;
}

/* The index of the node named `name`, or VCT_NO_NODE. */
static uint32_t node_named(const builder *b, const char *name) {
    for (uint32_t n = 0; n < b->s->node_count; ++n)
        if (strcmp(b->node_names[n], name) == 0)
            return n;
    return VCT_NO_NODE;
}

static int is_gltf(const char *path) {
    const char *dot = strrchr(path, '.');
    return dot && (strcasecmp(dot, ".gltf") == 0 || strcasecmp(dot, ".glb") == 0);
}

static void read_camera(const builder *b, const struct aiScene *sc, const char *path,
                        vct_scene *s) {
    s->camera_attachment.node = VCT_NO_NODE;
    if (sc->mNumCameras == 0)
        return;
    const struct aiCamera *cam = sc->mCameras[0];
    struct aiMatrix4x4 identity, world;
    aiIdentityMatrix4(&identity);
    if (!find_node(sc->mRootNode, cam->mName.data, &identity, &world))
        world = identity;
    /* glTF cameras sit at their node's origin by definition; assimp 5.2 also
     * copies the node's translation into mPosition, which would count it twice. */
    struct aiVector3D pos = cam->mPosition;
    if (is_gltf(path))
        pos.x = pos.y = pos.z = 0.0f;
    struct aiVector3D target = {pos.x + cam->mLookAt.x, pos.y + cam->mLookAt.y,
                                pos.z + cam->mLookAt.z};
    xform_point(&world, &pos, s->camera.position);
    xform_point(&world, &target, s->camera.look_at);
    xform_dir(&world, &cam->mUp, s->camera.up);
    /* in its node's space too, for posing */
    vct_attachment *at = &s->camera_attachment;
    at->node = node_named(b, cam->mName.data);
    const float look[3] = {cam->mLookAt.x, cam->mLookAt.y, cam->mLookAt.z};
    at->look_distance = sqrtf(look[0] * look[0] + look[1] * look[1] + look[2] * look[2]);
    for (int k = 0; k < 3; ++k) {
        at->position[k] = (&pos.x)[k];
        at->direction[k] = at->look_distance > 0.0f ? look[k] / at->look_distance : 0.0f;
        at->up[k] = (&cam->mUp.x)[k];
    }
    float aspect = cam->mAspect > 0.0f ? cam->mAspect : 1.0f;
    float fov_y;
    if (is_gltf(path))
        fov_y = cam->mHorizontalFOV / aspect; /* assimp stores yfov * aspect for glTF */
    else
        fov_y = 2.0f * atanf(tanf(cam->mHorizontalFOV) / aspect); /* half horizontal angle */
    s->camera.fov_y_deg = fov_y * 180.0f / VCT_PI_F;
    s->has_camera = s->camera.fov_y_deg > 0.0f && s->camera.fov_y_deg < 180.0f;
}

/* Keys of one part of a channel: times in seconds and n floats each. */
static int copy_keys(uint32_t count, float **times, float **values, int n) {
    *times = malloc(sizeof(float) * (count + 1));
    *values = malloc(sizeof(float) * n * (count + 1));
    return *times && *values;
}

/* One channel: the node it moves (by name) and its keys. */
static int read_channel(const builder *b, const struct aiNodeAnim *ch, double ticks,
                        vct_animation_channel *out) {
    const vct_scene *s = b->s;
    out->node = VCT_NO_NODE;
    for (uint32_t n = 0; n < s->node_count && out->node == VCT_NO_NODE; ++n)
        if (strcmp(b->node_names[n], ch->mNodeName.data) == 0)
            out->node = n;
    out->translation_keys = ch->mNumPositionKeys;
    out->rotation_keys = ch->mNumRotationKeys;
    out->scale_keys = ch->mNumScalingKeys;
    if (!copy_keys(ch->mNumPositionKeys, &out->translation_times, &out->translations, 3) ||
        !copy_keys(ch->mNumRotationKeys, &out->rotation_times, &out->rotations, 4) ||
        !copy_keys(ch->mNumScalingKeys, &out->scale_times, &out->scales, 3))
        return 0;
    for (unsigned k = 0; k < ch->mNumPositionKeys; ++k) {
        const struct aiVectorKey *key = &ch->mPositionKeys[k];
        out->translation_times[k] = (float)(key->mTime / ticks);
        const float v[3] = {key->mValue.x, key->mValue.y, key->mValue.z};
        memcpy(&out->translations[3 * k], v, sizeof v);
    }
    for (unsigned k = 0; k < ch->mNumRotationKeys; ++k) {
        const struct aiQuatKey *key = &ch->mRotationKeys[k];
        out->rotation_times[k] = (float)(key->mTime / ticks);
        const float q[4] = {key->mValue.x, key->mValue.y, key->mValue.z, key->mValue.w};
        memcpy(&out->rotations[4 * k], q, sizeof q);
    }
    for (unsigned k = 0; k < ch->mNumScalingKeys; ++k) {
        const struct aiVectorKey *key = &ch->mScalingKeys[k];
        out->scale_times[k] = (float)(key->mTime / ticks);
        const float v[3] = {key->mValue.x, key->mValue.y, key->mValue.z};
        memcpy(&out->scales[3 * k], v, sizeof v);
    }
    return 1;
}

/* One part of a channel (translation, rotation or scale): its times
 * finite and increasing, its values finite, a scale never 0 on an axis, a
 * rotation not of length 0. */
static int check_keys(const vct_scene *s, const char *animation, const char *node, const char *part,
                      const float *times, const float *values, uint32_t count, int n,
                      vct_error *err) {
    for (uint32_t k = 0; k < count; ++k) {
        const float *v = &values[n * k];
        const char *bad = NULL;
        if (!isfinite(times[k]))
            bad = "its time is not finite";
        else if (k > 0 && !(times[k] > times[k - 1]))
            bad = "its time is not after the key before's: key times must increase";
        for (int c = 0; !bad && c < n; ++c)
            if (!isfinite(v[c]))
                bad = "a value is not finite";
        if (!bad && n == 3 && strcmp(part, "scale") == 0 &&
            (v[0] == 0.0f || v[1] == 0.0f || v[2] == 0.0f))
            bad = "a scale of 0 collapses the node";
        if (!bad && n == 4 && v[0] == 0.0f && v[1] == 0.0f && v[2] == 0.0f && v[3] == 0.0f)
            bad = "a rotation of length 0 is no rotation";
        if (bad)
            return vct_fail(err, VCT_ERR_INPUT,
                            "scene %s: animation \"%s\", the channel of node \"%s\": %s key %u "
                            "(at %g s): %s",
                            s->source, animation, node, part, k, (double)times[k], bad);
    }
    return VCT_OK;
}

static int check_channel(const vct_scene *s, const char *animation, const char *node,
                         const vct_animation_channel *c, vct_error *err) {
    int rc = check_keys(s, animation, node, "translation", c->translation_times, c->translations,
                        c->translation_keys, 3, err);
    if (rc == VCT_OK)
        rc = check_keys(s, animation, node, "rotation", c->rotation_times, c->rotations,
                        c->rotation_keys, 4, err);
    if (rc == VCT_OK)
        rc = check_keys(s, animation, node, "scale", c->scale_times, c->scales, c->scale_keys, 3,
                        err);
    return rc;
}

/* The file's animations: name, duration and each channel's keys. */
static int read_animations(const builder *b, const struct aiScene *sc, vct_scene *s,
                           vct_error *err) {
    if (sc->mNumAnimations == 0)
        return VCT_OK;
    s->animations = calloc(sc->mNumAnimations, sizeof *s->animations);
    if (!s->animations)
        return vct_fail(err, VCT_ERR_MEMORY, "scene %s: out of host memory", s->source);
    for (unsigned a = 0; a < sc->mNumAnimations; ++a) {
        const struct aiAnimation *an = sc->mAnimations[a];
        vct_animation_info *info = &s->animations[s->animation_count++];
        snprintf(info->name, sizeof info->name, "%.63s", an->mName.data);
        /* key times are in ticks */
        const double ticks = an->mTicksPerSecond > 0.0 ? an->mTicksPerSecond : 1.0;
        info->channel = calloc(an->mNumChannels + 1, sizeof *info->channel);
        if (!info->channel)
            return vct_fail(err, VCT_ERR_MEMORY, "scene %s: out of host memory", s->source);
        for (unsigned c = 0; c < an->mNumChannels; ++c) {
            info->channels++; /* counted first, so that release frees a part made */
            if (!read_channel(b, an->mChannels[c], ticks, &info->channel[c]))
                return vct_fail(err, VCT_ERR_MEMORY, "scene %s: out of host memory", s->source);
            if (info->channel[c].node == VCT_NO_NODE)
                return vct_fail(err, VCT_ERR_INPUT,
                                "scene %s: animation \"%s\" moves node \"%s\", which the file "
                                "does not have",
                                s->source, info->name, an->mChannels[c]->mNodeName.data);
            const int rc = check_channel(s, info->name, an->mChannels[c]->mNodeName.data,
                                         &info->channel[c], err);
            if (rc != VCT_OK)
                return rc;
        }
        double last = 0.0;
        for (unsigned c = 0; c < an->mNumChannels; ++c) {
            const struct aiNodeAnim *ch = an->mChannels[c];
            if (ch->mNumPositionKeys)
                last = fmax(last, ch->mPositionKeys[ch->mNumPositionKeys - 1].mTime);
            if (ch->mNumRotationKeys)
                last = fmax(last, ch->mRotationKeys[ch->mNumRotationKeys - 1].mTime);
            if (ch->mNumScalingKeys)
                last = fmax(last, ch->mScalingKeys[ch->mNumScalingKeys - 1].mTime);
        }
        info->duration_s = last / ticks;
    }
    return VCT_OK;
}

static int read_lights(const builder *b, const struct aiScene *sc, const char *path, vct_scene *s,
                       vct_error *err) {
    s->light_attachments = calloc(sc->mNumLights + 1, sizeof *s->light_attachments);
    if (!s->light_attachments)
        return vct_fail(err, VCT_ERR_MEMORY, "scene %s: out of host memory", path);
    for (unsigned i = 0; i < sc->mNumLights; ++i) {
        const struct aiLight *al = sc->mLights[i];
        vct_light l;
        memset(&l, 0, sizeof l);
        switch (al->mType) {
        case aiLightSource_POINT:
            l.type = VCT_LIGHT_POINT;
            break;
        case aiLightSource_SPOT:
            l.type = VCT_LIGHT_SPOT;
            break;
        case aiLightSource_DIRECTIONAL:
            l.type = VCT_LIGHT_DIRECTIONAL;
            break;
        default:
            ++s->ignored_lights;
            continue;
        }
        struct aiMatrix4x4 identity, world;
        aiIdentityMatrix4(&identity);
        if (!find_node(sc->mRootNode, al->mName.data, &identity, &world))
            world = identity;
        xform_point(&world, &al->mPosition, l.position);
        xform_dir(&world, &al->mDirection, l.direction);
        l.color[0] = al->mColorDiffuse.r;
        l.color[1] = al->mColorDiffuse.g;
        l.color[2] = al->mColorDiffuse.b;
        l.inner_cone = al->mAngleInnerCone;
        l.outer_cone = al->mAngleOuterCone;
        int rc = vct_scene_add_light(s, &l, err);
        if (rc)
            return rc;
        vct_attachment *at = &s->light_attachments[s->light_attachment_count++];
        at->node = node_named(b, al->mName.data);
        for (int k = 0; k < 3; ++k) {
            at->position[k] = (&al->mPosition.x)[k];
            at->direction[k] = (&al->mDirection.x)[k];
        }
    }
    return VCT_OK;
}

static int file_exists_near(const char *model, const char *rel) {
    if (rel[0] == '*')
        return 1; /* embedded texture */
    if (strncmp(rel, "data:", 5) == 0)
        return 1;
    char path[2048];
    vct_path_beside(model, rel, path, sizeof path);
    return access(path, R_OK) == 0;
}

static int read_materials(const struct aiScene *sc, const char *path, vct_scene *s,
                          vct_error *err) {
    s->material_count = sc->mNumMaterials ? sc->mNumMaterials : 1;
    s->materials = calloc(s->material_count, sizeof *s->materials);
    if (!s->materials)
        return vct_fail(err, VCT_ERR_MEMORY, "scene %s: out of host memory", path);
    for (unsigned i = 0; i < s->material_count; ++i) {
        vct_material *m = &s->materials[i];
        *m = vct_material_default();
        if (i >= sc->mNumMaterials)
            break;
        const struct aiMaterial *am = sc->mMaterials[i];
        struct aiString name;
        if (aiGetMaterialString(am, AI_MATKEY_NAME, &name) == aiReturn_SUCCESS)
            snprintf(m->name, sizeof m->name, "%.63s", name.data);
        struct aiColor4D c;
        if (aiGetMaterialColor(am, AI_MATKEY_BASE_COLOR, &c) == aiReturn_SUCCESS ||
            aiGetMaterialColor(am, AI_MATKEY_COLOR_DIFFUSE, &c) == aiReturn_SUCCESS) {
            m->albedo[0] = c.r;
            m->albedo[1] = c.g;
            m->albedo[2] = c.b;
            m->alpha = c.a;
        }
        struct aiString mode;
        if (aiGetMaterialString(am, AI_MATKEY_GLTF_ALPHAMODE, &mode) == aiReturn_SUCCESS &&
            (strcmp(mode.data, "MASK") == 0 || strcmp(mode.data, "BLEND") == 0)) {
            float cutoff = 0.5f;
            if (strcmp(mode.data, "MASK") == 0)
                aiGetMaterialFloatArray(am, AI_MATKEY_GLTF_ALPHACUTOFF, &cutoff, NULL);
            m->alpha_cutoff = cutoff;
        }
        float scale = 1.0f;
        aiGetMaterialFloatArray(am, AI_MATKEY_EMISSIVE_INTENSITY, &scale, NULL);
        if (aiGetMaterialColor(am, AI_MATKEY_COLOR_EMISSIVE, &c) == aiReturn_SUCCESS) {
            m->emission[0] = c.r * scale;
            m->emission[1] = c.g * scale;
            m->emission[2] = c.b * scale;
        }
        if (aiGetMaterialColor(am, AI_MATKEY_COLOR_SPECULAR, &c) == aiReturn_SUCCESS) {
            m->specular[0] = c.r;
            m->specular[1] = c.g;
            m->specular[2] = c.b;
        }
        float f;
        if (aiGetMaterialFloatArray(am, AI_MATKEY_SHININESS, &f, NULL) == aiReturn_SUCCESS &&
            f > 0.0f)
            m->roughness = sqrtf(sqrtf(2.0f / (f + 2.0f))); /* Phong exponent -> roughness */
        if (aiGetMaterialFloatArray(am, AI_MATKEY_ROUGHNESS_FACTOR, &f, NULL) == aiReturn_SUCCESS)
            m->roughness = f;
        if (aiGetMaterialFloatArray(am, AI_MATKEY_METALLIC_FACTOR, &f, NULL) == aiReturn_SUCCESS)
            m->metallic = f;
        if (aiGetMaterialFloatArray(am, AI_MATKEY_REFRACTI, &f, NULL) == aiReturn_SUCCESS &&
            f >= 1.0f)
            m->ior = f;
        if (aiGetMaterialFloatArray(am, AI_MATKEY_TRANSMISSION_FACTOR, &f, NULL) ==
            aiReturn_SUCCESS)
            m->transmission = f;
        else if (m->alpha_cutoff == 0.0f &&
                 aiGetMaterialFloatArray(am, AI_MATKEY_OPACITY, &f, NULL) == aiReturn_SUCCESS &&
                 f < 1.0f) /* a mask's alpha is its own, not transmission */
            m->transmission = 1.0f - f;
        /* A missing texture of any kind is a broken scene (base colour is read
         * by scene_textures.c; the others are not used yet). */
        for (int type = aiTextureType_DIFFUSE; type <= aiTextureType_TRANSMISSION; ++type) {
            unsigned count = aiGetMaterialTextureCount(am, (enum aiTextureType)type);
            for (unsigned t = 0; t < count; ++t) {
                struct aiString tex;
                if (aiGetMaterialTexture(am, (enum aiTextureType)type, t, &tex, NULL, NULL, NULL,
                                         NULL, NULL, NULL) == aiReturn_SUCCESS &&
                    !file_exists_near(path, tex.data))
                    return vct_fail(err, VCT_ERR_INPUT,
                                    "scene %s: material \"%s\" names texture \"%s\", which does "
                                    "not exist",
                                    path, m->name, tex.data);
            }
        }
    }
    return VCT_OK;
}

vct_scene *vct_scene_load(const char *path, vct_error *err) {
    if (access(path, R_OK) != 0) {
        vct_fail(err, VCT_ERR_IO, "scene %s: cannot read the file", path);
        return NULL;
    }
    if (vct_gltf_precheck(path, err) || vct_obj_precheck(path, err))
        return NULL;
    const struct aiScene *sc = aiImportFile(path, aiProcess_Triangulate);
    if (!sc || !sc->mRootNode) {
        vct_fail(err, VCT_ERR_INPUT, "scene %s: assimp could not load it: %s", path,
                 aiGetErrorString());
        if (sc)
            aiReleaseImport(sc);
        return NULL;
    }
    vct_scene *s = calloc(1, sizeof *s);
    if (!s) {
        aiReleaseImport(sc);
        vct_fail(err, VCT_ERR_MEMORY, "scene %s: out of host memory", path);
        return NULL;
    }
    snprintf(s->source, sizeof s->source, "%s", path);
    builder b = {s, 0, 0,   0, 0, path, err, malloc(sizeof(int32_t) * (sc->mNumMeshes + 1)),
                 0, 0, NULL};
    for (unsigned i = 0; b.mesh_of && i < sc->mNumMeshes; ++i)
        b.mesh_of[i] = -1;
    struct aiMatrix4x4 identity;
    aiIdentityMatrix4(&identity);
    int rc = read_materials(sc, path, s, err);
    if (rc == VCT_OK)
        rc = vct_gltf_extensions_apply(path, s, err);
    if (rc == VCT_OK)
        rc = vct_scene_load_textures(sc, path, s, err);
    if (rc == VCT_OK && !b.mesh_of)
        rc = vct_fail(err, VCT_ERR_MEMORY, "scene %s: out of host memory", path);
    if (rc == VCT_OK)
        rc = walk(&b, sc, sc->mRootNode, &identity, VCT_NO_NODE);
    free(b.mesh_of);
    /* node names live in assimp's scene: kept for the animations, then gone */
    if (rc == VCT_OK)
        rc = read_lights(&b, sc, path, s, err);
    if (rc == VCT_OK)
        rc = read_animations(&b, sc, s, err);
    if (rc == VCT_OK && s->animation_count)
        rc = vct_gltf_sampler_modes(path, s, b.node_names, err);
    if (rc == VCT_OK && s->triangle_count == 0)
        rc = vct_fail(err, VCT_ERR_INPUT, "scene %s: no triangles to render (%u meshes)", path,
                      sc->mNumMeshes);
    if (rc == VCT_OK)
        rc = vct_scene_validate(s, err);
    if (rc == VCT_OK) {
        vct_scene_default_camera(s, &s->camera);
        read_camera(&b, sc, path, s);
    }
    aiReleaseImport(sc);
    free(b.node_names);
    if (rc != VCT_OK) {
        vct_scene_release(s);
        return NULL;
    }
    return s;
}
