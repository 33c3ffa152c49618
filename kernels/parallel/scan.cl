/* Exclusive/inclusive scan of uint and stream compaction.
 *
 * Reduce-then-scan in three launches: scan_reduce sums each group's span
 * (64-bit), scan_group_offsets scans those sums serially and reports the
 * total, scan_downsweep rescans each span with its group offset. A group walks
 * its span in tiles of WG * ITEM_SPAN elements, each work-item owning
 * ITEM_SPAN consecutive ones, so one kernel serves GPUs (WG 256, short spans)
 * and CPUs (WG 1, long spans walked at memory speed).
 *
 * Options: -D WG=<work-group size> -D ITEM_SPAN=<elements per work-item>. */
#include "parallel/wg_scan.h"

#ifndef WG
#define WG 256
#endif
#ifndef ITEM_SPAN
#define ITEM_SPAN 4
#endif

/* as_flags: count non-zero inputs as 1 (for compaction) instead of summing. */
inline uint scan_value(uint x, uint as_flags) {
    return as_flags ? (uint)(x != 0u) : x;
}

__kernel __attribute__((reqd_work_group_size(WG, 1, 1))) void
scan_reduce(__global const uint *in, uint n, uint span, uint as_flags, __global ulong *group_sums) {
    __local ulong partial[WG];
    const uint lid = get_local_id(0);
    uint begin, end;
    group_range(get_group_id(0), span, n, &begin, &end);
    ulong sum = 0;
    for (uint i = begin + lid; i < end; i += WG)
        sum += scan_value(in[i], as_flags);
    ulong total;
    wg_exclusive_scan_ulong(sum, partial, &total);
    if (lid == 0)
        group_sums[get_group_id(0)] = total;
}

/* One work-item: groups are few (at most 1024). offsets[groups] = total. */
__kernel void scan_group_offsets(__global ulong *sums, uint groups) {
    ulong running = 0;
    for (uint g = 0; g < groups; ++g) {
        ulong s = sums[g];
        sums[g] = running;
        running += s;
    }
    sums[groups] = running;
}

__kernel __attribute__((reqd_work_group_size(WG, 1, 1))) void
scan_downsweep(__global const uint *in, __global uint *out, uint n, uint span, uint as_flags,
               uint inclusive, __global const ulong *group_offsets) {
    __local ulong item_sums[WG];
    const uint lid = get_local_id(0);
    uint begin, end;
    group_range(get_group_id(0), span, n, &begin, &end);
    ulong carry = group_offsets[get_group_id(0)];
    for (uint tile = begin; tile < end; tile += WG * ITEM_SPAN) {
        const uint mine = tile + lid * ITEM_SPAN;
        const uint mine_end = min(end, mine + ITEM_SPAN);
        ulong sum = 0;
        for (uint i = mine; i < mine_end; ++i)
            sum += scan_value(in[i], as_flags);
        ulong tile_total;
        ulong prefix = carry + wg_exclusive_scan_ulong(sum, item_sums, &tile_total);
        for (uint i = mine; i < mine_end; ++i) {
            const uint x = scan_value(in[i], as_flags);
            if (inclusive) {
                prefix += x;
                out[i] = (uint)prefix;
            } else {
                out[i] = (uint)prefix;
                prefix += x;
            }
        }
        carry += tile_total;
    }
}

/* Compaction: out[offsets[i]] = in[i] where flags[i] != 0 (offsets from an
 * exclusive flag scan), which keeps the input order. */
__kernel void compact_scatter(__global const uint *in, __global const uint *flags,
                              __global const uint *offsets, uint n, __global uint *out) {
    const uint i = get_global_id(0);
    if (i < n && flags[i] != 0u)
        out[offsets[i]] = in[i];
}
