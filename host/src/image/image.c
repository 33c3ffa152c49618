/* Image files: PFM (raw linear radiance) and PNG (tone mapped, tone.c, and
 * sRGB encoded).
 * Both are written to a temporary name and renamed, so a failure leaves
 * nothing half-written. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#include <stb/stb_image_write.h>

#include "runtime/error.h"

static int finish_file(FILE *f, const char *tmp, const char *path, vct_error *err) {
    int ok = !ferror(f);
    ok = (fclose(f) == 0) && ok;
    if (!ok || rename(tmp, path) != 0) {
        remove(tmp);
        return vct_fail(err, VCT_ERR_IO, "image: could not write %s", path);
    }
    return VCT_OK;
}

vct_status vct_image_write_pfm(const vct_image *im, const char *path, vct_error *err) {
    char tmp[4096];
    snprintf(tmp, sizeof tmp, "%s.tmp%d", path, (int)getpid());
    FILE *f = fopen(tmp, "wb");
    if (!f)
        return vct_fail(err, VCT_ERR_IO, "image: cannot create %s", path);
    /* Negative scale: little-endian. Rows go bottom to top. */
    fprintf(f, "PF\n%d %d\n-1.0\n", im->width, im->height);
    float *row = malloc(12ull * im->width);
    for (int y = im->height - 1; row && y >= 0; --y) {
        for (int x = 0; x < im->width; ++x)
            memcpy(&row[3 * x], &im->rgba[4 * ((size_t)y * im->width + x)], 12);
        fwrite(row, 12, (size_t)im->width, f);
    }
    if (!row) {
        fclose(f);
        remove(tmp);
        return vct_fail(err, VCT_ERR_MEMORY, "image: out of host memory");
    }
    free(row);
    return finish_file(f, tmp, path, err);
}

static unsigned char srgb8(float display) {
    if (!(display > 0.0f))
        return 0;
    if (display >= 1.0f)
        return 255;
    float s =
        display <= 0.0031308f ? 12.92f * display : 1.055f * powf(display, 1.0f / 2.4f) - 0.055f;
    return (unsigned char)lrintf(s * 255.0f);
}

static void write_to_file(void *context, void *data, int size) {
    fwrite(data, 1, (size_t)size, (FILE *)context);
}

vct_status vct_image_write_png_tone(const vct_image *im, const char *path, const vct_tone *tone,
                                    float *applied, vct_error *err) {
    size_t pixels = (size_t)im->width * im->height;
    unsigned char *rgb = malloc(3 * pixels);
    if (!rgb)
        return vct_fail(err, VCT_ERR_MEMORY, "image: out of host memory");
    const float stops = vct_tone_exposure(tone, im->rgba, pixels);
    if (applied)
        *applied = stops;
    const float scale = exp2f(stops);
    for (size_t i = 0; i < pixels; ++i)
        for (int c = 0; c < 3; ++c)
            rgb[3 * i + c] = srgb8(vct_tone_curve_apply(tone->curve, im->rgba[4 * i + c] * scale));
    char tmp[4096];
    snprintf(tmp, sizeof tmp, "%s.tmp%d", path, (int)getpid());
    FILE *f = fopen(tmp, "wb");
    if (!f) {
        free(rgb);
        return vct_fail(err, VCT_ERR_IO, "image: cannot create %s", path);
    }
    int ok = stbi_write_png_to_func(write_to_file, f, im->width, im->height, 3, rgb, im->width * 3);
    free(rgb);
    if (!ok) {
        fclose(f);
        remove(tmp);
        return vct_fail(err, VCT_ERR_IO, "image: PNG encoding of %s failed", path);
    }
    return finish_file(f, tmp, path, err);
}

vct_status vct_image_write_png(const vct_image *im, const char *path, float exposure,
                               vct_error *err) {
    const vct_tone tone = {0, exposure, VCT_TONE_CLIP};
    return vct_image_write_png_tone(im, path, &tone, NULL, err);
}

vct_status vct_image_read_pfm(const char *path, vct_image *im, vct_error *err) {
    memset(im, 0, sizeof *im);
    FILE *f = fopen(path, "rb");
    if (!f)
        return vct_fail(err, VCT_ERR_IO, "image: cannot read %s", path);
    char magic[3] = {0};
    int w = 0, h = 0;
    float scale = 0.0f;
    int ok = fscanf(f, "%2s %d %d %f", magic, &w, &h, &scale) == 4 && fgetc(f) != EOF;
    int channels = strcmp(magic, "PF") == 0 ? 3 : (strcmp(magic, "Pf") == 0 ? 1 : 0);
    if (!ok || !channels || w <= 0 || h <= 0 || w > 65536 || h > 65536 || scale >= 0.0f) {
        fclose(f);
        return vct_fail(err, VCT_ERR_INPUT,
                        "image: %s is not a little-endian PFM (PF or Pf header)", path);
    }
    im->width = w;
    im->height = h;
    im->rgba = malloc(16ull * w * h);
    float *row = malloc(4ull * channels * w);
    for (int y = h - 1; ok && im->rgba && row && y >= 0; --y) {
        ok = fread(row, 4ull * channels, (size_t)w, f) == (size_t)w;
        for (int x = 0; ok && x < w; ++x) {
            float *px = &im->rgba[4 * ((size_t)y * w + x)];
            for (int c = 0; c < 3; ++c)
                px[c] = row[channels == 3 ? 3 * x + c : x];
            px[3] = 1.0f;
        }
    }
    free(row);
    fclose(f);
    if (!ok || !im->rgba) {
        vct_image_release(im);
        return vct_fail(err, VCT_ERR_INPUT, "image: %s is truncated", path);
    }
    return VCT_OK;
}

void vct_image_release(vct_image *image) {
    free(image->rgba);
    image->rgba = NULL;
}
