/* vct: the host scene: meshes and their instances, the flat arrays of
 * positions, triangles and materials made from them, lights and a camera,
 * loaded from a file or built from arrays.
 *
 * A scene is plain host memory the caller owns: any thread may read it, one
 * at a time may change it. A device scene (vct/device_scene.h) reads it at
 * every commit, so it must outlive the device scenes made from it and must
 * not change while one of them commits or renders. */
#ifndef VCT_API_SCENE_H
#define VCT_API_SCENE_H

#include "vct/export.h"

#include <stdint.h>

#include "vct/error.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct vct_material {
    char name[64];
    float albedo[3];   /* diffuse reflectance */
    float emission[3]; /* emitted radiance Le */
    float specular[3]; /* specular reflectance (or metallic tint) */
    float metallic;
    float roughness;    /* 0 = mirror, 1 = diffuse-like */
    float transmission; /* 0..1 */
    float ior;
    /* Base-colour texture: 1 + its index in vct_scene.textures, 0 for none
     * (so that a zeroed material has none). The texture's linear colour
     * multiplies `albedo` (glTF's baseColorFactor). */
    uint32_t albedo_texture;
    uint32_t texture_wrap; /* VCT_WRAP_CLAMP_S | VCT_WRAP_CLAMP_T; else repeat */
    /* Alpha mask (glTF alphaMode MASK; BLEND, which is not blended, is read
     * as MASK at 0.5): every ray passes the surface where `alpha` (glTF's
     * baseColorFactor alpha) times the base-colour texture's alpha is below
     * `alpha_cutoff`. 0: no mask, the surface is opaque. */
    float alpha;
    float alpha_cutoff;
} vct_material;

#define VCT_WRAP_CLAMP_S 1u
#define VCT_WRAP_CLAMP_T 2u

/* An image texture, decoded: rgb linear (from sRGB), alpha as stored. */
typedef struct vct_texture {
    char name[256];
    int width, height;
    float *rgba; /* width * height * 4, rows from the image's top */
} vct_texture;

typedef enum vct_light_type {
    VCT_LIGHT_POINT = 0,
    VCT_LIGHT_SPOT = 1,
    VCT_LIGHT_DIRECTIONAL = 2,
} vct_light_type;

typedef struct vct_light {
    vct_light_type type;
    float position[3];
    float direction[3]; /* direction the light travels (spot, directional) */
    float color[3];     /* point/spot: radiant intensity W/sr; directional: irradiance */
    float inner_cone;   /* spot: radians, full intensity inside */
    float outer_cone;   /* spot: radians, zero outside */
    /* Size for soft shadows (0: a point, hard shadows): point and spot, the
     * radius of the disk facing the lit point, in world units; directional,
     * the angular radius in radians (below 1). The light is shaded as from
     * its centre, times the fraction of it that the point sees. */
    float radius;
} vct_light;

typedef struct vct_camera {
    float position[3];
    float look_at[3];
    float up[3];
    float fov_y_deg;
} vct_camera;

/* A mesh in its own space: what several instances may share. */
typedef struct vct_mesh {
    uint32_t vertex_count, triangle_count;
    float *positions;    /* 3 * vertex_count, object space */
    uint32_t *triangles; /* 3 * triangle_count, into this mesh's vertices */
} vct_mesh;

/* A mesh placed in the world. The scene's flat arrays hold every instance's
 * triangles, transformed, in instance order: instance i's are
 * first_triangle .. first_triangle + its mesh's triangle_count - 1, and its
 * vertices from first_vertex on. */
typedef struct vct_instance {
    uint32_t mesh;
    uint32_t node;       /* the node that places it (vct_scene.nodes), or VCT_NO_NODE */
    float transform[12]; /* row-major 3x4: world = transform * (p, 1) */
    uint32_t first_triangle, first_vertex;
} vct_instance;

#define VCT_NO_NODE 0xffffffffu

/* A node of the file's tree: instances hang from nodes, and animations move
 * them. Parents come before their children. */
typedef struct vct_node {
    uint32_t parent; /* VCT_NO_NODE for a root */
    float rest[12];  /* its transform relative to its parent, row-major 3x4 */
    float translation[3], rotation[4], scale[3]; /* the same as T R S (rotation x y z w) */
} vct_node;

/* What an animation does to one node: keys of its translation, rotation
 * (x y z w) and scale, each at times in seconds, interpolated linearly
 * (rotations spherically), stepped, or along cubic Hermite splines, and
 * held before the first key and after the last. A part without keys stays
 * at rest. */
typedef struct vct_animation_channel {
    uint32_t node;
    uint32_t translation_keys, rotation_keys, scale_keys;
    /* 1 where the part's keys step (glTF's STEP sampler): each key held
     * until the next, not interpolated */
    uint8_t translation_step, rotation_step, scale_step;
    float *translation_times, *translations; /* 3 floats per key */
    float *rotation_times, *rotations;       /* 4 per key */
    float *scale_times, *scales;             /* 3 per key */
    /* glTF's CUBICSPLINE: per key its in-tangent, then its out-tangent
     * (2 x 3 or 2 x 4 floats, in units per second); NULL for other parts.
     * A cubic rotation is normalised after the spline. */
    float *translation_tangents, *rotation_tangents, *scale_tangents;
} vct_animation_channel;

/* A camera or light that a node of the file carries, in that node's space,
 * so that posing the node (vct_scene_pose) moves it. */
typedef struct vct_attachment {
    uint32_t node;       /* VCT_NO_NODE: carried by none */
    float position[3];   /* a camera's eye, a light's position */
    float direction[3];  /* where a camera looks (towards its look_at) or a light shines */
    float up[3];         /* a camera's up */
    float look_distance; /* a camera: from the eye to its look_at */
} vct_attachment;

/* An animation of the file (glTF's). The scene holds the file's rest pose
 * until vct_scene_pose poses it. */
typedef struct vct_animation_info {
    char name[64];
    double duration_s; /* its last key's time */
    uint32_t channels; /* nodes it moves */
    vct_animation_channel *channel;
} vct_animation_info;

typedef struct vct_scene {
    char source[512];
    uint32_t vertex_count;
    uint32_t triangle_count;
    uint32_t material_count;
    uint32_t light_count;
    float *positions;    /* 3 * vertex_count */
    uint32_t *triangles; /* 3 * triangle_count */
    uint32_t *triangle_material;
    vct_material *materials;
    vct_light *lights;
    float *uvs; /* 2 * vertex_count texture coordinates, or NULL (all 0) */
    uint32_t texture_count;
    vct_texture *textures;
    vct_camera camera;
    int has_camera;
    /* Radiance arriving from every direction where nothing is hit (a
     * constant environment, 0 by default): lights what is open to the sky. */
    float ambient[3];
    uint32_t degenerate_triangles; /* zero-area triangles, kept but never hit */
    uint32_t ignored_lights;       /* lights of the file of a type vct has not (area, ambient) */
    /* The meshes and their instances the flat arrays were made from (a
     * file's node tree, or one mesh and one instance for arrays); 0 and
     * NULL for a scene that is only flat arrays. */
    uint32_t mesh_count, instance_count;
    vct_mesh *meshes;
    vct_instance *instances;
    uint32_t node_count, animation_count;
    vct_node *nodes;
    vct_animation_info *animations;
    /* The nodes that carry the camera and the file's lights (the first
     * light_attachment_count lights): posing moves them with their nodes. */
    vct_attachment camera_attachment;
    uint32_t light_attachment_count;
    vct_attachment *light_attachments;
    float bounds_min[3], bounds_max[3];
} vct_scene;

/* Loads OBJ+MTL, glTF 2.0 or anything assimp reads; flattens the node tree. */
VCT_API vct_scene *vct_scene_load(const char *path, vct_error *err);
/* Builds a scene from arrays (copied); validates like a loaded file. */
VCT_API vct_scene *vct_scene_from_arrays(const float *positions, uint32_t vertex_count,
                                         const uint32_t *triangles, uint32_t triangle_count,
                                         const uint32_t *triangle_material,
                                         const vct_material *materials, uint32_t material_count,
                                         vct_error *err);
VCT_API vct_status vct_scene_add_light(vct_scene *scene, const vct_light *light, vct_error *err);
/* Places instance `instance` with a new transform: its vertices in the flat
 * arrays are transformed again (as loading does, in double), the bounds
 * updated. A transform with a value that is not finite, or that makes a
 * vertex not finite, is refused and nothing changes. */
/* Places mesh `mesh` once more, at `transform`: its triangles and vertices
 * are appended to the flat arrays, with the materials and texture
 * coordinates of the mesh's first instance. */
VCT_API vct_status vct_scene_add_instance(vct_scene *scene, uint32_t mesh,
                                          const float transform[12], vct_error *err);
VCT_API vct_status vct_scene_set_instance_transform(vct_scene *scene, uint32_t instance,
                                                    const float transform[12], vct_error *err);
/* Checks indices, finite values, non-empty; counts degenerates; sets bounds. */
VCT_API vct_status vct_scene_validate(vct_scene *scene, vct_error *err);
/* Poses the scene as animation `animation` has it at `seconds`: every
 * instance under a node it moves takes its new transform (its vertices in
 * the flat arrays rewritten), the rest keep theirs bit for bit. */
VCT_API vct_status vct_scene_pose(vct_scene *scene, uint32_t animation, double seconds,
                                  vct_error *err);
/* A default camera framing the scene's bounds, looking down -z. */
VCT_API void vct_scene_default_camera(const vct_scene *scene, vct_camera *camera);
VCT_API void vct_scene_release(vct_scene *scene);
VCT_API vct_material vct_material_default(void);

#ifdef __cplusplus
}
#endif
#endif
