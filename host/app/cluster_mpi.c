/* Joining and leaving the MPI job, rank 0's command line for all, and what
 * the ranks share: their messages, their failures and the bytes they send. */
#include <fcntl.h>
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cluster.h"
#include "cluster_mpi.h"

static int joined, rank, size = 1, thread_level;
static FILE *errors; /* a worker's own stderr, kept for its errors */
static uint64_t sent_bytes;

static int launched_by_mpi(void) {
    return getenv("OMPI_COMM_WORLD_SIZE") || getenv("PMI_SIZE") || getenv("PMIX_RANK");
}

/* Rank 0's arguments, packed one after the other with their NULs, for all. */
static int share_arguments(int *argc, char ***argv) {
    static char *packed;
    static char **args;
    int bytes = 0;
    if (rank == 0)
        for (int i = 0; i < *argc; ++i)
            bytes += (int)strlen((*argv)[i]) + 1;
    MPI_Bcast(&bytes, 1, MPI_INT, 0, MPI_COMM_WORLD);
    packed = malloc((size_t)bytes);
    args = malloc(sizeof(char *) * ((size_t)bytes + 1));
    if (!packed || !args) {
        fprintf(stderr, "vct: out of host memory for the command line\n");
        return 1;
    }
    if (rank == 0)
        for (int i = 0, at = 0; i < *argc; ++i) {
            memcpy(packed + at, (*argv)[i], strlen((*argv)[i]) + 1);
            at += (int)strlen((*argv)[i]) + 1;
        }
    MPI_Bcast(packed, bytes, MPI_CHAR, 0, MPI_COMM_WORLD);
    cli_cluster_count_sent(rank == 0 ? (uint64_t)bytes * (uint64_t)(size - 1) : 0);
    int n = 0;
    for (int at = 0; at < bytes; at += (int)strlen(packed + at) + 1)
        args[n++] = packed + at;
    args[n] = NULL;
    *argc = n;
    *argv = args;
    return 0;
}

int cli_cluster_start(int *argc, char ***argv) {
    if (!launched_by_mpi())
        return 0;
    /* serialized: rank 0 hands out frames from a thread of its own while
     * its main thread renders */
    if (MPI_Init_thread(argc, argv, MPI_THREAD_SERIALIZED, &thread_level) != MPI_SUCCESS) {
        fprintf(stderr, "vct: MPI_Init_thread failed: run under mpirun from Open MPI\n");
        return 1;
    }
    joined = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    if (share_arguments(argc, argv) != 0)
        return 1;
    if (rank > 0) {
        const int fd = dup(2);
        errors = fd >= 0 ? fdopen(fd, "w") : NULL;
        if (!freopen("/dev/null", "w", stdout) || !freopen("/dev/null", "w", stderr))
            return 1;
    }
    return 0;
}

void cli_cluster_end(void) {
    if (joined)
        MPI_Finalize();
    joined = 0;
}

FILE *cli_cluster_errors(const char **tag) {
    static char name[48];
    snprintf(name, sizeof name, size > 1 ? " (rank %d of %d)" : "", rank, size);
    *tag = name;
    return errors ? errors : stderr;
}

int cli_cluster_rank(void) {
    return rank;
}

int cli_cluster_size(void) {
    return size;
}

int cli_cluster_threads(void) {
    return thread_level >= MPI_THREAD_SERIALIZED;
}

void cli_cluster_fail(const char *what, const vct_error *err) {
    char host[MPI_MAX_PROCESSOR_NAME] = "";
    int length = 0;
    MPI_Get_processor_name(host, &length);
    FILE *out = errors ? errors : stderr;
    fprintf(out, "vct (rank %d of %d, %s): %s: %s\n", rank, size, host, what,
            err && err->message[0] ? err->message : "failed");
    fflush(out);
    MPI_Abort(MPI_COMM_WORLD, 1); /* the others would wait for this rank forever */
    exit(1);
}

void cli_cluster_count_sent(uint64_t bytes) {
    __atomic_add_fetch(&sent_bytes, bytes, __ATOMIC_RELAXED);
}

uint64_t cli_cluster_sent(void) {
    return __atomic_load_n(&sent_bytes, __ATOMIC_RELAXED);
}
