/* The two-level BVH: each placed mesh's BVH built once in its own space by
 * the one-level builder, the top level over the instances' world boxes
 * built here, on the host. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "accel/bvh2.h"
#include "accel/tri_vertices.h"
#include "scene/instances.h"

#define STAGE "bvh build"
#define INSTANCE_FLOAT4S 5
#define NODE_FLOATS 32
#define LEAF_BIT 0x80000000u
#define EMPTY_REF 0xFFFFFFFFu

typedef vct_mesh_tree mesh_tree;

/* A mesh as a scene of its own, in its space, for the one-level builder. */
static int mesh_tree_build(vct_context *ctx, const vct_mesh *m, vct_bvh_builder builder,
                           mesh_tree *t, vct_error *err) {
    vct_material material = vct_material_default();
    vct_scene s;
    memset(&s, 0, sizeof s);
    s.vertex_count = m->vertex_count;
    s.triangle_count = m->triangle_count;
    s.positions = m->positions;
    s.triangles = m->triangles;
    s.material_count = 1;
    s.materials = &material;
    s.triangle_material = calloc(m->triangle_count + 1ull, sizeof(uint32_t));
    if (!s.triangle_material)
        return vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory", STAGE);
    for (int k = 0; k < 3; ++k) {
        s.bounds_min[k] = INFINITY;
        s.bounds_max[k] = -INFINITY;
    }
    for (uint32_t i = 0; i < 3 * m->triangle_count; ++i)
        for (int k = 0; k < 3; ++k) {
            const float p = m->positions[3 * m->triangles[i] + k];
            s.bounds_min[k] = fminf(s.bounds_min[k], p);
            s.bounds_max[k] = fmaxf(s.bounds_max[k], p);
        }
    vct_bvh *b = vct_bvh_build(ctx, &s, builder, err);
    free(s.triangle_material);
    if (!b)
        return err->status;
    t->node_count = b->node_count;
    t->depth = b->depth;
    t->nodes = malloc(128ull * (b->node_count ? b->node_count : 1));
    t->tri_ids = malloc(4ull * (m->triangle_count ? m->triangle_count : 1));
    int rc = t->nodes && t->tri_ids
                 ? vct_bvh_read(ctx, b, t->nodes, t->tri_ids, err)
                 : vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory", STAGE);
    vct_bvh_free(b);
    for (int k = 0; k < 3; ++k) {
        t->lo[k] = INFINITY;
        t->hi[k] = -INFINITY;
        for (int c = 0; rc == VCT_OK && t->node_count && c < 4; ++c) {
            t->lo[k] = fminf(t->lo[k], t->nodes[8 * k + c]);
            t->hi[k] = fmaxf(t->hi[k], t->nodes[8 * k + 4 + c]);
        }
    }
    return rc;
}

/* An instance as the top level sees it: its world box and centre. */
typedef struct placed {
    uint32_t instance;
    double lo[3], hi[3], centre[3];
} placed;

typedef struct top_build {
    float *nodes;
    uint32_t count, cap, depth;
    const placed *items;
    uint32_t *order; /* leaf slot -> placed item */
    uint32_t slots;
    int sorted; /* 0: a sort ran out of memory */
} top_build;

typedef struct keyed {
    double key;
    uint32_t id;
} keyed;

static int compare_keyed(const void *a, const void *b) {
    const keyed *x = a, *y = b;
    return x->key < y->key ? -1 : x->key > y->key ? 1 : (x->id > y->id) - (x->id < y->id);
}

/* Sorts ids[0..n) along the widest axis of their centres (ties by id, so
 * that the tree is the same on every run). 0 without memory. */
static int sort_widest(const placed *items, uint32_t *ids, uint32_t n) {
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (uint32_t i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) {
            lo[k] = fmin(lo[k], items[ids[i]].centre[k]);
            hi[k] = fmax(hi[k], items[ids[i]].centre[k]);
        }
    int axis = hi[1] - lo[1] > hi[0] - lo[0] ? 1 : 0;
    if (hi[2] - lo[2] > hi[axis] - lo[axis])
        axis = 2;
    keyed *k = malloc(n * sizeof *k);
    if (!k)
        return 0;
    for (uint32_t i = 0; i < n; ++i)
        k[i] = (keyed){items[ids[i]].centre[axis], ids[i]};
    qsort(k, n, sizeof *k, compare_keyed);
    for (uint32_t i = 0; i < n; ++i)
        ids[i] = k[i].id;
    free(k);
    return 1;
}

/* The subtree over ids[0..n): a leaf of one instance, or a node whose up to
 * four children split the items at medians of their widest axes. */
static uint32_t top_subtree(top_build *tb, uint32_t *ids, uint32_t n, uint32_t depth, float *lo,
                            float *hi) {
    if (depth > tb->depth)
        tb->depth = depth;
    if (n == 1) {
        const placed *p = &tb->items[ids[0]];
        for (int k = 0; k < 3; ++k) {
            lo[k] = (float)p->lo[k];
            hi[k] = (float)p->hi[k];
        }
        tb->order[tb->slots] = ids[0];
        return LEAF_BIT | tb->slots++;
    }
    const uint32_t node = tb->count++;
    uint32_t first[5], counts[4], groups = 0;
    tb->sorted &= sort_widest(tb->items, ids, n);
    const uint32_t half = n / 2, parts[2][2] = {{0, half}, {half, n - half}};
    for (int h = 0; h < 2; ++h) {
        uint32_t *sub = ids + parts[h][0], m = parts[h][1];
        if (m >= 2 && n > 3) {
            tb->sorted &= sort_widest(tb->items, sub, m);
            first[groups] = parts[h][0];
            counts[groups++] = m / 2;
            first[groups] = parts[h][0] + m / 2;
            counts[groups++] = m - m / 2;
        } else {
            first[groups] = parts[h][0];
            counts[groups++] = m;
        }
    }
    float child_lo[4][3], child_hi[4][3];
    uint32_t refs[4] = {EMPTY_REF, EMPTY_REF, EMPTY_REF, EMPTY_REF};
    for (uint32_t c = 0; c < groups; ++c)
        refs[c] = top_subtree(tb, ids + first[c], counts[c], depth + 1, child_lo[c], child_hi[c]);
    float *out = tb->nodes + NODE_FLOATS * node;
    for (int k = 0; k < 3; ++k) {
        lo[k] = INFINITY;
        hi[k] = -INFINITY;
        for (uint32_t c = 0; c < 4; ++c) {
            out[8 * k + c] = c < groups ? child_lo[c][k] : INFINITY;
            out[8 * k + 4 + c] = c < groups ? child_hi[c][k] : -INFINITY;
            if (c < groups) {
                lo[k] = fminf(lo[k], child_lo[c][k]);
                hi[k] = fmaxf(hi[k], child_hi[c][k]);
            }
        }
    }
    uint32_t node_refs[8] = {refs[0],   refs[1],   refs[2],   refs[3],
                             EMPTY_REF, EMPTY_REF, EMPTY_REF, EMPTY_REF};
    memcpy(out + 24, node_refs, sizeof node_refs);
    return node;
}

/* The inverse of a 3x4 affine transform, in double; 0 when singular. */
static int invert(const float m[12], double inv[12]) {
    const double a = m[0], b = m[1], c = m[2], d = m[4], e = m[5], f = m[6], g = m[8], h = m[9],
                 i = m[10];
    const double det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
    if (!(fabs(det) > 0.0) || !isfinite(det))
        return 0;
    const double r[9] = {(e * i - f * h) / det, (c * h - b * i) / det, (b * f - c * e) / det,
                         (f * g - d * i) / det, (a * i - c * g) / det, (c * d - a * f) / det,
                         (d * h - e * g) / det, (b * g - a * h) / det, (a * e - b * d) / det};
    for (int row = 0; row < 3; ++row) {
        for (int k = 0; k < 3; ++k)
            inv[4 * row + k] = r[3 * row + k];
        inv[4 * row + 3] = -(r[3 * row] * m[3] + r[3 * row + 1] * m[7] + r[3 * row + 2] * m[11]);
    }
    return 1;
}

/* An instance's world box (its mesh's root box through its transform),
 * padded for the transform's rounding and the scene's tolerance, and its
 * record's padding terms. */
static void place(const vct_instance *in, const mesh_tree *t, float tolerance, placed *p,
                  float padding[2]) {
    const float *m = in->transform;
    double reach = fmax(fabs(m[3]), fmax(fabs(m[7]), fabs(m[11])));
    for (int k = 0; k < 3; ++k) {
        p->lo[k] = INFINITY;
        p->hi[k] = -INFINITY;
    }
    for (int corner = 0; corner < 8; ++corner) {
        const double c[3] = {corner & 1 ? t->hi[0] : t->lo[0], corner & 2 ? t->hi[1] : t->lo[1],
                             corner & 4 ? t->hi[2] : t->lo[2]};
        for (int r = 0; r < 3; ++r) {
            const double w =
                m[4 * r] * c[0] + m[4 * r + 1] * c[1] + m[4 * r + 2] * c[2] + m[4 * r + 3];
            p->lo[r] = fmin(p->lo[r], w);
            p->hi[r] = fmax(p->hi[r], w);
            reach = fmax(reach, fabs(w));
        }
    }
    const double pad = tolerance + 16.0 * FLT_EPSILON * reach;
    for (int k = 0; k < 3; ++k) {
        p->lo[k] -= pad;
        p->hi[k] += pad;
        p->centre[k] = 0.5 * (p->lo[k] + p->hi[k]);
    }
    double inv[12] = {0}, norm = 0.0;
    invert(m, inv); /* the caller checked it has one */
    for (int r = 0; r < 3; ++r)
        norm = fmax(norm, fabs(inv[4 * r]) + fabs(inv[4 * r + 1]) + fabs(inv[4 * r + 2]));
    padding[0] = (float)(64.0 * FLT_EPSILON * norm);
    padding[1] = (float)(2.0 * reach);
}

void vct_bvh2_free(vct_bvh2 *b) {
    if (!b)
        return;
    vct_buffer_release(b->ctx, b->nodes);
    vct_buffer_release(b->ctx, b->instances);
    vct_buffer_release(b->ctx, b->tri_ids);
    vct_buffer_release(b->ctx, b->tri_vertices);
    free(b->trees);
    free(b);
}

/* The instances placed: their records in the top level's leaf order and
 * the top level's nodes (top_cap slots), from the meshes' trees. */
static int place_all(vct_bvh2 *b, const vct_scene *s, float *top, float **records_out,
                     vct_error *err) {
    const mesh_tree *trees = b->trees;
    placed *items = calloc(s->instance_count + 1, sizeof *items);
    float *records = calloc(4ull * INSTANCE_FLOAT4S * (s->instance_count + 1), sizeof(float));
    float *by_instance = calloc(4ull * INSTANCE_FLOAT4S * (s->instance_count + 1), sizeof(float));
    top_build tb = {top, 0, 0, 0, items, calloc(s->instance_count + 1, sizeof(uint32_t)), 0, 1};
    int rc = items && records && by_instance && tb.order
                 ? VCT_OK
                 : vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory", STAGE);
    uint32_t n = 0;
    for (uint32_t i = 0; rc == VCT_OK && i < s->instance_count; ++i) {
        const vct_instance *in = &s->instances[i];
        const mesh_tree *t = &trees[in->mesh];
        double inv[12];
        if (!t->node_count || !invert(in->transform, inv))
            continue; /* no triangles, or flattened to zero area: never hit */
        float padding[2];
        items[n].instance = i;
        place(in, t, b->tolerance, &items[n], padding);
        float *r = by_instance + 4 * INSTANCE_FLOAT4S * i;
        for (int k = 0; k < 12; ++k)
            r[k] = (float)inv[k];
        const uint32_t at[4] = {b->top_cap + t->root, t->first_id, in->first_triangle, 0};
        memcpy(r + 12, at, sizeof at);
        r[16] = padding[0];
        r[17] = padding[1];
        ++n;
    }
    uint32_t *order = rc == VCT_OK ? calloc(n + 1, sizeof *order) : NULL;
    if (rc == VCT_OK && !order)
        rc = vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory", STAGE);
    for (uint32_t k = 0; rc == VCT_OK && k < n; ++k)
        order[k] = k;
    float lo[3], hi[3];
    if (rc == VCT_OK && n == 1) {
        /* a root node above the lone leaf, as traversal starts at node 0 */
        tb.count = 1;
        const uint32_t leaf = top_subtree(&tb, order, 1, 1, lo, hi);
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 4; ++c) {
                top[8 * k + c] = c ? INFINITY : lo[k];
                top[8 * k + 4 + c] = c ? -INFINITY : hi[k];
            }
        const uint32_t refs[8] = {leaf,      EMPTY_REF, EMPTY_REF, EMPTY_REF,
                                  EMPTY_REF, EMPTY_REF, EMPTY_REF, EMPTY_REF};
        memcpy(top + 24, refs, sizeof refs);
    } else if (rc == VCT_OK && n > 1) {
        top_subtree(&tb, order, n, 1, lo, hi);
    }
    if (rc == VCT_OK && !tb.sorted)
        rc = vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory", STAGE);
    b->top_nodes = tb.count;
    b->instance_count = tb.slots;
    if (rc == VCT_OK && tb.depth + b->depth > VCT_BVH_MAX_DEPTH)
        rc = vct_fail(err, VCT_ERR_OVERFLOW,
                      "%s: the two levels are %u deep, beyond the %d traversal keeps: use "
                      "--accel grid",
                      STAGE, tb.depth + b->depth, VCT_BVH_MAX_DEPTH);
    for (uint32_t slot = 0; rc == VCT_OK && slot < tb.slots; ++slot)
        memcpy(records + 4 * INSTANCE_FLOAT4S * slot,
               by_instance + 4 * INSTANCE_FLOAT4S * items[tb.order[slot]].instance,
               16ull * INSTANCE_FLOAT4S);
    free(order);
    free(items);
    free(by_instance);
    free(tb.order);
    if (rc != VCT_OK) {
        free(records);
        return rc;
    }
    *records_out = records;
    return VCT_OK;
}

/* The instances buffer made again from records (their count may change). */
static int instances_upload(vct_bvh2 *b, const float *records, vct_error *err) {
    vct_buffer_release(b->ctx, b->instances);
    b->instances =
        vct_buffer_create(b->ctx, STAGE, "instances", 16ull * INSTANCE_FLOAT4S * b->instance_count,
                          CL_MEM_READ_ONLY, records, err);
    return b->instances ? VCT_OK : (int)err->status;
}

int vct_bvh2_move(vct_context *ctx, vct_bvh2 *b, const vct_scene *s, vct_error *err) {
    if (s->instance_count > b->top_cap || s->triangle_count != b->triangle_count ||
        !vct_instances_consistent(s))
        return vct_fail(err, VCT_ERR_INPUT,
                        "%s: the scene gained instances or triangles, or its positions are not "
                        "its instances': build the structure again",
                        STAGE);
    vct_stage_begin(ctx, STAGE);
    float *top = calloc(b->top_cap, 128), *records = NULL;
    cl_mem vertices = NULL;
    int rc = top ? vct_tri_vertices_upload(ctx, s, STAGE, &vertices, err)
                 : vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory", STAGE);
    if (rc == VCT_OK)
        rc = place_all(b, s, top, &records, err);
    if (rc == VCT_OK && b->top_nodes)
        rc = vct_buffer_write(ctx, STAGE, b->nodes, 0, 128ull * b->top_nodes, top, err);
    if (rc == VCT_OK)
        rc = instances_upload(b, records, err);
    if (rc == VCT_OK) {
        vct_buffer_release(ctx, b->tri_vertices);
        b->tri_vertices = vertices;
        vertices = NULL;
    }
    vct_buffer_release(ctx, vertices);
    free(top);
    free(records);
    vct_stage_end(ctx);
    return rc;
}

vct_bvh2 *vct_bvh2_build(vct_context *ctx, const vct_scene *s, vct_bvh_builder builder,
                         vct_error *err) {
    vct_bvh2 *b = calloc(1, sizeof *b);
    uint8_t *used = calloc(s->mesh_count + 1, 1);
    int rc = b && used ? VCT_OK : vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory", STAGE);
    if (rc == VCT_OK) {
        b->trees = calloc(s->mesh_count + 1, sizeof *b->trees);
        rc = b->trees ? VCT_OK : vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory", STAGE);
    }
    vct_scene_frame f;
    vct_scene_frame_of(s, &f);
    if (rc == VCT_OK) {
        b->ctx = ctx;
        b->scene_extent = f.extent;
        b->tolerance = f.tolerance;
        b->triangle_count = s->triangle_count;
        b->mesh_count = s->mesh_count;
        /* room for the largest top level the instances can need, so that
         * moving them rewrites it in place */
        b->top_cap = s->instance_count ? s->instance_count : 1;
        rc = vct_tri_vertices_upload(ctx, s, STAGE, &b->tri_vertices, err);
    }
    for (uint32_t i = 0; rc == VCT_OK && i < s->instance_count; ++i)
        used[s->instances[i].mesh] = 1;
    /* each placed mesh once, in its own space; their nodes after the top level's */
    for (uint32_t m = 0; rc == VCT_OK && m < s->mesh_count; ++m) {
        if (!used[m] || s->meshes[m].triangle_count == 0)
            continue;
        mesh_tree *t = &b->trees[m];
        rc = mesh_tree_build(ctx, &s->meshes[m], builder, t, err);
        t->root = b->mesh_nodes;
        t->first_id = b->mesh_triangles;
        b->mesh_nodes += t->node_count;
        b->mesh_triangles += s->meshes[m].triangle_count;
        if (t->depth > b->depth)
            b->depth = t->depth;
    }
    float *nodes = rc == VCT_OK ? calloc(b->top_cap + b->mesh_nodes + 1ull, 128) : NULL;
    uint32_t *ids = rc == VCT_OK ? malloc(4ull * (b->mesh_triangles + 1)) : NULL;
    float *records = NULL;
    if (rc == VCT_OK && (!nodes || !ids))
        rc = vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory", STAGE);
    if (rc == VCT_OK)
        rc = place_all(b, s, nodes, &records, err);
    for (uint32_t m = 0; rc == VCT_OK && m < s->mesh_count; ++m) {
        const mesh_tree *t = &b->trees[m];
        if (!t->node_count)
            continue;
        memcpy(nodes + NODE_FLOATS * (b->top_cap + t->root), t->nodes, 128ull * t->node_count);
        memcpy(ids + t->first_id, t->tri_ids, 4ull * s->meshes[m].triangle_count);
    }
    if (rc == VCT_OK) {
        b->nodes =
            vct_buffer_create(ctx, STAGE, "two-level BVH nodes",
                              128ull * (b->top_cap + b->mesh_nodes), CL_MEM_READ_WRITE, nodes, err);
        b->tri_ids = b->nodes
                         ? vct_buffer_create(ctx, STAGE, "meshes' sorted triangles",
                                             4ull * b->mesh_triangles, CL_MEM_READ_ONLY, ids, err)
                         : NULL;
        rc = b->tri_ids ? instances_upload(b, records, err) : (int)err->status;
    }
    /* the meshes' nodes live on the device now; their boxes and places stay */
    for (uint32_t m = 0; b && b->trees && m < s->mesh_count; ++m) {
        free(b->trees[m].nodes);
        free(b->trees[m].tri_ids);
        b->trees[m].nodes = NULL;
        b->trees[m].tri_ids = NULL;
    }
    free(nodes);
    free(ids);
    free(records);
    free(used);
    if (rc != VCT_OK) {
        vct_bvh2_free(b);
        return NULL;
    }
    return b;
}
