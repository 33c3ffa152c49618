/* What every part of a group uses: its threads (one per active device, at
 * once) and the dropping of a device that failed. */
#include <pthread.h>
#include <stdio.h>

#include "multi/group.h"

int vct_group_active_count(const vct_group *g) {
    int n = 0;
    for (int i = 0; i < g->count; ++i)
        n += g->devices[i].active;
    return n;
}

void vct_group_drop(vct_group *g, int i, const vct_error *why) {
    vct_group_device *d = &g->devices[i];
    if (!d->active)
        return;
    d->active = 0;
    d->share = 0.0;
    snprintf(d->dropped, sizeof d->dropped, "%s", why->message);
    ++g->faults;
    if (!g->log)
        return;
    char message[2048 + 512];
    snprintf(message, sizeof message, "device %d (%s) dropped: %s; the others take its work",
             d->info.index, d->info.name, d->dropped);
    g->log(g->log_user, message);
}

typedef struct worker {
    vct_group *g;
    int device;
    vct_group_work work;
    void *arg;
} worker;

static void *worker_main(void *p) {
    worker *w = p;
    w->work(w->g, w->device, w->arg);
    return NULL;
}

int vct_group_each(vct_group *g, vct_group_work work, void *arg, vct_error *err) {
    pthread_t threads[VCT_GROUP_MAX];
    worker workers[VCT_GROUP_MAX];
    int started[VCT_GROUP_MAX] = {0};
    for (int i = 0; i < g->count; ++i) {
        if (!g->devices[i].active)
            continue;
        workers[i] = (worker){g, i, work, arg};
        started[i] = pthread_create(&threads[i], NULL, worker_main, &workers[i]) == 0;
    }
    /* A device that got no thread works on this one, after the others started. */
    for (int i = 0; i < g->count; ++i)
        if (g->devices[i].active && !started[i])
            work(g, i, arg);
    for (int i = 0; i < g->count; ++i)
        if (started[i])
            pthread_join(threads[i], NULL);
    (void)err;
    return VCT_OK;
}
