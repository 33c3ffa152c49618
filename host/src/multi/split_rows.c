/* Row bands: each active device renders a band of the image, its height
 * set by the device's share; bands start on the method's alignment and
 * also render the rows around them that their own rows depend on (halos),
 * so that every row equals the whole image's. A band whose device fails is
 * split again among the others. */
#include <stdlib.h>
#include <string.h>

#include "multi/balance.h"
#include "multi/group.h"
#include "multi/pass_sync.h"

typedef struct band {
    int first, rows;
} band;

typedef struct rows_round {
    const vct_render_job *job;
    int width, height, halo_above, halo_below;
    vct_pass_sync *sync; /* photon mapping: the bands' barrier per pass */
    band bands[VCT_GROUP_MAX];
    vct_image images[VCT_GROUP_MAX];
    vct_render_result results[VCT_GROUP_MAX];
    vct_error errors[VCT_GROUP_MAX];
    int rc[VCT_GROUP_MAX];
    double ms[VCT_GROUP_MAX];
} rows_round;

/* The rows band b renders: its own and its halos, within the image. */
static band rendered_rows(const rows_round *r, band b) {
    const int first = b.first - r->halo_above > 0 ? b.first - r->halo_above : 0;
    const int end =
        b.first + b.rows + r->halo_below < r->height ? b.first + b.rows + r->halo_below : r->height;
    return (band){first, end - first};
}

static void render_band(vct_group *g, int i, void *arg) {
    rows_round *r = arg;
    const band b = r->bands[i];
    r->rc[i] = VCT_OK;
    if (b.rows == 0)
        return;
    vct_render_job job = *r->job;
    job.accel = g->accel[i];
    job.voxels = g->voxels[i];
    const band drawn = rendered_rows(r, b);
    job.width = r->width;
    job.height = drawn.rows;
    job.band.first = drawn.first;
    job.band.height = r->height;
    if (r->sync) {
        job.band.pass_sync = vct_pass_sync_wait;
        job.band.pass_sync_user = r->sync;
    }
    const double t0 = vct_now_ms();
    r->rc[i] = vct_render(g->ctx[i], &job, &r->images[i], &r->results[i], &r->errors[i]);
    r->ms[i] = vct_now_ms() - t0;
    if (r->sync && r->rc[i] != VCT_OK)
        vct_pass_sync_fail(r->sync, i);
}

/* Photon mapping resumed: the bands of the frames before (the statistics
 * of each band's pixels live on its device). */
static int reuse_pm_bands(const vct_group *g, const vct_render_job *job, rows_round *r) {
    if (job->method != VCT_METHOD_PM || !job->pm.resume || g->pm_height != r->height)
        return 0;
    for (int i = 0; i < g->count; ++i) {
        if (g->pm_rows[i] && !g->devices[i].active)
            return 0;
        r->bands[i] = (band){g->pm_first[i], g->pm_rows[i]};
    }
    return 1;
}

/* VCT_GROUP_SHARES=a,b,...: fixed shares, in the group's order, instead of
 * measured ones: to test any split without depending on timing. */
static int fixed_shares(const vct_group *g, double *share) {
    const char *list = getenv("VCT_GROUP_SHARES");
    if (!list || !*list)
        return 0;
    for (int i = 0; i < g->count; ++i) {
        char *end = NULL;
        share[i] = strtod(list, &end);
        list = *end == ',' ? end + 1 : end;
        if (!g->devices[i].active || !(share[i] > 0.0))
            share[i] = 0.0;
    }
    return 1;
}

/* Shares of the active devices (the fastest alone, when it is measured to
 * beat them all), equal when none has one left. */
static void active_shares(const vct_group *g, double *share) {
    if (!fixed_shares(g, share)) {
        const int solo = g->solo.state != VCT_ALL_DEVICES && g->devices[g->solo.device].active;
        for (int i = 0; i < g->count; ++i)
            share[i] = !g->devices[i].active ? 0.0
                       : solo                ? (i == g->solo.device ? 1.0 : 0.0)
                                             : g->devices[i].share;
    }
    int with_share = 0;
    for (int i = 0; i < g->count; ++i)
        with_share += share[i] > 0.0;
    for (int i = 0; i < g->count && !with_share; ++i)
        share[i] = g->devices[i].active ? 1.0 : 0.0;
}

/* Where a range's rows go: rgba holds rows [first_row, first_row + rows)
 * of an image width x height (the whole image, or a band of it). */
typedef struct rows_target {
    float *rgba;
    int width, height, first_row, rows;
} rows_target;

static int render_range(vct_group *g, const vct_render_job *job, int first, int rows,
                        const rows_target *t, vct_render_result *result, int measure,
                        vct_error *err);

/* Band i's own rows into the image, what it did into the result, and with
 * `measure` its time into its speed. */
static void take_band(vct_group *g, const rows_round *r, int i, const rows_target *t,
                      vct_render_result *result, int measure) {
    const band b = r->bands[i];
    const size_t row_floats = 4 * (size_t)r->width;
    const int skip = b.first - rendered_rows(r, b).first;
    memcpy(t->rgba + (size_t)(b.first - t->first_row) * row_floats,
           r->images[i].rgba + (size_t)skip * row_floats,
           (size_t)b.rows * row_floats * sizeof(float));
    result->traced += r->results[i].traced;
    result->camera_rays += r->results[i].camera_rays;
    result->spp = r->results[i].spp; /* photon mapping: the passes every band made */
    result->photons = r->results[i].photons;
    if (!measure)
        return;
    vct_group_device *d = &g->devices[i];
    d->last_ms = r->ms[i];
    d->last_work = b.rows;
    if (g->solo.state == VCT_ALL_DEVICES) {
        /* averaged with the last measurement: one slow frame (a page
         * fault, a busy host) does not swing the shares */
        const double speed = r->ms[i] > 0.0 ? b.rows / (r->ms[i] * 1e-3) : 0.0;
        d->speed = d->speed > 0.0 ? 0.5 * (d->speed + speed) : speed;
    }
}

/* Photon mapping's bands after their round: all complete, or a failure
 * stopped them all and the frame starts again without the device that
 * failed (the bands' grids must agree, pass after pass). */
static int lockstep_outcome(vct_group *g, const vct_render_job *job, rows_round *r,
                            const rows_target *t, vct_render_result *result, vct_error *err) {
    int failed = -1;
    for (int i = 0; i < g->count; ++i)
        if (r->bands[i].rows && r->rc[i] != VCT_OK && (failed < 0 || r->sync->culprit[i]))
            failed = i;
    if (failed >= 0 && (r->rc[failed] == VCT_ERR_INPUT || r->sync->outer)) {
        /* the caller's to fix, not the device's fault; or bands beyond the
         * group went on without this one, and cannot start the frame again */
        *err = r->errors[failed];
        return r->rc[failed];
    }
    if (failed >= 0) {
        for (int i = 0; i < g->count; ++i)
            if (r->bands[i].rows && r->rc[i] != VCT_OK && (r->sync->culprit[i] || i == failed))
                vct_group_drop(g, i, &r->errors[i]);
        for (int i = 0; i < g->count; ++i)
            vct_image_release(&r->images[i]);
        g->pm_height = 0; /* the statistics of every band are gone */
        if (vct_group_active_count(g) == 0) {
            *err = r->errors[failed];
            return err->status ? (int)err->status : VCT_ERR_OPENCL;
        }
        vct_render_job fresh = *job;
        fresh.pm.resume = 0;
        return render_range(g, &fresh, t->first_row, t->rows, t, result, 0, err);
    }
    g->pm_height = t->height;
    for (int i = 0; i < g->count; ++i) {
        const band b = r->bands[i];
        g->pm_first[i] = b.first;
        g->pm_rows[i] = b.rows;
        if (b.rows)
            take_band(g, r, i, t, result, 1);
        vct_image_release(&r->images[i]);
    }
    return VCT_OK;
}

/* Renders rows [first, first + rows) of the image into `t`; measure:
 * this round's times set the devices' speeds. */
static int render_range(vct_group *g, const vct_render_job *job, int first, int rows,
                        const rows_target *t, vct_render_result *result, int measure,
                        vct_error *err) {
    int align, above, below;
    vct_band_shape(job, &align, &above, &below);
    rows_round *r = calloc(1, sizeof *r);
    if (!r)
        return vct_fail(err, VCT_ERR_MEMORY, "devices: out of host memory");
    r->job = job;
    r->width = t->width;
    r->height = t->height;
    r->halo_above = above;
    r->halo_below = below;
    double share[VCT_GROUP_MAX];
    int units[VCT_GROUP_MAX];
    if (reuse_pm_bands(g, job, r))
        goto render;
    active_shares(g, share);
    /* The image's last row, when it is a row of square corners, is the
     * bottom edge of the squares above it: it goes with them, never alone. */
    const int edge_row = below == 1 && first + rows == t->height && rows > 1;
    const int unit_count = (rows - edge_row + align - 1) / align;
    vct_balance_split(g->count, share, unit_count, units);
    int at = first, last = -1;
    for (int i = 0; i < g->count; ++i) {
        const int take =
            units[i] * align < first + rows - at ? units[i] * align : first + rows - at;
        r->bands[i] = (band){at, take};
        at += take;
        if (take)
            last = i;
    }
    if (last >= 0)
        r->bands[last].rows += first + rows - at; /* the remainder */
render:;
    vct_pass_sync sync;
    if (job->method == VCT_METHOD_PM) {
        int members = 0;
        for (int i = 0; i < g->count; ++i)
            members += r->bands[i].rows > 0;
        vct_pass_sync_init(&sync, members);
        sync.outer = job->band.pass_sync; /* a band of a taller image: agree with its others */
        sync.outer_user = job->band.pass_sync_user;
        r->sync = &sync;
    }
    int rc = vct_group_each(g, render_band, r, err);
    if (r->sync) {
        vct_pass_sync_destroy(&sync);
        rc = rc == VCT_OK ? lockstep_outcome(g, job, r, t, result, err) : rc;
        free(r);
        return rc;
    }
    /* A refused job is the caller's to fix, not the device's fault. */
    for (int i = 0; rc == VCT_OK && i < g->count; ++i)
        if (r->bands[i].rows && r->rc[i] == VCT_ERR_INPUT) {
            *err = r->errors[i];
            rc = VCT_ERR_INPUT;
        }
    band failed[VCT_GROUP_MAX];
    int failures = 0, last_failure = -1;
    for (int i = 0; rc == VCT_OK && i < g->count; ++i) {
        const band b = r->bands[i];
        if (b.rows == 0)
            continue;
        if (r->rc[i] != VCT_OK) {
            vct_group_drop(g, i, &r->errors[i]);
            failed[failures++] = b;
            last_failure = i;
            continue;
        }
        take_band(g, r, i, t, result, measure);
    }
    for (int i = 0; i < g->count; ++i)
        vct_image_release(&r->images[i]);
    if (failures && vct_group_active_count(g) == 0)
        *err = r->errors[last_failure];
    free(r);
    if (failures && vct_group_active_count(g) == 0)
        return err->status ? (int)err->status : VCT_ERR_OPENCL;
    for (int k = 0; rc == VCT_OK && k < failures; ++k)
        rc = render_range(g, job, failed[k].first, failed[k].rows, t, result, 0, err);
    return rc;
}

/* What frame times of the devices together and alone may be compared
 * over: the same method, size, subsampling and rays at edges. */
static uint64_t job_signature(const vct_render_job *job, int width, int height) {
    const uint64_t subsample = job->method == VCT_METHOD_WHITTED   ? job->whitted.subsample
                               : job->method == VCT_METHOD_RAYCAST ? job->raycast.subsample
                                                                   : 0;
    return (uint64_t)job->method | (uint64_t)width << 8 | (uint64_t)height << 24 | subsample << 40 |
           (uint64_t)(job->vct.sparse_diffuse != 0) << 56 |
           (uint64_t)(job->vct.edge_samples & 15u) << 57;
}

/* A band of a taller image: the whole image's rows [band.first, band.first
 * + height), rendered as the group renders rows of a range, straight into
 * an image of the band's rows. */
static int render_band_rows(vct_group *g, const vct_render_job *job, vct_image *image,
                            vct_render_result *result, vct_error *err) {
    vct_render_job whole = *job;
    whole.height = job->band.height;
    whole.band.first = whole.band.height = 0; /* pass_sync stays: render_range reads it */
    const int width = job->width, first = job->band.first, rows = job->height;
    image->rgba = malloc(16 * (size_t)width * (size_t)rows);
    if (!image->rgba)
        return vct_fail(err, VCT_ERR_MEMORY, "devices: out of host memory");
    image->width = width;
    image->height = rows;
    const rows_target t = {image->rgba, width, whole.height, first, rows};
    vct_render_result sum;
    memset(&sum, 0, sizeof sum);
    const double t0 = vct_now_ms();
    const int rc = render_range(g, &whole, first, rows, &t, &sum, 1, err);
    if (rc != VCT_OK) {
        vct_image_release(image);
        return rc;
    }
    if (result) {
        *result = sum;
        result->method = job->method;
        result->width = width;
        result->height = rows;
        result->seconds = (vct_now_ms() - t0) * 1e-3;
    }
    return VCT_OK;
}

int vct_group_render_rows(vct_group *g, const vct_render_job *job, vct_image *image,
                          vct_render_result *result, vct_error *err) {
    if (job->band.height)
        return render_band_rows(g, job, image, result, err);
    vct_render_result sum;
    memset(&sum, 0, sizeof sum);
    const int width = job->width, height = job->height;
    if (width <= 0 || height <= 0 || width > 32768 || height > 32768)
        return vct_fail(err, VCT_ERR_INPUT, "render: image size %dx%d is outside 1..32768", width,
                        height);
    const double t0 = vct_now_ms();
    const uint64_t signature = job_signature(job, width, height);
    if (signature != g->solo_job) { /* times of another job say nothing of this one */
        memset(&g->solo, 0, sizeof g->solo);
        g->solo_job = signature;
    }
    image->width = width;
    image->height = height;
    image->rgba = malloc(16 * (size_t)width * (size_t)height);
    int rc = image->rgba ? VCT_OK : vct_fail(err, VCT_ERR_MEMORY, "devices: out of host memory");
    for (int i = 0; i < g->count; ++i)
        g->devices[i].last_ms = g->devices[i].last_work = 0.0;
    const rows_target t = {image->rgba, width, height, 0, height};
    if (rc == VCT_OK)
        rc = render_range(g, job, 0, height, &t, &sum, 1, err);
    if (rc != VCT_OK) {
        vct_image_release(image);
        return rc;
    }
    double speed[VCT_GROUP_MAX], share[VCT_GROUP_MAX];
    int active[VCT_GROUP_MAX], fastest = -1;
    for (int i = 0; i < g->count; ++i) {
        active[i] = g->devices[i].active;
        speed[i] = g->devices[i].speed;
        share[i] = g->devices[i].share;
        if (active[i] && (fastest < 0 || speed[i] > speed[fastest]))
            fastest = i;
    }
    int settled = 1;
    if (g->solo.state == VCT_ALL_DEVICES) {
        settled = !vct_balance_shares(g->count, active, speed, share);
        for (int i = 0; i < g->count; ++i)
            g->devices[i].share = share[i];
    }
    if (vct_group_active_count(g) > 1)
        vct_solo_next(&g->solo, vct_now_ms() - t0, settled, fastest);
    if (result) {
        *result = sum;
        result->method = job->method;
        result->width = width;
        result->height = height;
        result->seconds = (vct_now_ms() - t0) * 1e-3;
        if (result->traced > (uint64_t)width * height)
            result->traced = (uint64_t)width * height; /* halo rows traced twice */
    }
    return VCT_OK;
}
