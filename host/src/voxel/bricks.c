/* Bricks and their filtering (kernels/voxel/bricks.cl), and the pool they live
 * in: a buffer, or an image3d filled from a buffer of the same layout. */
#include <stdio.h>
#include <string.h>

#include "runtime/runtime.h"
#include "vct_types.h"
#include "voxel/voxels.h"

#define CREATE_STAGE "brick creation"
#define FILTER_STAGE "brick filtering"
#define REFRESH_STAGE "radiance filtering"
#define IMAGE_SLAB 64u /* bricks per row and column of an image pool */
#define TEXEL_BYTES 8u /* half4 */

static uint32_t div_up(uint64_t a, uint64_t b) {
    return (uint32_t)((a + b - 1) / b);
}

static void count_bricks(const vct_voxel_info *v, vct_brick_info *b) {
    const uint32_t levels = v->levels;
    b->bricks = v->voxels ? (v->nodes - 1) / 8 : 0;
    for (uint32_t l = 0; l < levels && v->voxels; ++l) {
        b->level_bricks[l] = v->level_nodes[l + 1] / 8;
        b->level_first[l] = (v->level_start[l + 1] - 1) / 8;
    }
    b->directional_bricks = b->anisotropic && levels >= 2 ? b->level_first[levels - 1] : 0;
    const double r = v->resolution;
    b->dense_rgba8_bytes = (uint64_t)(4.0 * r * r * r);
}

/* Pool size in bricks for `bricks` bricks with rows of `row` bricks. */
static void pool_shape(uint32_t bricks, uint32_t row, uint32_t shape[3]) {
    const uint32_t n = bricks ? bricks : 1;
    shape[0] = n < row ? n : row;
    const uint32_t rows = div_up(n, shape[0]);
    shape[1] = rows < row ? rows : row;
    shape[2] = div_up(n, (uint64_t)shape[0] * shape[1]);
}

static uint64_t shape_bytes(const uint32_t s[3]) {
    return 27ull * TEXEL_BYTES * s[0] * s[1] * s[2];
}

static uint64_t pool_bytes(uint32_t bricks, uint32_t row) {
    uint32_t s[3];
    pool_shape(bricks, row, s);
    return shape_bytes(s);
}

static int has_half_rgba_3d(vct_context *ctx) {
    cl_image_format formats[256];
    cl_uint n = 0;
    if (clGetSupportedImageFormats(ctx->context, CL_MEM_READ_ONLY, CL_MEM_OBJECT_IMAGE3D, 256,
                                   formats, &n) != CL_SUCCESS)
        return 0;
    for (cl_uint i = 0; i < n && i < 256; ++i)
        if (formats[i].image_channel_order == CL_RGBA &&
            formats[i].image_channel_data_type == CL_HALF_FLOAT)
            return 1;
    return 0;
}

/* Why an image pool of `shape` cannot be used here, or NULL if it can. */
static const char *image_refusal(vct_context *ctx, const uint32_t shape[3], uint64_t bytes) {
    if (!ctx->info.image_support)
        return "the device has no image support";
    if (!has_half_rgba_3d(ctx))
        return "the device has no half-float RGBA 3D images";
    size_t limit[3] = {0, 0, 0};
    const cl_device_info what[3] = {CL_DEVICE_IMAGE3D_MAX_WIDTH, CL_DEVICE_IMAGE3D_MAX_HEIGHT,
                                    CL_DEVICE_IMAGE3D_MAX_DEPTH};
    for (int a = 0; a < 3; ++a) {
        clGetDeviceInfo(ctx->device, what[a], sizeof limit[a], &limit[a], NULL);
        if (3ull * shape[a] > limit[a])
            return "the pool exceeds the device's 3D image size";
    }
    return bytes > ctx->info.max_alloc ? "the pool exceeds the device's allocation limit" : NULL;
}

static int choose_storage(vct_context *ctx, vct_brick_storage storage, vct_brick_info *b,
                          vct_error *err) {
    uint32_t image_shape[3];
    pool_shape(b->bricks, IMAGE_SLAB, image_shape);
    const char *refusal = b->bricks == 0
                              ? "there are no bricks"
                              : image_refusal(ctx, image_shape, pool_bytes(b->bricks, IMAGE_SLAB));
    if (storage == VCT_BRICKS_IMAGE && b->bricks == 0)
        storage = VCT_BRICKS_BUFFER; /* nothing to sample: any kind will do */
    if (storage == VCT_BRICKS_IMAGE && refusal)
        return vct_fail(err, VCT_ERR_INPUT, "bricks: an image3d pool was asked for but %s",
                        refusal);
    if (storage == VCT_BRICKS_IMAGE) {
        b->image = 1;
        snprintf(b->storage_reason, sizeof b->storage_reason, "image3d, as asked");
    } else if (storage == VCT_BRICKS_BUFFER) {
        snprintf(b->storage_reason, sizeof b->storage_reason, "buffer, as asked");
    } else if (refusal) {
        snprintf(b->storage_reason, sizeof b->storage_reason, "buffer: %s", refusal);
    } else if (!ctx->info.is_gpu) {
        snprintf(b->storage_reason, sizeof b->storage_reason,
                 "buffer: a CPU device samples images in software, slower than a buffer");
    } else {
        b->image = 1;
        snprintf(b->storage_reason, sizeof b->storage_reason,
                 "image3d: the GPU filters trilinearly in hardware");
    }
    const uint32_t row = b->image ? IMAGE_SLAB : 1;
    pool_shape(b->bricks, row, b->pool);
    b->channel_bytes = pool_bytes(b->bricks, row);
    return VCT_OK;
}

static int channel_count(const vct_brick_info *b) {
    return b->anisotropic ? VCT_BRICK_CHANNELS : VCT_BRICK_PLANE + 1;
}

/* Channel c has bricks [channel_first, channel_bricks): the directions at
 * levels 0 .. L-2, and with them isotropic radiance at level L-1 only. */
static uint32_t channel_bricks(const vct_brick_info *b, int c) {
    return c >= VCT_BRICK_RADIANCE_DIR0 ? b->directional_bricks : b->bricks;
}

static uint32_t channel_first(const vct_brick_info *b, int c) {
    return c == VCT_BRICK_RADIANCE && b->anisotropic ? b->directional_bricks : 0;
}

/* Channel c's pool: the same rows and columns as the main pool (the kernels
 * address every channel alike), only as many slabs as it needs. */
static void channel_shape(const vct_brick_info *b, int c, uint32_t shape[3]) {
    const uint32_t n = channel_bricks(b, c);
    shape[0] = b->pool[0];
    shape[1] = b->pool[1];
    shape[2] = div_up(n ? n : 1, (uint64_t)shape[0] * shape[1]);
}

static int allocate_buffers(vct_context *ctx, vct_voxels *v, vct_error *err) {
    vct_brick_info *b = &v->brick_info;
    static const char *names[VCT_BRICK_CHANNELS] = {
        "albedo bricks",      "normal bricks",      "radiance bricks",    "shade bricks",
        "plane bricks",       "+x radiance bricks", "+y radiance bricks", "+z radiance bricks",
        "-x radiance bricks", "-y radiance bricks", "-z radiance bricks", "+x dark bricks",
        "+y dark bricks",     "+z dark bricks",     "-x dark bricks",     "-y dark bricks",
        "-z dark bricks"};
    b->pool_bytes = 0;
    for (int c = 0; c < channel_count(b); ++c) {
        uint32_t shape[3];
        channel_shape(b, c, shape);
        const uint64_t bytes = shape_bytes(shape);
        int rc = vct_voxel_buffer_fits(ctx, &v->info, "bricks", names[c], (double)bytes, err);
        if (rc != VCT_OK)
            return rc;
        v->brick_buffer[c] =
            vct_buffer_create(ctx, CREATE_STAGE, names[c], bytes, CL_MEM_READ_WRITE, NULL, err);
        if (!v->brick_buffer[c])
            return err->status;
        b->pool_bytes += bytes;
    }
    return VCT_OK;
}

typedef struct level_run {
    vct_context *ctx;
    vct_voxels *v;
    cl_program program;
    const char *stage;
    cl_uint pool[2];
    /* The build finds each brick's window through the child tiles of the 27
     * nodes around its node (`around`, transient) and keeps it in
     * v->brick_window; later passes read the window (window_ready). */
    cl_mem around;
    cl_uint window_ready;
} level_run;

/* Every brick's neighbourhood, top-down: level l's from level l-1's; and
 * room for the windows found from them. */
static int run_around(level_run *r, vct_error *err) {
    vct_voxels *v = r->v;
    vct_brick_info *b = &v->brick_info;
    b->window_bytes = 64ull * 4 * b->bricks;
    int rc = vct_voxel_buffer_fits(r->ctx, &v->info, "bricks", "brick windows",
                                   (double)b->window_bytes, err);
    if (rc != VCT_OK)
        return rc;
    r->around = vct_buffer_create(r->ctx, r->stage, "brick neighbourhoods", 27ull * 4 * b->bricks,
                                  CL_MEM_READ_WRITE, NULL, err);
    v->brick_window = r->around ? vct_buffer_create(r->ctx, r->stage, "brick windows",
                                                    b->window_bytes, CL_MEM_READ_WRITE, NULL, err)
                                : NULL;
    rc = v->brick_window ? VCT_OK : (int)err->status;
    for (cl_uint l = 0; l < v->info.levels && rc == VCT_OK; ++l)
        rc = vct_run_kernel(r->ctx, r->program, "brick_around", r->stage, b->level_bricks[l], err,
                            6, VCT_ARG_OF(v->child), VCT_ARG_OF(v->tile_parent), VCT_ARG(level, l),
                            VCT_ARG(first_brick, b->level_first[l]),
                            VCT_ARG(count, b->level_bricks[l]), VCT_ARG_OF(r->around));
    return rc;
}

/* Work-items per group for the brick kernels, whose private arrays take
 * kilobytes per work-item (a 9^3 lattice table, 7x7 columns): PoCL's own
 * choice, thousands per group, overflowed its threads' stacks at 256^3. */
#define BRICK_GROUP 64

/* Level L-1 bricks from the voxels: albedo and normal when `geometry`,
 * radiance and its sides when `radiance_too`. */
static int run_leaf(const level_run *r, int geometry, int radiance_too, vct_error *err) {
    vct_voxels *v = r->v;
    const uint32_t level = v->info.levels - 1, first = v->brick_info.level_first[level];
    const uint32_t count = v->brick_info.level_bricks[level];
    const cl_uint has_radiance = v->radiance != NULL && v->side != NULL;
    const cl_uint from = geometry ? VCT_BRICK_ALBEDO : VCT_BRICK_RADIANCE;
    const cl_uint to = radiance_too ? VCT_BRICK_PLANE + 1 : VCT_BRICK_RADIANCE;
    /* unused arrays stand in for what is not read or written */
    cl_mem radiance = has_radiance ? v->radiance : v->albedo;
    cl_mem side = has_radiance ? v->side : v->albedo;
    cl_mem pools[VCT_BRICK_PLANE + 1];
    for (int c = 0; c <= VCT_BRICK_PLANE; ++c)
        pools[c] = v->brick_buffer[c] ? v->brick_buffer[c] : v->brick_buffer[VCT_BRICK_RADIANCE];
    return vct_run_kernel_grouped(
        r->ctx, r->program, "brick_leaf", r->stage, count, BRICK_GROUP, err, 19,
        VCT_ARG_OF(v->child), VCT_ARG_OF(r->around), VCT_ARG(window, v->brick_window),
        VCT_ARG_OF(r->window_ready), VCT_ARG(first_brick, first), VCT_ARG_OF(count),
        VCT_ARG_OF(v->albedo), VCT_ARG_OF(v->normal), VCT_ARG_OF(radiance), VCT_ARG_OF(side),
        VCT_ARG_OF(has_radiance), VCT_ARG(channel_from, from), VCT_ARG(channel_to, to),
        VCT_ARG_OF(r->pool), VCT_ARG(albedo_pool, pools[0]), VCT_ARG(normal_pool, pools[1]),
        VCT_ARG(radiance_pool, pools[2]), VCT_ARG(shade_pool, pools[3]),
        VCT_ARG(plane_pool, pools[4]));
}

/* brick_filter over `channels` pools of one level, four at a time. */
static int run_filter_channels(const level_run *r, cl_uint first, cl_uint count, const cl_mem *list,
                               cl_uint channels, vct_error *err) {
    vct_voxels *v = r->v;
    int rc = VCT_OK;
    for (cl_uint done = 0; done < channels && rc == VCT_OK; done += 4) {
        const cl_uint n = channels - done < 4 ? channels - done : 4;
        const cl_mem *c = list + done;
        rc = vct_run_kernel_grouped(r->ctx, r->program, "brick_filter", r->stage, count,
                                    BRICK_GROUP, err, 12, VCT_ARG_OF(v->child),
                                    VCT_ARG_OF(r->around), VCT_ARG(window, v->brick_window),
                                    VCT_ARG_OF(r->window_ready), VCT_ARG(first_brick, first),
                                    VCT_ARG_OF(count), VCT_ARG_OF(r->pool), VCT_ARG(channels, n),
                                    VCT_ARG(c0, c[0]), VCT_ARG(c1, c[n > 1 ? 1 : 0]),
                                    VCT_ARG(c2, c[n > 2 ? 2 : 0]), VCT_ARG(c3, c[n > 3 ? 3 : 0]));
    }
    return rc;
}

/* The six directions of level `level`'s bricks, of the brighter sides and
 * of the darker ones, from the level below: from the leaves' one isotropic
 * value (less their shade for the darker sides), or from its directions. */
static int run_filter_dir(const level_run *r, int level, vct_error *err) {
    vct_voxels *v = r->v;
    const vct_brick_info *b = &v->brick_info;
    cl_mem *pool = v->brick_buffer;
    const cl_uint first = b->level_first[level], count = b->level_bricks[level];
    const cl_uint one_source = level + 2 == (int)v->info.levels;
    cl_mem *bright = pool + VCT_BRICK_RADIANCE_DIR0, *dark = pool + VCT_BRICK_DARK_DIR0;
    cl_mem src[6], dark_src[6];
    for (int d = 0; d < 6; ++d) {
        src[d] = one_source ? pool[VCT_BRICK_RADIANCE] : bright[d];
        dark_src[d] = one_source ? pool[VCT_BRICK_RADIANCE] : dark[d];
    }
    /* the geometry's brick_filter found this level's windows */
    const cl_uint window_ready = 1;
    return vct_run_kernel_grouped(
        r->ctx, r->program, "brick_filter_dir", r->stage, count, BRICK_GROUP, err, 33,
        VCT_ARG_OF(v->child), VCT_ARG_OF(r->around), VCT_ARG(window, v->brick_window),
        VCT_ARG_OF(window_ready), VCT_ARG(first_brick, first), VCT_ARG_OF(count),
        VCT_ARG_OF(r->pool), VCT_ARG(s0, src[0]), VCT_ARG(s1, src[1]), VCT_ARG(s2, src[2]),
        VCT_ARG(s3, src[3]), VCT_ARG(s4, src[4]), VCT_ARG(s5, src[5]), VCT_ARG(d0, bright[0]),
        VCT_ARG(d1, bright[1]), VCT_ARG(d2, bright[2]), VCT_ARG(d3, bright[3]),
        VCT_ARG(d4, bright[4]), VCT_ARG(d5, bright[5]), VCT_ARG_OF(one_source),
        VCT_ARG(shade, pool[VCT_BRICK_SHADE]), VCT_ARG(e0, dark_src[0]), VCT_ARG(e1, dark_src[1]),
        VCT_ARG(e2, dark_src[2]), VCT_ARG(e3, dark_src[3]), VCT_ARG(e4, dark_src[4]),
        VCT_ARG(e5, dark_src[5]), VCT_ARG(f0, dark[0]), VCT_ARG(f1, dark[1]), VCT_ARG(f2, dark[2]),
        VCT_ARG(f3, dark[3]), VCT_ARG(f4, dark[4]), VCT_ARG(f5, dark[5]));
}

/* Levels L-2 .. 0, each from the level below: albedo and normal when
 * `geometry`; radiance (its directions when anisotropic) and its sides when
 * `radiance_too`. */
static int run_filters(const level_run *r, int geometry, int radiance_too, vct_error *err) {
    vct_voxels *v = r->v;
    const vct_brick_info *b = &v->brick_info;
    cl_mem *pool = v->brick_buffer;
    int rc = VCT_OK;
    for (int level = (int)v->info.levels - 2; level >= 0 && rc == VCT_OK; --level) {
        const cl_uint first = b->level_first[level], count = b->level_bricks[level];
        /* the channels to filter, first to last: (albedo, normal), radiance */
        cl_mem list[5];
        cl_uint channels = 0;
        if (geometry) {
            list[channels++] = pool[VCT_BRICK_ALBEDO];
            list[channels++] = pool[VCT_BRICK_NORMAL];
        }
        /* Anisotropic cones read the six directions above the leaves: no
         * isotropic radiance there. */
        if (radiance_too && !b->anisotropic)
            list[channels++] = pool[VCT_BRICK_RADIANCE];
        if (radiance_too) {
            list[channels++] = pool[VCT_BRICK_SHADE];
            list[channels++] = pool[VCT_BRICK_PLANE];
        }
        rc = run_filter_channels(r, first, count, list, channels, err);
        if (rc != VCT_OK || !b->anisotropic || !radiance_too)
            continue;
        rc = run_filter_dir(r, level, err);
    }
    return rc;
}

/* Image pools: copies channels [from, to) from their build buffers. */
static int copy_to_images(const level_run *r, int from, int to, vct_error *err) {
    vct_voxels *v = r->v;
    vct_brick_info *b = &v->brick_info;
    for (int c = from; c < to && b->image; ++c) {
        uint32_t shape[3];
        channel_shape(b, c, shape);
        if (!v->brick_image[c]) {
            const cl_image_format format = {CL_RGBA, CL_HALF_FLOAT};
            cl_image_desc desc = {0};
            desc.image_type = CL_MEM_OBJECT_IMAGE3D;
            desc.image_width = 3u * shape[0];
            desc.image_height = 3u * shape[1];
            desc.image_depth = 3u * shape[2];
            v->brick_image[c] =
                vct_image3d_create(r->ctx, r->stage, "brick pool image", &format, &desc, err);
            if (!v->brick_image[c])
                return err->status;
        }
        const size_t origin[3] = {0, 0, 0};
        const size_t region[3] = {3u * shape[0], 3u * shape[1], 3u * shape[2]};
        cl_event ev = NULL;
        VCT_CL(err, r->stage,
               clEnqueueCopyBufferToImage(r->ctx->queue, v->brick_buffer[c], v->brick_image[c], 0,
                                          origin, region, 0, NULL, &ev));
        int rc = vct_record_event(r->ctx, ev, "copy to image", err);
        if (rc != VCT_OK)
            return rc;
    }
    return VCT_OK;
}

static int level_run_init(vct_context *ctx, vct_voxels *v, const char *stage, level_run *r,
                          vct_error *err) {
    r->ctx = ctx;
    r->v = v;
    r->stage = stage;
    r->pool[0] = v->brick_info.pool[0];
    r->pool[1] = v->brick_info.pool[1];
    /* kernels that read only windows take them in place of the neighbourhoods */
    r->around = v->brick_window;
    r->window_ready = v->brick_window != NULL;
    return vct_program_get(ctx, "voxel/bricks.cl", "", &r->program, err);
}

vct_status vct_bricks_build(vct_context *ctx, vct_voxels *v, const vct_brick_options *options,
                            vct_error *err) {
    if (!v->child)
        return vct_fail(err, VCT_ERR_INPUT, "bricks: build the octree first (vct_octree_build)");
    const vct_brick_options defaults = {VCT_BRICKS_AUTO, 0, 0};
    if (!options)
        options = &defaults;
    vct_bricks_release(v);
    vct_brick_info *b = &v->brick_info;
    memset(b, 0, sizeof *b);
    b->anisotropic = options->anisotropic != 0;
    count_bricks(&v->info, b);
    vct_stage_begin(ctx, CREATE_STAGE);
    int rc = choose_storage(ctx, options->storage, b, err);
    if (rc == VCT_OK)
        rc = allocate_buffers(ctx, v, err);
    level_run r = {0};
    if (rc == VCT_OK)
        rc = level_run_init(ctx, v, CREATE_STAGE, &r, err);
    if (rc == VCT_OK && b->bricks)
        rc = run_around(&r, err);
    const int radiance_too = !options->radiance_later;
    if (rc == VCT_OK && b->bricks)
        rc = run_leaf(&r, 1, radiance_too, err);
    if (rc == VCT_OK)
        rc = vct_finish(ctx, CREATE_STAGE, err);
    vct_stage_begin(ctx, FILTER_STAGE);
    r.stage = FILTER_STAGE;
    if (rc == VCT_OK && b->bricks)
        rc = run_filters(&r, 1, radiance_too, err);
    if (rc == VCT_OK)
        rc = copy_to_images(&r, 0, radiance_too ? channel_count(b) : VCT_BRICK_RADIANCE, err);
    if (rc == VCT_OK && b->image) {
        /* geometry never changes: only the radiance buffers stay, for re-filtering */
        b->staging_bytes = b->pool_bytes;
        for (int c = VCT_BRICK_ALBEDO; c <= VCT_BRICK_NORMAL; ++c) {
            b->staging_bytes -= b->channel_bytes;
            vct_buffer_release(ctx, v->brick_buffer[c]);
            v->brick_buffer[c] = NULL;
        }
    }
    if (rc == VCT_OK)
        rc = vct_finish(ctx, FILTER_STAGE, err);
    vct_stage_end(ctx);
    if (r.around != v->brick_window) /* the windows replace the neighbourhoods */
        vct_buffer_release(ctx, r.around);
    if (rc != VCT_OK) {
        vct_bricks_release(v);
    } else {
        v->has_bricks = 1;
        v->radiance_ready = radiance_too;
    }
    return rc;
}

int vct_bricks_radiance_check(const vct_voxels *v, const char *stage, vct_error *err) {
    if (v->has_bricks && !v->radiance_ready)
        return vct_fail(err, VCT_ERR_INPUT,
                        "%s: the bricks' radiance waits for light injection "
                        "(built with radiance_later): call vct_voxels_inject_light first",
                        stage);
    return VCT_OK;
}

/* The radiance bricks again from the voxels' radiance: the leaf level's,
 * then (filter) every coarser level's. */
static int refresh_radiance(vct_context *ctx, vct_voxels *v, int filter, vct_error *err) {
    if (!v->has_bricks)
        return VCT_OK;
    if (v->brick_info.bricks == 0) {
        v->radiance_ready = 1;
        return VCT_OK;
    }
    vct_stage_begin(ctx, REFRESH_STAGE);
    level_run r = {0};
    int rc = level_run_init(ctx, v, REFRESH_STAGE, &r, err);
    const int channels = channel_count(&v->brick_info);
    if (rc == VCT_OK) /* r.window_ready: the windows found by the build */
        rc = run_leaf(&r, 0, 1, err);
    if (rc == VCT_OK && filter)
        rc = run_filters(&r, 0, 1, err);
    if (rc == VCT_OK)
        rc = copy_to_images(&r, VCT_BRICK_RADIANCE, channels, err);
    if (rc == VCT_OK)
        rc = vct_finish(ctx, REFRESH_STAGE, err);
    vct_stage_end(ctx);
    if (rc == VCT_OK)
        v->radiance_ready = 1;
    return rc;
}

int vct_bricks_refresh_radiance(vct_context *ctx, vct_voxels *v, vct_error *err) {
    return refresh_radiance(ctx, v, 1, err);
}

int vct_bricks_refresh_leaves(vct_context *ctx, vct_voxels *v, vct_error *err) {
    return refresh_radiance(ctx, v, 0, err);
}

int vct_bricks_info_get(const vct_voxels *v, vct_brick_info *info) {
    if (!v->has_bricks)
        return 0;
    *info = v->brick_info;
    return 1;
}

vct_status vct_bricks_read(vct_context *ctx, const vct_voxels *v, int channel, uint32_t first,
                           uint32_t count, float *out, vct_error *err) {
    const char *stage = "brick read";
    const vct_brick_info *b = &v->brick_info;
    if (!v->has_bricks)
        return vct_fail(err, VCT_ERR_INPUT, "%s: build the bricks first (vct_bricks_build)", stage);
    if (channel < 0 || channel >= channel_count(b) ||
        (uint64_t)first + count > channel_bricks(b, channel))
        return vct_fail(err, VCT_ERR_INPUT,
                        "%s: channel %d, bricks %u..%u: not built (%u bricks, %u directional)",
                        stage, channel, first, first + count, b->bricks, b->directional_bricks);
    if (first < channel_first(b, channel))
        return vct_fail(err, VCT_ERR_INPUT,
                        "%s: bricks %u..%u: anisotropic bricks keep isotropic radiance at the "
                        "leaves only, from brick %u; read the directional channels above",
                        stage, first, first + count, channel_first(b, channel));
    if (channel >= VCT_BRICK_RADIANCE && vct_bricks_radiance_check(v, stage, err))
        return err->status;
    if (count == 0)
        return VCT_OK;
    cl_program p;
    int rc =
        vct_program_get(ctx, "voxel/brick_gather.cl", b->image ? "-DVCT_BRICK_IMAGE" : "", &p, err);
    cl_mem dst = rc == VCT_OK ? vct_buffer_create(ctx, stage, "texels", 27ull * 16 * count,
                                                  CL_MEM_WRITE_ONLY, NULL, err)
                              : NULL;
    cl_mem src = b->image ? v->brick_image[channel] : v->brick_buffer[channel];
    const cl_uint pool[2] = {b->pool[0], b->pool[1]};
    if (rc == VCT_OK)
        rc = dst ? vct_run_kernel(ctx, p, "brick_gather", stage, 27ull * count, err, 5,
                                  VCT_ARG(p, src), VCT_ARG_OF(pool), VCT_ARG_OF(first),
                                  VCT_ARG_OF(count), VCT_ARG(out, dst))
                 : (int)err->status;
    if (rc == VCT_OK)
        rc = vct_buffer_read(ctx, stage, dst, 0, 27ull * 16 * count, out, err);
    vct_buffer_release(ctx, dst);
    return rc;
}

vct_status vct_bricks_sample(vct_context *ctx, const vct_voxels *v, int channel, uint32_t level,
                             const float *points, uint32_t n, float *out, vct_error *err) {
    const char *stage = "brick sample";
    const vct_brick_info *b = &v->brick_info;
    if (!v->has_bricks)
        return vct_fail(err, VCT_ERR_INPUT, "%s: build the bricks first (vct_bricks_build)", stage);
    const uint32_t top = channel >= VCT_BRICK_RADIANCE_DIR0 ? v->info.levels - 1 : v->info.levels;
    if (channel < 0 || channel >= channel_count(b) || level >= top)
        return vct_fail(err, VCT_ERR_INPUT, "%s: channel %d has no bricks at level %u", stage,
                        channel, level);
    if (channel_first(b, channel) && level + 1 < v->info.levels)
        return vct_fail(err, VCT_ERR_INPUT,
                        "%s: level %u: anisotropic bricks keep isotropic radiance at the leaves "
                        "(level %u) only; sample the directional channels above",
                        stage, level, v->info.levels - 1);
    if (channel >= VCT_BRICK_RADIANCE && vct_bricks_radiance_check(v, stage, err))
        return err->status;
    if (n == 0 || b->bricks == 0) {
        memset(out, 0, 16ull * n);
        return VCT_OK;
    }
    cl_program p;
    int rc =
        vct_program_get(ctx, "voxel/brick_gather.cl", b->image ? "-DVCT_BRICK_IMAGE" : "", &p, err);
    cl_mem q = rc == VCT_OK ? vct_buffer_create(ctx, stage, "points", 16ull * n, CL_MEM_READ_ONLY,
                                                (void *)points, err)
                            : NULL;
    cl_mem dst =
        q ? vct_buffer_create(ctx, stage, "samples", 16ull * n, CL_MEM_WRITE_ONLY, NULL, err)
          : NULL;
    cl_mem src = b->image ? v->brick_image[channel] : v->brick_buffer[channel];
    const cl_uint pool[2] = {b->pool[0], b->pool[1]};
    vct_volume_desc vol;
    vct_voxels_volume_desc(v, &vol);
    if (rc == VCT_OK)
        rc = dst ? vct_run_kernel(ctx, p, "brick_probe", stage, n, err, 8, VCT_ARG(p, src),
                                  VCT_ARG_OF(pool), VCT_ARG_OF(v->child), VCT_ARG_OF(vol),
                                  VCT_ARG_OF(level), VCT_ARG(points, q), VCT_ARG_OF(n),
                                  VCT_ARG(out, dst))
                 : (int)err->status;
    if (rc == VCT_OK)
        rc = vct_buffer_read(ctx, stage, dst, 0, 16ull * n, out, err);
    vct_buffer_release(ctx, dst);
    vct_buffer_release(ctx, q);
    return rc;
}

vct_brick_options vct_brick_options_default(void) {
    const vct_brick_options o = {VCT_BRICKS_AUTO, 0, 0};
    return o;
}
