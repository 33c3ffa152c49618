/* Light-space triangle bins (kernels/light/light_bins.cl): count -> scan ->
 * write -> sort -> ranges over the cube-map cells of the binned lights. */
#include <math.h>
#include <string.h>

#include "accel/accel.h"
#include "light/light_bins_host.h"
#include "parallel/parallel.h"
#include "vct_types.h"

/* Each sort key is a cell above at least MIN_DISTANCE_BITS of distance,
 * rounded up to whole radix digits (one sort pass each): 128 distance steps
 * already stop a ray within a few voxels of its start. */
#define MIN_DISTANCE_BITS 7
#define MAX_CELL_BITS (32 - MIN_DISTANCE_BITS)
#define MIN_FACE_RES 4u
#define MAX_FACE_RES 512u

static int binned(const vct_light *l) {
    return l->type != VCT_LIGHT_DIRECTIONAL && l->radius == 0.0f;
}

/* About four triangles per cell over the six faces. Finer cells test fewer
 * triangles per ray but cost more to bin: on a 100k-triangle scene, one
 * to eight triangles per cell all took 98-111 ms (rays and bins together). */
static uint32_t face_res_for(uint32_t triangles, uint32_t lights) {
    uint32_t f = (uint32_t)ceil(sqrt(triangles / 24.0));
    f = f < MIN_FACE_RES ? MIN_FACE_RES : (f > MAX_FACE_RES ? MAX_FACE_RES : f);
    while (f > MIN_FACE_RES && vct_key_bits_for(6ull * f * f * lights) > MAX_CELL_BITS)
        f /= 2;
    return f;
}

/* The largest distance from l to the scene's box: the last quantum. */
static double farthest_corner(const vct_scene *s, const float l[3]) {
    double far2 = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        double d2 = 0.0;
        for (int k = 0; k < 3; ++k) {
            const double c = (corner >> k) & 1 ? s->bounds_max[k] : s->bounds_min[k];
            d2 += (c - l[k]) * (c - l[k]);
        }
        far2 = fmax(far2, d2);
    }
    return sqrt(far2);
}

#define DEFAULT_MAX_ENTRIES (1ull << 24)

static int make_desc(vct_context *ctx, const vct_scene *s, int enabled, uint32_t face_res,
                     const char *stage, vct_light_bins *b, int *key_bits, int *bits,
                     uint64_t *cells, vct_error *err) {
    const uint32_t n = s->light_count;
    for (uint32_t i = 0; enabled && s->triangle_count && i < n; ++i)
        b->lights += (uint32_t)binned(&s->lights[i]);
    b->face_res =
        b->lights ? (face_res ? face_res : face_res_for(s->triangle_count, b->lights)) : 0;
    *cells = 6ull * b->face_res * b->face_res * b->lights;
    if (*cells > (1ull << MAX_CELL_BITS))
        return vct_fail(err, VCT_ERR_INPUT,
                        "%s: %u lights of %u x %u cells per face exceed 2^%d light-bin cells: "
                        "choose a smaller face resolution",
                        stage, b->lights, b->face_res, b->face_res, MAX_CELL_BITS);
    const int cell_bits = vct_key_bits_for(*cells ? *cells : 1), digit = ctx->radix_bits;
    *key_bits = (cell_bits + MIN_DISTANCE_BITS + digit - 1) / digit * digit;
    *key_bits = *key_bits > 32 ? 32 : *key_bits;
    *bits = *key_bits - cell_bits;
    vct_light_bins_desc *d = calloc(n + 1, sizeof *d);
    if (!d)
        return vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory", stage);
    uint32_t first = 0;
    for (uint32_t i = 0; b->lights && i < n; ++i) {
        const vct_light *l = &s->lights[i];
        if (!binned(l))
            continue;
        const double far = farthest_corner(s, l->position);
        const double quanta = (double)((1u << *bits) - 1u);
        for (int k = 0; k < 3; ++k)
            d[i].light.s[k] = l->position[k];
        d[i].light.s[3] = far > 0.0 ? (float)(quanta / far) : 0.0f;
        d[i].info.s[0] = first;
        d[i].info.s[1] = b->face_res;
        d[i].info.s[2] = (cl_uint)*bits;
        d[i].info.s[3] = 1;
        first += 6u * b->face_res * b->face_res;
    }
    b->desc =
        vct_buffer_create(ctx, stage, "light bins", sizeof *d * (n + 1), CL_MEM_READ_ONLY, d, err);
    free(d);
    return b->desc ? VCT_OK : (int)err->status;
}

/* Counts and writes the (cell, triangle) pairs; sets *too_many, writing
 * nothing, when there are more than max_entries. */
static int write_pairs(vct_context *ctx, const vct_scene *s, const vct_accel *g, cl_program p,
                       const char *stage, uint64_t max_entries, vct_light_bins *b, cl_mem *keys,
                       int *too_many, vct_error *err) {
    const uint32_t n = s->triangle_count, lights = s->light_count;
    cl_mem tri_vertices = vct_accel_tri_vertices(g);
    cl_mem counts =
        vct_buffer_create(ctx, stage, "light bin counts", 4ull * n, CL_MEM_READ_WRITE, NULL, err);
    int rc = counts ? vct_run_kernel(ctx, p, "light_bins_count", stage, n, err, 5,
                                     VCT_ARG_OF(tri_vertices), VCT_ARG(triangles, n),
                                     VCT_ARG_OF(b->desc), VCT_ARG_OF(lights), VCT_ARG_OF(counts))
                    : (int)err->status;
    uint64_t total = 0;
    if (rc == VCT_OK)
        rc = vct_scan_u32(ctx, counts, counts, n, 0, &total, err);
    *too_many = rc == VCT_ERR_OVERFLOW || (rc == VCT_OK && total > max_entries);
    if (*too_many) {
        memset(err, 0, sizeof *err);
        vct_buffer_release(ctx, counts);
        return VCT_OK;
    }
    b->entries = (uint32_t)total;
    const size_t bytes = 4ull * (total ? total : 1);
    if (rc == VCT_OK) {
        *keys =
            vct_buffer_create(ctx, stage, "light bin keys", bytes, CL_MEM_READ_WRITE, NULL, err);
        b->tris = *keys ? vct_buffer_create(ctx, stage, "light bin triangles", bytes,
                                            CL_MEM_READ_WRITE, NULL, err)
                        : NULL;
        rc = b->tris ? VCT_OK : (int)err->status;
    }
    if (rc == VCT_OK && total)
        rc = vct_run_kernel(ctx, p, "light_bins_write", stage, n, err, 7, VCT_ARG_OF(tri_vertices),
                            VCT_ARG(triangles, n), VCT_ARG_OF(b->desc), VCT_ARG_OF(lights),
                            VCT_ARG(offsets, counts), VCT_ARG_OF(*keys), VCT_ARG(ids, b->tris));
    vct_buffer_release(ctx, counts);
    return rc;
}

int vct_light_bins_build(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                         const vct_light_bins_options *options, const char *stage,
                         vct_light_bins *b, vct_error *err) {
    vct_light_bins_options o = {-1, 0, 0};
    if (options)
        o = *options;
    if (o.enabled < 0)
        o.enabled = !ctx->info.is_gpu;
    if (!o.max_entries) {
        o.max_entries = ctx->info.max_alloc / 4;
        o.max_entries = o.max_entries < DEFAULT_MAX_ENTRIES ? o.max_entries : DEFAULT_MAX_ENTRIES;
    }
    memset(b, 0, sizeof *b);
    int key_bits = 0, bits = 0, too_many = 0;
    uint64_t cells = 0;
    int rc = make_desc(ctx, s, o.enabled, o.face_res, stage, b, &key_bits, &bits, &cells, err);
    cl_program p = NULL;
    if (rc == VCT_OK && b->lights)
        rc = vct_program_get(ctx, "light/light_bins.cl", "", &p, err);
    cl_mem keys = NULL;
    if (rc == VCT_OK && b->lights)
        rc = write_pairs(ctx, s, g, p, stage, o.max_entries, b, &keys, &too_many, err);
    if (rc == VCT_OK && too_many) { /* every light back to the grid */
        vct_light_bins_release(ctx, b);
        const vct_light_bins_options none = {0, 0, 1};
        return vct_light_bins_build(ctx, s, g, &none, stage, b, err);
    }
    if (rc == VCT_OK && b->entries)
        rc = vct_sort_pairs_u32(ctx, keys, b->tris, b->entries, key_bits, err);
    if (rc == VCT_OK) {
        b->ranges = vct_buffer_create(ctx, stage, "light bin ranges", 8ull * (cells ? cells : 1),
                                      CL_MEM_READ_WRITE, NULL, err);
        rc = b->ranges ? vct_buffer_fill_u32(ctx, stage, b->ranges, 0, 2 * (cells ? cells : 1), err)
                       : (int)err->status;
    }
    const cl_uint distance_bits = (cl_uint)bits;
    if (rc == VCT_OK && b->entries)
        rc = vct_run_kernel(ctx, p, "light_bins_ranges", stage, b->entries, err, 4,
                            VCT_ARG_OF(keys), VCT_ARG(n, b->entries), VCT_ARG(bits, distance_bits),
                            VCT_ARG_OF(b->ranges));
    b->keys = keys;
    if (rc == VCT_OK && !b->keys) { /* no light binned: the kernels still take buffers */
        b->keys = vct_buffer_create(ctx, stage, "light bin keys", 4, CL_MEM_READ_WRITE, NULL, err);
        b->tris = b->keys ? vct_buffer_create(ctx, stage, "light bin triangles", 4,
                                              CL_MEM_READ_WRITE, NULL, err)
                          : NULL;
        rc = b->tris ? VCT_OK : (int)err->status;
    }
    if (rc != VCT_OK)
        vct_light_bins_release(ctx, b);
    return rc;
}

int vct_light_bins_set_args(cl_kernel k, int first, const vct_light_bins *b, const char *stage,
                            vct_error *err) {
    return vct_set_args(err, stage, k, first, 4, VCT_ARG(bins_desc, b->desc),
                        VCT_ARG(bin_ranges, b->ranges), VCT_ARG(bin_keys, b->keys),
                        VCT_ARG(bin_tris, b->tris));
}

void vct_light_bins_release(vct_context *ctx, vct_light_bins *b) {
    vct_buffer_release(ctx, b->desc);
    vct_buffer_release(ctx, b->ranges);
    vct_buffer_release(ctx, b->keys);
    vct_buffer_release(ctx, b->tris);
    memset(b, 0, sizeof *b);
}
