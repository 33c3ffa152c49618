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
static int quantise(const vct_scene *s, const vct_voxel_info *info, cl_int *out, vct_error *err) {
    const double scale = UNITS / info->side, lo = -(double)UNITS, hi = 2.0 * UNITS;
    for (uint32_t t = 0; t < s->triangle_count; ++t) {
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
        cl_int *o = out + 12ull * t;
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

/* Fragments: chunks -> scan -> count -> scan -> write, then a stable sort. */
static int make_fragments(voxelize_state *st, vct_error *err) {
    vct_context *ctx = st->ctx;
    vct_voxel_info *info = &st->v->info;
    const uint32_t n = info->triangles;
    st->chunk_start =
        vct_buffer_create(ctx, STAGE, "chunk offsets", 4ull * n, CL_MEM_READ_WRITE, NULL, err);
    st->tri_normals = st->chunk_start ? vct_buffer_create(ctx, STAGE, "triangle normals", 16ull * n,
                                                          CL_MEM_READ_WRITE, NULL, err)
                                      : NULL;
    if (!st->tri_normals)
        return err->status;
    int rc = vct_run_kernel(ctx, st->program, "vox_chunks", STAGE, n, err, 4, VCT_ARG_OF(st->tris),
                            VCT_ARG(vol, st->desc), VCT_ARG(chunks, st->chunk_start),
                            VCT_ARG_OF(st->tri_normals));
    uint64_t total = 0;
    if (rc == VCT_OK)
        rc = vct_scan_u32(ctx, st->chunk_start, st->chunk_start, n, 0, &total, err);
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
    rc =
        vct_run_kernel(ctx, st->program, "vox_count", STAGE, st->chunks, err, 6,
                       VCT_ARG_OF(st->tris), VCT_ARG(vol, st->desc), VCT_ARG_OF(st->thin),
                       VCT_ARG_OF(st->chunk_start), VCT_ARG_OF(st->chunks), VCT_ARG_OF(st->counts));
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
    info->fragments = (uint32_t)total;
    info->fragment_bytes = 8ull * total;
    st->frag_keys =
        vct_buffer_create(ctx, STAGE, "fragment keys", 4ull * total, CL_MEM_READ_WRITE, NULL, err);
    st->frag_ids = st->frag_keys ? vct_buffer_create(ctx, STAGE, "fragment triangles", 4ull * total,
                                                     CL_MEM_READ_WRITE, NULL, err)
                                 : NULL;
    if (!st->frag_ids)
        return err->status;
    rc = vct_run_kernel(ctx, st->program, "vox_write", STAGE, st->chunks, err, 8,
                        VCT_ARG_OF(st->tris), VCT_ARG(vol, st->desc), VCT_ARG_OF(st->thin),
                        VCT_ARG_OF(st->chunk_start), VCT_ARG_OF(st->chunks),
                        VCT_ARG(offsets, st->counts), VCT_ARG(keys, st->frag_keys),
                        VCT_ARG(ids, st->frag_ids));
    vct_buffer_release(ctx, st->counts);
    st->counts = NULL;
    if (rc == VCT_OK)
        rc = vct_sort_pairs_u32(ctx, st->frag_keys, st->frag_ids, info->fragments,
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

static int upload_triangles(voxelize_state *st, const vct_scene *s, vct_error *err) {
    vct_context *ctx = st->ctx;
    const uint32_t n = s->triangle_count;
    cl_int *q = malloc(48ull * (n ? n : 1));
    if (!q)
        return vct_fail(err, VCT_ERR_MEMORY, "voxelize: out of host memory");
    int rc = quantise(s, &st->v->info, q, err);
    if (rc == VCT_OK) {
        st->tris = vct_buffer_create(ctx, STAGE, "quantised triangles", 48ull * n, CL_MEM_READ_ONLY,
                                     n ? q : NULL, err);
        rc = st->tris ? VCT_OK : (int)err->status;
    }
    free(q);
    vct_material_desc *m = rc == VCT_OK ? malloc(sizeof *m * (s->material_count + 1)) : NULL;
    if (rc == VCT_OK && !m)
        rc = vct_fail(err, VCT_ERR_MEMORY, "voxelize: out of host memory");
    if (rc == VCT_OK) {
        for (uint32_t i = 0; i < s->material_count; ++i)
            vct_material_desc_make(&s->materials[i], &m[i]);
        st->materials = vct_buffer_create(ctx, STAGE, "materials", sizeof *m * s->material_count,
                                          CL_MEM_READ_ONLY, s->material_count ? m : NULL, err);
        rc = st->materials ? VCT_OK : (int)err->status;
    }
    free(m);
    if (rc == VCT_OK)
        rc = vct_scene_buffers_make(ctx, s, STAGE, &st->scene, err);
    return rc;
}

vct_voxels *vct_voxelize(vct_context *ctx, const vct_scene *s, const vct_voxel_options *o,
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
    vct_voxel_info *info = &v->info;
    info->resolution = o->resolution;
    while ((1u << info->levels) < o->resolution)
        ++info->levels;
    info->units = UNITS;
    info->triangles = s->triangle_count;
    if (o->has_bounds) {
        memcpy(info->origin, o->bounds_min, sizeof info->origin);
        info->side = o->bounds_size;
    } else {
        frame_scene(s, o->resolution, info->origin, &info->side);
    }
    voxelize_state st = {.ctx = ctx, .v = v, .thin = o->thin != 0};
    vct_voxels_volume_desc(v, &st.desc);
    vct_stage_begin(ctx, STAGE);
    int rc = vct_program_get(ctx, "voxel/voxelize.cl", "", &st.program, err);
    if (rc == VCT_OK)
        rc = upload_triangles(&st, s, err);
    if (rc == VCT_OK)
        rc = make_fragments(&st, err);
    if (rc == VCT_OK)
        rc = reduce_fragments(&st, err);
    if (rc == VCT_OK)
        rc = vct_finish(ctx, STAGE, err);
    cl_mem temps[] = {st.tris,   st.tri_normals, st.materials, st.chunk_start,
                      st.counts, st.frag_keys,   st.frag_ids};
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
