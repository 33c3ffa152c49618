/* The scene's frame and its triangles' vertices on the device. */
#include <float.h>
#include <math.h>

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

int vct_tri_vertices_upload(vct_context *ctx, const vct_scene *s, const char *stage, cl_mem *out,
                            vct_error *err) {
    const uint32_t n = s->triangle_count;
    cl_program p;
    int rc = vct_program_get(ctx, "accel/tri_vertices.cl", "", &p, err);
    cl_mem pos = rc == VCT_OK ? vct_buffer_create(ctx, stage, "vertex positions",
                                                  12ull * (s->vertex_count ? s->vertex_count : 1),
                                                  CL_MEM_READ_ONLY, NULL, err)
                              : NULL;
    cl_mem tri = pos ? vct_buffer_create(ctx, stage, "triangle indices", 12ull * (n ? n : 1),
                                         CL_MEM_READ_ONLY, NULL, err)
                     : NULL;
    *out = tri ? vct_buffer_create(ctx, stage, "triangle vertices", 48ull * (n ? n : 1),
                                   CL_MEM_READ_WRITE, NULL, err)
               : NULL;
    rc = *out ? VCT_OK : (int)err->status;
    if (rc == VCT_OK && n) {
        rc = vct_buffer_write(ctx, stage, pos, 0, 12ull * s->vertex_count, s->positions, err);
        if (rc == VCT_OK)
            rc = vct_buffer_write(ctx, stage, tri, 0, 12ull * n, s->triangles, err);
        if (rc == VCT_OK)
            rc = vct_run_kernel(ctx, p, "gather_tri_vertices", stage, n, err, 4, VCT_ARG_OF(pos),
                                VCT_ARG_OF(tri), VCT_ARG_OF(n), VCT_ARG_OF(*out));
    }
    vct_buffer_release(ctx, tri);
    vct_buffer_release(ctx, pos);
    if (rc != VCT_OK) {
        vct_buffer_release(ctx, *out);
        *out = NULL;
    }
    return rc;
}
