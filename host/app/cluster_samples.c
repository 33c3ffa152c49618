/* vct render under mpirun, the path tracer: the sample sequence is dealt in
 * chunks to whichever rank asks, each rank sums its chunks exactly
 * (vct/partial.h), and the ranks' sums add in any order, so the image is
 * one process's, bit for bit. */
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "cli_common.h"
#include "cluster_render.h"

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
        cluster_wait_for(TAG_ASK, &st);
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
int cluster_render_samples(member *m, vct_image *image, vct_image *variance, vct_aovs *parts,
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
    int rc = cluster_prepare(m, err);
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
    if (m->opt->denoise) {
        job.pathtrace.variance = variance;
        job.pathtrace.indirect = &parts->indirect;
    }
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
