/* --video: a sequence's numbered frames encoded into one video by ffmpeg,
 * when it is installed. */
#ifndef VCT_APP_CLI_VIDEO_H
#define VCT_APP_CLI_VIDEO_H

#include "options.h"

/* Before rendering: VCT_ERR_INPUT, with what to do, when --video cannot be
 * made (no ffmpeg on the PATH, frames that are not PNG or EXR, no
 * --frames); VCT_OK when it can or was not asked for. */
int cli_video_check(const cli_options *opt, const char *pattern, vct_error *err);
/* After the frames are written: encodes frames[0] .. [1] of `pattern` into
 * opt->video at opt->fps (written to a temporary name, then renamed). */
int cli_video_make(const cli_options *opt, const char *pattern, vct_error *err);

#endif
