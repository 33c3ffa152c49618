/* A host program of someone else's: lists the devices, then renders a scene
 * by every method through the installed library and kernels: load,
 * context, device scene, render, write.
 * Usage: vct_consumer SCENE OUT_PREFIX */
#include <stdio.h>
#include <string.h>

#include <vct/vct.h>

static int fail(const vct_error *err) {
    fprintf(stderr, "vct_consumer: %s\n", err->message);
    return 1;
}

/* One method through the device scene: its job, the render, the file. */
static int render(vct_device_scene *ds, vct_method method, const char *prefix, vct_error *err) {
    vct_render_job job = vct_render_job_default(method, 128, 128);
    job.voxel_options.resolution = 64;
    job.pathtrace.spp = 4;
    job.pm.passes = 2;
    job.pm.photons_per_pass = 16384;
    vct_image image = {0};
    int rc = vct_device_scene_render(ds, &job, &image, NULL, err);
    char path[1024];
    snprintf(path, sizeof path, "%s_%s.pfm", prefix, vct_method_name(method));
    if (rc == VCT_OK)
        rc = vct_image_write_pfm(&image, path, err);
    if (rc == VCT_OK)
        printf("wrote %s\n", path);
    vct_image_release(&image);
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
    vct_device_scene *ds = ctx ? vct_device_scene_create(ctx, scene, &err) : NULL;
    int rc = ds ? VCT_OK : (int)err.status;
    const vct_method methods[] = {VCT_METHOD_RAYCAST, VCT_METHOD_WHITTED, VCT_METHOD_PATHTRACE,
                                  VCT_METHOD_PM, VCT_METHOD_VCT};
    for (size_t m = 0; rc == VCT_OK && m < sizeof methods / sizeof *methods; ++m)
        rc = render(ds, methods[m], argv[2], &err);
    vct_device_scene_release(ds);
    vct_context_release(ctx);
    vct_scene_release(scene);
    return rc == VCT_OK ? 0 : fail(&err);
}
