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
 * the measured devices' mean). Inactive devices get 0. */
void vct_balance_shares(int n, const int *active, const double *speed, double *share);

/* Splits `units` units among n devices by share (a device with a share
 * gets at least one unit while there are units enough): counts[n]. */
void vct_balance_split(int n, const double *share, int units, int *counts);

#endif
