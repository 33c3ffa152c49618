/* Posing a scene by its animation: the file whose first sphere an animation
 * moves (linear translation keys at 0, 1 and 2 s). Its instance follows the
 * keys (between them, on them, held after the last), its vertices in the
 * flat arrays are its mesh's through the new transform, every other instance
 * keeps its transform and vertices bit for bit, and bad requests (another
 * animation, a NaN time, a NaN key) are refused with the scene unchanged. */
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

int main(void) {
    check_pose_at(0.5, -4.2f);  /* halfway between the first two keys */
    check_pose_at(1.0, -3.5f);  /* on a key */
    check_pose_at(5.0, -4.9f);  /* after the last: held there */
    check_pose_at(-1.0, -4.9f); /* before the first */
    check_refusals();
    return check_exit("test_pose");
}
