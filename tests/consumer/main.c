/* A host program of someone else's: lists the devices, then renders a scene
 * by ray casting and by voxel cone tracing through the installed library
 * and kernels. Usage: vct_consumer SCENE OUT_PREFIX */
#include <stdio.h>
#include <string.h>

#include <vct/vct.h>

static int fail(const vct_error *err) {
    fprintf(stderr, "vct_consumer: %s\n", err->message);
    return 1;
}

static int render(vct_context *ctx, const vct_scene *scene, const vct_accel *accel,
                  vct_method method, const char *prefix, vct_error *err) {
    vct_render_job job = vct_render_job_default(method, 128, 128);
    job.scene = scene;
    job.accel = accel;
    vct_voxels *voxels = NULL;
    vct_plan plan;
    int rc = VCT_OK;
    if (method == VCT_METHOD_VCT) {
        vct_plan_make(scene, NULL, &plan);
        vct_voxel_options vo = {0};
        vo.resolution = 64;
        const vct_brick_options bo = {VCT_BRICKS_AUTO, 0, 0}; /* isotropic, as vct render */
        const vct_cone_settings cones = vct_cone_settings_default();
        rc = vct_vct_prepare(ctx, scene, accel, &plan, &vo, &bo, VCT_DEFAULT_BOUNCES, &cones,
                             &voxels, err);
        job.voxels = voxels;
        job.plan = &plan;
    }
    vct_image image = {0};
    if (rc == VCT_OK)
        rc = vct_render(ctx, &job, &image, NULL, err);
    char path[1024];
    snprintf(path, sizeof path, "%s_%s.pfm", prefix, vct_method_name(method));
    if (rc == VCT_OK)
        rc = vct_image_write_pfm(&image, path, err);
    if (rc == VCT_OK)
        printf("wrote %s\n", path);
    vct_image_free(&image);
    vct_voxels_free(voxels);
    return rc;
}

int main(int argc, char **argv) {
    if (argc != 3) {
        fprintf(stderr, "usage: vct_consumer SCENE OUT_PREFIX\n");
        return 2;
    }
    printf("vct %s (header %s), kernel ABI %d, kernels from %s\n", vct_version(),
           VCT_VERSION_STRING, vct_kernel_abi_version(), vct_kernel_source_dir());
    vct_error err = {0};
    vct_device_info devices[16];
    const int n = vct_list_devices(devices, 16, &err);
    if (n < 0)
        return fail(&err);
    for (int i = 0; i < n; ++i)
        printf("device %d: %s (%s)\n", devices[i].index, devices[i].name, devices[i].platform);
    vct_scene *scene = vct_scene_load(argv[1], &err);
    if (!scene)
        return fail(&err);
    vct_context *ctx = vct_context_create(NULL, &err);
    vct_accel *accel = ctx ? vct_accel_build(ctx, scene, NULL, &err) : NULL;
    int rc = accel ? VCT_OK : (int)err.status;
    if (rc == VCT_OK)
        rc = render(ctx, scene, accel, VCT_METHOD_RAYCAST, argv[2], &err);
    if (rc == VCT_OK)
        rc = render(ctx, scene, accel, VCT_METHOD_VCT, argv[2], &err);
    vct_accel_free(accel);
    vct_context_destroy(ctx);
    vct_scene_free(scene);
    return rc == VCT_OK ? 0 : fail(&err);
}
