/* Scene loading through assimp: the shipped Cornell box (OBJ and glTF), a
 * generated glTF whose node tree, camera and spot / directional lights must
 * come out flattened and converted to the engine's conventions, and a file
 * whose one mesh many nodes place (kept as meshes and instances). */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "scene/instances.h"

static int near(float a, float b, float tol) {
    return fabsf(a - b) <= tol * fmaxf(1.0f, fabsf(b));
}

static void check_cornell(const char *dir) {
    char path[1024];
    vct_error err = {0};
    snprintf(path, sizeof path, "%s/scenes/cornell_box.gltf", dir);
    vct_scene *s = vct_scene_load(path, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    CHECK(s->triangle_count == 30, "cornell glTF: %u triangles", s->triangle_count);
    CHECK(s->light_count == 1 && s->lights[0].type == VCT_LIGHT_POINT, "cornell glTF: lights");
    CHECK(s->light_count == 1 && near(s->lights[0].position[1], 448.8f, 1e-6f) &&
              near(s->lights[0].color[0], 6e5f, 1e-6f),
          "cornell glTF: light at y %g, intensity %g", s->lights[0].position[1],
          s->lights[0].color[0]);
    CHECK(s->has_camera && near(s->camera.position[2], -800.0f, 1e-6f) &&
              near(s->camera.look_at[2] - s->camera.position[2], 1.0f, 1e-5f) &&
              near(s->camera.fov_y_deg, 39.3077f, 1e-4f),
          "cornell glTF camera: z %g, look-at z %g, fov %g", s->camera.position[2],
          s->camera.look_at[2], s->camera.fov_y_deg);
    CHECK(near(s->bounds_max[0], 556.0f, 1e-6f) && near(s->bounds_max[2], 559.2f, 1e-6f),
          "cornell glTF bounds");
    vct_scene_release(s);

    snprintf(path, sizeof path, "%s/scenes/cornell_box.obj", dir);
    s = vct_scene_load(path, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    CHECK(s->triangle_count == 30 && s->light_count == 0, "cornell OBJ: %u triangles",
          s->triangle_count);
    int red = 0;
    for (uint32_t m = 0; m < s->material_count; ++m)
        red += strcmp(s->materials[m].name, "red") == 0 &&
               near(s->materials[m].albedo[0], 0.63f, 1e-6f) &&
               near(s->materials[m].albedo[1], 0.065f, 1e-6f);
    CHECK(red == 1, "cornell OBJ: the red material's albedo");
    vct_scene_release(s);
}

/* One triangle in a child node (translated by (10, 0, 0)) of a parent scaled
 * by 2; a spot light pointing down -y, a sun rotated to travel along -y too. */
static const char *gltf =
    "{\"asset\":{\"version\":\"2.0\"},"
    "\"extensionsUsed\":[\"KHR_lights_punctual\"],"
    "\"extensions\":{\"KHR_lights_punctual\":{\"lights\":["
    "{\"name\":\"spot\",\"type\":\"spot\",\"color\":[1,0.5,0.25],\"intensity\":8,"
    "\"spot\":{\"innerConeAngle\":0.2,\"outerConeAngle\":0.5}},"
    "{\"name\":\"sun\",\"type\":\"directional\",\"color\":[1,1,1],\"intensity\":3}]}},"
    "\"scene\":0,\"scenes\":[{\"nodes\":[0,2,3]}],"
    "\"nodes\":["
    "{\"name\":\"parent\",\"scale\":[2,2,2],\"children\":[1]},"
    "{\"name\":\"child\",\"translation\":[10,0,0],\"mesh\":0},"
    "{\"name\":\"spot\",\"translation\":[0,5,0],\"rotation\":[-0.7071068,0,0,0.7071068],"
    "\"extensions\":{\"KHR_lights_punctual\":{\"light\":0}}},"
    "{\"name\":\"sun\",\"rotation\":[-0.7071068,0,0,0.7071068],"
    "\"extensions\":{\"KHR_lights_punctual\":{\"light\":1}}}],"
    "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],"
    "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\","
    "\"min\":[0,0,0],\"max\":[1,1,0]}],"
    "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36}],"
    "\"buffers\":[{\"byteLength\":36,\"uri\":\"data:application/octet-stream;base64,"
    "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA\"}]}";

/* Loads `text` as a glTF file of a private directory. */
static vct_scene *load_gltf_text(const char *text) {
    char dir[] = "/tmp/vct-scene-XXXXXX", path[64];
    if (!mkdtemp(dir))
        exit(1);
    snprintf(path, sizeof path, "%s/scene.gltf", dir);
    FILE *f = fopen(path, "w");
    if (!f || fputs(text, f) < 0 || fclose(f) != 0)
        exit(1);
    vct_error err = {0};
    vct_scene *s = vct_scene_load(path, &err);
    unlink(path);
    rmdir(dir);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    return s;
}

static void check_hierarchy(void) {
    vct_scene *s = load_gltf_text(gltf);
    CHECK(s->triangle_count == 1, "hierarchy: %u triangles", s->triangle_count);
    /* Vertex (1, 0, 0) -> child (11, 0, 0) -> parent scale 2 -> (22, 0, 0). */
    float max_x = -1e9f;
    for (uint32_t v = 0; v < s->vertex_count; ++v)
        max_x = fmaxf(max_x, s->positions[3 * v]);
    CHECK(near(max_x, 22.0f, 1e-6f) && near(s->bounds_min[0], 20.0f, 1e-6f) &&
              near(s->bounds_max[1], 2.0f, 1e-6f),
          "hierarchy: x from %g to %g, y up to %g", s->bounds_min[0], max_x, s->bounds_max[1]);
    CHECK(s->instance_count == 1 && s->mesh_count == 1 && vct_instances_consistent(s),
          "hierarchy: %u instances of %u meshes, consistent %d", s->instance_count, s->mesh_count,
          vct_instances_consistent(s));
    if (s->instance_count == 1) {
        float p[3];
        const float one[3] = {1.0f, 0.0f, 0.0f};
        vct_instance_transform_point(s->instances[0].transform, one, p);
        CHECK(near(p[0], 22.0f, 1e-6f), "hierarchy: the instance takes (1 0 0) to x %g", p[0]);
    }
    CHECK(s->light_count == 2, "hierarchy: %u lights", s->light_count);
    for (uint32_t i = 0; i < s->light_count; ++i) {
        const vct_light *l = &s->lights[i];
        CHECK(near(l->direction[1], -1.0f, 1e-5f) && fabsf(l->direction[0]) < 1e-5f,
              "light %u travels along (%g %g %g), expected -y", i, l->direction[0], l->direction[1],
              l->direction[2]);
        if (l->type == VCT_LIGHT_SPOT) {
            CHECK(near(l->position[1], 5.0f, 1e-6f), "spot at y %g", l->position[1]);
            CHECK(near(l->color[1], 4.0f, 1e-6f), "spot intensity %g", l->color[1]);
            CHECK(near(l->outer_cone, 0.5f, 1e-5f) && near(l->inner_cone, 0.2f, 1e-5f),
                  "spot cones %g %g", l->inner_cone, l->outer_cone);
        } else {
            CHECK(l->type == VCT_LIGHT_DIRECTIONAL && near(l->color[0], 3.0f, 1e-6f),
                  "sun: type %d, irradiance %g", l->type, l->color[0]);
        }
    }
    vct_scene_release(s);
}

/* The node tree kept: the file whose sphere 64 nodes place holds it once, each
 * instance's transform gives its vertices in the flat arrays bit for bit,
 * and the file's animation is listed with its duration. */
static void check_instances(void) {
    vct_scene *s = check_scene_file("scenes/instanced_spheres.gltf");
    CHECK(s->mesh_count == 3 && s->instance_count == 66, "%u meshes, %u instances", s->mesh_count,
          s->instance_count);
    uint32_t uses[3] = {0, 0, 0};
    for (uint32_t i = 0; i < s->instance_count && s->instances[i].mesh < 3; ++i)
        uses[s->instances[i].mesh]++;
    CHECK(uses[2] == 64 && s->meshes[2].triangle_count == 5120,
          "the sphere: %u instances of %u triangles", uses[2], s->meshes[2].triangle_count);
    CHECK(s->triangle_count == 2 + 2 + 64 * 5120, "%u flat triangles", s->triangle_count);
    CHECK(vct_instances_consistent(s), "an instance's transform does not give its vertices");
    CHECK(s->animation_count == 1 && strcmp(s->animations[0].name, "roll") == 0 &&
              fabs(s->animations[0].duration_s - 2.0) < 1e-6 && s->animations[0].channels == 1,
          "animations: %u, the first \"%s\" of %g s over %u nodes", s->animation_count,
          s->animation_count ? s->animations[0].name : "",
          s->animation_count ? s->animations[0].duration_s : 0.0,
          s->animation_count ? s->animations[0].channels : 0u);
    vct_scene_release(s);
}

/* glTF materials as authored: emissiveFactor times
 * KHR_materials_emissive_strength (which assimp 5.2 leaves out), and
 * transmission with its ior, metallic and roughness factors; alpha masks
 * (alphaMode MASK with its cutoff, BLEND read as MASK at 0.5, OPAQUE none). */
static const char *gltf_materials =
    "{\"asset\":{\"version\":\"2.0\"},"
    "\"extensionsUsed\":[\"KHR_materials_emissive_strength\",\"KHR_materials_transmission\","
    "\"KHR_materials_ior\"],"
    "\"materials\":["
    "{\"name\":\"lamp\",\"emissiveFactor\":[1,0.5,0.25],"
    "\"extensions\":{\"KHR_materials_emissive_strength\":{\"emissiveStrength\":8}}},"
    "{\"name\":\"glass\",\"pbrMetallicRoughness\":{\"metallicFactor\":0,\"roughnessFactor\":0.1},"
    "\"extensions\":{\"KHR_materials_transmission\":{\"transmissionFactor\":1},"
    "\"KHR_materials_ior\":{\"ior\":1.33}}},"
    "{\"name\":\"gold\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[1,0.8,0.3,1],"
    "\"metallicFactor\":1,\"roughnessFactor\":0.35}},"
    "{\"name\":\"leaves\",\"alphaMode\":\"MASK\",\"alphaCutoff\":0.3,"
    "\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.2,0.6,0.1,0.8]}},"
    "{\"name\":\"veil\",\"alphaMode\":\"BLEND\"}],"
    "\"scene\":0,\"scenes\":[{\"nodes\":[0,1,2,3,4]}],"
    "\"nodes\":[{\"mesh\":0},{\"mesh\":1},{\"mesh\":2},{\"mesh\":3},{\"mesh\":4}],"
    "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"material\":0}]},"
    "{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"material\":1}]},"
    "{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"material\":2}]},"
    "{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"material\":3}]},"
    "{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"material\":4}]}],"
    "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\","
    "\"min\":[0,0,0],\"max\":[1,1,0]}],"
    "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36}],"
    "\"buffers\":[{\"byteLength\":36,\"uri\":\"data:application/octet-stream;base64,"
    "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA\"}]}";

static const vct_material *named(const vct_scene *s, const char *name) {
    for (uint32_t m = 0; m < s->material_count; ++m)
        if (strcmp(s->materials[m].name, name) == 0)
            return &s->materials[m];
    return NULL;
}

static void check_materials(void) {
    vct_scene *s = load_gltf_text(gltf_materials);
    const vct_material *lamp = named(s, "lamp"), *glass = named(s, "glass"),
                       *gold = named(s, "gold");
    CHECK(lamp && near(lamp->emission[0], 8.0f, 1e-6f) && near(lamp->emission[1], 4.0f, 1e-6f) &&
              near(lamp->emission[2], 2.0f, 1e-6f),
          "emissiveFactor times emissiveStrength: (%g %g %g)", lamp ? lamp->emission[0] : -1,
          lamp ? lamp->emission[1] : -1, lamp ? lamp->emission[2] : -1);
    CHECK(glass && near(glass->transmission, 1.0f, 1e-6f) && near(glass->ior, 1.33f, 1e-6f) &&
              near(glass->roughness, 0.1f, 1e-6f),
          "glass: transmission %g, ior %g, roughness %g", glass ? glass->transmission : -1,
          glass ? glass->ior : -1, glass ? glass->roughness : -1);
    CHECK(gold && near(gold->metallic, 1.0f, 1e-6f) && near(gold->roughness, 0.35f, 1e-6f) &&
              near(gold->albedo[1], 0.8f, 1e-6f),
          "gold: metallic %g, roughness %g, base colour g %g", gold ? gold->metallic : -1,
          gold ? gold->roughness : -1, gold ? gold->albedo[1] : -1);
    const vct_material *leaves = named(s, "leaves"), *veil = named(s, "veil");
    CHECK(leaves && near(leaves->alpha_cutoff, 0.3f, 1e-6f) && near(leaves->alpha, 0.8f, 1e-6f) &&
              near(leaves->transmission, 0.0f, 0.0f),
          "leaves: alpha cutoff %g, alpha %g, transmission %g (a mask's alpha is no "
          "transmission)",
          leaves ? leaves->alpha_cutoff : -1, leaves ? leaves->alpha : -1,
          leaves ? leaves->transmission : -1);
    CHECK(veil && near(veil->alpha_cutoff, 0.5f, 1e-6f), "veil (BLEND): alpha cutoff %g",
          veil ? veil->alpha_cutoff : -1);
    CHECK(gold && gold->alpha_cutoff == 0.0f, "gold (OPAQUE): alpha cutoff %g",
          gold ? gold->alpha_cutoff : -1);
    vct_scene_release(s);
}

int main(void) {
    const char *dir = getenv("VCT_SOURCE_DIR");
    check_cornell(dir ? dir : ".");
    check_hierarchy();
    check_instances();
    check_materials();
    return check_exit("test_scene_load");
}
