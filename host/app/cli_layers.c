/* Layers beside the image: cone tracing's AOVs, the denoiser's guides. */
#include <stdio.h>
#include <string.h>

#include "cli_common.h"
#include "cli_layers.h"

void cli_layers_add(cli_layers *l, const char *name, const vct_image *image, const char *channels) {
    if (l->count < CLI_MAX_LAYERS)
        l->layer[l->count++] = (vct_exr_layer){name, image, channels};
}

void cli_layers_add_aovs(cli_layers *l, const vct_aovs *a) {
    cli_layers_add(l, "direct", &a->direct, "RGB");
    cli_layers_add(l, "indirect", &a->indirect, "RGB");
    cli_layers_add(l, "specular", &a->specular, "RGB");
    cli_layers_add(l, "ao", &a->ao, "Y");
    cli_layers_add(l, "position", &a->position, "XYZ");
    cli_layers_add(l, "normal", &a->normal, "XYZ");
    cli_layers_add(l, "albedo", &a->albedo, "RGB");
    cli_layers_add(l, "indirect_variance", &a->indirect_variance, "Y");
}

vct_image *cli_layers_own(cli_layers *l) {
    if (l->owned_count == CLI_MAX_LAYERS)
        return NULL;
    vct_image *im = &l->owned[l->owned_count++];
    memset(im, 0, sizeof *im);
    return im;
}

void cli_layers_free(cli_layers *l) {
    for (int i = 0; i < l->owned_count; ++i)
        vct_image_release(&l->owned[i]);
    l->owned_count = l->count = 0;
}

/* Beside a .png or .pfm image: STEM_layer.pfm, ... */
static int write_layer_files(const cli_layers *l, const char *out, vct_error *err) {
    const char *dot = strrchr(out, '.');
    const int stem = dot ? (int)(dot - out) : (int)strlen(out);
    for (int i = 0; i < l->count; ++i) {
        char path[4096];
        snprintf(path, sizeof path, "%.*s_%s.pfm", stem, out, l->layer[i].name);
        int rc = vct_image_write_pfm(l->layer[i].image, path, err);
        if (rc)
            return rc;
        printf("wrote %s (%s, linear)\n", path, l->layer[i].name);
    }
    return VCT_OK;
}

int cli_write_image(const cli_options *opt, const vct_image *image, const cli_layers *l,
                    const char *out, vct_error *err) {
    int rc = cli_make_parent_dir(out, err);
    const char *dot = strrchr(out, '.');
    const int png = dot && strcmp(dot, ".png") == 0, exr = dot && strcmp(dot, ".exr") == 0;
    const int extra = l ? l->count : 0;
    float stops = 0.0f;
    if (rc == VCT_OK && exr) {
        vct_exr_layer layers[CLI_MAX_LAYERS + 1] = {{NULL, image, "RGB"}};
        for (int i = 0; i < extra; ++i)
            layers[1 + i] = l->layer[i];
        rc = vct_image_write_exr(layers, 1 + extra, opt->exr_float ? VCT_EXR_FLOAT : VCT_EXR_HALF,
                                 out, err);
    } else if (rc == VCT_OK) {
        rc = png ? vct_image_write_png_tone(image, out, &opt->tone, &stops, err)
                 : vct_image_write_pfm(image, out, err);
    }
    if (rc == VCT_OK && png)
        printf("wrote %s (%dx%d, exposure %+.2f stops%s, %s curve, sRGB)\n", out, image->width,
               image->height, stops, opt->tone.auto_exposure ? " from the image" : "",
               vct_tone_curve_name(opt->tone.curve));
    else if (rc == VCT_OK)
        printf("wrote %s (%dx%d, linear radiance%s%s)\n", out, image->width, image->height,
               !exr             ? ""
               : opt->exr_float ? ", 32-bit floats"
                                : ", half floats",
               exr && extra ? ", with its layers" : "");
    if (rc == VCT_OK && extra && !exr)
        rc = write_layer_files(l, out, err);
    return rc;
}
