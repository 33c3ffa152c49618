/* Shares of the work from measured speeds: what a device group gives each
 * device next. */
#ifndef VCT_MULTI_BALANCE_H
#define VCT_MULTI_BALANCE_H

/* A device whose speed would earn it less than this share gets none: its
 * part would cost the frame more in overhead than it saves. */
#define VCT_BALANCE_MIN_SHARE 0.03
/* Shares move this fraction of the way to the measured target per render. */
#define VCT_BALANCE_DAMPING 0.5
/* Changes smaller than this (for every device) are noise: shares stay. */
#define VCT_BALANCE_DEAD_BAND 0.02

/* share[n]: the current shares (summing to 1 over the active devices), set
 * to the next ones from speed[n] (work per second; 0: not measured, then
 * the measured devices' mean). Inactive devices get 0. Returns 1 when the
 * shares moved, 0 when they held (settled, within the dead band). */
int vct_balance_shares(int n, const int *active, const double *speed, double *share);

/* Whether the devices together beat the fastest alone: measured, not
 * assumed (devices may share cores, memory or a bus). Once the shares have
 * settled (or after VCT_SOLO_AFTER frames) one frame runs on the fastest
 * device alone; the faster way is
 * kept, and the other tried again every VCT_SOLO_RETRY frames. */
#define VCT_SOLO_RETRY 50
#define VCT_SOLO_AFTER 4
/* Frames together before the first probe: the first pays for building
 * kernels and buffers, and against a warm frame alone it lost every time
 * (a loaded host then kept a group of equal devices on one). */
#define VCT_SOLO_WARM 2
typedef enum vct_solo_state { VCT_ALL_DEVICES, VCT_SOLO_PROBE, VCT_SOLO } vct_solo_state;
typedef struct vct_solo {
    vct_solo_state state;
    int device;             /* the fastest, in the probe and solo states */
    double all_ms, solo_ms; /* last frame times measured each way (0: none) */
    int frames;             /* frames since the last change of state */
} vct_solo;

/* The state for the next frame, given this frame's time and whether the
 * shares settled; fastest: the fastest active device. */
void vct_solo_next(vct_solo *solo, double frame_ms, int settled, int fastest);

/* Splits `units` units among n devices by share (a device with a share
 * gets at least one unit while there are units enough): counts[n]. */
void vct_balance_split(int n, const double *share, int units, int *counts);

#endif
