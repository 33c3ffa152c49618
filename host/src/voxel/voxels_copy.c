/* Voxels built on one device, copied to another: every buffer and image is
 * read back and written there, as it is. What the copy costs against a
 * build is measured by bench_multi. */
#include <stdlib.h>
#include <string.h>

#include "voxel/voxels.h"

#define STAGE "voxel copy"

static cl_mem copy_buffer(vct_context *to, const vct_voxels *src, cl_mem mem, vct_error *err) {
    size_t bytes = 0;
    cl_mem_flags flags = 0;
    if (vct_cl_check(err, clGetMemObjectInfo(mem, CL_MEM_SIZE, sizeof bytes, &bytes, NULL), STAGE,
                     "clGetMemObjectInfo(CL_MEM_SIZE)") ||
        vct_cl_check(err, clGetMemObjectInfo(mem, CL_MEM_FLAGS, sizeof flags, &flags, NULL), STAGE,
                     "clGetMemObjectInfo(CL_MEM_FLAGS)"))
        return NULL;
    void *host = malloc(bytes ? bytes : 1);
    if (!host) {
        vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory (%zu bytes)", STAGE, bytes);
        return NULL;
    }
    cl_mem copy = NULL;
    if (vct_buffer_read(src->ctx, STAGE, mem, 0, bytes, host, err) == VCT_OK)
        copy = vct_buffer_create(to, STAGE, "voxel data", bytes,
                                 flags & (CL_MEM_READ_WRITE | CL_MEM_READ_ONLY | CL_MEM_WRITE_ONLY),
                                 host, err);
    free(host);
    return copy;
}

static cl_mem copy_image(vct_context *to, const vct_voxels *src, cl_mem mem, vct_error *err) {
    cl_image_format format;
    cl_image_desc desc;
    memset(&desc, 0, sizeof desc);
    desc.image_type = CL_MEM_OBJECT_IMAGE3D;
    if (vct_cl_check(err, clGetImageInfo(mem, CL_IMAGE_FORMAT, sizeof format, &format, NULL), STAGE,
                     "clGetImageInfo") ||
        vct_cl_check(
            err,
            clGetImageInfo(mem, CL_IMAGE_WIDTH, sizeof desc.image_width, &desc.image_width, NULL),
            STAGE, "clGetImageInfo") ||
        vct_cl_check(err,
                     clGetImageInfo(mem, CL_IMAGE_HEIGHT, sizeof desc.image_height,
                                    &desc.image_height, NULL),
                     STAGE, "clGetImageInfo") ||
        vct_cl_check(
            err,
            clGetImageInfo(mem, CL_IMAGE_DEPTH, sizeof desc.image_depth, &desc.image_depth, NULL),
            STAGE, "clGetImageInfo"))
        return NULL;
    if (!to->info.image_support) {
        vct_fail(err, VCT_ERR_INPUT,
                 "%s: the bricks are images and %s has none: build the voxels there", STAGE,
                 to->info.name);
        return NULL;
    }
    const size_t origin[3] = {0, 0, 0},
                 region[3] = {desc.image_width, desc.image_height, desc.image_depth};
    void *host = malloc(8 * region[0] * region[1] * region[2]); /* half RGBA texels */
    if (!host) {
        vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory", STAGE);
        return NULL;
    }
    cl_mem copy = NULL;
    if (vct_cl_check(err,
                     clEnqueueReadImage(src->ctx->queue, mem, CL_TRUE, origin, region, 0, 0, host,
                                        0, NULL, NULL),
                     STAGE, "clEnqueueReadImage") == VCT_OK)
        copy = vct_image3d_create(to, STAGE, "brick pool image", &format, &desc, err);
    if (copy && vct_cl_check(err,
                             clEnqueueWriteImage(to->queue, copy, CL_TRUE, origin, region, 0, 0,
                                                 host, 0, NULL, NULL),
                             STAGE, "clEnqueueWriteImage") != VCT_OK) {
        vct_buffer_release(to, copy);
        copy = NULL;
    }
    free(host);
    return copy;
}

vct_voxels *vct_voxels_copy(vct_context *ctx, const vct_voxels *src, vct_error *err) {
    vct_voxels *v = malloc(sizeof *v);
    if (!v) {
        vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory", STAGE);
        return NULL;
    }
    *v = *src;
    v->ctx = ctx;
    /* not copied: an update on this device voxelizes everything again */
    v->tris = v->tri_normals = NULL;
    cl_mem *mems[] = {
        &v->keys,           &v->albedo,       &v->normal,          &v->emission,
        &v->fragment_start, &v->fragment_tri, &v->radiance,        &v->direct_radiance,
        &v->child,          &v->neighbours,   &v->tile_parent,     &v->brick_window,
        &v->side,           &v->direct_side,  &v->before_radiance, &v->before_side};
    const size_t buffers = sizeof mems / sizeof mems[0];
    cl_mem *bricks[2 * VCT_BRICK_CHANNELS];
    for (int c = 0; c < VCT_BRICK_CHANNELS; ++c) {
        bricks[c] = &v->brick_buffer[c];
        bricks[VCT_BRICK_CHANNELS + c] = &v->brick_image[c];
    }
    /* Nothing of src's may be released with the copy, whatever fails. */
    for (size_t i = 0; i < buffers; ++i)
        *mems[i] = NULL;
    for (int c = 0; c < 2 * VCT_BRICK_CHANNELS; ++c)
        *bricks[c] = NULL;
    vct_stage_begin(ctx, STAGE);
    int rc = VCT_OK;
    const cl_mem *from[] = {
        &src->keys,           &src->albedo,       &src->normal,          &src->emission,
        &src->fragment_start, &src->fragment_tri, &src->radiance,        &src->direct_radiance,
        &src->child,          &src->neighbours,   &src->tile_parent,     &src->brick_window,
        &src->side,           &src->direct_side,  &src->before_radiance, &src->before_side};
    for (size_t i = 0; rc == VCT_OK && i < buffers; ++i)
        if (*from[i] && !(*mems[i] = copy_buffer(ctx, src, *from[i], err)))
            rc = err->status;
    for (int c = 0; rc == VCT_OK && c < VCT_BRICK_CHANNELS; ++c) {
        if (src->brick_buffer[c] &&
            !(v->brick_buffer[c] = copy_buffer(ctx, src, src->brick_buffer[c], err)))
            rc = err->status;
        if (rc == VCT_OK && src->brick_image[c] &&
            !(v->brick_image[c] = copy_image(ctx, src, src->brick_image[c], err)))
            rc = err->status;
    }
    vct_stage_end(ctx);
    if (rc != VCT_OK) {
        vct_voxels_release(v);
        return NULL;
    }
    return v;
}
