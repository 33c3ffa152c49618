/* Exact sums of floats: each value becomes a 128-bit two's-complement
 * fixed-point number (hi: 64 bits above the binary point, lo: 64 below) and
 * is added without rounding. A sum is then the same whatever order its terms
 * arrive in: one launch or many, one device or several. Magnitudes below
 * 2^-64 are dropped and those of 2^63 or more saturate; radiance lives far
 * inside that range. */
#ifndef VCT_EXACT_SUM_H
#define VCT_EXACT_SUM_H

/* x: hi, y: lo. */
typedef ulong2 exact_sum;

inline exact_sum exact_negate(exact_sum a) {
    const ulong lo = ~a.y + 1ul;
    return (exact_sum)(~a.x + (lo == 0ul ? 1ul : 0ul), lo);
}

inline exact_sum exact_from_float(float v) {
    const uint bits = as_uint(v);
    const int e = (int)((bits >> 23) & 0xffu);
    if (e == 0)
        return (exact_sum)(0ul); /* zero or subnormal: below 2^-64 anyway */
    const ulong m = (ulong)((bits & 0x7fffffu) | 0x800000u);
    /* v = m 2^(e - 150); lo's lowest bit weighs 2^-64. */
    const int s = e - 86;
    exact_sum r;
    if (s <= -24)
        r = (exact_sum)(0ul);
    else if (s < 0)
        r = (exact_sum)(0ul, m >> (uint)(-s));
    else if (s == 0)
        r = (exact_sum)(0ul, m);
    else if (s < 64)
        r = (exact_sum)(m >> (uint)(64 - s), m << (uint)s);
    else if (s <= 103)
        r = (exact_sum)(m << (uint)(s - 64), 0ul);
    else
        r = (exact_sum)(0x7ffffffffffffffful, ~0ul); /* infinities and NaN never get here */
    return (bits >> 31) ? exact_negate(r) : r;
}

inline exact_sum exact_add(exact_sum a, exact_sum b) {
    const ulong lo = a.y + b.y;
    return (exact_sum)(a.x + b.x + (lo < a.y ? 1ul : 0ul), lo);
}

/* The nearest float, give or take the rounding of its two halves. */
inline float exact_to_float(exact_sum a) {
    const int negative = (long)a.x < 0;
    if (negative)
        a = exact_negate(a);
    const float v = (float)a.x + (float)a.y * 0x1p-64f;
    return negative ? -v : v;
}

#endif
