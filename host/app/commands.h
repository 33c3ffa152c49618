/* The vct subcommands. Each returns a process exit code. */
#ifndef VCT_APP_COMMANDS_H
#define VCT_APP_COMMANDS_H

#include "options.h"

int cmd_devices(const cli_options *opt);
int cmd_info(const cli_options *opt);
int cmd_render(const cli_options *opt);
int cmd_compare(const cli_options *opt);
int cmd_voxelize(const cli_options *opt);
int cmd_compile(const cli_options *opt);

#endif
