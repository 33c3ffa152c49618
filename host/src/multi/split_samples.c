/* The path tracer over several devices: the sample sequence is handed out
 * in chunks to whichever device is free, each device adds its chunks to its
 * own exact sums, and the sums are added on the host and resolved on one
 * device. Exact sums add up the same in any order, so the image is the one
 * device's, bit for bit. A device that fails loses its sums: every chunk it
 * had is handed out again. */
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "multi/group.h"
#include "vct/partial.h"
#include "pathtrace/pathtrace.h"

#define STAGE "path trace"

typedef struct chunk {
    uint32_t first, count;
} chunk;

typedef struct chunk_list {
    chunk *items;
    int count, capacity;
} chunk_list;

typedef struct sample_run {
    vct_group *g;
    const vct_render_job *job;
    pthread_mutex_t lock;
    uint32_t next, end; /* samples not yet handed out (fixed count) */
    double deadline_ms; /* time mode: hand out until then */
    uint32_t chunk_size;
    chunk_list redo;                /* chunks of failed devices */
    chunk_list done[VCT_GROUP_MAX]; /* chunks each device has summed */
    vct_pathtrace_options opt[VCT_GROUP_MAX];
    vct_pt_session pt[VCT_GROUP_MAX];
    int began[VCT_GROUP_MAX];
    int rc[VCT_GROUP_MAX];
    vct_error errors[VCT_GROUP_MAX];
    double ms[VCT_GROUP_MAX];
    uint64_t samples[VCT_GROUP_MAX];
    int out_of_memory;
} sample_run;

static int list_push(chunk_list *l, chunk c) {
    if (l->count == l->capacity) {
        const int cap = l->capacity ? 2 * l->capacity : 16;
        chunk *items = realloc(l->items, (size_t)cap * sizeof *items);
        if (!items)
            return 0;
        l->items = items;
        l->capacity = cap;
    }
    l->items[l->count++] = c;
    return 1;
}

/* The next chunk for a device (count 0: none left). */
static chunk take(sample_run *s, int device) {
    chunk c = {0, 0};
    pthread_mutex_lock(&s->lock);
    if (s->redo.count > 0) {
        c = s->redo.items[--s->redo.count];
    } else if (s->deadline_ms > 0.0 ? vct_now_ms() < s->deadline_ms : s->next < s->end) {
        c.first = s->next;
        c.count = s->deadline_ms > 0.0 || s->end - s->next > s->chunk_size ? s->chunk_size
                                                                           : s->end - s->next;
        s->next += c.count;
    }
    if (c.count && !list_push(&s->done[device], c)) {
        s->out_of_memory = 1;
        list_push(&s->redo, c); /* capacity was there: it was just popped or is new */
        c.count = 0;
    }
    pthread_mutex_unlock(&s->lock);
    return c;
}

static void device_samples(vct_group *g, int i, void *arg) {
    sample_run *s = arg;
    const double t0 = vct_now_ms();
    int rc = VCT_OK;
    if (!s->began[i]) {
        rc = vct_pt_begin(g->ctx[i], s->job->scene, g->accel[i], &s->opt[i], &s->pt[i],
                          &s->errors[i]);
        s->began[i] = 1;
    }
    for (chunk c = rc == VCT_OK ? take(s, i) : (chunk){0, 0}; rc == VCT_OK && c.count;
         c = take(s, i)) {
        rc = vct_pt_run(&s->pt[i], c.first, c.count, 1, &s->errors[i]);
        if (rc == VCT_OK)
            s->samples[i] += c.count;
    }
    s->rc[i] = rc;
    s->ms[i] += vct_now_ms() - t0;
}

/* Every active device's sums added into `sum` (zeroed, `bytes` long). */
static int host_sums(sample_run *s, uint64_t *sum, size_t bytes, uint32_t *discarded,
                     vct_error *err) {
    vct_group *g = s->g;
    uint64_t *part = malloc(bytes);
    int rc = part ? VCT_OK : vct_fail(err, VCT_ERR_MEMORY, "devices: out of host memory");
    *discarded = 0;
    for (int i = 0; rc == VCT_OK && i < g->count; ++i) {
        if (!g->devices[i].active || !s->began[i])
            continue;
        uint32_t dropped = 0;
        rc = vct_pt_sums_read(&s->pt[i], part, &dropped, err);
        if (rc == VCT_OK)
            vct_sample_sums_add_words(sum, part, bytes / 16);
        *discarded += dropped;
    }
    free(part);
    return rc;
}

/* Every active device's sums added into one buffer on device `into`. */
static int merge_sums(sample_run *s, int into, cl_mem *merged, uint32_t *discarded,
                      vct_error *err) {
    const size_t bytes = vct_sample_sums_bytes(s->opt[into].width, s->opt[into].height);
    uint64_t *sum = calloc(bytes / 8, 8);
    int rc = sum ? host_sums(s, sum, bytes, discarded, err)
                 : vct_fail(err, VCT_ERR_MEMORY, "devices: out of host memory");
    *merged = rc == VCT_OK
                  ? vct_buffer_create(s->g->ctx[into], STAGE, "summed accumulations", bytes,
                                      CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sum, err)
                  : NULL;
    if (rc == VCT_OK && !*merged)
        rc = err->status;
    free(sum);
    return rc;
}

static void drop_failed(sample_run *s) {
    vct_group *g = s->g;
    for (int i = 0; i < g->count; ++i) {
        if (!g->devices[i].active || s->rc[i] == VCT_OK)
            continue;
        vct_group_drop(g, i, &s->errors[i]);
        /* its sums are gone: every chunk it had is handed out again */
        for (int k = 0; k < s->done[i].count; ++k)
            s->out_of_memory |= !list_push(&s->redo, s->done[i].items[k]);
        s->done[i].count = 0;
        if (s->began[i])
            vct_pt_end(&s->pt[i], s->rc[i], NULL, NULL, NULL, &s->errors[i]);
        s->began[i] = 0;
    }
}

static int run_rounds(sample_run *s, vct_error *err) {
    vct_group *g = s->g;
    for (;;) {
        for (int i = 0; i < g->count; ++i)
            s->rc[i] = VCT_OK;
        int rc = vct_group_each(g, device_samples, s, err);
        if (rc != VCT_OK)
            return rc;
        int failed = -1;
        for (int i = 0; i < g->count; ++i) {
            if (g->devices[i].active && s->rc[i] == VCT_ERR_INPUT) {
                *err = s->errors[i]; /* the caller's to fix, not the device's fault */
                return VCT_ERR_INPUT;
            }
            if (g->devices[i].active && s->rc[i] != VCT_OK)
                failed = i;
        }
        if (failed >= 0 && vct_group_active_count(g) == 1) {
            *err = s->errors[failed];
            drop_failed(s);
            return err->status ? (int)err->status : VCT_ERR_OPENCL;
        }
        drop_failed(s);
        if (s->out_of_memory)
            return vct_fail(err, VCT_ERR_MEMORY, "devices: out of host memory");
        if (s->redo.count == 0 && (s->deadline_ms > 0.0 || s->next >= s->end))
            return VCT_OK;
    }
}

/* A run of samples [first, first + count) of the job (count 0: until
 * deadline_ms), or NULL without host memory. */
static sample_run *run_make(vct_group *g, const vct_render_job *job, uint32_t first, uint32_t count,
                            double deadline_ms) {
    const vct_pathtrace_options *opt = &job->pathtrace;
    sample_run *s = calloc(1, sizeof *s);
    if (!s)
        return NULL;
    pthread_mutex_init(&s->lock, NULL);
    s->g = g;
    s->job = job;
    const uint32_t per_pass = opt->samples_per_pass ? opt->samples_per_pass : 1;
    s->next = first;
    s->end = first + count;
    s->deadline_ms = deadline_ms;
    const uint32_t share = count / (8u * (uint32_t)vct_group_active_count(g));
    s->chunk_size = share > per_pass ? share / per_pass * per_pass : per_pass;
    for (int i = 0; i < g->count; ++i) {
        s->opt[i] = *opt;
        s->opt[i].width = job->width;
        s->opt[i].height = job->height;
        s->opt[i].progress = 0;
    }
    return s;
}

/* Each device's part of the run, for the scheduler and --stats. */
static void record_devices(sample_run *s) {
    for (int i = 0; i < s->g->count; ++i) {
        if (!s->began[i])
            continue;
        vct_group_device *d = &s->g->devices[i];
        d->last_ms = s->ms[i];
        d->last_work = (double)s->samples[i];
        d->speed = s->ms[i] > 0.0 ? s->samples[i] / (s->ms[i] * 1e-3) : 0.0;
    }
}

static void run_free(sample_run *s) {
    for (int i = 0; i < s->g->count; ++i)
        free(s->done[i].items);
    free(s->redo.items);
    pthread_mutex_destroy(&s->lock);
    free(s);
}

vct_status vct_group_render_samples(vct_group *g, const vct_render_job *job, uint32_t first,
                                    uint32_t count, vct_sample_sums *sums, vct_error *err) {
    memset(sums, 0, sizeof *sums);
    if (job->method != VCT_METHOD_PATHTRACE)
        return vct_fail(err, VCT_ERR_INPUT, "%s: the job's method must be the path tracer", STAGE);
    vct_render_job own = *job;
    own.pathtrace.resume = 0; /* each device's sums hold this range alone */
    own.pathtrace.variance = own.pathtrace.indirect = NULL;
    sample_run *s = run_make(g, &own, first, count, 0.0);
    if (!s)
        return vct_fail(err, VCT_ERR_MEMORY, "devices: out of host memory");
    int rc = count ? run_rounds(s, err) : VCT_OK;
    const size_t bytes = vct_sample_sums_bytes(job->width, job->height);
    sums->data = rc == VCT_OK ? calloc(bytes / 8, 8) : NULL;
    if (rc == VCT_OK && !sums->data)
        rc = vct_fail(err, VCT_ERR_MEMORY, "devices: out of host memory for the sums");
    if (rc == VCT_OK)
        rc = host_sums(s, sums->data, bytes, &sums->discarded, err);
    for (int i = 0; i < g->count; ++i)
        if (s->began[i])
            vct_pt_end(&s->pt[i], VCT_OK, NULL, NULL, NULL, &s->errors[i]);
    record_devices(s);
    run_free(s);
    g->pt_done = 0;
    if (rc != VCT_OK) {
        vct_sample_sums_release(sums);
        return rc;
    }
    sums->width = job->width;
    sums->height = job->height;
    sums->samples = count;
    return VCT_OK;
}

int vct_group_render_chunks(vct_group *g, const vct_render_job *job, vct_image *image,
                            vct_render_result *result, vct_error *err) {
    const vct_pathtrace_options *opt = &job->pathtrace;
    if (opt->spp == 0 && !(opt->time_limit_s > 0.0))
        return vct_fail(err, VCT_ERR_INPUT, "%s: give a sample count (--spp) or a time (--time)",
                        STAGE);
    const double t0 = vct_now_ms();
    if (!opt->resume)
        g->pt_done = 0;
    sample_run *s =
        run_make(g, job, g->pt_done, opt->spp, opt->spp ? 0.0 : t0 + opt->time_limit_s * 1e3);
    if (!s)
        return vct_fail(err, VCT_ERR_MEMORY, "devices: out of host memory");
    int rc = run_rounds(s, err);
    int into = -1;
    for (int i = 0; i < g->count && into < 0; ++i)
        if (g->devices[i].active && s->began[i])
            into = i;
    cl_mem merged = NULL;
    uint32_t discarded = 0;
    if (rc == VCT_OK && into < 0)
        rc = vct_fail(err, VCT_ERR_INPUT, "%s: no device traced a sample", STAGE);
    if (rc == VCT_OK)
        rc = merge_sums(s, into, &merged, &discarded, err);
    const uint32_t total = (uint32_t)(s->deadline_ms > 0.0 ? s->next : s->end);
    for (int i = 0; i < g->count; ++i) {
        if (!s->began[i])
            continue;
        if (i == into)
            rc = vct_pt_end(&s->pt[i], rc, merged, image, NULL, err);
        else
            vct_pt_end(&s->pt[i], VCT_OK, NULL, NULL, NULL, &s->errors[i]);
    }
    record_devices(s);
    if (merged)
        vct_buffer_release(g->ctx[into], merged);
    g->pt_done = rc == VCT_OK ? total : 0;
    if (result) {
        memset(result, 0, sizeof *result);
        result->method = job->method;
        result->width = opt->width;
        result->height = opt->height;
        result->spp = total;
        result->discarded = discarded;
        result->seconds = (vct_now_ms() - t0) * 1e-3;
    }
    run_free(s);
    return rc;
}
