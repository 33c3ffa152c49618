/* emitter_pick for a list of numbers against one CDF, for its test against
 * a plain search in C (tests/light/test_emitter_pick.c). */
#include "light/emitters.h"

__kernel void emitter_pick_probe(__global const float *cdf, uint count, __global const float *u,
                                 uint n, __global uint *out) {
    const uint i = get_global_id(0);
    if (i >= n)
        return;
    const emitter_view e = {0, cdf, 0, count, 1u};
    out[i] = emitter_pick(&e, u[i]);
}
