/* The frame a set of diffuse cones is laid out in about a surface's normal,
 * turned about it by an angle hashed from a seed of the point the cones
 * leave (a voxel's key; the cell of a sixteenth of a voxel a camera hit lies
 * in). With one
 * frame for every point of a plane, all of them look along the same few
 * directions: a small bright patch (a spot light's pool on a floor) falls
 * into a cone at some points and between cones at others, and the gathered
 * light comes out in blotches the size of the patch's distance. Turned per
 * voxel, neighbouring voxels and pixels look along different directions,
 * and the patch is met as fine-grained variation that the sparse passes'
 * fill averages. The price: a moving camera's indirect light changes a
 * little more from frame to frame (bench/flicker.sh). The frame depends on
 * the normal's axis, not its sign, so that a surface wound the other way
 * gathers along the same directions. */
#ifndef VCT_CONE_FRAME_H
#define VCT_CONE_FRAME_H

#include "scene/bsdf.h" /* basis_of */
#include "scene/rng.h"
#include "scene/turn.h"

/* A camera hit's seed: the cell of a sixteenth of a voxel that holds it,
 * so that neighbouring pixels turn their gather apart and its noise is
 * a pixel's, which the sparse fill and the indirect filter average (cells
 * of 2x2x2 voxels left blotches their size: the suite's mean NRMSE 0.0629
 * against 0.0618). The rounding of the hit's position (a triangle wound the
 * other way, a band of rows on another device) does not change it but at a
 * cell's border. */
inline uint cone_point_seed(float3 origin, float side, uint res, float3 p) {
    const float cells = (float)(res * 16u);
    const int3 c = convert_int3_rtn((p - origin) * (cells / side));
    return (uint)c.x ^ rng_hash((uint)c.y ^ rng_hash((uint)c.z));
}

inline void cone_frame(float3 n, uint seed, float3 *t, float3 *b) {
    const float3 a = fabs(n);
    const float major = a.x >= a.y && a.x >= a.z ? n.x : (a.y >= a.z ? n.y : n.z);
    float3 t0, b0;
    basis_of(major < 0.0f ? -n : n, &t0, &b0);
    const float2 cs = turn_cos_sin((float)(rng_hash(seed) >> 8) * (1.0f / 16777216.0f));
    *t = cs.x * t0 + cs.y * b0;
    *b = cs.x * b0 - cs.y * t0;
}

#endif
