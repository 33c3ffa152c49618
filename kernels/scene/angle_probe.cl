/* angle_of for a list of (sine, cosine) pairs, for its test against the C
 * library in double precision (tests/scene/test_angle.c). */
#include "scene/angle.h"

__kernel void angle_probe(__global const float2 *sc, uint n, __global float *out) {
    const uint i = get_global_id(0);
    if (i < n)
        out[i] = angle_of(sc[i].x, sc[i].y);
}
