/* OpenEXR files through OpenEXR's C library (OpenEXRCore): linear half or
 * float channels, the image as R, G, B and each layer as name.R, name.G, ...
 * as compositors read them. Written to a temporary name and renamed by the
 * library, so a failure leaves nothing. */
#include <OpenEXR/openexr.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "runtime/error.h"
#include "vct/image.h"

/* A layer's channel name, "R" or "direct.R", and where its values are. */
typedef struct exr_source {
    char name[64];
    const float *values; /* the component, in rgba pixels */
} exr_source;

static int exr_fail(vct_error *err, exr_result_t rc, const char *what, const char *path) {
    return vct_fail(err, VCT_ERR_IO, "image: OpenEXR: %s %s failed: %s", what, path,
                    exr_get_default_error_message(rc));
}

static int collect_sources(const vct_exr_layer *layers, int count, exr_source *src, int max, int *n,
                           vct_error *err) {
    *n = 0;
    for (int l = 0; l < count; ++l) {
        const vct_exr_layer *layer = &layers[l];
        const char *channels = layer->channels ? layer->channels : "RGB";
        const size_t len = strlen(channels);
        if (len < 1 || len > 4)
            return vct_fail(err, VCT_ERR_INPUT, "image: EXR layer channels \"%s\": 1 to 4",
                            channels);
        if (layer->image->width != layers[0].image->width ||
            layer->image->height != layers[0].image->height)
            return vct_fail(err, VCT_ERR_INPUT, "image: EXR layer \"%s\" is %dx%d, not %dx%d",
                            layer->name ? layer->name : "", layer->image->width,
                            layer->image->height, layers[0].image->width, layers[0].image->height);
        for (size_t c = 0; c < len; ++c) {
            if (*n == max)
                return vct_fail(err, VCT_ERR_INPUT, "image: more than %d EXR channels", max);
            exr_source *s = &src[(*n)++];
            if (layer->name && *layer->name)
                snprintf(s->name, sizeof s->name, "%s.%c", layer->name, channels[c]);
            else
                snprintf(s->name, sizeof s->name, "%c", channels[c]);
            s->values = layer->image->rgba + c;
        }
    }
    return VCT_OK;
}

static const exr_source *find_source(const exr_source *src, int n, const char *name) {
    for (int i = 0; i < n; ++i)
        if (strcmp(src[i].name, name) == 0)
            return &src[i];
    return NULL;
}

/* Our side of a channel: one float of each rgba pixel, rows of `width`. */
static void rgba_float_layout(exr_coding_channel_info_t *ch, int width) {
    ch->user_data_type = EXR_PIXEL_FLOAT;
    ch->user_bytes_per_element = 4;
    ch->user_pixel_stride = 16;
    ch->user_line_stride = 16 * width;
}

/* Encodes every chunk of scanlines. */
static exr_result_t write_chunks(exr_context_t ctx, const exr_source *src, int n, int width,
                                 int height) {
    int32_t lines = 1;
    exr_result_t rc = exr_get_scanlines_per_chunk(ctx, 0, &lines);
    for (int y = 0; rc == EXR_ERR_SUCCESS && y < height; y += lines) {
        exr_chunk_info_t chunk;
        exr_encode_pipeline_t encode;
        memset(&encode, 0, sizeof encode);
        rc = exr_write_scanline_chunk_info(ctx, 0, y, &chunk);
        if (rc == EXR_ERR_SUCCESS)
            rc = exr_encoding_initialize(ctx, 0, &chunk, &encode);
        for (int c = 0; rc == EXR_ERR_SUCCESS && c < encode.channel_count; ++c) {
            exr_coding_channel_info_t *ch = &encode.channels[c];
            const exr_source *s = find_source(src, n, ch->channel_name);
            rgba_float_layout(ch, width);
            ch->encode_from_ptr = (const uint8_t *)(s->values + 4 * (size_t)chunk.start_y * width);
        }
        if (rc == EXR_ERR_SUCCESS)
            rc = exr_encoding_choose_default_routines(ctx, 0, &encode);
        if (rc == EXR_ERR_SUCCESS)
            rc = exr_encoding_run(ctx, 0, &encode);
        exr_encoding_destroy(ctx, &encode);
    }
    return rc;
}

vct_status vct_image_write_exr(const vct_exr_layer *layers, int count, vct_exr_pixel pixel,
                               const char *path, vct_error *err) {
    enum { MAX_CHANNELS = 64 };
    exr_source src[MAX_CHANNELS];
    int n = 0;
    if (count < 1)
        return vct_fail(err, VCT_ERR_INPUT, "image: an EXR file needs at least one layer");
    int rc = collect_sources(layers, count, src, MAX_CHANNELS, &n, err);
    if (rc)
        return rc;
    const int width = layers[0].image->width, height = layers[0].image->height;
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    exr_context_t ctx = NULL;
    exr_result_t xr = exr_start_write(&ctx, path, EXR_INTERMEDIATE_TEMP_FILE, &init);
    if (xr != EXR_ERR_SUCCESS)
        return exr_fail(err, xr, "creating", path);
    int part = 0;
    xr = exr_add_part(ctx, "rgba", EXR_STORAGE_SCANLINE, &part);
    if (xr == EXR_ERR_SUCCESS)
        xr = exr_initialize_required_attr_simple(ctx, part, width, height, EXR_COMPRESSION_ZIP);
    const exr_pixel_type_t type = pixel == VCT_EXR_FLOAT ? EXR_PIXEL_FLOAT : EXR_PIXEL_HALF;
    for (int i = 0; xr == EXR_ERR_SUCCESS && i < n; ++i)
        xr = exr_add_channel(ctx, part, src[i].name, type, EXR_PERCEPTUALLY_LINEAR, 1, 1);
    if (xr == EXR_ERR_SUCCESS)
        xr = exr_write_header(ctx);
    if (xr == EXR_ERR_SUCCESS)
        xr = write_chunks(ctx, src, n, width, height);
    if (xr != EXR_ERR_SUCCESS) {
        /* Freed without its temporary file becoming `path`. */
        exr_finish(&ctx);
        return exr_fail(err, xr, "writing", path);
    }
    xr = exr_finish(&ctx);
    return xr == EXR_ERR_SUCCESS ? VCT_OK : exr_fail(err, xr, "finishing", path);
}

/* Decodes R, G and B of every chunk into rgba. */
static exr_result_t read_chunks(exr_context_t ctx, float *rgba, int width, int height, int32_t y0) {
    int32_t lines = 1;
    exr_result_t rc = exr_get_scanlines_per_chunk(ctx, 0, &lines);
    for (int y = 0; rc == EXR_ERR_SUCCESS && y < height; y += lines) {
        exr_chunk_info_t chunk;
        exr_decode_pipeline_t decode;
        memset(&decode, 0, sizeof decode);
        rc = exr_read_scanline_chunk_info(ctx, 0, y0 + y, &chunk);
        if (rc == EXR_ERR_SUCCESS)
            rc = exr_decoding_initialize(ctx, 0, &chunk, &decode);
        for (int c = 0; rc == EXR_ERR_SUCCESS && c < decode.channel_count; ++c) {
            exr_coding_channel_info_t *ch = &decode.channels[c];
            const char *names = "RGB";
            const char *at =
                strlen(ch->channel_name) == 1 ? strchr(names, ch->channel_name[0]) : NULL;
            if (!at || !*at)
                continue; /* left NULL: not decoded */
            rgba_float_layout(ch, width);
            ch->decode_to_ptr =
                (uint8_t *)(rgba + 4 * (size_t)(chunk.start_y - y0) * width + (at - names));
        }
        if (rc == EXR_ERR_SUCCESS)
            rc = exr_decoding_choose_default_routines(ctx, 0, &decode);
        if (rc == EXR_ERR_SUCCESS)
            rc = exr_decoding_run(ctx, 0, &decode);
        exr_decoding_destroy(ctx, &decode);
    }
    return rc;
}

vct_status vct_image_read_exr(const char *path, vct_image *image, vct_error *err) {
    memset(image, 0, sizeof *image);
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    exr_context_t ctx = NULL;
    exr_result_t xr = exr_start_read(&ctx, path, &init);
    if (xr != EXR_ERR_SUCCESS)
        return exr_fail(err, xr, "reading", path);
    exr_attr_box2i_t box;
    exr_storage_t storage = EXR_STORAGE_LAST_TYPE;
    const exr_attr_chlist_t *channels = NULL;
    xr = exr_get_data_window(ctx, 0, &box);
    if (xr == EXR_ERR_SUCCESS)
        xr = exr_get_storage(ctx, 0, &storage);
    if (xr == EXR_ERR_SUCCESS)
        xr = exr_get_channels(ctx, 0, &channels);
    if (xr != EXR_ERR_SUCCESS) {
        exr_finish(&ctx);
        return exr_fail(err, xr, "reading", path);
    }
    int has = 0;
    for (int c = 0; c < channels->num_channels; ++c) {
        const char *name = channels->entries[c].name.str;
        has |= (strcmp(name, "R") == 0) | (strcmp(name, "G") == 0) << 1 |
               (strcmp(name, "B") == 0) << 2;
    }
    const long long w = (long long)box.max.x - box.min.x + 1,
                    h = (long long)box.max.y - box.min.y + 1;
    if (storage != EXR_STORAGE_SCANLINE || has != 7 || w < 1 || h < 1 || w > 65536 || h > 65536) {
        exr_finish(&ctx);
        return vct_fail(err, VCT_ERR_INPUT,
                        "image: %s: vct reads scanline EXR files with R, G and B channels", path);
    }
    image->width = (int)w;
    image->height = (int)h;
    image->rgba = calloc((size_t)(w * h), 16);
    if (!image->rgba) {
        exr_finish(&ctx);
        return vct_fail(err, VCT_ERR_MEMORY, "image: out of host memory reading %s", path);
    }
    xr = read_chunks(ctx, image->rgba, image->width, image->height, box.min.y);
    exr_finish(&ctx);
    if (xr != EXR_ERR_SUCCESS) {
        vct_image_release(image);
        return exr_fail(err, xr, "decoding", path);
    }
    for (size_t i = 0; i < (size_t)(w * h); ++i)
        image->rgba[4 * i + 3] = 1.0f;
    return VCT_OK;
}
