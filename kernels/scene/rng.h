/* Counter-based random numbers: each (seed, pixel, sample) starts its own
 * stream, so images do not depend on how work-items are scheduled. */
#ifndef VCT_RNG_H
#define VCT_RNG_H

/* A well-mixing 32-bit hash (lowbias32 by C. Wellons). */
inline uint rng_hash(uint x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

inline uint rng_start(uint seed, uint pixel, uint sample) {
    return rng_hash(seed ^ rng_hash(pixel ^ rng_hash(sample + 0x9e3779b9u)));
}

/* Uniform in [0, 1): the top 24 bits of the next state. */
inline float rng_next(uint *state) {
    *state = rng_hash(*state + 0x9e3779b9u);
    return (float)(*state >> 8) * (1.0f / 16777216.0f);
}

#endif
