/* A barrier per photon pass with a max-reduction of the bands' radii. */
#include "multi/pass_sync.h"

void vct_pass_sync_init(vct_pass_sync *s, int members) {
    *s = (vct_pass_sync){0};
    pthread_mutex_init(&s->lock, NULL);
    pthread_cond_init(&s->changed, NULL);
    s->members = members;
}

void vct_pass_sync_destroy(vct_pass_sync *s) {
    pthread_cond_destroy(&s->changed);
    pthread_mutex_destroy(&s->lock);
}

int vct_pass_sync_wait(void *user, uint32_t pass, uint32_t radius_bits[2]) {
    /* every band runs the same passes in the same order */
    vct_pass_sync *s = user;
    pthread_mutex_lock(&s->lock);
    /* positive floats order as their bits do; 0 is "no radius yet" */
    for (int m = 0; m < 2; ++m)
        if (radius_bits[m] > s->gathering[m])
            s->gathering[m] = radius_bits[m];
    const unsigned generation = s->generation;
    if (++s->arrived == s->members) {
        if (s->outer && s->outer(s->outer_user, pass, s->gathering) != 0)
            s->stopped = 1; /* the other bands stopped: so do these */
        s->agreed[0] = s->gathering[0], s->agreed[1] = s->gathering[1];
        s->gathering[0] = s->gathering[1] = 0;
        s->arrived = 0;
        ++s->generation;
        pthread_cond_broadcast(&s->changed);
    }
    while (generation == s->generation && !s->stopped)
        pthread_cond_wait(&s->changed, &s->lock);
    const int stopped = generation == s->generation;
    radius_bits[0] = s->agreed[0], radius_bits[1] = s->agreed[1];
    pthread_mutex_unlock(&s->lock);
    return stopped;
}

void vct_pass_sync_fail(vct_pass_sync *s, int device) {
    pthread_mutex_lock(&s->lock);
    if (!s->stopped)
        s->culprit[device] = 1;
    s->stopped = 1;
    pthread_cond_broadcast(&s->changed);
    pthread_mutex_unlock(&s->lock);
}
