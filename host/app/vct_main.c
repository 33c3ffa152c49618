/* vct: command-line front end of the engine. */
#include <stdio.h>
#include <string.h>

#include "cluster.h"
#include "commands.h"
#include "vct/version.h"

static int run(int argc, char **argv) {
    const char *first = argc > 1 ? argv[1] : "";
    if (argc < 2 || strcmp(first, "-h") == 0 || strcmp(first, "--help") == 0) {
        cli_print_commands(argc < 2 ? stderr : stdout);
        return argc < 2 ? 2 : 0;
    }
    if (strcmp(first, "--version") == 0) {
        printf("vct %s (library %s, kernel interface %d)\n", VCT_VERSION_STRING, vct_version(),
               vct_kernel_abi_version());
        return 0;
    }
    if (strcmp(first, "--reference") == 0) {
        cli_print_reference(stdout);
        return 0;
    }
    for (const cli_command *const *c = vct_commands; *c; ++c) {
        if (strcmp((*c)->name, first) != 0)
            continue;
        /* under mpirun only render is shared; rank 0 runs the others alone */
        if (cli_cluster_rank() > 0 && strcmp(first, "render") != 0)
            return 0;
        cli_options opt;
        const int rc = cli_parse(*c, "vct", argc - 1, argv + 1, &opt);
        return rc < 0 ? 0 : rc ? rc : (*c)->run(&opt);
    }
    fprintf(stderr,
            "vct: unknown command \"%s\" (commands: devices, info, render, voxelize, "
            "compare; see vct --help)\n",
            first);
    return 2;
}

int main(int argc, char **argv) {
    if (cli_cluster_start(&argc, &argv) != 0)
        return 1;
    const int rc = run(argc, argv);
    cli_cluster_end();
    return rc;
}
