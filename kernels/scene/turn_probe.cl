/* turn_cos_sin for a list of fractions of a turn, for its test against the
 * C library in double precision (tests/scene/test_turn.c). */
#include "scene/turn.h"

__kernel void turn_probe(__global const float *u, uint n, __global float2 *out) {
    const uint i = get_global_id(0);
    if (i < n)
        out[i] = turn_cos_sin(u[i]);
}
