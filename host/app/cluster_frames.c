/* vct render under mpirun, a sequence: frames are dealt one at a time to
 * whichever rank asks (rank 0 deals from a second thread and renders too),
 * so a slow rank costs only its own frames; rank 0 writes every frame. */
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli_layers.h"
#include "cmd_render_frame.h"
#include "cmd_render_group.h"
#include "cli_common.h"
#include "cluster_render.h"

/* A finished frame, as a worker reports it before asking for the next. */
typedef struct frame_report {
    int32_t index; /* into the frames to render; -1: none yet */
    int32_t width, height, unused;
    double seconds;
} frame_report;

typedef struct dealer {
    member *m;
    const char *pattern;
    const int *frames;
    int count, next;
    pthread_mutex_t lock;
    int *rank_of;    /* per frame, for --stats */
    double *seconds; /* per frame */
} dealer;

/* The next frame to render (an index into frames), or -1. */
static int deal(dealer *d, int rank) {
    pthread_mutex_lock(&d->lock);
    const int k = d->next < d->count ? d->next++ : -1;
    if (k >= 0)
        d->rank_of[k] = rank;
    pthread_mutex_unlock(&d->lock);
    return k;
}

/* mpirun stops rank 0 with SIGTERM when another rank dies: a file being
 * written then is finished (and renamed into place) before it goes, so
 * that no temporary file is left. */
static int writing, stop_signal;

static void stop_after_writes(int sig) {
    if (__atomic_load_n(&writing, __ATOMIC_SEQ_CST) == 0) {
        signal(sig, SIG_DFL);
        raise(sig);
    }
    __atomic_store_n(&stop_signal, sig, __ATOMIC_SEQ_CST);
}

static void write_frame(dealer *d, int k, const vct_image *image, double seconds, int rank) {
    char path[1024];
    vct_error err = {0};
    int rc = cli_frame_path(d->pattern, d->frames[k], path, sizeof path, &err);
    __atomic_add_fetch(&writing, 1, __ATOMIC_SEQ_CST);
    if (rc == VCT_OK)
        rc = cli_write_image(d->m->opt, image, NULL, path, &err);
    const int sig = __atomic_load_n(&stop_signal, __ATOMIC_SEQ_CST);
    if (__atomic_sub_fetch(&writing, 1, __ATOMIC_SEQ_CST) == 0 && sig) {
        signal(sig, SIG_DFL);
        raise(sig);
    }
    if (rc != VCT_OK)
        cli_cluster_fail("writing a frame", &err);
    d->seconds[k] = seconds;
    fprintf(stderr, "frame %d: %s (rank %d, %.2f s)\n", d->frames[k], path, rank, seconds);
}

static void *serve(void *arg) {
    dealer *d = arg;
    for (int left = d->m->size - 1; left > 0;) {
        frame_report r;
        MPI_Status st;
        cluster_wait_for(TAG_READY, &st);
        MPI_Recv(&r, sizeof r, MPI_BYTE, st.MPI_SOURCE, TAG_READY, MPI_COMM_WORLD, &st);
        const int from = st.MPI_SOURCE;
        if (r.index >= 0) {
            vct_image im = {0};
            im.width = r.width;
            im.height = r.height;
            im.rgba = malloc(16 * (size_t)r.width * r.height);
            if (!im.rgba)
                cli_cluster_fail("receiving a frame", &(vct_error){.message = "out of memory"});
            MPI_Recv(im.rgba, 4 * r.width * r.height, MPI_FLOAT, from, TAG_PIXELS, MPI_COMM_WORLD,
                     MPI_STATUS_IGNORE);
            write_frame(d, r.index, &im, r.seconds, from);
            vct_image_release(&im);
        }
        int next = deal(d, from);
        MPI_Send(&next, 1, MPI_INT, from, TAG_FRAME, MPI_COMM_WORLD);
        cli_cluster_count_sent(sizeof next);
        left -= next < 0;
    }
    return NULL;
}

/* The rank's devices up to date with the scene (a group's device scenes
 * commit here; one device's at its render). */
static void render_frame(member *m, dealer *d, int k, cli_frame *f, double *seconds) {
    vct_error err = {0};
    const double t0 = MPI_Wtime();
    int rc = vct_scene_pose(m->scene, 0, (double)d->frames[k] / m->opt->fps, &err);
    if (rc == VCT_OK)
        rc = m->group ? cli_devices_frame(m->group, m->scene, m->opt, m->method, &m->build, f, &err)
                      : cli_frame_make(m->ctx, m->ds, m->scene, m->opt, m->method, f, &err);
    if (rc != VCT_OK)
        cli_cluster_fail("rendering a frame", &err);
    *seconds = MPI_Wtime() - t0;
    m->stats.seconds += *seconds;
    m->stats.work += 1;
}

static void work_frames(member *m, dealer *d) {
    frame_report r = {-1, 0, 0, 0, 0.0};
    cli_frame f;
    memset(&f, 0, sizeof f);
    for (;;) {
        MPI_Send(&r, sizeof r, MPI_BYTE, 0, TAG_READY, MPI_COMM_WORLD);
        cli_cluster_count_sent(sizeof r);
        if (r.index >= 0) {
            const int floats = 4 * f.image.width * f.image.height;
            MPI_Send(f.image.rgba, floats, MPI_FLOAT, 0, TAG_PIXELS, MPI_COMM_WORLD);
            cli_cluster_count_sent(4 * (uint64_t)floats);
            cli_frame_release(&f);
        }
        int k = -1;
        MPI_Recv(&k, 1, MPI_INT, 0, TAG_FRAME, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (k < 0)
            return;
        render_frame(m, d, k, &f, &r.seconds);
        r.index = k;
        r.width = f.image.width;
        r.height = f.image.height;
    }
}

/* Rank 0's own frames, while its other thread serves the workers. */
static void render_own_frames(member *m, dealer *d) {
    for (int k; (k = deal(d, 0)) >= 0;) {
        cli_frame f;
        double seconds;
        render_frame(m, d, k, &f, &seconds);
        write_frame(d, k, &f.image, seconds, 0);
        cli_frame_release(&f);
    }
}

static void print_frames(const dealer *d) {
    fprintf(stderr, "%-7s %-5s %9s\n", "frame", "rank", "seconds");
    for (int k = 0; k < d->count; ++k)
        fprintf(stderr, "%-7d %-5d %9.3f\n", d->frames[k], d->rank_of[k], d->seconds[k]);
}

int cluster_render_sequence(member *m, const char *pattern) {
    vct_error err = {0};
    const int total = m->opt->frames[1] - m->opt->frames[0] + 1;
    dealer d;
    memset(&d, 0, sizeof d);
    d.m = m;
    d.pattern = pattern;
    int *frames = calloc((size_t)total, sizeof *frames);
    d.rank_of = calloc((size_t)total, sizeof *d.rank_of);
    d.seconds = calloc((size_t)total, sizeof *d.seconds);
    if (!frames || !d.rank_of || !d.seconds)
        cli_cluster_fail("a sequence", &(vct_error){.message = "out of host memory"});
    /* rank 0 decides which frames are left (--resume looks at its files) */
    int rc = VCT_OK;
    if (m->rank == 0)
        rc = cli_frames_left(m->opt, m->scene, pattern, frames, &d.count, &err);
    MPI_Bcast(&rc, 1, MPI_INT, 0, MPI_COMM_WORLD);
    if (rc != VCT_OK) {
        free(frames);
        free(d.rank_of);
        free(d.seconds);
        return m->rank == 0 ? cli_fail(&err) : 1;
    }
    MPI_Bcast(&d.count, 1, MPI_INT, 0, MPI_COMM_WORLD);
    MPI_Bcast(frames, d.count, MPI_INT, 0, MPI_COMM_WORLD);
    d.frames = frames;
    if (m->rank == 0 && d.count < total)
        fprintf(stderr, "vct render --resume: %d of %d frames are there; rendering %d\n",
                total - d.count, total, d.count);
    m->work_unit = "frames";
    if (m->rank == 0) {
        signal(SIGTERM, stop_after_writes);
        signal(SIGINT, stop_after_writes);
    }
    pthread_mutex_init(&d.lock, NULL);
    if (m->rank > 0) {
        work_frames(m, &d);
    } else if (!cli_cluster_threads()) {
        serve(&d); /* MPI allows one thread: rank 0 only deals */
    } else {
        pthread_t server;
        if (pthread_create(&server, NULL, serve, &d) != 0)
            cli_cluster_fail("a sequence", &(vct_error){.message = "no thread to deal frames"});
        render_own_frames(m, &d);
        pthread_join(server, NULL);
    }
    pthread_mutex_destroy(&d.lock);
    if (m->rank == 0 && m->opt->stats)
        print_frames(&d);
    free(frames);
    free(d.rank_of);
    free(d.seconds);
    return 0;
}
