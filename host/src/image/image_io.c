/* Image files by their name's ending: .exr (exr.c), .pfm and .png
 * (image.c). */
#include <string.h>
#include <strings.h>

#include "runtime/error.h"
#include "vct/image.h"

vct_status vct_image_write_tone(const vct_image *im, const char *path, const vct_tone *tone,
                                vct_error *err) {
    const char *dot = strrchr(path, '.');
    if (dot && strcasecmp(dot, ".pfm") == 0)
        return vct_image_write_pfm(im, path, err);
    if (dot && strcasecmp(dot, ".png") == 0)
        return vct_image_write_png_tone(im, path, tone, NULL, err);
    if (dot && strcasecmp(dot, ".exr") == 0) {
        const vct_exr_layer layer = {NULL, im, "RGB"};
        return vct_image_write_exr(&layer, 1, VCT_EXR_HALF, path, err);
    }
    return vct_fail(err, VCT_ERR_INPUT, "image: %s: the name must end in .exr, .pfm or .png", path);
}

vct_status vct_image_write(const vct_image *im, const char *path, float exposure, vct_error *err) {
    const vct_tone tone = {0, exposure, VCT_TONE_CLIP};
    return vct_image_write_tone(im, path, &tone, err);
}

vct_status vct_image_read(const char *path, vct_image *im, vct_error *err) {
    const char *dot = strrchr(path, '.');
    if (dot && strcasecmp(dot, ".exr") == 0)
        return vct_image_read_exr(path, im, err);
    return vct_image_read_pfm(path, im, err);
}
