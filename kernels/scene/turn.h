/* The cosine and sine of a fraction u of a full turn (angle 2 pi u), for
 * sampling directions about an axis. The library's sinpi/cospi reduce any
 * argument and cost more than the rest of a diffuse bounce on some CPU
 * drivers; here u is reduced to the nearest quarter turn, exactly, and the
 * rest (at most an eighth of a turn) goes through Taylor polynomials whose
 * first omitted terms are below 3e-8. */
#ifndef VCT_TURN_H
#define VCT_TURN_H

inline float2 turn_cos_sin(float u) {
    const float x = 4.0f * u;                       /* quarter turns */
    const float q = floor(x + 0.5f);                /* the nearest one */
    const float a = (x - q) * 1.57079632679489662f; /* radians, |a| <= pi / 4 */
    const float a2 = a * a;
    const float s =
        a * (1.0f + a2 * (-1.0f / 6.0f +
                          a2 * (1.0f / 120.0f + a2 * (-1.0f / 5040.0f + a2 * (1.0f / 362880.0f)))));
    const float c =
        1.0f + a2 * (-0.5f + a2 * (1.0f / 24.0f + a2 * (-1.0f / 720.0f + a2 * (1.0f / 40320.0f))));
    const int k = (int)q & 3; /* turn (c, s) by k quarter turns */
    const float ck = k == 0 ? c : k == 1 ? -s : k == 2 ? -c : s;
    const float sk = k == 0 ? s : k == 1 ? c : k == 2 ? -s : -c;
    return (float2)(ck, sk);
}

#endif
