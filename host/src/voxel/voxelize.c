/* Triangle-parallel voxelization (kernels/voxel/voxelize.cl): the volume's frame,
 * vertex quantisation, and count -> scan -> write -> sort -> reduce. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "runtime/runtime.h"
#include "scene/scene_device.h"
#include "vct_types.h"
#include "voxel/voxels.h"

#define STAGE "voxelize"
#define UNITS (1u << VCT_VOLUME_UNITS_LOG2)

static int check_options(const vct_voxel_options *o, vct_error *err) {
    const uint32_t r = o->resolution;
    if (r < 2 || r > VCT_VOXEL_MAX_RES || (r & (r - 1)))
        return vct_fail(err, VCT_ERR_INPUT,
                        "voxelize: resolution %u is not a power of two from 2 to %u (--voxel-res)",
                        r, VCT_VOXEL_MAX_RES);
    if (o->has_bounds &&
        !(o->bounds_size > 0.0 && isfinite(o->bounds_size) && isfinite(o->bounds_min[0]) &&
          isfinite(o->bounds_min[1]) && isfinite(o->bounds_min[2])))
        return vct_fail(err, VCT_ERR_INPUT,
                        "voxelize: bounds need a finite corner and a positive size "
                        "(--voxel-bounds x,y,z,size)");
    return VCT_OK;
}

/* A cube around the scene's box with about one voxel of margin per side. */
static void frame_scene(const vct_scene *s, uint32_t res, double origin[3], double *side) {
    double ext = 0.0, mag = 0.0;
    for (int k = 0; k < 3; ++k) {
        ext = fmax(ext, (double)s->bounds_max[k] - s->bounds_min[k]);
        mag = fmax(mag, fmax(fabs(s->bounds_min[k]), fabs(s->bounds_max[k])));
    }
    if (!(ext > 0.0))
        ext = fmax(mag * 1e-3, 1e-3);
    *side = ext * (res + 2.0) / res;
    for (int k = 0; k < 3; ++k)
        origin[k] = 0.5 * ((double)s->bounds_min[k] + s->bounds_max[k]) - 0.5 * *side;
}

/* Vertices in integer units (x, y, z) with the material in the first
 * vertex's w. Triangles wholly outside the cube become zero-area; one that
 * crosses the cube but reaches beyond the exact range is refused. */
static int quantise(const vct_scene *s, const vct_voxel_info *info, uint32_t first, uint32_t end,
                    cl_int *out, vct_error *err) {
    const double scale = UNITS / info->side, lo = -(double)UNITS, hi = 2.0 * UNITS;
    for (uint32_t t = first; t < end; ++t) {
        double q[3][3];
        int outside_low[3] = {1, 1, 1}, outside_high[3] = {1, 1, 1}, in_range = 1;
        for (int i = 0; i < 3; ++i) {
            const float *p = s->positions + 3ull * s->triangles[3ull * t + i];
            for (int k = 0; k < 3; ++k) {
                q[i][k] = nearbyint(((double)p[k] - info->origin[k]) * scale);
                outside_low[k] &= q[i][k] < 0.0;
                outside_high[k] &= q[i][k] > UNITS;
                in_range &= q[i][k] >= lo && q[i][k] <= hi;
            }
        }
        int outside = 0;
        for (int k = 0; k < 3; ++k)
            outside |= outside_low[k] | outside_high[k];
        cl_int *o = out + 12ull * (t - first);
        memset(o, 0, 12 * sizeof *o);
        if (outside)
            continue;
        if (!in_range)
            return vct_fail(err, VCT_ERR_INPUT,
                            "voxelize: triangle %u crosses the voxel bounds and reaches more than "
                            "one bounds size beyond them; enlarge --voxel-bounds or cut the mesh",
                            t);
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 3; ++k)
                o[4 * i + k] = (cl_int)q[i][k];
        o[3] = (cl_int)s->triangle_material[t];
    }
    return VCT_OK;
}

typedef struct voxelize_state {
    vct_context *ctx;
    vct_voxels *v;
    vct_volume_desc desc;
    cl_int thin;
    cl_program program;
    cl_mem tris, tri_normals, materials, chunk_start, counts, frag_keys, frag_ids;
    uint32_t chunks;
    vct_scene_buffers scene; /* the textures, for the voxels' albedo */
} voxelize_state;

/* Fragments of triangles first .. first + count - 1 into st->frag_keys and
 * st->frag_ids (*total of them), their normals into st->tri_normals:
 * chunks -> scan -> count -> scan -> write, then a stable sort. */
static int make_fragments(voxelize_state *st, uint32_t first, uint32_t count, uint32_t *total_out,
                          vct_error *err) {
    vct_context *ctx = st->ctx;
    vct_voxel_info *info = &st->v->info;
    vct_volume_desc desc = st->desc;
    desc.res.s[3] = count; /* the kernels' triangles, from first */
    st->chunk_start = vct_buffer_create(ctx, STAGE, "chunk offsets", 4ull * (count ? count : 1),
                                        CL_MEM_READ_WRITE, NULL, err);
    if (!st->chunk_start)
        return err->status;
    int rc = vct_run_kernel(ctx, st->program, "vox_chunks", STAGE, count, err, 5,
                            VCT_ARG_OF(st->tris), VCT_ARG(vol, desc), VCT_ARG(first_tri, first),
                            VCT_ARG(chunks, st->chunk_start), VCT_ARG_OF(st->tri_normals));
    uint64_t total = 0;
    if (rc == VCT_OK)
        rc = vct_scan_u32(ctx, st->chunk_start, st->chunk_start, count, 0, &total, err);
    if (rc == VCT_ERR_OVERFLOW)
        rc = vct_fail(err, VCT_ERR_MEMORY,
                      "voxelize: more than 2^32 work chunks: lower --voxel-res");
    if (rc)
        return rc;
    st->chunks = (uint32_t)total;
    st->counts = vct_buffer_create(ctx, STAGE, "chunk fragment counts", 4ull * st->chunks,
                                   CL_MEM_READ_WRITE, NULL, err);
    if (!st->counts)
        return err->status;
    rc = vct_run_kernel(ctx, st->program, "vox_count", STAGE, st->chunks, err, 7,
                        VCT_ARG_OF(st->tris), VCT_ARG(vol, desc), VCT_ARG(first_tri, first),
                        VCT_ARG_OF(st->thin), VCT_ARG_OF(st->chunk_start), VCT_ARG_OF(st->chunks),
                        VCT_ARG_OF(st->counts));
    if (rc == VCT_OK)
        rc = vct_scan_u32(ctx, st->counts, st->counts, st->chunks, 0, &total, err);
    if (rc == VCT_ERR_OVERFLOW)
        rc = vct_fail(err, VCT_ERR_MEMORY,
                      "voxelize: more than 2^32 fragments at %u^3: --voxel-res %u would fit",
                      info->resolution, info->resolution / 2);
    if (rc == VCT_OK)
        rc = vct_voxel_buffer_fits(ctx, info, STAGE, "fragment keys", 4.0 * (double)total, err);
    if (rc)
        return rc;
    *total_out = (uint32_t)total;
    st->frag_keys = vct_buffer_create(ctx, STAGE, "fragment keys", 4ull * (total ? total : 1),
                                      CL_MEM_READ_WRITE, NULL, err);
    st->frag_ids = st->frag_keys
                       ? vct_buffer_create(ctx, STAGE, "fragment triangles",
                                           4ull * (total ? total : 1), CL_MEM_READ_WRITE, NULL, err)
                       : NULL;
    if (!st->frag_ids)
        return err->status;
    rc = vct_run_kernel(ctx, st->program, "vox_write", STAGE, st->chunks, err, 9,
                        VCT_ARG_OF(st->tris), VCT_ARG(vol, desc), VCT_ARG(first_tri, first),
                        VCT_ARG_OF(st->thin), VCT_ARG_OF(st->chunk_start), VCT_ARG_OF(st->chunks),
                        VCT_ARG(offsets, st->counts), VCT_ARG(keys, st->frag_keys),
                        VCT_ARG(ids, st->frag_ids));
    vct_buffer_release(ctx, st->counts);
    st->counts = NULL;
    vct_buffer_release(ctx, st->chunk_start);
    st->chunk_start = NULL;
    if (rc == VCT_OK)
        rc = vct_sort_pairs_u32(ctx, st->frag_keys, st->frag_ids, (uint32_t)total,
                                3 * (int)info->levels, err);
    return rc;
}

/* Voxels: one per run of equal keys, its fragments averaged. */
static int reduce_fragments(voxelize_state *st, vct_error *err) {
    vct_context *ctx = st->ctx;
    vct_voxels *v = st->v;
    const uint32_t f = v->info.fragments;
    cl_mem index =
        vct_buffer_create(ctx, STAGE, "voxel index", 4ull * f, CL_MEM_READ_WRITE, NULL, err);
    if (!index)
        return err->status;
    int rc = vct_run_kernel(ctx, st->program, "vox_heads", STAGE, f, err, 3,
                            VCT_ARG(keys, st->frag_keys), VCT_ARG(n, f), VCT_ARG(heads, index));
    uint64_t voxels = 0;
    if (rc == VCT_OK)
        rc = vct_scan_u32(ctx, index, index, f, 0, &voxels, err);
    const uint32_t nv = (uint32_t)voxels;
    v->info.voxels = nv;
    v->info.voxel_bytes = nv * (8ull + 3 * 16ull) + 4ull * f;
    if (rc == VCT_OK)
        rc = vct_voxel_buffer_fits(ctx, &v->info, STAGE, "voxel attributes", 16.0 * nv, err);
    cl_mem start = NULL;
    if (rc == VCT_OK) {
        v->keys =
            vct_buffer_create(ctx, STAGE, "voxel keys", 4ull * nv, CL_MEM_READ_WRITE, NULL, err);
        start = v->keys ? vct_buffer_create(ctx, STAGE, "voxel fragment ranges", 4ull * nv,
                                            CL_MEM_READ_WRITE, NULL, err)
                        : NULL;
        rc = start ? VCT_OK : (int)err->status;
    }
    if (rc == VCT_OK)
        rc = vct_run_kernel(ctx, st->program, "vox_starts", STAGE, f, err, 5,
                            VCT_ARG(keys, st->frag_keys), VCT_ARG(n, f), VCT_ARG_OF(index),
                            VCT_ARG(voxel_keys, v->keys), VCT_ARG(voxel_start, start));
    vct_buffer_release(ctx, index);
    vct_buffer_release(ctx, st->frag_keys);
    st->frag_keys = NULL;
    cl_mem *outs[] = {&v->albedo, &v->normal, &v->emission};
    const char *names[] = {"voxel albedo", "voxel normals", "voxel emission"};
    for (int i = 0; i < 3 && rc == VCT_OK; ++i) {
        *outs[i] =
            vct_buffer_create(ctx, STAGE, names[i], 16ull * nv, CL_MEM_READ_WRITE, NULL, err);
        rc = *outs[i] ? VCT_OK : (int)err->status;
    }
    if (rc == VCT_OK)
        rc = vct_run_kernel(ctx, st->program, "vox_reduce", STAGE, nv, err, 15,
                            VCT_ARG(ids, st->frag_ids), VCT_ARG(voxel_start, start),
                            VCT_ARG(voxels, nv), VCT_ARG(fragments, f), VCT_ARG_OF(st->tri_normals),
                            VCT_ARG_OF(st->materials), VCT_ARG_OF(v->keys), VCT_ARG_OF(st->tris),
                            VCT_ARG(vol, st->desc), VCT_ARG_OF(st->scene.texels),
                            VCT_ARG_OF(st->scene.texture_table), VCT_ARG_OF(st->scene.tri_uvs),
                            VCT_ARG(albedo_out, v->albedo), VCT_ARG(normal_out, v->normal),
                            VCT_ARG(emission_out, v->emission));
    /* kept: light injection reads each voxel's fragments */
    v->fragment_start = start;
    v->fragment_tri = st->frag_ids;
    st->frag_ids = NULL;
    return rc;
}

/* Triangles first .. end - 1 quantised into st->tris (made for all of
 * them when first is 0 and it is not there yet). */
static int upload_triangles(voxelize_state *st, const vct_scene *s, uint32_t first, uint32_t end,
                            vct_error *err) {
    vct_context *ctx = st->ctx;
    const uint32_t n = end - first;
    cl_int *q = malloc(48ull * (n ? n : 1));
    if (!q)
        return vct_fail(err, VCT_ERR_MEMORY, "voxelize: out of host memory");
    int rc = quantise(s, &st->v->info, first, end, q, err);
    if (rc == VCT_OK && !st->tris) {
        const uint64_t all = s->triangle_count ? s->triangle_count : 1;
        st->tris = vct_buffer_create(ctx, STAGE, "quantised triangles", 48ull * all,
                                     CL_MEM_READ_ONLY, s->triangle_count ? q : NULL, err);
        st->tri_normals = st->tris ? vct_buffer_create(ctx, STAGE, "triangle normals", 16ull * all,
                                                       CL_MEM_READ_WRITE, NULL, err)
                                   : NULL;
        rc = st->tri_normals ? VCT_OK : (int)err->status;
    } else if (rc == VCT_OK && n) {
        rc = vct_buffer_write(ctx, STAGE, st->tris, 48ull * first, 48ull * n, q, err);
    }
    free(q);
    return rc;
}

static int upload_materials(voxelize_state *st, const vct_scene *s, vct_error *err) {
    vct_context *ctx = st->ctx;
    vct_material_desc *m = malloc(sizeof *m * (s->material_count + 1));
    if (!m)
        return vct_fail(err, VCT_ERR_MEMORY, "voxelize: out of host memory");
    for (uint32_t i = 0; i < s->material_count; ++i)
        vct_material_desc_make(&s->materials[i], &m[i]);
    st->materials = vct_buffer_create(ctx, STAGE, "materials", sizeof *m * s->material_count,
                                      CL_MEM_READ_ONLY, s->material_count ? m : NULL, err);
    free(m);
    int rc = st->materials ? VCT_OK : (int)err->status;
    if (rc == VCT_OK)
        rc = vct_scene_buffers_make(ctx, s, STAGE, &st->scene, err);
    return rc;
}

/* New voxels for s with o's settings, their volume framed, nothing built. */
static vct_voxels *voxels_new(vct_context *ctx, const vct_scene *s, const vct_voxel_options *o,
                              vct_error *err) {
    if (check_options(o, err))
        return NULL;
    vct_voxels *v = calloc(1, sizeof *v);
    if (!v) {
        vct_fail(err, VCT_ERR_MEMORY, "voxelize: out of host memory");
        return NULL;
    }
    v->ctx = ctx;
    v->bounce_rest = !o->exact_bounces;
    v->dense_bounces = o->dense_bounces;
    vct_voxel_info *info = &v->info;
    info->resolution = o->resolution;
    while ((1u << info->levels) < o->resolution)
        ++info->levels;
    info->units = UNITS;
    info->triangles = s->triangle_count;
    uint8_t *used = calloc(s->material_count + 1, 1); /* materials some triangle has */
    for (uint32_t t = 0; used && t < s->triangle_count; ++t)
        used[s->triangle_material[t]] = 1;
    for (uint32_t m = 0; m < s->material_count; ++m)
        for (int c = 0; c < 3 && (!used || used[m]); ++c)
            v->albedo_max[c] = fmax(v->albedo_max[c], (double)s->materials[m].albedo[c]);
    free(used);
    if (o->has_bounds) {
        memcpy(info->origin, o->bounds_min, sizeof info->origin);
        info->side = o->bounds_size;
    } else {
        frame_scene(s, o->resolution, info->origin, &info->side);
    }
    return v;
}

/* The fragments before of the triangles outside [lo, hi), in their order,
 * into *keys and *ids (*count of them). */
static int kept_fragments(voxelize_state *st, const vct_voxels *before, uint32_t lo, uint32_t hi,
                          cl_mem *keys, cl_mem *ids, uint32_t *count, vct_error *err) {
    vct_context *ctx = st->ctx;
    const uint32_t f = before->info.fragments, nv = before->info.voxels;
    const size_t bytes = 4ull * (f ? f : 1);
    cl_mem all_keys =
        vct_buffer_create(ctx, STAGE, "fragment keys before", bytes, CL_MEM_READ_WRITE, NULL, err);
    cl_mem keep = all_keys ? vct_buffer_create(ctx, STAGE, "fragments kept", bytes,
                                               CL_MEM_READ_WRITE, NULL, err)
                           : NULL;
    cl_mem index = keep ? vct_buffer_create(ctx, STAGE, "kept fragment index", bytes,
                                            CL_MEM_READ_WRITE, NULL, err)
                        : NULL;
    int rc = index ? VCT_OK : (int)err->status;
    if (rc == VCT_OK)
        rc = vct_run_kernel(
            ctx, st->program, "vox_kept", STAGE, nv, err, 9, VCT_ARG(voxel_keys, before->keys),
            VCT_ARG(voxel_start, before->fragment_start), VCT_ARG(voxels, nv),
            VCT_ARG(fragments, f), VCT_ARG(ids, before->fragment_tri), VCT_ARG(moved_lo, lo),
            VCT_ARG(moved_hi, hi), VCT_ARG(keys, all_keys), VCT_ARG_OF(keep));
    uint64_t kept = 0;
    if (rc == VCT_OK)
        rc = vct_scan_u32(ctx, keep, index, f, 0, &kept, err);
    *count = (uint32_t)kept;
    if (rc == VCT_OK) {
        *keys = vct_buffer_create(ctx, STAGE, "kept fragment keys", 4ull * (kept ? kept : 1),
                                  CL_MEM_READ_WRITE, NULL, err);
        *ids = *keys ? vct_buffer_create(ctx, STAGE, "kept fragment triangles",
                                         4ull * (kept ? kept : 1), CL_MEM_READ_WRITE, NULL, err)
                     : NULL;
        rc = *ids ? VCT_OK : (int)err->status;
    }
    if (rc == VCT_OK)
        rc = vct_run_kernel(ctx, st->program, "vox_compact", STAGE, f, err, 7,
                            VCT_ARG(keys, all_keys), VCT_ARG(ids, before->fragment_tri),
                            VCT_ARG_OF(keep), VCT_ARG_OF(index), VCT_ARG(n, f),
                            VCT_ARG(kept_keys, *keys), VCT_ARG(kept_ids, *ids));
    vct_buffer_release(ctx, all_keys);
    vct_buffer_release(ctx, keep);
    vct_buffer_release(ctx, index);
    return rc;
}

/* The kept fragments and the moved triangles' new ones (st->frag_*),
 * merged into st->frag_*. */
static int merge_fragments(voxelize_state *st, cl_mem kept_keys, cl_mem kept_ids, uint32_t kept,
                           uint32_t fresh, vct_error *err) {
    vct_context *ctx = st->ctx;
    const uint64_t total = (uint64_t)kept + fresh;
    if (total > UINT32_MAX)
        return vct_fail(err, VCT_ERR_MEMORY, "voxelize: more than 2^32 fragments");
    int rc = vct_voxel_buffer_fits(ctx, &st->v->info, STAGE, "fragment keys", 4.0 * total, err);
    cl_mem keys = rc == VCT_OK
                      ? vct_buffer_create(ctx, STAGE, "fragment keys", 4ull * (total ? total : 1),
                                          CL_MEM_READ_WRITE, NULL, err)
                      : NULL;
    cl_mem ids = keys ? vct_buffer_create(ctx, STAGE, "fragment triangles",
                                          4ull * (total ? total : 1), CL_MEM_READ_WRITE, NULL, err)
                      : NULL;
    if (rc == VCT_OK && !ids)
        rc = err->status;
    if (rc == VCT_OK)
        rc = vct_run_kernel(ctx, st->program, "vox_merge", STAGE, total, err, 8,
                            VCT_ARG(a_keys, kept_keys), VCT_ARG(a_ids, kept_ids), VCT_ARG(a, kept),
                            VCT_ARG(b_keys, st->frag_keys), VCT_ARG(b_ids, st->frag_ids),
                            VCT_ARG(b, fresh), VCT_ARG_OF(keys), VCT_ARG_OF(ids));
    vct_buffer_release(ctx, st->frag_keys);
    vct_buffer_release(ctx, st->frag_ids);
    st->frag_keys = keys;
    st->frag_ids = ids;
    if (rc == VCT_OK) {
        st->v->info.fragments = (uint32_t)total;
        st->v->info.fragment_bytes = 8ull * total;
    }
    return rc;
}

/* The voxels' fragments, all or (before) those of the moved triangles
 * merged with the rest kept, then the voxels. */
static int voxelize_into(voxelize_state *st, const vct_scene *s, vct_voxels *before, uint32_t lo,
                         uint32_t hi, vct_error *err) {
    vct_voxel_info *info = &st->v->info;
    int rc = vct_program_get(st->ctx, "voxel/voxelize.cl", "", &st->program, err);
    if (rc == VCT_OK)
        rc = before ? upload_triangles(st, s, lo, hi, err)
                    : upload_triangles(st, s, 0, s->triangle_count, err);
    if (rc == VCT_OK)
        rc = upload_materials(st, s, err);
    uint32_t fresh = 0;
    if (rc == VCT_OK)
        rc = before ? make_fragments(st, lo, hi - lo, &fresh, err)
                    : make_fragments(st, 0, s->triangle_count, &fresh, err);
    if (rc == VCT_OK && !before) {
        info->fragments = fresh;
        info->fragment_bytes = 8ull * fresh;
    }
    if (rc == VCT_OK && before) {
        cl_mem kept_keys = NULL, kept_ids = NULL;
        uint32_t kept = 0;
        rc = kept_fragments(st, before, lo, hi, &kept_keys, &kept_ids, &kept, err);
        if (rc == VCT_OK)
            rc = merge_fragments(st, kept_keys, kept_ids, kept, fresh, err);
        vct_buffer_release(st->ctx, kept_keys);
        vct_buffer_release(st->ctx, kept_ids);
    }
    if (rc == VCT_OK)
        rc = reduce_fragments(st, err);
    return rc;
}

static vct_voxels *voxelize(vct_context *ctx, const vct_scene *s, const vct_voxel_options *o,
                            vct_voxels *before, uint32_t lo, uint32_t hi, vct_error *err) {
    vct_voxels *v = voxels_new(ctx, s, o, err);
    if (!v)
        return NULL;
    /* what moved is voxelized again where the triangles before are at hand
     * in the same volume frame */
    if (before && !(before->tris && before->tri_normals && before->fragment_tri &&
                    before->info.triangles == s->triangle_count && lo <= hi &&
                    hi <= s->triangle_count && vct_voxels_same_frame(before, v)))
        before = NULL;
    voxelize_state st = {.ctx = ctx, .v = v, .thin = o->thin != 0};
    if (before) { /* taken over: the triangles that did not move are there */
        st.tris = before->tris;
        st.tri_normals = before->tri_normals;
        before->tris = before->tri_normals = NULL;
    }
    vct_voxels_volume_desc(v, &st.desc);
    vct_stage_begin(ctx, STAGE);
    int rc = voxelize_into(&st, s, before, lo, hi, err);
    if (rc == VCT_OK)
        rc = vct_finish(ctx, STAGE, err);
    /* kept for the next update */
    v->tris = st.tris;
    v->tri_normals = st.tri_normals;
    cl_mem temps[] = {st.materials, st.chunk_start, st.counts, st.frag_keys, st.frag_ids};
    for (size_t i = 0; i < sizeof temps / sizeof temps[0]; ++i)
        vct_buffer_release(ctx, temps[i]);
    vct_scene_buffers_release(ctx, &st.scene);
    vct_stage_end(ctx);
    if (rc != VCT_OK) {
        vct_voxels_release(v);
        return NULL;
    }
    return v;
}

vct_voxels *vct_voxelize(vct_context *ctx, const vct_scene *s, const vct_voxel_options *o,
                         vct_error *err) {
    return voxelize(ctx, s, o, NULL, 0, 0, err);
}

vct_voxels *vct_voxelize_moved(vct_context *ctx, const vct_scene *s, const vct_voxel_options *o,
                               vct_voxels *before, uint32_t moved_lo, uint32_t moved_hi,
                               vct_error *err) {
    return voxelize(ctx, s, o, before, moved_lo, moved_hi, err);
}

vct_status vct_voxels_read(vct_context *ctx, const vct_voxels *v, uint32_t *keys, float *albedo,
                           float *normal, float *emission, vct_error *err) {
    const size_t n = v->info.voxels;
    int rc = VCT_OK;
    if (keys)
        rc = vct_buffer_read(ctx, "voxel read", v->keys, 0, 4 * n, keys, err);
    if (rc == VCT_OK && albedo)
        rc = vct_buffer_read(ctx, "voxel read", v->albedo, 0, 16 * n, albedo, err);
    if (rc == VCT_OK && normal)
        rc = vct_buffer_read(ctx, "voxel read", v->normal, 0, 16 * n, normal, err);
    if (rc == VCT_OK && emission)
        rc = vct_buffer_read(ctx, "voxel read", v->emission, 0, 16 * n, emission, err);
    return rc;
}

vct_voxel_options vct_voxel_options_default(void) {
    vct_voxel_options o;
    memset(&o, 0, sizeof o);
    o.resolution = 128;
    return o;
}
