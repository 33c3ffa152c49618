/* Cone marching through the filtered brick hierarchy.
 *
 * A cone of half-angle theta from origin o along unit d is sampled at
 * distances t, starting one voxel out. Its diameter there is
 * D = max(2 t tan(theta), 2 voxels); it reads the level whose samples are D / 2
 * apart (level L-1 samples are one voxel apart, each level up doubles that),
 * interpolating between the two nearest levels, and steps on by
 * step * D. A sample's opacity stands for a thickness of its spacing; for a
 * different step it is corrected to 1 - (1 - a)^(step / spacing), its colour
 * scaled alike. Samples composite front to back:
 *     C += (1 - A) c,  A += (1 - A) a
 * (c is premultiplied, as the pool stores it). The march stops when A
 * reaches the stop opacity, or when the cone leaves the volume, after one
 * last sample just inside it for the way from the previous sample's step to
 * the boundary: then what it still sees, (1 - A), is the environment's
 * radiance.
 *
 * Every sample is seen from the side of its surface the cone starts on
 * (voxel_side.h): a wall lit on one face shows its dark face to cones from
 * behind it.
 *
 * Build with -DVCT_ANISOTROPIC to read the six directional radiance pools
 * (weighted by the squared direction components) at levels 0 .. L-2, and
 * with -DVCT_CONE_NEAREST_LEVEL to read, instead of the two levels around
 * the diameter, the nearest one alone, its opacity corrected for that
 * level's own spacing. */
#ifndef VCT_CONE_TRACE_H
#define VCT_CONE_TRACE_H

#include "voxel/brick_pool.h"
#include "voxel/octree.h"
#include "vct_types.h"

#define CONE_MAX_STEPS 4096u

#ifdef VCT_ANISOTROPIC
#define CONE_POOLS                                                                                 \
    BRICK_POOL radiance, BRICK_POOL shade_pool, BRICK_POOL plane_pool, BRICK_POOL dir0,            \
        BRICK_POOL dir1, BRICK_POOL dir2, BRICK_POOL dir3, BRICK_POOL dir4, BRICK_POOL dir5,       \
        BRICK_POOL dark0, BRICK_POOL dark1, BRICK_POOL dark2, BRICK_POOL dark3, BRICK_POOL dark4,  \
        BRICK_POOL dark5
#define CONE_POOLS_PASS                                                                            \
    radiance, shade_pool, plane_pool, dir0, dir1, dir2, dir3, dir4, dir5, dark0, dark1, dark2,     \
        dark3, dark4, dark5
#else
#define CONE_POOLS BRICK_POOL radiance, BRICK_POOL shade_pool, BRICK_POOL plane_pool
#define CONE_POOLS_PASS radiance, shade_pool, plane_pool
#endif

typedef struct cone_result {
    float3 radiance; /* what the cone sees, the environment included */
    float alpha;     /* opacity accumulated along it */
    float ao_alpha;  /* opacity accumulated within the AO distance */
    float level_sum; /* sum of the (fractional) levels sampled */
    uint samples;
    int left; /* 1: it left the volume */
} cone_result;

/* A sided surface (voxel_side.h) is seen from its darker side where the
 * cone's origin lies behind its plane, from its brighter side where it lies
 * before it, and as a blend within SIDE_TOLERANCE sample spacings of it.
 * Where surfaces meet, one plane stands for several:
 *  - planes whose normals disagree (the filtered normal is short) count
 *    less, not at all below SIDE_COHERENT_MIN of a unit normal's length;
 *  - surfaces lit much more weigh more (voxel_side.h), so a dark floor has
 *    no say about a sunlit wall beside it;
 *  - at an object's convex edge, a mean plane through both faces puts an
 *    origin that sees one face from before it, beside the other, behind:
 *    such views see the darker side: what darkens the atrium's columns and
 *    the Cornell box's blocks (README, "The scene suite", with what was
 *    tried against it).
 * A side is seen only by a cone that comes at it: one heading along the
 * side's own normal (leaving it, or grazing it: the floor a cone starts
 * from, which its wide samples take in further on) sees its light fade,
 * fully by a normal component of 1 / SIDE_FACING_FADE. Without this, a lit
 * surface lit itself through its own cones, more so the finer the voxels. */
#define SIDE_TOLERANCE 0.05f
#define SIDE_FACING_FADE 2.0f
#define SIDE_COHERENT_MIN 0.3f
#define SIDE_COHERENT_FULL 0.7f

/* A sample whose plane passes the cone's origin at the distance the cone
 * was lifted off its surface (cone_lift), on the side the cone leaves, is
 * that surface, which a sample beside the cone takes in edge-on: it
 * neither lights nor hides what the cone looks for. It counts less the
 * nearer its plane lies to that distance (none from SIDE_OWN_REACH sample
 * spacings away), as far as its planes agree (side_coherence). Without
 * this, the outer cones of a wall read the wall itself as a dark occluder
 * at coarse levels (the scene suite's NRMSE 0.0996 -> 0.0988 at 128^2,
 * 0.1101 -> 0.1093 at 256^2). A plane through the origin (a cone started
 * inside a wall) or ahead of the cone (a wall it heads for) still stops it. */
#define SIDE_OWN_REACH 1.0f

/* How far along to the darker side a sample is seen from `dist` (volume
 * units) before its plane: 0 (before it) .. 1 (behind it); spacing: the
 * level's sample spacing in volume units. */
inline float side_behind(float dist, float spacing) {
    return clamp(0.5f - dist / (2.0f * SIDE_TOLERANCE * spacing), 0.0f, 1.0f);
}

/* How much of a side whose unit normal has component `facing` along the
 * cone's direction the cone sees (1: it comes at the side). */
inline float side_facing(float facing) {
    return clamp(1.0f - SIDE_FACING_FADE * facing, 0.0f, 1.0f);
}

/* How much a sample whose plane passes `dist` (volume units) from a cone's
 * origin lifted `lift` off its surface is that surface: 1 at the lift, 0
 * from SIDE_OWN_REACH sample spacings away from it; 0 for lift < 0 and for
 * a plane the cone heads for (`facing`: the cone's direction along the
 * plane's normal, of the other sign than dist). */
inline float side_own(float dist, float facing, float lift, float spacing) {
    return lift < 0.0f || dist * facing < 0.0f
               ? 0.0f
               : clamp(1.0f - fabs(fabs(dist) - lift) / (SIDE_OWN_REACH * spacing), 0.0f, 1.0f);
}

/* How much a sample of plane pl and shade sh is one surface's: planes
 * whose normals disagree count less (both weigh each voxel by its opacity
 * times how one-sided it is, voxel_side.h). */
inline float side_coherence(float4 sh, float4 pl) {
    return clamp((length(pl.xyz) / fmax(sh.w, 1e-6f) - SIDE_COHERENT_MIN) /
                     (SIDE_COHERENT_FULL - SIDE_COHERENT_MIN),
                 0.0f, 1.0f);
}

/* Brick b's trilinear sample at `at` ([0, 2]^3 texel units) of a level-`level`
 * node, seen by a cone travelling along d from from.xyz (volume units less
 * 0.5), lifted from.w (volume units; < 0: a ray's hit, no lift) off its
 * surface; spacing: the level's sample spacing in volume units. *coherence
 * drops to side_coherence where a one-sided surface's planes disagree. */
VCT_INLINE float4 cone_brick_sample(CONE_POOLS, uint2 pool, uint b, float3 at, uint level,
                                    uint levels, float3 d, float4 from, float spacing,
                                    float *coherence) {
#ifdef VCT_BRICK_IMAGE
#define CONE_POOL_READ(p) brick_sample(p, pool, b, at)
#else
    const brick_lerp l = brick_lerp_at(pool, b, at); /* shared by every pool */
#define CONE_POOL_READ(p) brick_lerp_read(p, l)
#endif
    float4 s;
#ifdef VCT_ANISOTROPIC
    const int directional = level + 1u < levels;
    const float3 w = d * d;
    if (directional) {
        const float4 sx = d.x >= 0.0f ? CONE_POOL_READ(dir0) : CONE_POOL_READ(dir3);
        const float4 sy = d.y >= 0.0f ? CONE_POOL_READ(dir1) : CONE_POOL_READ(dir4);
        const float4 sz = d.z >= 0.0f ? CONE_POOL_READ(dir2) : CONE_POOL_READ(dir5);
        s = (w.x * sx + w.y * sy + w.z * sz) / (w.x + w.y + w.z);
    } else
#endif
    {
        s = CONE_POOL_READ(radiance);
    }
    (void)level;
    (void)levels;
    (void)d;
    if (!(s.w > 0.0f))
        return s; /* empty here: no side to see */
    const float4 pl = CONE_POOL_READ(plane_pool);
    const float len = length(pl.xyz);
    if (!(len > 1e-6f))
        return s; /* no one-sided surface */
    const float dist = (dot(pl.xyz, from.xyz) - pl.w) / len;
    const float4 shade = CONE_POOL_READ(shade_pool);
    const float coherent = side_coherence(shade, pl);
    *coherence = fmin(*coherence, coherent);
    const float facing = dot(d, pl.xyz) / len;
    const float front = mix(1.0f, side_facing(facing), coherent),
                back = mix(1.0f, side_facing(-facing), coherent);
    const float turn =
        dist < SIDE_TOLERANCE * spacing ? side_behind(dist, spacing) * coherent : 0.0f;
    const float keep = 1.0f - coherent * side_own(dist, facing, from.w, spacing);
    if (!(turn > 0.0f))
        return keep * (float4)(s.xyz * front, s.w); /* before the plane */
    float4 dark = (float4)(s.xyz - shade.xyz, s.w); /* isotropic: itself less the shade */
#ifdef VCT_ANISOTROPIC
    if (directional) {
        const float4 dx = d.x >= 0.0f ? CONE_POOL_READ(dark0) : CONE_POOL_READ(dark3);
        const float4 dy = d.y >= 0.0f ? CONE_POOL_READ(dark1) : CONE_POOL_READ(dark4);
        const float4 dz = d.z >= 0.0f ? CONE_POOL_READ(dark2) : CONE_POOL_READ(dark5);
        dark = (w.x * dx + w.y * dy + w.z * dz) / (w.x + w.y + w.z);
    }
#endif
    return keep * (float4)(mix(s.xyz * front, dark.xyz * back, turn), mix(s.w, dark.w, turn));
#undef CONE_POOL_READ
}

/* The octree nodes, from the root down to level `depth`, that hold the
 * previous sample's cell (`cell`, in cells of the finest brick level). A
 * cone's samples lie close together, so the next descent starts at the
 * deepest node the two cells share instead of at the root. */
typedef struct cone_path {
    uint node[VCT_VOXEL_MAX_LEVELS];
    uint3 cell;
    uint depth;
} cone_path;

inline cone_path cone_path_root(void) {
    cone_path p;
    p.node[0] = 0u;
    p.cell = (uint3)(0u);
    p.depth = 0u;
    return p;
}

/* The pool at `at` (volume units, [0, 1)^3) and fractional level `level`:
 * one descent reads both neighbouring levels. Empty nodes read 0.
 * *coherence: the least of the levels' (cone_brick_sample), 1 to start. */
VCT_INLINE float4 cone_sample(CONE_POOLS, uint2 pool, __global const uint *child, uint levels,
                              float3 at, float level, float3 d, float4 from, cone_path *path,
                              float *coherence) {
    const uint coarse = (uint)level, finest = levels - 1u;
    const float f = level - (float)coarse;
    const uint fine = f > 0.0f ? min(coarse + 1u, finest) : coarse; /* a whole level: one */
    float4 value[2] = {(float4)(0.0f), (float4)(0.0f)};
    /* Scaling by a power of two is exact: a coarser level's cell is the
     * finest one's shifted right. */
    const uint3 cell = min(convert_uint3(at * (float)(1u << finest)), (uint3)((1u << finest) - 1u));
    /* the levels whose cells agree lie above the highest differing bit */
    const uint3 diff = cell ^ path->cell;
    const uint differ = diff.x | diff.y | diff.z;
    const uint shared = differ == 0u ? finest : finest - 1u - (31u - clz(differ));
    uint depth = min(shared, path->depth);
    for (uint l = min(depth, coarse); l <= fine; ++l) {
        if (l > depth) {
            const uint first = child[path->node[l - 1u]];
            if (first == OCT_NULL)
                break; /* empty here and below */
            path->node[l] = first + octant_of_cell(cell, finest - l);
            depth = l;
        }
        if (l >= coarse) {
            const uint b = brick_of(child, path->node[l]);
            if (b == BRICK_NULL)
                break;
            const float3 in_cell = at * (float)(1u << l) - convert_float3(cell >> (finest - l));
            value[l - coarse] =
                cone_brick_sample(CONE_POOLS_PASS, pool, b, 2.0f * in_cell, l, levels, d, from,
                                  0.5f / (float)(1u << l), coherence);
        }
    }
    path->cell = cell;
    path->depth = depth;
    return fine == coarse ? value[0] : value[0] + f * (value[1] - value[0]);
}

/* The fractional octree level whose samples are diameter / 2 apart (finest
 * the leaves' level, min_diameter two leaf voxels), clamped to the tree. */
inline float cone_level(float finest, float diameter, float min_diameter) {
    return clamp(finest - native_log2(diameter / min_diameter), 0.0f, finest);
}

/* Where a cone from surface point p with normal n starts: lifted off the
 * surface by the offset (in voxels), so that it does not see its own voxel. */
/* The cone offset in world units. */
inline float cone_lift(const vct_cone_desc *c) {
    return c->march.y * (c->volume.w / (float)c->res.x);
}

inline float3 cone_origin(const vct_cone_desc *c, float3 p, float3 n) {
    return p + n * cone_lift(c);
}

/* 1 - (1 - a)^ratio: opacity a of one thickness over `ratio` of it. pow is
 * slow on CPU devices (on PoCL, one pow per cone, for the last sample at the
 * volume's boundary, cost the diffuse cones about 10%), and the common
 * ratios (2, 1, 1/2, 1/4) need no power at all. */
inline float opacity_over(float a, float ratio) {
    const float clear = 1.0f - a;
    if (ratio == 1.0f)
        return a;
    if (ratio == 2.0f)
        return a * (2.0f - a);
    if (ratio == 0.5f)
        return 1.0f - sqrt(clear);
    if (ratio == 0.25f)
        return 1.0f - sqrt(sqrt(clear));
    return clear > 0.0f ? 1.0f - native_exp2(ratio * native_log2(clear)) : 1.0f;
}

/* Distance along unit d from origin to where it leaves the volume's cube,
 * if it is inside. */
inline float cone_volume_exit(const vct_cone_desc *c, float3 origin, float3 d) {
    const float3 from = (origin - c->volume.xyz) * c->ambient.w, along = d * c->ambient.w;
    const float3 face = select((float3)(0.0f), (float3)(1.0f), along > 0.0f);
    const float3 t = select((face - from) / along, (float3)(INFINITY), along == 0.0f);
    return fmin(fmin(t.x, t.y), t.z);
}

/* Composites sample s, whose opacity stands for one spacing, over `ratio`
 * spacings, behind what r has gathered. */
inline void cone_composite(cone_result *r, float4 s, float ratio) {
    const float a_in = clamp(s.w, 0.0f, 1.0f);
    const float a = a_in > 0.0f ? opacity_over(a_in, ratio) : 0.0f;
    const float3 colour = a_in > 0.0f ? s.xyz * (a / a_in) : (float3)(0.0f);
    r->radiance += (1.0f - r->alpha) * colour;
    r->alpha += (1.0f - r->alpha) * a;
}

/* Marches one cone up to distance max_t; origin is already lifted off its
 * surface. Each sample stands for the step around it. Where the next sample
 * would lie outside the volume, one last sample just inside the boundary
 * stands for the rest of the way, so that a wall on the volume's face is not
 * stepped over (the Cornell box's walls are). */
VCT_INLINE cone_result cone_trace(CONE_POOLS, __global const uint *child, const vct_cone_desc *c,
                                  float3 origin, float3 d, float tan_half, float max_t) {
    cone_result r = {(float3)(0.0f), 0.0f, 0.0f, 0.0f, 0u, 0};
    const uint levels = c->res.y;
    const float voxel = c->volume.w / (float)c->res.x, min_diameter = 2.0f * voxel;
    const float finest = (float)(levels - 1u), root_spacing = voxel * exp2(finest);
    const float exit = cone_volume_exit(c, origin, d);
    float t = voxel, last = 0.0f; /* last: the boundary sample's thickness */
    cone_path path = cone_path_root();
    /* the origin as the bricks' planes measure it, and its lift */
    const float4 from =
        (float4)((origin - c->volume.xyz) * c->ambient.w - 0.5f, c->march.y / (float)c->res.x);
    for (uint i = 0; i < CONE_MAX_STEPS && t <= max_t; ++i) {
        const float3 at = (origin + t * d - c->volume.xyz) * c->ambient.w;
        if (any(at < 0.0f) || any(at >= 1.0f)) {
            r.left = 1;
            break;
        }
        const float diameter = fmax(2.0f * t * tan_half, min_diameter);
#ifdef VCT_CONE_NEAREST_LEVEL
        const float level = rint(cone_level(finest, diameter, min_diameter));
        const float spacing = voxel * exp2(finest - level);
        const int follows = 0; /* the spacing is the level's own */
#else
        const float level = cone_level(finest, diameter, min_diameter);
        const float spacing = level > 0.0f ? 0.5f * diameter : root_spacing;
        const int follows = level > 0.0f;
#endif
        float coherence = 1.0f; /* the march decides by its origin alone */
        const float4 s = cone_sample(CONE_POOLS_PASS, c->res.zw, child, levels, at, level, d, from,
                                     &path, &coherence);
        const float step = c->march.x * diameter;
        /* Where the level follows the diameter, the samples are D / 2 apart
         * and step / spacing is 2 * step fraction; otherwise (a whole level,
         * the root, the last sample's thickness) it is divided out. */
        const float thickness_ratio = last > 0.0f ? last / spacing
                                      : follows   ? 2.0f * c->march.x
                                                  : step / spacing;
        cone_composite(&r, s, thickness_ratio);
        if (t <= c->march.z)
            r.ao_alpha = r.alpha;
        r.level_sum += level;
        ++r.samples;
        if (r.alpha >= c->march.w || last > 0.0f)
            break;
        const float rest = exit - (t + 0.5f * step);
        if (t + step >= exit && rest > 0.0f && exit <= max_t) {
            last = rest;
            t = exit * 0.99999f;
        } else {
            t += step;
        }
    }
    if (last > 0.0f)
        r.left = 1;
    if (r.left)
        r.radiance += (1.0f - r.alpha) * c->ambient.xyz;
    return r;
}

#endif
