/* Segmented sum over runs of equal keys in a sorted key array.
 *
 * segment_heads flags the first element of each run; an exclusive scan of the
 * flags (scan.cl) numbers the runs; segment_starts records each run's first
 * index and key; segment_sum adds each run's values serially in input order,
 * so the float result is identical on every device and schedule.
 *
 * Options: -D KEY_T=uint|ulong. */
#ifndef KEY_T
#define KEY_T uint
#endif

__kernel void segment_heads(__global const KEY_T *keys, uint n, __global uint *heads) {
    const uint i = get_global_id(0);
    if (i < n)
        heads[i] = (i == 0 || keys[i] != keys[i - 1]) ? 1u : 0u;
}

__kernel void segment_starts(__global const KEY_T *keys, __global const uint *heads,
                             __global const uint *run_index, uint n, __global uint *starts,
                             __global KEY_T *run_keys) {
    const uint i = get_global_id(0);
    if (i < n && heads[i]) {
        starts[run_index[i]] = i;
        run_keys[run_index[i]] = keys[i];
    }
}

__kernel void segment_sum_f4(__global const float4 *values, __global const uint *starts, uint runs,
                             uint n, __global float4 *sums) {
    const uint r = get_global_id(0);
    if (r >= runs)
        return;
    const uint end = r + 1 < runs ? starts[r + 1] : n;
    float4 sum = (float4)(0.0f);
    for (uint i = starts[r]; i < end; ++i)
        sum += values[i];
    sums[r] = sum;
}
