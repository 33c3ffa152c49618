/* The cosine and sine of a fraction u of a full turn (angle 2 pi u), for
 * sampling directions about an axis. The library's sinpi/cospi reduce any
 * argument and cost more than the rest of a diffuse bounce on some CPU
 * drivers; here u is reduced to the nearest quarter turn, exactly, and the
 * rest (at most an eighth of a turn) goes through Taylor polynomials whose
 * first omitted terms are below 3e-8. */
#ifndef VCT_TURN_H
#define VCT_TURN_H

/* One text for one fraction (float) and for a vector of them in lanes
 * (float16, where rays go in packets): each lane gets what the scalar form
 * gives its fraction, bit for bit. */
#define TURN_DEFINE(name, F, I, to_int)                                                            \
    inline void name(F u, F *cos_out, F *sin_out) {                                                \
        const F x = 4.0f * u;                       /* quarter turns */                            \
        const F q = floor(x + 0.5f);                /* the nearest one */                          \
        const F a = (x - q) * 1.57079632679489662f; /* radians, |a| <= pi / 4 */                   \
        const F a2 = a * a;                                                                        \
        const F s =                                                                                \
            a * (1.0f +                                                                            \
                 a2 * (-1.0f / 6.0f +                                                              \
                       a2 * (1.0f / 120.0f + a2 * (-1.0f / 5040.0f + a2 * (1.0f / 362880.0f)))));  \
        const F c =                                                                                \
            1.0f +                                                                                 \
            a2 * (-0.5f + a2 * (1.0f / 24.0f + a2 * (-1.0f / 720.0f + a2 * (1.0f / 40320.0f))));   \
        const I k = to_int(q) & 3; /* turn (c, s) by k quarter turns */                            \
        *cos_out = k == 0 ? c : k == 1 ? -s : k == 2 ? -c : s;                                     \
        *sin_out = k == 0 ? s : k == 1 ? c : k == 2 ? -s : -c;                                     \
    }

#define TURN_TO_INT(x) ((int)(x))
TURN_DEFINE(turn_cos_sin_parts, float, int, TURN_TO_INT)
#ifdef VCT_PACKETS
TURN_DEFINE(turn_cos_sin16, float16, int16, convert_int16)
#endif

inline float2 turn_cos_sin(float u) {
    float c, s;
    turn_cos_sin_parts(u, &c, &s);
    return (float2)(c, s);
}

#endif
