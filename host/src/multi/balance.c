/* Proportional shares, damped and with a dead band, as work-balancing
 * schedulers do, with a floor below which a device is not worth its
 * overhead. */
#include <math.h>

#include "multi/balance.h"

static void normalise(int n, double *share) {
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
        sum += share[i];
    for (int i = 0; i < n; ++i)
        share[i] = sum > 0.0 ? share[i] / sum : 0.0;
}

int vct_balance_shares(int n, const int *active, const double *speed, double *share) {
    double known = 0.0, measured = 0.0;
    int live = 0;
    for (int i = 0; i < n; ++i)
        if (active[i]) {
            ++live;
            if (speed[i] > 0.0)
                known += speed[i], measured += 1.0;
        }
    if (live == 0)
        return 0;
    double target[64], prior_sum = 0.0;
    for (int i = 0; i < n && i < 64; ++i) {
        target[i] = !active[i]       ? 0.0
                    : speed[i] > 0.0 ? speed[i]
                    : measured       ? known / measured
                                     : 1.0;
        prior_sum += share[i];
    }
    normalise(n, target);
    for (int i = 0; i < n; ++i)
        if (target[i] < VCT_BALANCE_MIN_SHARE)
            target[i] = 0.0;
    normalise(n, target);
    int moved = !(prior_sum > 0.0);
    for (int i = 0; i < n; ++i)
        if (!active[i] || fabs(target[i] - share[i]) >= VCT_BALANCE_DEAD_BAND ||
            (target[i] == 0.0 && share[i] > 0.0))
            moved = 1;
    if (!moved)
        return 0;
    for (int i = 0; i < n; ++i)
        share[i] = target[i] == 0.0 || !(prior_sum > 0.0)
                       ? target[i]
                       : share[i] + (target[i] - share[i]) * VCT_BALANCE_DAMPING;
    normalise(n, share);
    return 1;
}

void vct_solo_next(vct_solo *solo, double frame_ms, int settled, int fastest) {
    ++solo->frames;
    switch (solo->state) {
    case VCT_ALL_DEVICES:
        solo->all_ms = frame_ms;
        /* after the shares settle, or a few frames of noise that keeps them moving */
        if (solo->frames >= VCT_SOLO_WARM && (settled || solo->frames >= VCT_SOLO_AFTER) &&
            fastest >= 0 && (solo->solo_ms == 0.0 || solo->frames > VCT_SOLO_RETRY)) {
            solo->state = VCT_SOLO_PROBE;
            solo->device = fastest;
            solo->frames = 0;
        }
        break;
    case VCT_SOLO_PROBE:
        solo->solo_ms = frame_ms;
        /* within 2 %: the devices together, which stay measured */
        solo->state = frame_ms < 0.98 * solo->all_ms ? VCT_SOLO : VCT_ALL_DEVICES;
        solo->frames = 0;
        break;
    case VCT_SOLO:
        solo->solo_ms = frame_ms;
        if (solo->frames > VCT_SOLO_RETRY) {
            solo->state = VCT_ALL_DEVICES;
            solo->frames = 0;
        }
        break;
    }
}

void vct_balance_split(int n, const double *share, int units, int *counts) {
    int with_share = 0;
    for (int i = 0; i < n; ++i)
        with_share += share[i] > 0.0;
    double cumulative = 0.0;
    int given = 0, seen = 0;
    for (int i = 0; i < n; ++i) {
        counts[i] = 0;
        if (!(share[i] > 0.0))
            continue;
        ++seen;
        cumulative += share[i];
        int end = seen == with_share ? units : (int)lround(cumulative * units);
        /* one unit at least for each device with a share, while units last */
        const int later = with_share - seen;
        if (end <= given && given < units - later)
            end = given + 1;
        if (end > units - later)
            end = units - later > given ? units - later : given;
        counts[i] = end - given;
        given = end;
    }
}
