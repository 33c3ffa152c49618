/* vct render over several devices (--device 0,2 | all | gpu | cpu). */
#ifndef VCT_APP_CMD_RENDER_GROUP_H
#define VCT_APP_CMD_RENDER_GROUP_H

#include "options.h"

int cli_render_group(const cli_options *opt, const vct_scene *s, vct_method method,
                     const char *out);

#endif
