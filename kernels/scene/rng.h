/* Counter-based random numbers: each (seed, pixel, sample) starts its own
 * stream, so images do not depend on how work-items are scheduled. */
#ifndef VCT_RNG_H
#define VCT_RNG_H

/* A well-mixing 32-bit hash (lowbias32 by C. Wellons), the next number of
 * a stream, uniform in [0, 1) (the top 24 bits of the next state), and the
 * stream of (seed, pixel, sample). One
 * text for one stream (uint) and, where rays go in packets, for a packet's
 * streams in vector lanes (uint16), so that each lane draws the numbers its
 * own stream would. */
#define RNG_DEFINE(hash, next, start, U, F, convert)                                               \
    inline U hash(U x) {                                                                           \
        x ^= x >> 16;                                                                              \
        x *= 0x7feb352du;                                                                          \
        x ^= x >> 15;                                                                              \
        x *= 0x846ca68bu;                                                                          \
        x ^= x >> 16;                                                                              \
        return x;                                                                                  \
    }                                                                                              \
    inline F next(U *state) {                                                                      \
        *state = hash(*state + 0x9e3779b9u);                                                       \
        return convert(*state >> 8) * (1.0f / 16777216.0f);                                        \
    }                                                                                              \
    inline U start(uint seed, uint pixel, U sample) {                                              \
        return hash(seed ^ hash(pixel ^ hash(sample + 0x9e3779b9u)));                              \
    }

#define RNG_TO_FLOAT(x) ((float)(x))
RNG_DEFINE(rng_hash, rng_next, rng_start, uint, float, RNG_TO_FLOAT)
#ifdef VCT_PACKETS
RNG_DEFINE(rng_hash16, rng_next16, rng_start16, uint16, float16, convert_float16)
#endif

/* Where i (< n) goes in a permutation of 0 .. n - 1 chosen by key: rounds
 * of steps that are each one-to-one on the bits below n's next power of two
 * (xor, odd multiply, add, xor with a right shift), walked until the value
 * falls below n again (cycle walking), so that it stays one-to-one on n. */
inline uint rng_permute(uint i, uint n, uint key) {
    if (n <= 1u)
        return 0u;
    uint mask = n - 1u;
    mask |= mask >> 1;
    mask |= mask >> 2;
    mask |= mask >> 4;
    mask |= mask >> 8;
    mask |= mask >> 16;
    const uint k1 = rng_hash(key), k2 = rng_hash(k1);
    uint x = i;
    do {
        for (uint round = 0u; round < 3u; ++round) {
            x = (x ^ (k1 >> (8u * round))) & mask;
            x = (x * (2u * (k2 >> (8u * round)) + 1u)) & mask;
            x ^= x >> 1;
            x = (x + (k2 >> (4u * round))) & mask;
            x ^= x >> 2;
        }
    } while (x >= n);
    return x;
}

#endif
