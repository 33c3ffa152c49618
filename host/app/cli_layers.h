/* What a render writes beside its image (--aov, --denoise): layers of the
 * EXR file, or PFM files beside a PFM or PNG image. */
#ifndef VCT_APP_CLI_LAYERS_H
#define VCT_APP_CLI_LAYERS_H

#include "options.h"

#define CLI_MAX_LAYERS 16

typedef struct cli_layers {
    vct_exr_layer layer[CLI_MAX_LAYERS];
    int count;
    vct_image owned[CLI_MAX_LAYERS]; /* images made for a layer, freed with it */
    int owned_count;
} cli_layers;

/* Adds a layer of `image` (kept by the caller) named `name`, its channels
 * one letter each from rgba ("RGB", "XYZ", "Y"). */
void cli_layers_add(cli_layers *l, const char *name, const vct_image *image, const char *channels);
/* Adds cone tracing's AOVs. */
void cli_layers_add_aovs(cli_layers *l, const vct_aovs *aovs);
/* An empty image the layers own, or NULL when full. */
vct_image *cli_layers_own(cli_layers *l);
void cli_layers_free(cli_layers *l);

/* The image as EXR or PFM (linear) or PNG (tone mapped), by the name's
 * ending, and a line; the layers in the EXR file, or PFM files beside the
 * others (NAME_layer.pfm). */
int cli_write_image(const cli_options *opt, const vct_image *image, const cli_layers *layers,
                    const char *out, vct_error *err);

#endif
