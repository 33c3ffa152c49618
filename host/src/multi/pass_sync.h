/* Photon mapping over row bands: every pass, the bands agree on the whole
 * image's largest radii (a barrier over the devices), so that each builds
 * the whole image's grids. A band that fails stops the others, and the
 * frame starts again on the devices left. */
#ifndef VCT_MULTI_PASS_SYNC_H
#define VCT_MULTI_PASS_SYNC_H

#include <pthread.h>
#include <stdint.h>

#include "multi/group.h"

typedef struct vct_pass_sync {
    pthread_mutex_t lock;
    pthread_cond_t changed;
    int members;           /* bands taking part */
    int arrived;           /* at the current barrier */
    unsigned generation;   /* barriers passed */
    uint32_t gathering[2]; /* the largest radii (float bits) so far at this barrier */
    uint32_t agreed[2];    /* at the last barrier passed */
    int stopped;           /* a band failed: the others stop at their next barrier */
    /* Bands of the image beyond this group's (vct_band.pass_sync): the
     * group's largest radii are agreed with them before its bands go on. */
    int (*outer)(void *user, uint32_t pass, uint32_t radius_bits[2]);
    void *outer_user;
    int culprit[VCT_GROUP_MAX];
} vct_pass_sync;

void vct_pass_sync_init(vct_pass_sync *s, int members);
void vct_pass_sync_destroy(vct_pass_sync *s);
/* The context hook (vct_context band_sync): user is the vct_pass_sync. */
int vct_pass_sync_wait(void *user, uint32_t pass, uint32_t radius_bits[2]);
/* Device `device` failed: the others are released, and it is the culprit
 * unless another failed first (then its failure was being stopped). */
void vct_pass_sync_fail(vct_pass_sync *s, int device);

#endif
