/* Work-group scans in local memory (Hillis-Steele). Every work-item of the
 * group must call them, with `buf` holding WG entries. WG is a compile-time
 * work-group size. */
#ifndef VCT_WG_SCAN_H
#define VCT_WG_SCAN_H

#define VCT_DEFINE_WG_EXCLUSIVE_SCAN(NAME, T)                                                      \
    T NAME(T x, __local T *buf, T *total) {                                                        \
        const uint lid = get_local_id(0);                                                          \
        const uint wg = get_local_size(0);                                                         \
        buf[lid] = x;                                                                              \
        barrier(CLK_LOCAL_MEM_FENCE);                                                              \
        for (uint off = 1; off < wg; off <<= 1) {                                                  \
            T t = lid >= off ? buf[lid - off] : (T)0;                                              \
            barrier(CLK_LOCAL_MEM_FENCE);                                                          \
            buf[lid] += t;                                                                         \
            barrier(CLK_LOCAL_MEM_FENCE);                                                          \
        }                                                                                          \
        T inclusive = buf[lid];                                                                    \
        *total = buf[wg - 1];                                                                      \
        barrier(CLK_LOCAL_MEM_FENCE);                                                              \
        return inclusive - x;                                                                      \
    }

VCT_DEFINE_WG_EXCLUSIVE_SCAN(wg_exclusive_scan_uint, uint)
VCT_DEFINE_WG_EXCLUSIVE_SCAN(wg_exclusive_scan_ulong, ulong)

/* The range [begin, end) of elements that work-group `group` owns when n
 * elements are split into spans of `span`. 64-bit so that n near 2^32 is safe. */
inline void group_range(uint group, uint span, uint n, uint *begin, uint *end) {
    ulong b = (ulong)group * span;
    ulong e = b + span;
    *begin = (uint)min(b, (ulong)n);
    *end = (uint)min(e, (ulong)n);
}

#endif
