/* The scene's frame and its triangles' vertices on the device. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "accel/tri_vertices.h"

void vct_scene_frame_of(const vct_scene *s, vct_scene_frame *f) {
    float ext = 0.0f, mag = 0.0f;
    for (int k = 0; k < 3; ++k) {
        ext = fmaxf(ext, s->bounds_max[k] - s->bounds_min[k]);
        mag = fmaxf(mag, fmaxf(fabsf(s->bounds_min[k]), fabsf(s->bounds_max[k])));
    }
    if (!(ext > 0.0f))
        ext = fmaxf(mag * 1e-3f, 1e-3f); /* a point-like scene still gets a box */
    const float margin = ext * 1e-4f + mag * 8.0f * FLT_EPSILON;
    for (int k = 0; k < 3; ++k) {
        f->lo[k] = s->bounds_min[k] - margin;
        f->hi[k] = s->bounds_max[k] + margin;
        if (f->hi[k] - f->lo[k] < ext * 1e-3f) {
            float mid = 0.5f * (f->lo[k] + f->hi[k]);
            f->lo[k] = mid - ext * 5e-4f;
            f->hi[k] = mid + ext * 5e-4f;
        }
    }
    f->extent = ext;
    f->tolerance = ext * 1e-5f + mag * 4.0f * FLT_EPSILON;
}

/* The alpha-mask block (kernels/accel/alpha_mask.h) of the scene's masked
 * materials, in float4s, and each triangle's slot (0: opaque); NULL block
 * when nothing is masked. `first` is the block's float4 index. */
typedef struct mask_block {
    float *data; /* 4 floats per float4 */
    size_t float4s;
    uint32_t *slot;
} mask_block;

static void put_u4(float *at, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    const uint32_t u[4] = {a, b, c, d};
    memcpy(at, u, sizeof u);
}

static int mask_block_make(const vct_scene *s, uint32_t first, mask_block *mb) {
    memset(mb, 0, sizeof *mb);
    const uint32_t n = s->triangle_count;
    uint32_t *material_slot = calloc(s->material_count + 1, sizeof *material_slot);
    uint32_t materials = 0, records = 0;
    size_t texels = 0;
    for (uint32_t m = 0; material_slot && m < s->material_count; ++m)
        if (s->materials[m].alpha_cutoff > 0.0f) {
            material_slot[m] = ++materials;
            const uint32_t t = s->materials[m].albedo_texture;
            if (t)
                texels += (size_t)s->textures[t - 1].width * s->textures[t - 1].height;
        }
    if (!material_slot || materials == 0) {
        free(material_slot);
        return material_slot ? VCT_OK : VCT_ERR_MEMORY;
    }
    for (uint32_t t = 0; t < n; ++t)
        records += material_slot[s->triangle_material[t]] != 0;
    const uint32_t record_at = first + 1, material_at = record_at + 2 * records;
    const uint32_t texel_at = material_at + 2 * materials;
    mb->float4s = 1 + 2ull * records + 2ull * materials + (texels + 3) / 4;
    mb->data = calloc(4 * mb->float4s, sizeof(float));
    mb->slot = calloc(n ? n : 1, sizeof *mb->slot);
    if (!mb->data || !mb->slot) {
        free(material_slot);
        return VCT_ERR_MEMORY;
    }
    float *d = mb->data;
    put_u4(d, record_at, material_at, texel_at, 0);
    float *alpha = d + 4ull * (texel_at - first);
    uint32_t next_texel = 0;
    for (uint32_t m = 0; m < s->material_count; ++m) {
        if (!material_slot[m])
            continue;
        const vct_material *mat = &s->materials[m];
        float *h = d + 4ull * (material_at - first + 2 * (material_slot[m] - 1));
        const vct_texture *tex = mat->albedo_texture ? &s->textures[mat->albedo_texture - 1] : NULL;
        put_u4(h, next_texel, tex ? (uint32_t)tex->width : 0, tex ? (uint32_t)tex->height : 0,
               mat->texture_wrap);
        h[4] = mat->alpha;
        h[5] = mat->alpha_cutoff;
        for (size_t i = 0; tex && i < (size_t)tex->width * tex->height; ++i)
            alpha[next_texel + i] = tex->rgba[4 * i + 3];
        next_texel += tex ? (uint32_t)(tex->width * tex->height) : 0;
    }
    uint32_t r = 0;
    for (uint32_t t = 0; t < n; ++t) {
        const uint32_t m = material_slot[s->triangle_material[t]];
        if (!m)
            continue;
        float *rec = d + 4ull * (record_at - first + 2 * r);
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = s->triangles[3 * t + k];
            rec[2 * k] = s->uvs ? s->uvs[2 * v] : 0.0f;
            rec[2 * k + 1] = s->uvs ? s->uvs[2 * v + 1] : 0.0f;
        }
        const uint32_t slot = m - 1;
        memcpy(&rec[6], &slot, sizeof slot);
        mb->slot[t] = ++r;
    }
    free(material_slot);
    return VCT_OK;
}

int vct_tri_vertices_upload(vct_context *ctx, const vct_scene *s, const char *stage, cl_mem *out,
                            vct_error *err) {
    const uint32_t n = s->triangle_count;
    mask_block mb;
    if (mask_block_make(s, 3 * n, &mb) != VCT_OK) {
        free(mb.data);
        free(mb.slot);
        return vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory for the alpha masks", stage);
    }
    const cl_uint has_masks = mb.data != NULL;
    cl_program p;
    int rc = vct_program_get(ctx, "accel/tri_vertices.cl", "", &p, err);
    cl_mem pos = rc == VCT_OK ? vct_buffer_create(ctx, stage, "vertex positions",
                                                  12ull * (s->vertex_count ? s->vertex_count : 1),
                                                  CL_MEM_READ_ONLY, NULL, err)
                              : NULL;
    cl_mem tri = pos ? vct_buffer_create(ctx, stage, "triangle indices", 12ull * (n ? n : 1),
                                         CL_MEM_READ_ONLY, NULL, err)
                     : NULL;
    cl_mem slots = tri ? vct_buffer_create(ctx, stage, "alpha mask slots", has_masks ? 4ull * n : 4,
                                           CL_MEM_READ_ONLY, has_masks ? mb.slot : NULL, err)
                       : NULL;
    *out = slots ? vct_buffer_create(ctx, stage, "triangle vertices",
                                     48ull * (n ? n : 1) + 16ull * mb.float4s, CL_MEM_READ_WRITE,
                                     NULL, err)
                 : NULL;
    rc = *out ? VCT_OK : (int)err->status;
    if (rc == VCT_OK && n) {
        rc = vct_buffer_write(ctx, stage, pos, 0, 12ull * s->vertex_count, s->positions, err);
        if (rc == VCT_OK)
            rc = vct_buffer_write(ctx, stage, tri, 0, 12ull * n, s->triangles, err);
        if (rc == VCT_OK)
            rc = vct_run_kernel(ctx, p, "gather_tri_vertices", stage, n, err, 6,
                                VCT_ARG(positions, pos), VCT_ARG(triangles, tri), VCT_ARG(count, n),
                                VCT_ARG(mask_slot, slots), VCT_ARG_OF(has_masks),
                                VCT_ARG(tri_vertices, *out));
        /* the block after the vertices, and where it starts in triangle 0's second w */
        const uint32_t head = 3 * n;
        if (rc == VCT_OK && has_masks)
            rc = vct_buffer_write(ctx, stage, *out, 48ull * n, 16ull * mb.float4s, mb.data, err);
        if (rc == VCT_OK && has_masks)
            rc = vct_buffer_write(ctx, stage, *out, 16 + 12, 4, &head, err);
    }
    free(mb.data);
    free(mb.slot);
    vct_buffer_release(ctx, slots);
    vct_buffer_release(ctx, tri);
    vct_buffer_release(ctx, pos);
    if (rc != VCT_OK) {
        vct_buffer_release(ctx, *out);
        *out = NULL;
    }
    return rc;
}
