/* The moved region of a committed scene (moved_region.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <xxhash.h>

#include "device_scene/moved_region.h"
#include "scene/scene_resident.h"

static uint32_t instance_vertices(const vct_scene *s, uint32_t i) {
    return s->meshes[s->instances[i].mesh].vertex_count;
}

static void measure(const vct_scene *s, uint32_t i, uint64_t *hash, float box[6]) {
    const uint32_t first = s->instances[i].first_vertex, n = instance_vertices(s, i);
    const float *p = s->positions + 3ull * first;
    *hash = XXH3_64bits(p, 12ull * n);
    for (int k = 0; k < 3; ++k)
        box[k] = INFINITY, box[3 + k] = -INFINITY;
    for (uint32_t v = 0; v < n; ++v)
        for (int k = 0; k < 3; ++k) {
            box[k] = fminf(box[k], p[3 * v + k]);
            box[3 + k] = fmaxf(box[3 + k], p[3 * v + k]);
        }
}

void vct_moved_region_init(vct_moved_region *r, const vct_scene *s) {
    free(r->hash);
    free(r->box);
    memset(r, 0, sizeof *r);
    r->instance_count = s->instance_count;
    r->hash = malloc(sizeof *r->hash * (s->instance_count + 1));
    r->box = malloc(sizeof *r->box * 6 * (s->instance_count + 1));
    if (!r->hash || !r->box) {
        r->everything = 1;
        r->instance_count = 0;
        return;
    }
    for (uint32_t i = 0; i < s->instance_count; ++i)
        measure(s, i, &r->hash[i], &r->box[6 * i]);
}

static void add_box(vct_moved_region *r, const float lo_hi[6]) {
    if (r->box_count == VCT_CARRY_BOXES) { /* full: the last box takes the rest */
        float *last = r->boxes[VCT_CARRY_BOXES - 1];
        for (int k = 0; k < 3; ++k) {
            last[k] = fminf(last[k], lo_hi[k]);
            last[3 + k] = fmaxf(last[3 + k], lo_hi[3 + k]);
        }
        return;
    }
    memcpy(r->boxes[r->box_count++], lo_hi, 6 * sizeof(float));
}

void vct_moved_region_note(vct_moved_region *r, const vct_scene *s, unsigned changed) {
    const unsigned places = VCT_CHANGED_POSITIONS | VCT_CHANGED_CAMERA;
    if ((changed & ~places) || s->instance_count != r->instance_count || !r->hash) {
        vct_moved_region_init(r, s);
        r->everything = 1;
        return;
    }
    if (!(changed & VCT_CHANGED_POSITIONS))
        return;
    for (uint32_t i = 0; i < s->instance_count; ++i) {
        uint64_t hash;
        float box[6];
        measure(s, i, &hash, box);
        if (hash == r->hash[i])
            continue;
        add_box(r, &r->box[6 * i]); /* where it was */
        add_box(r, box);            /* and where it is */
        const uint32_t first = s->instances[i].first_triangle,
                       end = first + s->meshes[s->instances[i].mesh].triangle_count;
        r->tri_lo = r->tri_hi > r->tri_lo && r->tri_lo < first ? r->tri_lo : first;
        r->tri_hi = r->tri_hi > end ? r->tri_hi : end;
        r->hash[i] = hash;
        memcpy(&r->box[6 * i], box, sizeof box);
    }
}

void vct_moved_region_clear(vct_moved_region *r) {
    r->everything = 0;
    r->box_count = 0;
    r->tri_lo = r->tri_hi = 0;
}

void vct_moved_region_boxes(const vct_moved_region *r, vct_voxel_carry *carry) {
    memset(carry->boxes, 0, sizeof carry->boxes);
    carry->moved_lo = r->everything ? 0 : r->tri_lo;
    carry->moved_hi = r->everything ? 0 : r->tri_hi;
    if (r->everything) {
        carry->box_count = 1;
        for (int k = 0; k < 3; ++k) {
            carry->boxes[0].s[k] = -INFINITY;
            carry->boxes[1].s[k] = INFINITY;
        }
        return;
    }
    carry->box_count = r->box_count;
    for (uint32_t b = 0; b < r->box_count; ++b)
        for (int k = 0; k < 3; ++k) {
            carry->boxes[2 * b].s[k] = r->boxes[b][k];
            carry->boxes[2 * b + 1].s[k] = r->boxes[b][3 + k];
        }
}

void vct_moved_region_release(vct_moved_region *r) {
    free(r->hash);
    free(r->box);
    memset(r, 0, sizeof *r);
}
