/* Ray traversal of the uniform triangle grid by 3D-DDA (Amanatides and Woo).
 * A triangle stored in several cells is accepted only when its hit lies in
 * the cell being visited (up to a small slack), so the first hit found is the
 * closest. Epsilons are relative to the scene's extent. */
#ifndef VCT_GRID_TRAVERSE_H
#define VCT_GRID_TRAVERSE_H

#include "accel/hit.h"
#include "accel/ray_tri.h"
#include "vct_types.h"

typedef struct accel_view {
    vct_accel_desc desc;
    __global const uint *cell_bits;   /* 1 bit per cell: holds any triangle */
    __global const uint *cell_ranges; /* (start, end) per cell into tri_ids */
    __global const uint *tri_ids;
    __global const float4 *tri_vertices; /* 3 per triangle */
} accel_view;

/* The first kernel arguments of every kernel that traverses the grid, and
 * the view built from them (set by the host's vct_grid_set_args). */
#define ACCEL_ARGS                                                                                 \
    vct_accel_desc accel, __global const uint *cell_bits, __global const uint *cell_ranges,        \
        __global const uint *tri_ids, __global const float4 *tri_vertices
#define ACCEL_VIEW() ((accel_view){accel, cell_bits, cell_ranges, tri_ids, tri_vertices})

inline uint grid_cell_index(uint3 c, uint4 res) {
    return c.x + res.x * (c.y + res.y * c.z);
}

/* Closest hit in (tmin, tmax]; any_hit: stop at the first one (shadow rays). */
__attribute__((always_inline)) inline int accel_trace(const accel_view *g, float3 org, float3 dir,
                                                      float tmin, float tmax, int any_hit,
                                                      hit_record *hit) {
    const float3 lo = g->desc.origin.xyz;
    const float3 size = g->desc.cell_size.xyz;
    const uint4 res = g->desc.res;
    const float3 hi = lo + size * convert_float3(res.xyz);
    const float3 inv = 1.0f / dir; /* +-inf on zero components */
    /* fmin/fmax drop the NaN of 0 * inf, so axis-parallel rays work. */
    const float3 t0 = (lo - org) * inv, t1 = (hi - org) * inv;
    const float3 tnear = fmin(t0, t1), tfar = fmax(t0, t1);
    float enter = fmax(fmax(tnear.x, tnear.y), fmax(tnear.z, tmin));
    float leave = fmin(fmin(tfar.x, tfar.y), fmin(tfar.z, tmax));
    if (!(enter <= leave))
        return 0;
    const ray_shear shear = ray_shear_make(org, dir);
    const float slack = g->desc.cell_size.w / length(dir);

    const float3 p = org + dir * enter;
    const int3 last = convert_int3(res.xyz) - 1;
    int3 cell = clamp(convert_int3_rtn((p - lo) * g->desc.inv_cell.xyz), (int3)(0), last);
    const int3 step = (int3)(dir.x > 0.0f ? 1 : -1, dir.y > 0.0f ? 1 : -1, dir.z > 0.0f ? 1 : -1);
    /* Exit distances of the first cell from its bounds, then one cell width
     * (tdelta) per step; axes the ray does not move along never come first. */
    const int3 parallel = dir == 0.0f;
    const float3 next_bound =
        lo + size * convert_float3(cell + (int3)(step.x > 0, step.y > 0, step.z > 0));
    float3 tnext = select((next_bound - org) * inv, (float3)(INFINITY), parallel);
    const float3 tdelta = select(fabs(size * inv), (float3)(INFINITY), parallel);
    /* The cell index and the cells left before the ray leaves the grid
     * advance with each step: no multiply, and one axis to test. */
    uint index = grid_cell_index(convert_uint3(cell), res);
    const int3 index_step = step * (int3)(1, (int)res.x, (int)(res.x * res.y));
    int3 left = select(cell, last - cell, step > 0);

    float best = tmax;
    int found = 0;
    for (;;) {
        const float cell_exit = fmin(fmin(tnext.x, tnext.y), tnext.z);
        /* The bitmask is small enough to stay in cache: empty cells cost no
         * trip to the range array. */
        if (g->cell_bits[index >> 5] & (1u << (index & 31u))) {
            const uint2 range = vload2(index, g->cell_ranges);
            for (uint i = range.x; i < range.y; ++i) {
                const uint tri = g->tri_ids[i];
                const float4 a = g->tri_vertices[3 * tri]; /* w: the alpha-mask slot */
                float t, u, v;
                if (ray_triangle(&shear, a.xyz, g->tri_vertices[3 * tri + 1].xyz,
                                 g->tri_vertices[3 * tri + 2].xyz, tmin, best, &t, &u, &v) &&
                    (t < best || !found || tri < hit->tri) && t <= cell_exit + slack &&
                    !accel_masked(g->tri_vertices, as_uint(a.w), u, v)) {
                    best = t;
                    found = 1;
                    hit->t = t;
                    hit->u = u;
                    hit->v = v;
                    hit->tri = tri;
                    if (any_hit)
                        return 1;
                }
            }
            if (found && best <= cell_exit)
                return 1;
        }
        if (cell_exit > leave)
            return found;
        /* Step along the axis whose boundary comes first. */
        if (tnext.x <= tnext.y && tnext.x <= tnext.z) {
            if (--left.x < 0)
                return found;
            index += index_step.x;
            tnext.x += tdelta.x;
        } else if (tnext.y <= tnext.z) {
            if (--left.y < 0)
                return found;
            index += index_step.y;
            tnext.y += tdelta.y;
        } else {
            if (--left.z < 0)
                return found;
            index += index_step.z;
            tnext.z += tdelta.z;
        }
    }
}

#endif
