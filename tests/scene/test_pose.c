/* Posing a scene by its animation: the file whose first sphere an animation
 * moves (linear translation keys at 0, 1 and 2 s). Its instance follows the
 * keys (between them, on them, held after the last), its vertices in the
 * flat arrays are its mesh's through the new transform, every other instance
 * keeps its transform and vertices bit for bit, and bad requests (another
 * animation, a NaN time, a NaN key) are refused with the scene unchanged. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "scene/instances.h"

/* The instance the animation's node places. */
static uint32_t animated_instance(const vct_scene *s) {
    const uint32_t node = s->animations[0].channel[0].node;
    for (uint32_t i = 0; i < s->instance_count; ++i)
        if (s->instances[i].node == node)
            return i;
    return UINT32_MAX;
}

static void check_pose_at(double seconds, float expect_x) {
    vct_error err = {0};
    vct_scene *rest = check_scene_file("scenes/instanced_spheres.gltf");
    vct_scene *s = check_scene_file("scenes/instanced_spheres.gltf");
    const uint32_t moved = animated_instance(s);
    CHECK(moved != UINT32_MAX, "no instance under the animated node");
    if (moved == UINT32_MAX)
        return;
    REQUIRE_OK(vct_scene_pose(s, 0, seconds, &err), err);
    const float *m = s->instances[moved].transform;
    CHECK(fabsf(m[3] - expect_x) < 1e-5f && fabsf(m[7] - 0.168f) < 1e-5f &&
              fabsf(m[11] + 4.9f) < 1e-5f,
          "at %g s the sphere is at (%g %g %g), expected x %g", seconds, m[3], m[7], m[11],
          expect_x);
    /* its scale and turn are the rest pose's */
    const float *r = rest->instances[moved].transform;
    float worst = 0.0f;
    for (int k = 0; k < 12; ++k)
        if (k % 4 != 3)
            worst = fmaxf(worst, fabsf(m[k] - r[k]));
    CHECK(worst < 1e-6f, "at %g s the sphere's rotation and scale moved by %g", seconds, worst);
    CHECK(vct_instances_consistent(s), "at %g s an instance's vertices are not its transform's",
          seconds);
    uint32_t changed = 0;
    for (uint32_t i = 0; i < s->instance_count; ++i) {
        if (i == moved)
            continue;
        const vct_instance *a = &s->instances[i], *b = &rest->instances[i];
        const uint32_t verts = s->meshes[a->mesh].vertex_count;
        changed += memcmp(a->transform, b->transform, sizeof a->transform) != 0 ||
                   memcmp(&s->positions[3ull * a->first_vertex],
                          &rest->positions[3ull * b->first_vertex], 12ull * verts) != 0;
    }
    CHECK(changed == 0, "at %g s %u instances the animation does not move changed", seconds,
          changed);
    printf("posed at %g s: the sphere at x %g, the other %u instances unchanged\n", seconds, m[3],
           s->instance_count - 1);
    vct_scene_release(s);
    vct_scene_release(rest);
}

static void check_refusals(void) {
    vct_error err = {0};
    vct_scene *s = check_scene_file("scenes/instanced_spheres.gltf");
    CHECK(vct_scene_pose(s, 1, 0.5, &err) == VCT_ERR_INPUT && strstr(err.message, "animation"),
          "a second animation that is not there: %s", err.message);
    CHECK(vct_scene_pose(s, 0, NAN, &err) == VCT_ERR_INPUT && strstr(err.message, "not finite"),
          "a time that is not a number: %s", err.message);
    /* a key that is not a number: refused before anything moves */
    vct_animation_channel *ch = &s->animations[0].channel[0];
    const float kept = ch->translations[3];
    ch->translations[3] = NAN;
    float before[12];
    const uint32_t moved = animated_instance(s);
    memcpy(before, s->instances[moved].transform, sizeof before);
    CHECK(vct_scene_pose(s, 0, 0.5, &err) == VCT_ERR_INPUT && strstr(err.message, "not finite"),
          "a NaN key: %s", err.message);
    CHECK(memcmp(before, s->instances[moved].transform, sizeof before) == 0,
          "a NaN key moved the instance");
    ch->translations[3] = kept;
    CHECK(vct_instances_consistent(s), "a refused pose changed the scene");
    vct_scene_release(s);
}

static float dist3(const float a[3], const float b[3]) {
    return sqrtf((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                 (a[2] - b[2]) * (a[2] - b[2]));
}

/* The camera and the light ride their animated nodes (moving_camera.gltf):
 * at rest they are where the file puts them; halfway to the first key the
 * eye is halfway along its path; on the key, the light is at its key and
 * the camera looks 10 degrees further left (about +y) than at rest. */
static void check_camera_and_light(void) {
    vct_error err = {0};
    vct_scene *s = check_scene_file("scenes/moving_camera.gltf");
    const vct_camera rest = s->camera;
    const vct_light rest_light = s->lights[0];
    REQUIRE_OK(vct_scene_pose(s, 0, 0.0, &err), err);
    CHECK(dist3(s->camera.position, rest.position) < 1e-5f &&
              dist3(s->camera.look_at, rest.look_at) < 1e-4f &&
              dist3(s->lights[0].position, rest_light.position) < 1e-5f,
          "posed at 0 s, the camera or the light left its rest place");
    REQUIRE_OK(vct_scene_pose(s, 0, 0.5, &err), err);
    const float half[3] = {1.0f, 1.6f, 5.75f}; /* between (0, 1.6, 6) and (2, 1.6, 5.5) */
    CHECK(dist3(s->camera.position, half) < 1e-5f, "at 0.5 s the eye is at (%g %g %g)",
          s->camera.position[0], s->camera.position[1], s->camera.position[2]);
    REQUIRE_OK(vct_scene_pose(s, 0, 1.0, &err), err);
    const float key[3] = {3.0f, 3.0f, 0.0f};
    CHECK(dist3(s->lights[0].position, key) < 1e-5f, "at 1 s the light is at (%g %g %g)",
          s->lights[0].position[0], s->lights[0].position[1], s->lights[0].position[2]);
    /* the view direction turned by +10 degrees about y from rest's */
    float d0[3], d1[3];
    for (int k = 0; k < 3; ++k) {
        d0[k] = rest.look_at[k] - rest.position[k];
        d1[k] = s->camera.look_at[k] - s->camera.position[k];
    }
    const float a0 = atan2f(-d0[0], -d0[2]), a1 = atan2f(-d1[0], -d1[2]);
    const float turned = (a1 - a0) * 180.0f / (float)CHECK_PI;
    CHECK(fabsf(turned - 10.0f) < 1e-3f && fabsf(d1[1] / dist3(d1, (float[3]){0, 0, 0}) -
                                                 d0[1] / dist3(d0, (float[3]){0, 0, 0})) < 1e-5f,
          "at 1 s the camera turned %g degrees about y (expected 10)", turned);
    CHECK(fabsf(dist3(s->camera.up, (float[3]){0, 0, 0}) - 1.0f) < 1e-5f,
          "the camera's up is not of unit length");
    printf("camera and light: ride their nodes (eye halfway at 0.5 s, light on its key and the "
           "view turned %.4f degrees at 1 s)\n",
           turned);
    vct_scene_release(s);
}

/* glTF's STEP sampler holds each key until the next (an unnamed node's,
 * matched as assimp names it); a LINEAR one beside it interpolates. */
static void check_step_keys(void) {
    vct_error err = {0};
    vct_scene *s = check_scene_file("tests/load/inputs/load_step_keys.gltf");
    const vct_animation_channel *c = s->animations[0].channel;
    int stepped = -1, turned = -1;
    for (uint32_t i = 0; i < s->animations[0].channels; ++i) {
        if (c[i].translation_keys)
            stepped = (int)i;
        if (c[i].rotation_keys)
            turned = (int)i;
    }
    if (stepped < 0 || turned < 0) {
        CHECK(0, "step_keys: the two channels were not read");
        vct_scene_release(s);
        return;
    }
    CHECK(c[stepped].translation_step && !c[turned].rotation_step,
          "step_keys: STEP read as %d, LINEAR as %d", c[stepped].translation_step,
          c[turned].rotation_step);
    uint32_t moved = 0;
    while (moved < s->instance_count && s->instances[moved].node != c[stepped].node)
        ++moved;
    CHECK(moved < s->instance_count, "step_keys: no instance of the stepped node");
    if (moved == s->instance_count) {
        vct_scene_release(s);
        return;
    }
    const double at[4] = {0.5, 0.999, 1.0, 1.5}, expect[4] = {0.0, 0.0, 1.0, 1.0};
    for (int k = 0; k < 4; ++k) {
        REQUIRE_OK(vct_scene_pose(s, 0, at[k], &err), err);
        const float x = s->instances[moved].transform[3];
        CHECK(fabsf(x - (float)expect[k]) < 1e-6f, "STEP keys at %g s: x %g, expected %g", at[k], x,
              expect[k]);
    }
    printf("STEP keys held until the next (x 0 at 0.5 and 0.999 s, 1 at 1 and 1.5 s)\n");
    vct_scene_release(s);
}

/* glTF's CUBICSPLINE samplers follow their tangents (assimp keeps only the
 * values): x from 1 at 0 s to 4 at 2 s, out-tangent 3, in-tangent 5, is
 * 1.84375 at 0.5 s and 2 at 1 s (a line would give 1.75 and 2.5); a turn
 * from 0 to 90 degrees with zero tangents, its quaternion's spline
 * normalised, is 13.21 degrees at 0.25 s (a slerp: 22.5). The buffers read
 * three ways: embedded, a file beside, a .glb's binary chunk. */
static void check_cubic_keys(const char *file) {
    vct_error err = {0};
    vct_scene *s = check_scene_file(file);
    uint32_t moved = UINT32_MAX, turned = UINT32_MAX;
    for (uint32_t i = 0; i < s->instance_count; ++i) {
        if (s->instances[i].transform[3] == 3.0f)
            turned = i;
        else
            moved = i;
    }
    if (moved == UINT32_MAX || turned == UINT32_MAX) {
        CHECK(0, "%s: the moved and the turned instances were not found", file);
        vct_scene_release(s);
        return;
    }
    const double at[4] = {0.5, 1.0, 2.0, 3.0}, expect[4] = {1.84375, 2.0, 4.0, 4.0};
    for (int k = 0; k < 4; ++k) {
        REQUIRE_OK(vct_scene_pose(s, 0, at[k], &err), err);
        const float x = s->instances[moved].transform[3];
        CHECK(fabs(x - expect[k]) < 1e-5, "%s: cubic spline at %g s: x %.6f, expected %g", file,
              at[k], x, expect[k]);
    }
    const double h = sqrt(0.5), y = 0.15625 * h, w = 0.84375 + 0.15625 * h;
    const double expect_deg = 2.0 * atan2(y, w) * 57.29577951308232;
    REQUIRE_OK(vct_scene_pose(s, 0, 0.25, &err), err);
    const float *m = s->instances[turned].transform;
    const double deg = atan2(m[2], m[0]) * 57.29577951308232;
    CHECK(fabs(deg - expect_deg) < 1e-3,
          "%s: cubic rotation at 0.25 s: %.4f degrees, expected %.4f", file, deg, expect_deg);
    printf("%s: cubic splines follow their tangents (x %.5f at 0.5 s; %.3f degrees at 0.25 s)\n",
           file, expect[0], expect_deg);
    vct_scene_release(s);
}

/* Keys that are equal hold the node still bit for bit between them: a
 * rotation blended with itself and normalised could round to another float
 * (a still camera that moved by an ulp changed a still sequence's pixels). */
static void check_equal_keys_hold(void) {
    vct_error err = {0};
    vct_scene *s = check_scene_file("scenes/instanced_spheres.gltf");
    vct_animation_channel *c = &s->animations[0].channel[0];
    free(c->rotation_times);
    free(c->rotations);
    c->rotation_keys = 2;
    c->rotation_times = malloc(2 * sizeof(float));
    c->rotations = malloc(8 * sizeof(float));
    const float q[4] = {0.1f, 0.3f, 0.2f, 0.92736f}; /* as stored: a few ulps off unit length */
    c->rotation_times[0] = 0.0f;
    c->rotation_times[1] = 1.0f;
    memcpy(c->rotations, q, sizeof q);
    memcpy(c->rotations + 4, q, sizeof q);
    const uint32_t moved = animated_instance(s);
    float first[12];
    REQUIRE_OK(vct_scene_pose(s, 0, 0.0, &err), err);
    memcpy(first, s->instances[moved].transform, sizeof first);
    int differ = 0;
    for (int k = 1; k < 10; ++k) {
        REQUIRE_OK(vct_scene_pose(s, 0, 0.1 * k, &err), err);
        for (int j = 0; j < 12; ++j)
            differ += j % 4 != 3 && s->instances[moved].transform[j] != first[j];
    }
    CHECK(differ == 0, "equal rotation keys: %d rotation entries differ between 0 and 1 s", differ);
    printf("equal rotation keys hold the node's turn bit for bit between them\n");
    vct_scene_release(s);
}

int main(void) {
    check_camera_and_light();
    check_step_keys();
    check_equal_keys_hold();
    check_cubic_keys("tests/load/inputs/cubic_keys.gltf");
    check_cubic_keys("tests/load/inputs/cubic_keys_bin.gltf");
    check_cubic_keys("tests/load/inputs/cubic_keys.glb");
    check_pose_at(0.5, -4.2f);  /* halfway between the first two keys */
    check_pose_at(1.0, -3.5f);  /* on a key */
    check_pose_at(5.0, -4.9f);  /* after the last: held there */
    check_pose_at(-1.0, -4.9f); /* before the first */
    check_refusals();
    return check_exit("test_pose");
}
