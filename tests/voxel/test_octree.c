/* The sparse voxel octree against a plain-C reference built from the voxel
 * keys: nodes per level, every node reachable once with its cell, leaves
 * pointing at their voxels, neighbour links, and the kernels' traversal
 * function on every voxel and on random cells of every level. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "mesh_gen.h"
#include "voxel_ref.h"

static vct_context *ctx;

static int cmp_u32(const void *a, const void *b) {
    const uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return x < y ? -1 : x > y;
}

/* Dense per-level map from cell to node (VCT_NODE_NULL where none). */
typedef struct level_map {
    uint32_t side;
    uint32_t *node;
} level_map;

static size_t cell_index(uint32_t side, const uint32_t c[3]) {
    return c[0] + (size_t)side * (c[1] + (size_t)side * c[2]);
}

static int in_set(const uint32_t *sorted, uint32_t n, uint32_t value) {
    return bsearch(&value, sorted, n, 4, cmp_u32) != NULL;
}

static void check_octree(const char *name, const vct_scene *s, const vct_voxel_options *o) {
    vct_error err = {0};
    vct_voxels *v = vct_voxelize(ctx, s, o, &err);
    REQUIRE_OK(v ? VCT_OK : err.status, err);
    REQUIRE_OK(vct_octree_build(ctx, v, &err), err);
    vct_voxel_info in;
    vct_voxels_info_get(v, &in);
    const uint32_t L = in.levels, nv = in.voxels, nodes = in.nodes;
    uint32_t *keys = malloc(4ull * (nv + 1)), *child = malloc(4ull * nodes),
             *nb = malloc(24ull * nodes);
    REQUIRE_OK(vct_voxels_read(ctx, v, keys, NULL, NULL, NULL, &err), err);
    REQUIRE_OK(vct_octree_read(ctx, v, child, nb, &err), err);

    /* Reference: occupied cells of every level as sorted Morton prefixes. */
    uint32_t *occupied[11], occupied_n[11];
    for (uint32_t l = 0; l <= L; ++l) {
        occupied[l] = malloc(4ull * (nv + 1));
        occupied_n[l] = 0;
        for (uint32_t i = 0; i < nv; ++i) {
            const uint32_t prefix = keys[i] >> (3 * (L - l));
            if (occupied_n[l] == 0 || occupied[l][occupied_n[l] - 1] != prefix)
                occupied[l][occupied_n[l]++] = prefix;
        }
    }
    int bad = 0;
    for (uint32_t i = 1; i < nv; ++i)
        bad += keys[i] <= keys[i - 1];
    CHECK(bad == 0, "%s: voxel keys ascend", name);
    CHECK(in.level_nodes[0] == 1, "%s: one root", name);
    for (uint32_t l = 1; l <= L; ++l)
        CHECK(in.level_nodes[l] == 8 * occupied_n[l - 1], "%s: level %u has %u nodes, expected %u",
              name, l, in.level_nodes[l], 8 * occupied_n[l - 1]);

    /* Walk from the root, giving every node its cell. */
    level_map map[11];
    uint32_t *cell_of = malloc(12ull * nodes), *level_of = malloc(4ull * nodes);
    uint32_t *seen = calloc(nodes, 4);
    for (uint32_t l = 0; l <= L; ++l) {
        map[l].side = 1u << l;
        map[l].node = malloc(4ull << (3 * l));
        memset(map[l].node, 0xff, 4ull << (3 * l));
    }
    uint32_t *queue = malloc(4ull * nodes), head = 0, tail = 0;
    queue[tail++] = 0;
    memset(cell_of, 0, 12);
    level_of[0] = 0;
    seen[0] = 1;
    map[0].node[0] = 0;
    int structure_bad = 0, leaf_bad = 0, empty_bad = 0;
    while (head < tail) {
        const uint32_t n = queue[head++], l = level_of[n], *c = &cell_of[3 * n];
        const uint32_t morton = ref_morton(c[0], c[1], c[2]);
        const int has_geometry = in_set(occupied[l], occupied_n[l], morton);
        empty_bad += has_geometry != (child[n] != VCT_NODE_NULL);
        if (l == L) {
            if (child[n] != VCT_NODE_NULL)
                leaf_bad += child[n] >= nv || keys[child[n]] != morton;
            continue;
        }
        if (child[n] == VCT_NODE_NULL)
            continue;
        const uint32_t first = child[n];
        if (first < in.level_start[l + 1] ||
            first + 8 > in.level_start[l + 1] + in.level_nodes[l + 1] || (first - 1) % 8) {
            ++structure_bad;
            continue;
        }
        for (uint32_t oct = 0; oct < 8; ++oct) {
            const uint32_t m = first + oct;
            if (seen[m]++) {
                ++structure_bad;
                continue;
            }
            level_of[m] = l + 1;
            for (int k = 0; k < 3; ++k)
                cell_of[3 * m + k] = 2 * c[k] + ((oct >> k) & 1u);
            map[l + 1].node[cell_index(map[l + 1].side, &cell_of[3 * m])] = m;
            queue[tail++] = m;
        }
    }
    CHECK(tail == nodes, "%s: %u of %u nodes reachable from the root", name, tail, nodes);
    CHECK(structure_bad == 0, "%s: %d child tiles out of place or shared", name, structure_bad);
    CHECK(empty_bad == 0, "%s: %d nodes disagree with the voxels on being empty", name, empty_bad);
    CHECK(leaf_bad == 0, "%s: %d leaves point at the wrong voxel", name, leaf_bad);

    /* Neighbour links: the node of the same level one cell over, if allocated. */
    int link_bad = 0;
    for (uint32_t i = 0; i < tail; ++i) {
        const uint32_t n = queue[i], l = level_of[n], side = 1u << l;
        for (int dir = 0; dir < 6; ++dir) {
            uint32_t c[3] = {cell_of[3 * n], cell_of[3 * n + 1], cell_of[3 * n + 2]};
            const int axis = dir % 3, step = dir < 3 ? 1 : -1;
            uint32_t expected = VCT_NODE_NULL;
            if ((step > 0 && c[axis] + 1 < side) || (step < 0 && c[axis] > 0)) {
                c[axis] += step;
                expected = map[l].node[cell_index(side, c)];
            }
            if (nb[6ull * n + dir] != expected && link_bad++ < 5)
                CHECK(0, "%s: node %u (level %u) link %d is %u, expected %u", name, n, l, dir,
                      nb[6ull * n + dir], expected);
        }
    }
    CHECK(link_bad == 0, "%s: %d neighbour links wrong", name, link_bad);

    /* Traversal: every voxel at the leaf level, then random cells of every level. */
    const uint32_t random_queries = 20000, nq = nv + random_queries;
    uint32_t *q = malloc(16ull * nq), *found = malloc(4ull * nq);
    uint64_t seed = 99;
    for (uint32_t i = 0; i < nq; ++i) {
        uint32_t l = L, c[3] = {0, 0, 0};
        if (i < nv) {
            for (uint32_t b = 0; b < L; ++b)
                for (int k = 0; k < 3; ++k)
                    c[k] |= ((keys[i] >> (3 * b + k)) & 1u) << b;
        } else {
            l = (uint32_t)(check_rand(&seed) % (L + 1));
            /* Half the random queries land next to geometry, half anywhere. */
            if ((i & 1) && nv) {
                const uint32_t key = keys[check_rand(&seed) % nv] >> (3 * (L - l));
                for (uint32_t b = 0; b < l; ++b)
                    for (int k = 0; k < 3; ++k)
                        c[k] |= ((key >> (3 * b + k)) & 1u) << b;
                c[check_rand(&seed) % 3] ^= 1u;
                for (int k = 0; k < 3; ++k)
                    c[k] &= (1u << l) - 1u;
            } else {
                for (int k = 0; k < 3; ++k)
                    c[k] = (uint32_t)(check_rand(&seed) % (1u << l));
            }
        }
        memcpy(&q[4 * i], c, 12);
        q[4 * i + 3] = l;
    }
    REQUIRE_OK(vct_octree_lookup(ctx, v, q, nq, found, &err), err);
    int voxel_missed = 0, lookup_bad = 0;
    for (uint32_t i = 0; i < nq; ++i) {
        const uint32_t l = q[4 * i + 3];
        const uint32_t expected = map[l].node[cell_index(1u << l, &q[4 * i])];
        lookup_bad += found[i] != expected;
        if (i < nv)
            voxel_missed += found[i] == VCT_NODE_NULL || child[found[i]] != i;
        const int empty = found[i] == VCT_NODE_NULL || child[found[i]] == VCT_NODE_NULL;
        lookup_bad += empty == in_set(occupied[l], occupied_n[l],
                                      ref_morton(q[4 * i], q[4 * i + 1], q[4 * i + 2]));
    }
    CHECK(voxel_missed == 0, "%s: %d voxels not found at the leaf level", name, voxel_missed);
    CHECK(lookup_bad == 0, "%s: %d lookups differ from the reference", name, lookup_bad);
    printf("%-28s %4u^3: %7u voxels, %8u nodes, %u lookups\n", name, in.resolution, nv, nodes, nq);

    /* Deterministic: a second build gives the same pool bit for bit. */
    vct_voxels *w = vct_voxelize(ctx, s, o, &err);
    REQUIRE_OK(w ? vct_octree_build(ctx, w, &err) : err.status, err);
    uint32_t *child2 = malloc(4ull * nodes), *nb2 = malloc(24ull * nodes);
    REQUIRE_OK(vct_octree_read(ctx, w, child2, nb2, &err), err);
    CHECK(memcmp(child, child2, 4ull * nodes) == 0 && memcmp(nb, nb2, 24ull * nodes) == 0,
          "%s: two builds are bit-identical", name);
    vct_voxels_release(w);
    free(child2);
    free(nb2);
    free(q);
    free(found);
    for (uint32_t l = 0; l <= L; ++l) {
        free(occupied[l]);
        free(map[l].node);
    }
    free(queue);
    free(cell_of);
    free(level_of);
    free(seen);
    free(keys);
    free(child);
    free(nb);
    vct_voxels_release(v);
}

static vct_scene *scene_of(const float *pos, uint32_t nv, const uint32_t *tri, uint32_t nt) {
    vct_error err = {0};
    vct_scene *s = vct_scene_from_arrays(pos, nv, tri, nt, NULL, NULL, 0, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    return s;
}

static vct_voxel_options voxel_options(uint32_t res, int unit_bounds) {
    vct_voxel_options o = {0};
    o.resolution = res;
    o.has_bounds = unit_bounds;
    o.bounds_size = res;
    return o;
}

/* A wall of voxels facing the camera: the centre pixel shows the albedo at
 * full headlight, the sky stays black. */
static void test_voxel_image(void) {
    const float wall[] = {2, 2, 8, 14, 2, 8, 14, 14, 8, 2, 2, 8, 14, 14, 8, 2, 14, 8};
    const uint32_t tri[] = {0, 1, 2, 3, 4, 5};
    vct_scene *s = scene_of(wall, 6, tri, 2);
    const float eye[3] = {8, 8, -20}, at[3] = {8, 8, 8}, up[3] = {0, 1, 0};
    memcpy(s->camera.position, eye, sizeof eye);
    memcpy(s->camera.look_at, at, sizeof at);
    memcpy(s->camera.up, up, sizeof up);
    s->camera.fov_y_deg = 40.0f;
    vct_voxel_options o = voxel_options(16, 1);
    vct_error err = {0};
    vct_voxels *v = vct_voxelize(ctx, s, &o, &err);
    REQUIRE_OK(v ? vct_octree_build(ctx, v, &err) : err.status, err);
    vct_image img = {0};
    REQUIRE_OK(vct_render_voxels(ctx, s, v, 33, 33, &img, &err), err);
    const float *centre = &img.rgba[4 * (16 * 33 + 16)], *corner = &img.rgba[0];
    const float albedo = vct_material_default().albedo[0];
    CHECK(fabsf(centre[0] - albedo) < 1e-3f, "centre pixel %g, albedo %g", centre[0], albedo);
    CHECK(corner[0] == 0.0f && corner[1] == 0.0f, "sky pixel %g", corner[0]);
    /* Level 2 (cells of 4 voxels): the wall's cells show as cubes lit on the
     * face the ray enters, reaching past the wall's leaf voxels. */
    vct_image coarse = {0};
    REQUIRE_OK(vct_render_voxels_level(ctx, s, v, 2, 33, 33, &coarse, &err), err);
    int grown = 0;
    for (int p = 0; p < 33 * 33; ++p) {
        const float leaf = img.rgba[4 * p], cube = coarse.rgba[4 * p];
        CHECK(!(leaf > 0.0f) || cube > 0.0f, "pixel %d: a voxel at the leaf level, none at 2", p);
        CHECK(cube == 0.0f || (cube >= 0.75f * 0.25f && cube <= 0.75f), "pixel %d: cube shade %g",
              p, cube);
        grown += cube > 0.0f && !(leaf > 0.0f);
    }
    const float facing = coarse.rgba[4 * (16 * 33 + 16)];
    CHECK(fabsf(facing - 0.75f) < 1e-2f, "cube facing the camera: %g, expected 0.75", facing);
    CHECK(grown > 0, "level 2 covers no more than the voxels");
    vct_image_release(&coarse);
    CHECK(vct_render_voxels_level(ctx, s, v, 5, 33, 33, &coarse, &err) == VCT_ERR_INPUT,
          "level 5 of a 16^3 octree should be refused");
    vct_image_release(&img);
    vct_voxels_release(v);
    vct_scene_release(s);
}

int main(void) {
    ctx = check_context();
    /* No voxels at all: the root alone, with no children. */
    const float zero[] = {1, 1, 1, 2, 2, 2, 3, 3, 3};
    const uint32_t tri[] = {0, 1, 2};
    vct_scene *s = scene_of(zero, 3, tri, 1);
    vct_voxel_options o = voxel_options(16, 1);
    check_octree("empty (zero-area triangle)", s, &o);
    vct_scene_release(s);
    const float tiny[] = {3.2f, 4.2f, 5.2f, 3.3f, 4.2f, 5.2f, 3.2f, 4.3f, 5.25f};
    s = scene_of(tiny, 3, tri, 1);
    check_octree("one voxel", s, &o);
    vct_scene_release(s);
    const float corner[] = {1.2f, 0.2f, 1.2f, 1.3f, 0.2f, 1.2f, 1.2f, 0.3f, 1.25f};
    s = scene_of(corner, 3, tri, 1);
    o = voxel_options(2, 1);
    check_octree("one voxel, resolution 2", s, &o);
    vct_scene_release(s);

    test_mesh soup = mesh_soup(2000, 0.0f, 5);
    s = scene_of(soup.pos, soup.nv, soup.tri, soup.nt);
    check_octree("random soup", s, &(vct_voxel_options){.resolution = 64});
    vct_scene_release(s);
    mesh_free(&soup);
    const float centre[3] = {0.5f, 0.5f, 0.5f};
    test_mesh sphere = mesh_icosphere(4, 0.45f, centre);
    s = scene_of(sphere.pos, sphere.nv, sphere.tri, sphere.nt);
    check_octree("icosphere", s, &(vct_voxel_options){.resolution = 128});
    vct_scene_release(s);
    mesh_free(&sphere);
    s = check_cornell_box();
    check_octree("Cornell box", s, &(vct_voxel_options){.resolution = 256});
    vct_scene_release(s);
    test_voxel_image();
    vct_context_release(ctx);
    return check_exit("test_octree");
}
