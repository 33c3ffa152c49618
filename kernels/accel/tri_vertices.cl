/* Triangle vertices gathered once into 3 float4 per triangle, the layout
 * every acceleration structure and ray query reads. */
__kernel void gather_tri_vertices(__global const float *positions, __global const uint *triangles,
                                  uint count, __global float4 *tri_vertices) {
    const uint t = get_global_id(0);
    if (t >= count)
        return;
    for (int k = 0; k < 3; ++k) {
        const uint v = triangles[3 * t + k];
        tri_vertices[3 * t + k] =
            (float4)(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2], 0.0f);
    }
}
