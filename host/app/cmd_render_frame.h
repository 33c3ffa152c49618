/* vct render on one device: one frame, or a sequence of an animation's. */
#ifndef VCT_APP_CMD_RENDER_FRAME_H
#define VCT_APP_CMD_RENDER_FRAME_H

#include "cli_layers.h"
#include "options.h"

/* A rendered frame and what is written beside it. */
typedef struct cli_frame {
    vct_image image, variance;
    vct_aovs aovs;
    cli_layers layers;
    vct_render_result result;
} cli_frame;

/* The scene as it is, through ds, with every output the options ask for
 * (AOV layers, the denoised image), not written. */
int cli_frame_make(vct_context *ctx, vct_device_scene *ds, const vct_scene *s,
                   const cli_options *opt, vct_method method, cli_frame *f, vct_error *err);
void cli_frame_release(cli_frame *f);

/* The scene as it is, through ds, with every output the options ask for
 * (AOV layers, denoising) written to `out`. */
int cli_render_frame(vct_context *ctx, vct_device_scene *ds, const vct_scene *s,
                     const cli_options *opt, vct_method method, const char *out, vct_error *err);
/* What renders each frame of a sequence: make(user, frame, err) renders
 * the scene as posed; ds, where one device scene holds the structures,
 * counts what each frame rebuilt for --stats (NULL: not counted). */
typedef struct cli_frame_source {
    int (*make)(void *user, cli_frame *frame, vct_error *err);
    void *user;
    vct_device_scene *ds;
} cli_frame_source;

/* Frames opt->frames[0] .. [1] of the scene's first animation (those not
 * written yet with --resume): each posed, made by `source` (which keeps
 * what a frame does not move) and written to the name `pattern` gives it
 * (one %d or %0Nd); with --stats, a table of the frames. */
int cli_render_frames(const cli_options *opt, vct_scene *s, const char *pattern,
                      const cli_frame_source *source, vct_error *err);
/* The frames of --frames still to render, in order, into frames (room for
 * all of them): every one, or with --resume those whose files are not
 * there. Refuses a pattern without a number and a scene without an
 * animation. */
int cli_frames_left(const cli_options *opt, const vct_scene *s, const char *pattern, int *frames,
                    int *count, vct_error *err);
/* The file of frame `frame`: the pattern's one %d or %0Nd (N below 10)
 * holds its number. VCT_ERR_INPUT for any other pattern. */
int cli_frame_path(const char *pattern, int frame, char *out, size_t size, vct_error *err);

#endif
