/* vct render over several devices (--device 0,2 | all | gpu | cpu). */
#ifndef VCT_APP_CMD_RENDER_GROUP_H
#define VCT_APP_CMD_RENDER_GROUP_H

#include "cmd_render_frame.h"
#include "options.h"

/* The group for --device's list, its devices named on stderr. */
vct_group *cli_devices_open(const cli_options *opt, vct_error *err);
/* What every device builds, as the options say (plan: cone tracing's). */
void cli_devices_build(const cli_options *opt, vct_method method, const vct_plan *plan,
                       vct_group_build *build);
/* --denoise after the devices' frame: on the first active device, with
 * guides of its own, so the image does not depend on how the frame was
 * split. */
int cli_devices_denoise(vct_group *g, const vct_scene *s, const cli_options *opt, vct_method method,
                        vct_image *image, const vct_image *variance, const vct_aovs *parts,
                        vct_error *err);
/* A frame on the group: prepared (the device scenes rebuild what changed),
 * rendered, denoised as asked. */
int cli_devices_frame(vct_group *g, const vct_scene *s, const cli_options *opt, vct_method method,
                      const vct_group_build *build, cli_frame *f, vct_error *err);
/* vct render over the group: a frame, or the frames of --frames. */
int cli_render_group(const cli_options *opt, vct_scene *s, vct_method method, const char *out);

#endif
