/* Triangle vertices gathered once into 3 float4 per triangle, the layout
 * every acceleration structure and ray query reads; w holds a masked
 * triangle's mask record (accel/alpha_mask.h), from mask_slot when
 * has_masks, else 0. */
__kernel void gather_tri_vertices(__global const float *positions, __global const uint *triangles,
                                  uint count, __global const uint *mask_slot, uint has_masks,
                                  __global float4 *tri_vertices) {
    const uint t = get_global_id(0);
    if (t >= count)
        return;
    for (int k = 0; k < 3; ++k) {
        const uint v = triangles[3 * t + k];
        const float w = k == 0 && has_masks ? as_float(mask_slot[t]) : 0.0f;
        tri_vertices[3 * t + k] =
            (float4)(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2], w);
    }
}
