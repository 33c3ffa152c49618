/* vct render under mpirun, the row methods: bands of rows, with the halos
 * vct_band_shape asks for, dealt to whichever rank asks; photon mapping:
 * a band per rank, the bands agreeing on their radii pass by pass. */
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "cli_common.h"
#include "cluster_render.h"

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
    int rc = cluster_prepare(m, &err);
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
        cluster_wait_for(TAG_READY, &st);
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

int cluster_render_bands(member *m, vct_image *image, vct_render_result *result, vct_error *err) {
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
