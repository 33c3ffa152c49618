/* After a render: the denoiser's guides, written as layers with --aov, and
 * the denoised image with --denoise. */
#include <string.h>

#include "cli_denoise.h"

/* Rays per pixel side for the guides: their edges antialiased as the
 * image's are. */
#define GUIDE_RAYS_PER_AXIS 4u

/* The distance (normal_depth's w) as an image of its own, in r. */
static void depth_image(const vct_image *nd, vct_image *depth) {
    const size_t pixels = (size_t)nd->width * nd->height;
    depth->rgba = malloc(16 * pixels);
    if (!depth->rgba)
        return;
    depth->width = nd->width;
    depth->height = nd->height;
    for (size_t i = 0; i < pixels; ++i) {
        depth->rgba[4 * i] = nd->rgba[4 * i + 3];
        depth->rgba[4 * i + 1] = depth->rgba[4 * i + 2] = 0.0f;
        depth->rgba[4 * i + 3] = 1.0f;
    }
}

int cli_denoise_image(vct_context *ctx, const vct_denoise_guides *g, const vct_image *image,
                      const vct_aovs *aovs, vct_image *out, vct_error *err) {
    const vct_denoise_options o = vct_denoise_options_default();
    if (!aovs || !aovs->indirect.rgba || !g->variance)
        return vct_denoise(ctx, image, g, &o, out, err);
    vct_denoise_guides parts = *g; /* the path tracer's direct and indirect parts */
    parts.indirect = &aovs->indirect;
    return vct_denoise(ctx, image, &parts, &o, out, err);
}

int cli_denoise_outputs(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                        const cli_options *opt, vct_method method, vct_image *image,
                        const vct_image *variance, const vct_aovs *aovs, cli_layers *layers,
                        vct_error *err) {
    const int guide_layers = opt->aov && method != VCT_METHOD_VCT;
    /* cone tracing's render filtered its own indirect light */
    const int filter = opt->denoise && method != VCT_METHOD_VCT;
    if (!filter && !guide_layers)
        return VCT_OK;
    vct_image *albedo = cli_layers_own(layers), *nd = cli_layers_own(layers);
    int rc = vct_render_guides(ctx, s, g, image->width, image->height, GUIDE_RAYS_PER_AXIS, albedo,
                               nd, err);
    if (rc == VCT_OK && opt->aov) {
        vct_image *depth = cli_layers_own(layers);
        depth_image(nd, depth);
        cli_layers_add(layers, "albedo", albedo, "RGB");
        cli_layers_add(layers, "normal", nd, "XYZ");
        if (depth->rgba)
            cli_layers_add(layers, "depth", depth, "Z");
        if (variance && variance->rgba)
            cli_layers_add(layers, "variance", variance, "Y");
    }
    if (rc != VCT_OK || !filter)
        return rc;
    const vct_denoise_guides guides = {albedo, nd, variance && variance->rgba ? variance : NULL,
                                       NULL, 0};
    vct_image denoised;
    rc = cli_denoise_image(ctx, &guides, image, aovs, &denoised, err);
    if (rc != VCT_OK)
        return rc;
    vct_image *noisy = opt->aov ? cli_layers_own(layers) : NULL;
    if (noisy) {
        *noisy = *image; /* the layers free it */
        cli_layers_add(layers, "noisy", noisy, "RGB");
    } else {
        vct_image_release(image);
    }
    *image = denoised;
    return VCT_OK;
}
