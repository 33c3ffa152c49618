/* Built without MPI: one process, which `mpirun` would only start N times
 * over. Under an MPI launcher that is refused rather than done N times. */
#include <stdio.h>
#include <stdlib.h>

#include "cluster.h"

/* Set by the launchers of Open MPI, MPICH and PMIx-based ones. */
static int launched_by_mpi(void) {
    const char *size = getenv("OMPI_COMM_WORLD_SIZE");
    if (!size)
        size = getenv("PMI_SIZE");
    return size && atoi(size) > 1;
}

int cli_cluster_start(int *argc, char ***argv) {
    (void)argc;
    (void)argv;
    if (!launched_by_mpi())
        return 0;
    fprintf(stderr, "vct: started as one of several MPI processes, but this vct was built "
                    "without MPI: install Open MPI (tools/deps.sh does) and build again\n");
    return 1;
}

void cli_cluster_end(void) {}

FILE *cli_cluster_errors(const char **tag) {
    *tag = "";
    return stderr;
}

int cli_cluster_rank(void) {
    return 0;
}

int cli_cluster_size(void) {
    return 1;
}

int cli_render_cluster(const cli_options *opt, vct_scene *s, vct_method method, const char *out) {
    (void)opt;
    (void)s;
    (void)method;
    (void)out;
    fprintf(stderr, "vct render: built without MPI\n");
    return 1;
}
