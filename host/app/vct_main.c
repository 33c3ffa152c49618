/* vct: command-line front end of the engine. */
#include <stdio.h>
#include <string.h>

#include "commands.h"

int main(int argc, char **argv) {
    cli_options opt;
    if (cli_parse(argc, argv, &opt))
        return 2;
    if (strcmp(opt.command, "devices") == 0)
        return cmd_devices(&opt);
    if (strcmp(opt.command, "info") == 0)
        return cmd_info(&opt);
    if (strcmp(opt.command, "render") == 0)
        return cmd_render(&opt);
    if (strcmp(opt.command, "compare") == 0)
        return cmd_compare(&opt);
    if (strcmp(opt.command, "voxelize") == 0)
        return cmd_voxelize(&opt);
    fprintf(stderr, "vct: unknown command \"%s\"\n", opt.command);
    cli_usage();
    return 2;
}
