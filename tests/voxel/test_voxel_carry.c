/* Direct light carried into new voxels after geometry moved (carry_direct,
 * then inject_direct for the rest): the Cornell box under a point light,
 * its green wall moved inward. Each new voxel's voxel before is the one at
 * its key (checked against the keys on the host), and the light of the new
 * voxels, kept where nothing that moved reaches and injected elsewhere,
 * equals a fresh injection bit for bit: a voxel kept in the moved wall's
 * old place, or in the shadow of the lamp room's sliding table, would
 * differ. Most voxels keep theirs. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "runtime/runtime.h"
#include "vct_types.h"
#include "voxel/voxels.h"

static vct_context *ctx;

static vct_voxels *voxels_of(const vct_scene *s, const vct_voxel_options *o) {
    vct_error err = {0};
    vct_voxels *v = vct_voxelize(ctx, s, o, &err);
    REQUIRE_OK(v ? VCT_OK : err.status, err);
    REQUIRE_OK(vct_octree_build(ctx, v, &err), err);
    return v;
}

static void read_light(vct_voxels *v, float **radiance, float **sides, uint32_t **keys) {
    vct_error err = {0};
    vct_voxel_info info;
    vct_voxels_info_get(v, &info);
    *radiance = malloc(16ull * info.voxels + 16);
    *sides = malloc(32ull * info.voxels + 16);
    *keys = malloc(4ull * info.voxels + 4);
    REQUIRE_OK(vct_voxels_read_radiance(ctx, v, *radiance, &err), err);
    REQUIRE_OK(vct_voxels_read_sides(ctx, v, *sides, &err), err);
    REQUIRE_OK(vct_voxels_read(ctx, v, *keys, NULL, NULL, NULL, &err), err);
}

static void box_of(const vct_scene *s, uint32_t i, cl_float4 *lo, cl_float4 *hi) {
    const uint32_t first = s->instances[i].first_vertex;
    for (int k = 0; k < 3; ++k)
        lo->s[k] = INFINITY, hi->s[k] = -INFINITY;
    for (uint32_t v = 0; v < s->meshes[s->instances[i].mesh].vertex_count; ++v)
        for (int k = 0; k < 3; ++k) {
            lo->s[k] = fminf(lo->s[k], s->positions[3ull * (first + v) + k]);
            hi->s[k] = fmaxf(hi->s[k], s->positions[3ull * (first + v) + k]);
        }
}

/* The boxes, before and after, of every instance whose vertices `move`
 * changed, into carry. */
typedef void (*move_fn)(vct_scene *s);

static void moved_boxes(vct_scene *s, move_fn move, vct_voxel_carry *carry) {
    const size_t bytes = 12ull * s->vertex_count;
    float *was = malloc(bytes + 4);
    memcpy(was, s->positions, bytes);
    cl_float4 *boxes = malloc(sizeof(cl_float4) * 2 * (s->instance_count + 1));
    for (uint32_t i = 0; i < s->instance_count; ++i)
        box_of(s, i, &boxes[2 * i], &boxes[2 * i + 1]);
    move(s);
    carry->box_count = 0;
    for (uint32_t i = 0; i < s->instance_count; ++i) {
        const uint32_t first = s->instances[i].first_vertex;
        const size_t n = 12ull * s->meshes[s->instances[i].mesh].vertex_count;
        if (memcmp(was + 3ull * first, s->positions + 3ull * first, n) == 0)
            continue;
        if (carry->box_count + 2 > VCT_CARRY_BOXES)
            break; /* the scenes here move one or two */
        carry->boxes[2 * carry->box_count] = boxes[2 * i];
        carry->boxes[2 * carry->box_count + 1] = boxes[2 * i + 1];
        ++carry->box_count;
        box_of(s, i, &carry->boxes[2 * carry->box_count], &carry->boxes[2 * carry->box_count + 1]);
        ++carry->box_count;
    }
    free(was);
    free(boxes);
}

static void check_carry(const char *label, vct_scene *s, move_fn move, uint32_t resolution) {
    vct_error err = {0};
    vct_voxel_options o = vct_voxel_options_default();
    o.resolution = resolution;
    vct_accel *a = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(a ? VCT_OK : err.status, err);
    vct_voxels *before = voxels_of(s, &o);
    REQUIRE_OK(vct_voxels_inject_light(ctx, s, a, before, &err), err);
    vct_voxel_carry carry;
    memset(&carry, 0, sizeof carry);
    carry.before = before;
    moved_boxes(s, move, &carry);
    vct_accel_release(a);
    a = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(a ? VCT_OK : err.status, err);
    vct_voxels *carried = voxels_of(s, &o), *fresh = voxels_of(s, &o);
    REQUIRE_OK(vct_voxels_inject_light_carried(ctx, s, a, carried, &carry, &err), err);
    REQUIRE_OK(vct_voxels_inject_light(ctx, s, a, fresh, &err), err);
    vct_voxel_info info, info_before;
    vct_voxels_info_get(carried, &info);
    vct_voxels_info_get(before, &info_before);
    uint32_t *from = malloc(4ull * info.voxels + 4);
    REQUIRE_OK(vct_buffer_read(ctx, "test", carry.carried_from, 0, 4ull * info.voxels, from, &err),
               err);
    float *rc, *sc, *rf, *sf, *rb, *sb;
    uint32_t *kc, *kf, *kb;
    read_light(carried, &rc, &sc, &kc);
    read_light(fresh, &rf, &sf, &kf);
    read_light(before, &rb, &sb, &kb);
    uint32_t kept = 0, wrong_from = 0, differ = 0, missed = 0;
    for (uint32_t v = 0, j = 0; v < info.voxels; ++v) {
        if (from[v] != VCT_NO_VOXEL) {
            ++kept;
            wrong_from += from[v] >= info_before.voxels || kb[from[v]] != kc[v];
        }
        differ += memcmp(&rc[4 * v], &rf[4 * v], 16) != 0 || memcmp(&sc[8 * v], &sf[8 * v], 32);
        /* a key absent before finds no voxel */
        while (j < info_before.voxels && kb[j] < kc[v])
            ++j;
        missed += !(j < info_before.voxels && kb[j] == kc[v]) && from[v] != VCT_NO_VOXEL;
    }
    CHECK(wrong_from == 0 && missed == 0,
          "%s, %u^3: %u voxels carried from another key, %u from a key absent before", label,
          resolution, wrong_from, missed);
    CHECK(differ == 0, "%s, %u^3: %u of %u voxels' light differs from a fresh injection", label,
          resolution, differ, info.voxels);
    CHECK(kept > info.voxels / 2 && kept < info.voxels,
          "%s, %u^3: %u of %u voxels kept their light (expected most, not all)", label, resolution,
          kept, info.voxels);
    printf("%s, %u^3: %u of %u voxels keep their direct light, the rest lit again; equal to a "
           "fresh injection bit for bit\n",
           label, resolution, kept, info.voxels);
    vct_buffer_release(ctx, carry.carried_from);
    free(from), free(rc), free(sc), free(kc), free(rf), free(sf), free(kf), free(rb), free(sb),
        free(kb);
    vct_voxels_release(before);
    vct_voxels_release(carried);
    vct_voxels_release(fresh);
    vct_accel_release(a);
}

/* The Cornell box's green wall, 60 mm inward. */
static void move_green_wall(vct_scene *s) {
    vct_error err = {0};
    for (uint32_t i = 0; i < s->instance_count; ++i) {
        const uint32_t t = s->instances[i].first_triangle;
        if (strcmp(s->materials[s->triangle_material[t]].name, "green") != 0)
            continue;
        float m[12];
        memcpy(m, s->instances[i].transform, sizeof m);
        m[3] += 60.0f;
        REQUIRE_OK(vct_scene_set_instance_transform(s, i, m, &err), err);
    }
}

/* The lamp room's table halfway along its slide, under the point light:
 * the table's shadow on the carpet and the wall moves with it. */
static void slide_table(vct_scene *s) {
    vct_error err = {0};
    REQUIRE_OK(vct_scene_pose(s, 0, 0.75, &err), err);
}

int main(void) {
    ctx = check_context();
    vct_scene *box = check_cornell_box_point_light();
    check_carry("Cornell box, green wall moved", box, move_green_wall, 32);
    vct_scene_release(box);
    box = check_cornell_box_point_light();
    check_carry("Cornell box, green wall moved", box, move_green_wall, 64);
    vct_scene_release(box);
    vct_scene *room = check_scene_file("scenes/suite/lamp_room.gltf");
    for (uint32_t m = 0; m < room->material_count; ++m) /* the point light alone */
        memset(room->materials[m].emission, 0, sizeof room->materials[m].emission);
    check_carry("lamp room, table slid", room, slide_table, 64);
    vct_scene_release(room);
    vct_context_release(ctx);
    return check_exit("test_voxel_carry");
}
