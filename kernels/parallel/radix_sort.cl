/* Stable LSD radix sort of (key, value) pairs, one digit of RADIX_BITS per pass.
 *
 * Per pass: radix_histogram counts each group's digits into
 * hist[digit * groups + group]; an exclusive scan of hist (scan.cl) gives every
 * (digit, group) its first output slot; radix_scatter walks the group's span
 * in order and writes each pair to its slot. With WG > 1 a tile is first
 * sorted by digit in local memory by RADIX_BITS stable one-bit splits, which
 * keeps the order of equal digits, so the sort is stable and deterministic.
 *
 * Options: -D KEY_T=uint|ulong -D RADIX_BITS=<1..8> -D WG=<work-group size>. */
#include "parallel/wg_scan.h"

#ifndef KEY_T
#define KEY_T uint
#endif
#ifndef RADIX_BITS
#define RADIX_BITS 4
#endif
#ifndef WG
#define WG 256
#endif
#define RADIX (1u << RADIX_BITS)

inline uint digit_of(KEY_T key, uint shift) {
    return (uint)(key >> shift) & (RADIX - 1u);
}

__kernel __attribute__((reqd_work_group_size(WG, 1, 1))) void
radix_histogram(__global const KEY_T *keys, uint n, uint span, uint shift, uint groups,
                __global uint *hist) {
    __local uint counts[RADIX];
    const uint lid = get_local_id(0);
    const uint group = get_group_id(0);
    for (uint d = lid; d < RADIX; d += WG)
        counts[d] = 0;
    barrier(CLK_LOCAL_MEM_FENCE);
    uint begin, end;
    group_range(group, span, n, &begin, &end);
    for (uint i = begin + lid; i < end; i += WG) {
#if WG == 1
        counts[digit_of(keys[i], shift)]++;
#else
        atomic_inc(&counts[digit_of(keys[i], shift)]);
#endif
    }
    barrier(CLK_LOCAL_MEM_FENCE);
    for (uint d = lid; d < RADIX; d += WG)
        hist[d * groups + group] = counts[d];
}

__kernel __attribute__((reqd_work_group_size(WG, 1, 1))) void
radix_scatter(__global const KEY_T *keys_in, __global const uint *values_in, uint n, uint span,
              uint shift, uint groups, __global const uint *offsets, __global KEY_T *keys_out,
              __global uint *values_out) {
    __local uint next_slot[RADIX];
    const uint lid = get_local_id(0);
    const uint group = get_group_id(0);
    for (uint d = lid; d < RADIX; d += WG)
        next_slot[d] = offsets[d * groups + group];
    barrier(CLK_LOCAL_MEM_FENCE);
    uint begin, end;
    group_range(group, span, n, &begin, &end);
#if WG == 1
    for (uint i = begin; i < end; ++i) {
        const KEY_T key = keys_in[i];
        const uint slot = next_slot[digit_of(key, shift)]++;
        keys_out[slot] = key;
        values_out[slot] = values_in[i];
    }
#else
    __local uint sorted_digit[WG];
    __local uint sorted_origin[WG];
    __local uint scan_buf[WG];
    __local uint digit_start[RADIX];
    for (uint tile = begin; tile < end; tile += WG) {
        const uint i = tile + lid;
        /* Past the end: the largest digit; a stable split keeps these last. */
        sorted_digit[lid] = i < end ? digit_of(keys_in[i], shift) : RADIX - 1u;
        sorted_origin[lid] = lid;
        barrier(CLK_LOCAL_MEM_FENCE);
        for (uint b = 0; b < RADIX_BITS; ++b) {
            const uint d = sorted_digit[lid];
            const uint o = sorted_origin[lid];
            const uint bit = (d >> b) & 1u;
            uint ones_total;
            const uint ones_before = wg_exclusive_scan_uint(bit, scan_buf, &ones_total);
            const uint pos = bit ? (WG - ones_total) + ones_before : lid - ones_before;
            barrier(CLK_LOCAL_MEM_FENCE);
            sorted_digit[pos] = d;
            sorted_origin[pos] = o;
            barrier(CLK_LOCAL_MEM_FENCE);
        }
        const uint d = sorted_digit[lid];
        if (lid == 0 || sorted_digit[lid - 1] != d)
            digit_start[d] = lid;
        barrier(CLK_LOCAL_MEM_FENCE);
        const uint src = tile + sorted_origin[lid];
        if (src < end) {
            const uint slot = next_slot[d] + (lid - digit_start[d]);
            keys_out[slot] = keys_in[src];
            values_out[slot] = values_in[src];
        }
        barrier(CLK_LOCAL_MEM_FENCE);
        /* The last work-item of each digit run advances that digit's slot. */
        if (lid == WG - 1 || sorted_digit[lid + 1] != d)
            next_slot[d] += lid + 1 - digit_start[d];
        barrier(CLK_LOCAL_MEM_FENCE);
    }
#endif
}
