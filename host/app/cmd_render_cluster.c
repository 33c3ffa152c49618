/* vct render across the ranks of an MPI job. Each rank renders on its own
 * device (or devices) through its own device scene; rank 0 writes every
 * file. How each kind of work is split:
 * - A sequence: frames are dealt one at a time to the rank that asks
 *   (rank 0 deals from a thread of its own and renders too), so a slow
 *   rank costs only its own frames; each frame is rendered whole.
 * - The path tracer: the sample sequence is dealt in chunks to whichever
 *   rank asks, each rank sums its chunks exactly (vct/partial.h), and the
 *   sums add in any order, so the image is one process's, bit for bit.
 * - The other methods: bands of rows (with the halos vct_band_shape asks
 *   for) dealt to whichever rank asks; photon mapping: a band per rank, the
 *   bands agreeing on their radii pass by pass. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cli_denoise.h"
#include "cli_layers.h"
#include "cluster.h"
#include "cmd_render_group.h"
#include "cli_common.h"
#include "cluster_render.h"

void cluster_wait_for(int tag, MPI_Status *st) {
    for (int ready = 0; !ready;) {
        MPI_Iprobe(MPI_ANY_SOURCE, tag, MPI_COMM_WORLD, &ready, st);
        if (!ready)
            nanosleep(&(struct timespec){0, 1000000}, NULL);
    }
}

/* Rank 0's other thread: takes each worker's frame, writes it, and deals
 * the worker its next, until every worker was told there is none. */

int cluster_prepare(member *m, vct_error *err) {
    return m->group ? vct_group_prepare(m->group, m->scene, &m->build, err) : VCT_OK;
}

/* Poses and renders frame k of the list. */

static int refused(const cli_options *opt, vct_method method) {
    const char *why = NULL;
    if (opt->aov)
        why = "--aov comes from one process: render it without mpirun";
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
    vct_aovs parts = {0}; /* the path tracer's indirect light, for --denoise */
    vct_render_result result = {0};
    int rc = m->method == VCT_METHOD_PATHTRACE
                 ? cluster_render_samples(m, &image, &variance, &parts, &result, &err)
                 : cluster_render_bands(m, &image, &result, &err);
    if (m->rank == 0) {
        cli_layers layers = {0};
        if (rc == VCT_OK) {
            cli_print_result(m->opt, &result);
            rc = m->group
                     ? (m->opt->denoise && m->method != VCT_METHOD_VCT
                            ? cli_devices_denoise(m->group, m->scene, m->opt, m->method, &image,
                                                  &variance, &parts, &err)
                            : VCT_OK)
                     : cli_denoise_outputs(m->ctx, m->scene, vct_device_scene_accel(m->ds), m->opt,
                                           m->method, &image, variance.rgba ? &variance : NULL,
                                           parts.indirect.rgba ? &parts : NULL, &layers, &err);
        }
        if (rc == VCT_OK)
            rc = cli_write_image(m->opt, &image, &layers, out, &err);
        cli_layers_free(&layers);
        if (rc != VCT_OK)
            cli_cluster_fail("rank 0's image", &err);
    }
    vct_image_release(&image);
    vct_image_release(&variance);
    vct_aovs_release(&parts);
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
    const int rc =
        opt->frames[1] >= 0 ? cluster_render_sequence(&m, out) : render_one_frame(&m, out);
    gather_stats(&m);
    vct_group_release(m.group);
    vct_device_scene_release(m.ds);
    vct_context_release(m.ctx);
    return rc;
}
