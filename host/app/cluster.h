/* vct across the processes of an MPI job: `mpirun -np N vct render ...`.
 * Every rank loads the scene and commits it on its own device; rank 0 reads
 * the command line (the others take it from rank 0) and writes every file.
 * Built with Open MPI when CMake finds it; without it the program is one
 * process, and these calls say so. */
#ifndef VCT_APP_CLUSTER_H
#define VCT_APP_CLUSTER_H

#include <stdio.h>

#include "options.h"

/* Joins the MPI job when an MPI launcher started this process (else does
 * nothing) and replaces the other ranks' arguments with rank 0's. Ranks
 * other than 0 print nothing but their errors. 0, or 1 after a message. */
int cli_cluster_start(int *argc, char ***argv);
/* Leaves the MPI job. */
void cli_cluster_end(void);
/* Where errors go: stderr, or a worker rank's own stderr (kept when the
 * rest of its output is silenced); tag names the rank (" (rank 2 of 3)"),
 * empty in one process. */
FILE *cli_cluster_errors(const char **tag);
int cli_cluster_rank(void);
int cli_cluster_size(void); /* 1 outside an MPI job */
/* The render across the ranks: a sequence dealt frame by frame, the path
 * tracer's samples split and summed exactly, the other methods in bands.
 * Called on every rank; the exit status. */
int cli_render_cluster(const cli_options *opt, vct_scene *s, vct_method method, const char *out);

#endif
