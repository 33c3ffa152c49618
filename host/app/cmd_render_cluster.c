/* vct render across the ranks of an MPI job. Each rank renders on its own
 * device through its own device scene; rank 0 writes every file.
 * - A sequence: frames are dealt one at a time to the rank that asks
 *   (rank 0 deals from a thread of its own and renders too), so a slow
 *   rank costs only its own frames; each frame is rendered whole.
 * - The path tracer: the sample sequence is dealt in chunks to whichever
 *   rank asks, each rank sums its chunks exactly (vct/partial.h), and the
 *   sums add in any order, so the image is one process's, bit for bit.
 * - The other methods: bands of rows (with the halos vct_band_shape asks
 *   for) dealt to whichever rank asks; photon mapping: a band per rank, the
 *   bands agreeing on their radii pass by pass. */
#include <mpi.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cli_common.h"
#include "cli_denoise.h"
#include "cli_layers.h"
#include "cluster.h"
#include "cluster_mpi.h"
#include "cmd_render_frame.h"
#include "cmd_render_group.h"
#include "cmd_render_vct.h"

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

/* ---- a sequence, frame by frame ----------------------------------------- */

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

/* Waits for a message of `tag` from any rank. MPI waits by spinning:
 * probing with naps leaves the core to the rendering thread beside this. */
static void wait_for(int tag, MPI_Status *st) {
    for (int ready = 0; !ready;) {
        MPI_Iprobe(MPI_ANY_SOURCE, tag, MPI_COMM_WORLD, &ready, st);
        if (!ready)
            nanosleep(&(struct timespec){0, 1000000}, NULL);
    }
}

/* Rank 0's other thread: takes each worker's frame, writes it, and deals
 * the worker its next, until every worker was told there is none. */
static void *serve(void *arg) {
    dealer *d = arg;
    for (int left = d->m->size - 1; left > 0;) {
        frame_report r;
        MPI_Status st;
        wait_for(TAG_READY, &st);
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
static int member_prepare(member *m, vct_error *err) {
    return m->group ? vct_group_prepare(m->group, m->scene, &m->build, err) : VCT_OK;
}

/* Poses and renders frame k of the list. */
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

static int render_sequence(member *m, const char *pattern) {
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
        rc = cli_frames_todo(m->opt, m->scene, pattern, frames, &d.count, &err);
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

/* ---- one frame: the path tracer's samples -------------------------------- */

static void add_sums(void *in, void *inout, int *len, MPI_Datatype *type) {
    (void)type;
    vct_sample_sums_add_words(inout, in, (size_t)*len);
}

/* The sample sequence, dealt in chunks to whichever rank asks. */
typedef struct chunk_dealer {
    member *m;
    const vct_render_job *job;
    pthread_mutex_t lock;
    uint32_t next, end, size;
    vct_sample_sums sums; /* this rank's chunks, added */
} chunk_dealer;

/* The next chunk, {first, count}; count 0: none left. */
static void chunk_take(chunk_dealer *c, uint32_t chunk[2]) {
    pthread_mutex_lock(&c->lock);
    chunk[0] = c->next;
    chunk[1] = c->end - c->next < c->size ? c->end - c->next : c->size;
    c->next += chunk[1];
    pthread_mutex_unlock(&c->lock);
}

/* Rank 0's other thread: a chunk to each rank that asks, until every
 * worker was told there is none. */
static void *serve_chunks(void *arg) {
    chunk_dealer *c = arg;
    for (int left = c->m->size - 1; left > 0;) {
        MPI_Status st;
        int unused;
        wait_for(TAG_ASK, &st);
        MPI_Recv(&unused, 1, MPI_INT, st.MPI_SOURCE, TAG_ASK, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        uint32_t chunk[2];
        chunk_take(c, chunk);
        MPI_Send(chunk, 2, MPI_UINT32_T, st.MPI_SOURCE, TAG_CHUNK, MPI_COMM_WORLD);
        cli_cluster_count_sent(sizeof chunk);
        left -= chunk[1] == 0;
    }
    return NULL;
}

/* Renders a chunk and adds it to this rank's sums. */
static void render_chunk(chunk_dealer *c, const uint32_t chunk[2]) {
    member *m = c->m;
    vct_error err = {0};
    vct_sample_sums part;
    const double t0 = MPI_Wtime();
    int rc = m->group
                 ? vct_group_render_samples(m->group, c->job, chunk[0], chunk[1], &part, &err)
                 : vct_device_scene_render_samples(m->ds, c->job, chunk[0], chunk[1], &part, &err);
    if (rc == VCT_OK)
        rc = vct_sample_sums_add(&c->sums, &part, &err);
    vct_sample_sums_release(&part);
    if (rc != VCT_OK)
        cli_cluster_fail("path tracing", &err);
    m->stats.seconds += MPI_Wtime() - t0;
    m->stats.work += chunk[1];
}

/* This rank's chunks: asked of rank 0, or (rank 0) taken beside the thread
 * that deals them to the others. */
static void render_chunks(chunk_dealer *c) {
    member *m = c->m;
    uint32_t chunk[2];
    if (m->rank > 0) {
        for (;;) {
            const int ask = 0;
            MPI_Send(&ask, 1, MPI_INT, 0, TAG_ASK, MPI_COMM_WORLD);
            MPI_Recv(chunk, 2, MPI_UINT32_T, 0, TAG_CHUNK, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            cli_cluster_count_sent(sizeof ask);
            if (!chunk[1])
                return;
            render_chunk(c, chunk);
        }
    }
    if (!cli_cluster_threads()) {
        serve_chunks(c); /* MPI allows one thread: rank 0 only deals */
        return;
    }
    pthread_t server;
    if (pthread_create(&server, NULL, serve_chunks, c) != 0)
        cli_cluster_fail("path tracing", &(vct_error){.message = "no thread to deal samples"});
    for (chunk_take(c, chunk); chunk[1]; chunk_take(c, chunk))
        render_chunk(c, chunk);
    pthread_join(server, NULL);
}

/* Rank 0's image from everyone's sums, resolved. The samples are dealt in
 * chunks as ranks ask; the sums are exact, so the order makes no
 * difference. */
static int render_samples(member *m, vct_image *image, vct_image *variance,
                          vct_render_result *result, vct_error *err) {
    vct_render_job job = cli_render_job(m->opt, m->method, m->scene);
    const uint32_t spp = job.pathtrace.spp;
    const double t0 = MPI_Wtime();
    chunk_dealer c;
    memset(&c, 0, sizeof c);
    c.m = m;
    c.job = &job;
    c.end = spp;
    c.size = spp / (4u * (uint32_t)m->size) ? spp / (4u * (uint32_t)m->size) : 1u;
    const size_t bytes = vct_sample_sums_bytes(job.width, job.height);
    c.sums.width = job.width;
    c.sums.height = job.height;
    c.sums.data = calloc(bytes / 8, 8);
    if (!c.sums.data)
        cli_cluster_fail("path tracing", &(vct_error){.message = "out of host memory"});
    int rc = member_prepare(m, err);
    if (rc != VCT_OK)
        cli_cluster_fail("path tracing", err);
    m->work_unit = "samples";
    pthread_mutex_init(&c.lock, NULL);
    render_chunks(&c);
    pthread_mutex_destroy(&c.lock);
    vct_sample_sums total = c.sums;
    total.data = m->rank == 0 ? malloc(bytes) : NULL;
    if (m->rank == 0 && !total.data)
        cli_cluster_fail("path tracing", &(vct_error){.message = "out of host memory"});
    MPI_Datatype pair;
    MPI_Type_contiguous(16, MPI_BYTE, &pair);
    MPI_Type_commit(&pair);
    MPI_Op add;
    MPI_Op_create(add_sums, 1, &add);
    MPI_Reduce(c.sums.data, total.data, (int)(bytes / 16), pair, add, 0, MPI_COMM_WORLD);
    MPI_Reduce(&c.sums.discarded, &total.discarded, 1, MPI_UINT32_T, MPI_SUM, 0, MPI_COMM_WORLD);
    cli_cluster_count_sent(m->rank ? bytes + 4 : 0);
    MPI_Op_free(&add);
    MPI_Type_free(&pair);
    vct_sample_sums_release(&c.sums);
    if (m->rank > 0)
        return VCT_OK;
    total.samples = spp;
    if (m->opt->denoise)
        job.pathtrace.variance = variance;
    rc = m->group ? vct_group_resolve_samples(m->group, &job, &total, image, err)
                  : vct_device_scene_resolve_samples(m->ds, &job, &total, image, err);
    memset(result, 0, sizeof *result);
    result->method = m->method;
    result->spp = spp;
    result->discarded = total.discarded;
    result->seconds = MPI_Wtime() - t0;
    vct_sample_sums_release(&total);
    return rc;
}

/* ---- one frame: bands of rows -------------------------------------------- */

/* Photon mapping: every band's largest radii of this pass, the largest of
 * all of them. */
static int agree_on_radii(void *user, uint32_t pass, uint32_t radius_bits[2]) {
    (void)user;
    (void)pass;
    uint32_t mine[2] = {radius_bits[0], radius_bits[1]};
    /* non-negative floats order as their bits do */
    MPI_Allreduce(mine, radius_bits, 2, MPI_UINT32_T, MPI_MAX, MPI_COMM_WORLD);
    cli_cluster_count_sent(sizeof mine);
    return 0;
}

/* Rows [first, end) of rank r: whole units of the band alignment, the
 * image's last row with the units above it where it is a row of corners. */
static void band_of(const vct_render_job *job, int r, int size, int *first, int *end) {
    int align, above, below;
    vct_band_shape(job, &align, &above, &below);
    const int h = job->height, edge_row = below == 1 && h > 1;
    const int units = (h - edge_row + align - 1) / align;
    *first = (int)((int64_t)units * r / size) * align;
    *end = r == size - 1 ? h : (int)((int64_t)units * (r + 1) / size) * align;
    *first = *first < h ? *first : h;
    *end = *end < h ? *end : h;
}

/* Rows [first, end) of the job's image into *rows (exactly those rows): one
 * device renders the halos vct_band_shape asks for and keeps its own rows;
 * a group is given its own rows and adds the halos its devices need. */
static void render_rows(member *m, const vct_render_job *job, int first, int end, vct_image *rows,
                        vct_render_result *counted) {
    vct_error err = {0};
    int align, above, below;
    vct_band_shape(job, &align, &above, &below);
    int from = first, to = end;
    if (!m->group) {
        from = first - above > 0 ? first - above : 0;
        to = end + below < job->height ? end + below : job->height;
    }
    vct_render_job band = *job;
    band.height = to - from;
    band.band.first = from;
    band.band.height = job->height;
    if (m->method == VCT_METHOD_PM) {
        band.band.pass_sync = agree_on_radii;
        band.band.pass_sync_user = m;
    }
    vct_image drawn = {0};
    vct_render_result r = {0};
    const double t0 = MPI_Wtime();
    int rc = member_prepare(m, &err);
    if (rc == VCT_OK)
        rc = m->group ? vct_group_render(m->group, &band, &drawn, &r, &err)
                      : vct_device_scene_render(m->ds, &band, &drawn, &r, &err);
    if (rc != VCT_OK)
        cli_cluster_fail("rendering a band", &err);
    m->stats.seconds += MPI_Wtime() - t0;
    m->stats.work += end - first;
    const size_t row_floats = 4 * (size_t)job->width;
    memset(rows, 0, sizeof *rows);
    rows->width = job->width;
    rows->height = end - first;
    rows->rgba = malloc(row_floats * sizeof(float) * (size_t)(end - first));
    if (!rows->rgba)
        cli_cluster_fail("rendering a band", &(vct_error){.message = "out of host memory"});
    memcpy(rows->rgba, drawn.rgba + row_floats * (size_t)(first - from),
           row_floats * sizeof(float) * (size_t)(end - first));
    vct_image_release(&drawn);
    const uint64_t traced = counted->traced + r.traced,
                   camera_rays = counted->camera_rays + r.camera_rays;
    *counted = r;
    counted->traced = traced;
    counted->camera_rays = camera_rays;
}

/* Photon mapping: one band per rank, all of them in lockstep pass by pass,
 * gathered on rank 0. */
static void render_pm_bands(member *m, const vct_render_job *job, vct_image *image,
                            vct_render_result *counted) {
    const int width = job->width;
    int first, end;
    band_of(job, m->rank, m->size, &first, &end);
    vct_image mine = {0};
    render_rows(m, job, first, end, &mine, counted);
    int *counts = calloc((size_t)m->size, sizeof(int)),
        *offsets = calloc((size_t)m->size, sizeof(int));
    if (!counts || !offsets)
        cli_cluster_fail("rendering a band", &(vct_error){.message = "out of host memory"});
    for (int r = 0; r < m->size; ++r) {
        int f, e;
        band_of(job, r, m->size, &f, &e);
        counts[r] = 4 * width * (e - f);
        offsets[r] = 4 * width * f;
    }
    MPI_Gatherv(mine.rgba, counts[m->rank], MPI_FLOAT, m->rank == 0 ? image->rgba : NULL, counts,
                offsets, MPI_FLOAT, 0, MPI_COMM_WORLD);
    cli_cluster_count_sent(m->rank ? 4 * (uint64_t)counts[m->rank] : 0);
    free(counts);
    free(offsets);
    vct_image_release(&mine);
}

/* The other methods: bands of a few alignment units, dealt to whichever
 * rank asks, their rows sent back to rank 0. */
typedef struct row_dealer {
    member *m;
    const vct_render_job *job;
    vct_image *image; /* rank 0's */
    pthread_mutex_t lock;
    int next, units, per_chunk, align;
} row_dealer;

/* The next band's rows {first, end}; first == end: none left. */
static void rows_take(row_dealer *d, int band[2]) {
    pthread_mutex_lock(&d->lock);
    const int u = d->next < d->units ? d->next : d->units;
    const int v = u + d->per_chunk < d->units ? u + d->per_chunk : d->units;
    d->next = v;
    pthread_mutex_unlock(&d->lock);
    const int h = d->job->height;
    band[0] = u * d->align < h ? u * d->align : h;
    band[1] = v == d->units ? (u == v ? band[0] : h) : v * d->align;
}

static void place_rows(row_dealer *d, const int band[2], const float *rows) {
    const size_t row_floats = 4 * (size_t)d->job->width;
    memcpy(d->image->rgba + row_floats * (size_t)band[0], rows,
           row_floats * sizeof(float) * (size_t)(band[1] - band[0]));
}

/* Rank 0's other thread: takes each worker's rows and deals it the next
 * band, until every worker was told there is none. */
static void *serve_rows(void *arg) {
    row_dealer *d = arg;
    const size_t row_floats = 4 * (size_t)d->job->width;
    float *rows = malloc(row_floats * sizeof(float) * (size_t)d->per_chunk * (size_t)d->align +
                         row_floats * sizeof(float) * (size_t)d->align);
    if (!rows)
        cli_cluster_fail("rendering a band", &(vct_error){.message = "out of host memory"});
    for (int left = d->m->size - 1; left > 0;) {
        MPI_Status st;
        int done[2];
        wait_for(TAG_READY, &st);
        const int from = st.MPI_SOURCE;
        MPI_Recv(done, 2, MPI_INT, from, TAG_READY, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (done[1] > done[0]) {
            MPI_Recv(rows, (int)(row_floats * (size_t)(done[1] - done[0])), MPI_FLOAT, from,
                     TAG_PIXELS, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            place_rows(d, done, rows);
        }
        int next[2];
        rows_take(d, next);
        MPI_Send(next, 2, MPI_INT, from, TAG_CHUNK, MPI_COMM_WORLD);
        cli_cluster_count_sent(sizeof next);
        left -= next[1] == next[0];
    }
    free(rows);
    return NULL;
}

static void render_dealt_rows(row_dealer *d, vct_render_result *counted) {
    member *m = d->m;
    int band[2] = {0, 0};
    vct_image rows = {0};
    if (m->rank > 0) {
        for (;;) {
            MPI_Send(band, 2, MPI_INT, 0, TAG_READY, MPI_COMM_WORLD);
            cli_cluster_count_sent(sizeof band);
            if (band[1] > band[0]) {
                const int floats = 4 * rows.width * rows.height;
                MPI_Send(rows.rgba, floats, MPI_FLOAT, 0, TAG_PIXELS, MPI_COMM_WORLD);
                cli_cluster_count_sent(4 * (uint64_t)floats);
                vct_image_release(&rows);
            }
            MPI_Recv(band, 2, MPI_INT, 0, TAG_CHUNK, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            if (band[1] == band[0])
                return;
            render_rows(m, d->job, band[0], band[1], &rows, counted);
        }
    }
    if (!cli_cluster_threads()) {
        serve_rows(d); /* MPI allows one thread: rank 0 only deals */
        return;
    }
    pthread_t server;
    if (pthread_create(&server, NULL, serve_rows, d) != 0)
        cli_cluster_fail("rendering a band", &(vct_error){.message = "no thread to deal bands"});
    for (rows_take(d, band); band[1] > band[0]; rows_take(d, band)) {
        render_rows(m, d->job, band[0], band[1], &rows, counted);
        place_rows(d, band, rows.rgba);
        vct_image_release(&rows);
    }
    pthread_join(server, NULL);
}

static int render_bands(member *m, vct_image *image, vct_render_result *result, vct_error *err) {
    (void)err;
    vct_render_job job = cli_render_job(m->opt, m->method, m->scene);
    if (m->method == VCT_METHOD_VCT)
        job.plan = &m->plan;
    const int width = job.width, height = job.height;
    m->work_unit = "rows";
    if (m->rank == 0) {
        memset(image, 0, sizeof *image);
        image->width = width;
        image->height = height;
        image->rgba = malloc(16 * (size_t)width * height);
        if (!image->rgba)
            cli_cluster_fail("rendering a band", &(vct_error){.message = "out of host memory"});
    }
    vct_render_result own = {0};
    if (m->method == VCT_METHOD_PM) {
        render_pm_bands(m, &job, image, &own);
    } else {
        int align, above, below;
        vct_band_shape(&job, &align, &above, &below);
        row_dealer d;
        memset(&d, 0, sizeof d);
        d.m = m;
        d.job = &job;
        d.image = image;
        d.align = align;
        /* the image's last row, a row of corners, goes with the units above it */
        d.units = (height - (below == 1 && height > 1) + align - 1) / align;
        d.per_chunk = d.units / (4 * m->size) ? d.units / (4 * m->size) : 1;
        pthread_mutex_init(&d.lock, NULL);
        render_dealt_rows(&d, &own);
        pthread_mutex_destroy(&d.lock);
    }
    uint64_t counted[2] = {own.traced, own.camera_rays}, summed[2] = {0, 0};
    MPI_Reduce(counted, summed, 2, MPI_UINT64_T, MPI_SUM, 0, MPI_COMM_WORLD);
    *result = own;
    result->traced = summed[0];
    result->camera_rays = summed[1];
    return VCT_OK;
}

/* ---- the command ---------------------------------------------------------- */

static int refused(const cli_options *opt, vct_method method) {
    const char *why = NULL;
    if (opt->aov)
        why = "--aov comes from one process: render it without mpirun";
    else if (opt->denoise && method == VCT_METHOD_VCT)
        why = "--denoise with cone tracing filters the indirect AOV, which comes from one "
              "process: render it without mpirun";
    else if (method == VCT_METHOD_PATHTRACE && opt->time_limit > 0.0f && opt->frames[1] < 0)
        why = "the path tracer is split by samples under MPI: give --spp, not --time";
    if (!why && method == VCT_METHOD_PM && opt->frames[1] < 0 && opt->height < cli_cluster_size())
        why = "photon mapping's bands take a row or more each: give fewer ranks than rows";
    if (why && cli_cluster_rank() == 0)
        fprintf(stderr, "vct render: %s\n", why);
    return why != NULL;
}

static void print_ranks(const member *m, const rank_stats *all) {
    fprintf(stderr, "%-5s %-20s %-36s %10s %9s %12s\n", "rank", "host", "device", m->work_unit,
            "seconds", "sent bytes");
    for (int r = 0; r < m->size; ++r)
        fprintf(stderr, "%-5d %-20.20s %-36.36s %10.0f %9.3f %12llu\n", r, all[r].host,
                all[r].device, all[r].work, all[r].seconds, (unsigned long long)all[r].sent);
}

/* Every rank's stats on rank 0, printed with --stats. */
static void gather_stats(member *m) {
    int length = 0;
    char host[MPI_MAX_PROCESSOR_NAME] = "";
    MPI_Get_processor_name(host, &length);
    snprintf(m->stats.host, sizeof m->stats.host, "%s", host);
    if (m->group) {
        const vct_group_device *d;
        const int n = vct_group_devices(m->group, &d);
        snprintf(m->stats.device, sizeof m->stats.device, "%d devices: %.80s", n, d[0].info.name);
    } else {
        snprintf(m->stats.device, sizeof m->stats.device, "%.95s",
                 vct_context_device(m->ctx)->name);
    }
    m->stats.sent = cli_cluster_sent();
    rank_stats *all = m->rank == 0 ? calloc((size_t)m->size, sizeof *all) : NULL;
    MPI_Gather(&m->stats, sizeof m->stats, MPI_BYTE, all, sizeof m->stats, MPI_BYTE, 0,
               MPI_COMM_WORLD);
    if (all && m->opt->stats) {
        if (m->ctx)
            cli_print_stats(m->ctx);
        print_ranks(m, all);
    }
    free(all);
}

static int render_one_frame(member *m, const char *out) {
    vct_error err = {0};
    vct_image image = {0}, variance = {0};
    vct_render_result result = {0};
    int rc = m->method == VCT_METHOD_PATHTRACE ? render_samples(m, &image, &variance, &result, &err)
                                               : render_bands(m, &image, &result, &err);
    if (m->rank == 0) {
        cli_layers layers = {0};
        if (rc == VCT_OK) {
            cli_print_result(m->opt, &result);
            rc = m->group
                     ? (m->opt->denoise ? cli_devices_denoise(m->group, m->scene, m->opt, m->method,
                                                              &image, &variance, &err)
                                        : VCT_OK)
                     : cli_denoise_outputs(m->ctx, m->scene, vct_device_scene_accel(m->ds), m->opt,
                                           m->method, &image, variance.rgba ? &variance : NULL,
                                           NULL, &layers, &err);
        }
        if (rc == VCT_OK)
            rc = cli_write_image(m->opt, &image, &layers, out, &err);
        cli_layers_free(&layers);
        if (rc != VCT_OK)
            cli_cluster_fail("rank 0's image", &err);
    }
    vct_image_release(&image);
    vct_image_release(&variance);
    return 0;
}

int cli_render_cluster(const cli_options *opt, vct_scene *s, vct_method method, const char *out) {
    if (refused(opt, method))
        return 1;
    member m;
    memset(&m, 0, sizeof m);
    m.opt = opt;
    m.method = method;
    m.scene = s;
    m.rank = cli_cluster_rank();
    m.size = cli_cluster_size();
    vct_error err = {0};
    vct_plan_make(s, opt->force, &m.plan);
    m.plan.emitters_by_cones = opt->emitters_by_cones;
    if (cli_device_list(opt)) {
        m.group = cli_devices_open(opt, &err);
        if (!m.group)
            cli_cluster_fail("opening the devices", &err);
        cli_devices_build(opt, method, &m.plan, &m.build);
    } else {
        m.ctx = cli_open_context(opt, &err);
        if (!m.ctx)
            cli_cluster_fail("opening the device", &err);
        m.ds = vct_device_scene_create(m.ctx, s, &err);
        if (!m.ds)
            cli_cluster_fail("committing the scene", &err);
    }
    if (m.rank == 0)
        fprintf(stderr, "vct: %d MPI ranks, each on %s\n", m.size,
                m.group ? "the devices --device lists" : "its own device");
    const int rc = opt->frames[1] >= 0 ? render_sequence(&m, out) : render_one_frame(&m, out);
    gather_stats(&m);
    vct_group_release(m.group);
    vct_device_scene_release(m.ds);
    vct_context_release(m.ctx);
    return rc;
}
