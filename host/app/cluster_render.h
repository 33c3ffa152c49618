/* What vct render's MPI files share (cmd_render_cluster.c runs the
 * command; cluster_frames.c, cluster_samples.c and cluster_bands.c split
 * the work): each rank's part, and the messages between ranks. */
#ifndef VCT_APP_CLUSTER_RENDER_H
#define VCT_APP_CLUSTER_RENDER_H

#include <mpi.h>

#include "cluster_mpi.h"
#include "options.h"

enum { TAG_READY = 1, TAG_PIXELS, TAG_FRAME, TAG_ASK, TAG_CHUNK };

/* What each rank did, gathered on rank 0 for --stats. */
typedef struct rank_stats {
    double seconds; /* rendering, wall clock */
    double work;    /* frames, rows or samples */
    uint64_t sent;  /* bytes handed to MPI */
    char host[64], device[96];
} rank_stats;

typedef struct member {
    const cli_options *opt;
    vct_method method;
    vct_scene *scene;
    /* one device: its context and device scene; several (--device's
     * list): a group, with what its devices build */
    vct_context *ctx;
    vct_device_scene *ds;
    vct_group *group;
    vct_plan plan;
    vct_group_build build;
    int rank, size;
    rank_stats stats;
    const char *work_unit; /* what stats.work counts */
} member;

/* Waits for a message of `tag` from any rank. MPI waits by spinning:
 * probing with naps leaves the core to the rendering thread beside this. */
void cluster_wait_for(int tag, MPI_Status *st);
/* The rank's devices up to date with the scene (a group's device scenes
 * commit here; one device's at its render). */
int cluster_prepare(member *m, vct_error *err);

/* A sequence, frames dealt to whichever rank asks; rank 0 writes them. */
int cluster_render_sequence(member *m, const char *pattern);
/* The path tracer: sample chunks dealt as ranks ask, their exact sums
 * reduced; rank 0's image (and, with --denoise, its variance and indirect
 * light in parts) resolved from them. */
int cluster_render_samples(member *m, vct_image *image, vct_image *variance, vct_aovs *parts,
                           vct_render_result *result, vct_error *err);
/* The other methods: bands of rows (photon mapping's in lockstep); rank
 * 0's image put together. */
int cluster_render_bands(member *m, vct_image *image, vct_render_result *result, vct_error *err);

#endif
