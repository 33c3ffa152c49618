/* vct voxelize: the voxel list, sparse voxel octree and filtered bricks of
 * a scene, lit when it has lights, with counts, memory per structure and
 * time per stage; optionally an image of the voxels ray marched through the
 * octree. */
#include <stdio.h>
#include <string.h>

#include "cli_common.h"
#include "commands.h"

static double mib(uint64_t bytes) {
    return bytes / 1048576.0;
}

static void print_voxels(const vct_voxel_info *v) {
    printf("volume: %u^3 voxels of %g, cube from (%g %g %g), side %g (%s)\n", v->resolution,
           v->side / v->resolution, v->origin[0], v->origin[1], v->origin[2], v->side,
           "vertices snapped to 1/2^18 of the side");
    printf("fragments %u, voxels %u (%.2f fragments per voxel)\n", v->fragments, v->voxels,
           v->voxels ? (double)v->fragments / v->voxels : 0.0);
    printf("octree: %u levels, %u nodes\n", v->levels + 1, v->nodes);
    for (uint32_t l = 0; l <= v->levels; ++l)
        printf("  level %2u (%4u^3): %u nodes\n", l, 1u << l, v->level_nodes[l]);
    const uint64_t dense = 4ull * v->resolution * v->resolution * v->resolution;
    printf("memory: voxels %.2f MiB, nodes %.2f MiB, neighbour links %.2f MiB, "
           "fragments (transient) %.2f MiB\n",
           mib(v->voxel_bytes), mib(v->node_bytes), mib(v->neighbour_bytes),
           mib(v->fragment_bytes));
    printf("        a dense RGBA8 %u^3 texture would take %.2f MiB\n", v->resolution, mib(dense));
}

static void print_bricks(const vct_brick_info *b, uint32_t levels) {
    printf("bricks: %u of 3x3x3 half-float RGBA texels (%s), %u with directional radiance\n",
           b->bricks, b->anisotropic ? "anisotropic" : "isotropic", b->directional_bricks);
    for (uint32_t l = 0; l < levels; ++l)
        printf("  level %2u: %u bricks\n", l, b->level_bricks[l]);
    printf("brick pool: %s; %ux%ux%u bricks per channel\n", b->storage_reason, b->pool[0],
           b->pool[1], b->pool[2]);
    printf("memory: bricks %.2f MiB (%.2f MiB per channel)", mib(b->pool_bytes),
           mib(b->channel_bytes));
    if (b->staging_bytes)
        printf(", plus %.2f MiB of radiance buffers kept for re-filtering", mib(b->staging_bytes));
    printf(", plus %.2f MiB of brick windows kept for re-filtering\n", mib(b->window_bytes));
}

int cmd_voxelize(const cli_options *opt) {
    vct_error err = {0};
    const char *out = opt->output;
    if (out && cli_check_output("vct voxelize", out))
        return 1;
    vct_scene *s = cli_load_scene(opt, &err);
    if (!s)
        return cli_fail(&err);
    cli_print_scene(s, stderr);
    vct_context *ctx = cli_open_context(opt, &err);
    if (!ctx) {
        vct_scene_release(s);
        return cli_fail(&err);
    }
    vct_voxel_options vo;
    cli_voxel_options(opt, 256, &vo);
    vct_voxels *v = vct_voxelize(ctx, s, &vo, &err);
    int rc = v ? vct_octree_build(ctx, v, &err) : err.status;
    /* With lights, inject direct light (shadows through the acceleration structure
     * or the lights' bins) first: the bricks then take every channel in
     * one pass. */
    vct_accel *accel = NULL;
    if (rc == VCT_OK && s->light_count) {
        accel = cli_accel_build(ctx, s, opt, &err);
        rc = accel ? vct_voxels_inject_light(ctx, s, accel, v, &err) : err.status;
    }
    const vct_brick_options bo = {opt->bricks, opt->anisotropic == 1, 0};
    if (rc == VCT_OK)
        rc = vct_bricks_build(ctx, v, &bo, &err);
    vct_image image = {0};
    if (rc == VCT_OK && out)
        rc = vct_render_voxels(ctx, s, v, opt->width, opt->height, &image, &err);
    if (rc == VCT_OK && out)
        rc = cli_make_parent_dir(out, &err);
    if (rc == VCT_OK && out)
        rc = vct_image_write(&image, out, opt->tone.auto_exposure ? 0.0f : opt->tone.exposure,
                             &err); /* shaded voxels: no automatic exposure */
    if (rc == VCT_OK) {
        vct_voxel_info info;
        vct_voxels_info_get(v, &info);
        print_voxels(&info);
        vct_brick_info bricks;
        if (vct_bricks_info_get(v, &bricks))
            print_bricks(&bricks, info.levels);
        cli_print_stats(ctx);
        if (out)
            printf("wrote %s (%dx%d, the voxels seen from the scene camera, %s)\n", out,
                   image.width, image.height,
                   s->light_count ? "their injected radiance" : "albedo under a headlight");
    }
    vct_image_release(&image);
    vct_accel_release(accel);
    vct_voxels_release(v);
    vct_context_release(ctx);
    vct_scene_release(s);
    return rc == VCT_OK ? 0 : cli_fail(&err);
}
