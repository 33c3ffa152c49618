/* The camera's diffuse gather, by rays: GATHER_RAYS_PER_CONE for each cone
 * of the preset (--cones), spread over the hemisphere about the hit's
 * normal by their cosine (gather_dir), through the acceleration structure.
 * Where a ray meets a surface, it takes the light a path tracer's second
 * vertex would send back: the direct light of every light and emitter
 * there, exactly (shadow rays, the texture's albedo), plus the light that
 * bounced off the leaf voxel there, on the side of its plane the ray sees
 * (the voxels' light less their direct light), or where the surface is
 * nearer than the voxels resolve, what a next vertex's ray brings. Where it
 * meets nothing, the sky's.
 *
 * Cones marched through the bricks read that light a footprint wide, and a
 * voxel cannot hold light that changes within it: in a hall lit through a
 * roof slit, the sun's strip on the floor (2.6 voxels wide) lit 3 voxels,
 * the foot of a column beside it got a quarter of its light and the light
 * was spread up the columns' sides. Rays see the geometry itself (the hall
 * 0.146 -> 0.093 NRMSE, the suite's mean 0.075 -> 0.056, the bounces'
 * light unchanged). What they cost is noise where few rays meet a small
 * bright patch (the ceiling 10 cm above a point light): there picks aim
 * more rays at it (gather_picks.h), and the sparse fill and the indirect
 * filter take the rest. A ray passes through glass, as the
 * voxels let light through it, and one that meets a mirror shows the
 * voxels' light there, as a cone's would. */
#ifndef VCT_DIFFUSE_RAYS_H
#define VCT_DIFFUSE_RAYS_H

#include "accel/accel.h"
#include "conetrace/cone_hit.h"
#include "conetrace/cone_trace.h"
#include "light/direct_light.h"
#include "light/emitters.h"
#include "render/gather_picks.h"
#include "render/shading_scene.h"
#include "scene/bsdf.h"
#include "scene/rng.h"
#include "scene/texture.h"
#include "scene/turn.h"
#include "voxel/octree.h"
#include "voxel/voxel_side.h"

/* Rays per cone of the preset (--cones): its count sets the gather's rays. */
#define GATHER_RAYS_PER_CONE 9u

/* Picks per cone of the preset: rays aimed at voxels by their direct
 * light (gather_picks.h). */
#define GATHER_PICKS_PER_CONE 2u

/* The voxels' light per leaf voxel, with its sides (voxel_side.h): all of
 * it, and its direct part alone (the same buffers before any bounce); and
 * the picks by their direct light. */
typedef struct gather_voxels {
    __global const float4 *total, *total_side, *direct, *direct_side;
    gather_picks picks;
} gather_voxels;

/* The leaf voxel holding p, or OCT_NULL. */
inline uint gather_voxel(__global const uint *child, const vct_cone_desc *c, float3 p) {
    const float3 at = clamp((p - c->volume.xyz) * c->ambient.w, 0.0f, 0.99999f);
    return octree_leaf_voxel(child, convert_uint3_rtz(at * (float)c->res.x), c->res.y);
}

/* What the gather reads of leaf voxel v: its light, side difference and
 * plane, and the same of its direct part. */
typedef struct gather_record {
    float4 total, total_difference, total_plane, direct, direct_difference, direct_plane;
} gather_record;

inline gather_record gather_load(const gather_voxels *gv, uint v) {
    const uint s = VCT_VOXEL_SIDE_FLOAT4S * v;
    return (gather_record){gv->total[v],  gv->total_side[s],  gv->total_side[s + 1u],
                           gv->direct[v], gv->direct_side[s], gv->direct_side[s + 1u]};
}

/* The light that bounced off a voxel (its record r), on the side of its
 * plane seen_from lies on. */
inline float3 gather_record_light(const gather_record *r, const vct_cone_desc *c,
                                  float3 seen_from) {
    const float3 o = (seen_from - c->volume.xyz) * c->ambient.w - 0.5f;
    return fmax(voxel_side_light(r->total, r->total_difference, r->total_plane, o) -
                    voxel_side_light(r->direct, r->direct_difference, r->direct_plane, o),
                0.0f);
}

/* What a gather ray found: a surface, nothing (the sky), or more than
 * GATHER_GLASS_MAX panes of glass on the way (no light). */
#define GATHER_GLASS_MAX 4u
#define GATHER_MISS 0
#define GATHER_HIT 1
#define GATHER_LOST 2

/* The first surface other than glass that the ray from `from` along unit
 * d meets within `reach`, as the voxels see the scene (glass lets light
 * through them unlit, and shadow rays stop at it: the light through glass
 * is the caustics pass's), once its first segment is traced (found, *h:
 * what accel_trace gave it, or a packet, which gives the same).
 * h->t is the distance from `from`. */
inline int gather_trace_on(const shading_scene *ps, float3 from, float3 d, float reach, int found,
                           hit_record *h) {
    float3 o = from;
    float travelled = 0.0f;
    for (uint pane = 0; pane <= GATHER_GLASS_MAX; ++pane) {
        if (pane > 0u)
            found = accel_trace(&ps->g, o, d, 0.0f, reach - travelled, 0, h);
        if (!found)
            return GATHER_MISS;
        const float t = h->t;
        h->t += travelled;
        const vct_material_desc m = ps->materials[ps->tri_material[h->tri]];
        if (!is_dielectric(&m))
            return GATHER_HIT;
        const float3 p = o + t * d;
        const float eps = surface_epsilon(&ps->g, p);
        o = p + d * eps;
        travelled += t + eps;
    }
    return GATHER_LOST;
}

/* gather_trace_on with the first segment traced here. */
inline int gather_trace(const shading_scene *ps, float3 from, float3 d, float reach,
                        hit_record *h) {
    return gather_trace_on(ps, from, d, reach, accel_trace(&ps->g, from, d, 0.0f, reach, 0, h), h);
}

/* The direct light surface point p (unit normal n, on the ray's side)
 * sends back, exactly: shadow rays to every light, emitter samples of
 * stream `seed`; m holds its texture's albedo. */
inline float3 gather_direct(const shading_scene *ps, const vct_material_desc *m, float3 p, float3 n,
                            uint seed) {
    direct_terms dt =
        direct_gather(&ps->g, ps->lights, ps->light_count, p, n, 1, (float3)(0.0f), -1.0f, 0);
#ifdef VCT_EMITTERS
    direct_emitters_part(&ps->g, &ps->e, ps->materials, ps->tri_material, p, n, (float3)(0.0f),
                         -1.0f, seed, 0u, 1u, &dt);
    const float3 glow = (float3)(0.0f);
#else
    /* emitters seen through the voxels: the camera's direct light left
     * them out, and their emission is the voxels' direct light */
    const float3 glow = m->emission.xyz;
#endif
    return glow + diffuse_color(m) * VCT_INV_PI * dt.irradiance;
}

/* A hit nearer its ray's origin than this many voxels lies in a gap the
 * voxels cannot resolve: the two surfaces share voxels, and a voxel's two
 * sides hold one plane's light (a ball's underside and the plinth it rests
 * on, a voxel apart, both read the plinth's: the plinth beside the ball got
 * 0.31 of the path tracer's indirect light). There the light that bounced
 * off the hit is gathered by one more ray, as a path tracer's next vertex
 * would, up to GATHER_NEAR_DEPTH vertices (a wedge's two faces light each
 * other back and forth: three left a plate leaning on a floor at 0.85 of
 * its light under the first voxel, five 0.93); beyond, the leaf voxel's.
 * The dense hall's NRMSE 0.047 -> 0.026; no suite scene's rose. */
#define GATHER_NEAR_VOXELS 2.0f
#define GATHER_NEAR_DEPTH 5u

/* Whether the surface at distance t along a gather ray, its vertex
 * `depth`, is its last: far enough for the voxels to resolve, or the
 * vertices' limit. */
inline int gather_last_vertex(const vct_cone_desc *c, float t, uint depth) {
    return t >= GATHER_NEAR_VOXELS * (c->volume.w / (float)c->res.x) ||
           depth + 1u >= GATHER_NEAR_DEPTH;
}

/* The point a hit t along a gather ray (cone tan_half) is seen from: off
 * the surface on the ray's side, a cone's diameter out (cone_hit_light). */
inline float3 gather_seen_from(const vct_cone_desc *c, float3 p, float3 n, float t,
                               float tan_half) {
    return p + n * fmax(2.0f * t * tan_half, 2.0f * (c->volume.w / (float)c->res.x));
}

/* The leaf voxel that holds a surface point p met along unit d: a quarter
 * voxel back along the ray, or where that lies in an empty one, a quarter
 * voxel on; OCT_NULL where neither is held. */
inline uint gather_surface_voxel(__global const uint *child, const vct_cone_desc *c, float3 p,
                                 float3 d) {
    const float voxel = c->volume.w / (float)c->res.x;
    const uint v = gather_voxel(child, c, p - d * (0.25f * voxel));
    return v != OCT_NULL ? v : gather_voxel(child, c, p + d * (0.25f * voxel));
}

/* Where a gather ray's bounced light at its first surface is not known
 * beforehand (gather_rays reads it for a group of rays at once). */
#define GATHER_UNKNOWN (-2.0f)

/* The light a gather ray from `from` along unit d brings back from h, the
 * surface it met; tan_half: its cone's aperture, seed: its stream (emitter
 * samples, the near vertices' rays); first: the bounced light at h where it
 * was read beforehand (-1 where no voxel holds h), else GATHER_UNKNOWN. */
inline float3 gather_hit_light(const shading_scene *ps, CONE_POOLS, __global const uint *child,
                               const vct_cone_desc *c, const gather_voxels *gv, float3 from,
                               float3 d, const hit_record *h, float tan_half, uint seed,
                               float3 first) {
    const float voxel = c->volume.w / (float)c->res.x;
    float3 sum = (float3)(0.0f), weight = (float3)(1.0f);
    hit_record hit = *h;
    for (uint depth = 0u;; ++depth) {
        float3 p, ng, n;
        int front;
        if (!surface_hit(&ps->g, &hit, d, &p, &ng, &n, &front))
            return sum;
        const float3 seen_from = gather_seen_from(c, p, n, hit.t, tan_half);
        vct_material_desc m = ps->materials[ps->tri_material[hit.tri]];
        const int last = gather_last_vertex(c, hit.t, depth);
        float3 bounced = (float3)(0.0f);
        if (last && depth == 0u && first.x != GATHER_UNKNOWN) {
            bounced = first;
        } else if (last) {
            const uint v = gather_surface_voxel(child, c, p, d);
            bounced = (float3)(-1.0f);
            if (v != OCT_NULL) {
                const gather_record r = gather_load(gv, v);
                bounced = gather_record_light(&r, c, seen_from);
            }
        }
        if (bounced.x < 0.0f || bsdf_delta_only(&m))
            return sum + weight * cone_hit_light(CONE_POOLS_PASS, child, c, from, d, hit.t,
                                                 tan_half, 1.0f, seen_from);
        m.albedo.xyz = texture_albedo(&ps->tv, &m, hit.tri, hit.u, hit.v);
        sum += weight * gather_direct(ps, &m, p, n, seed);
        if (last)
            return sum + weight * bounced;
        /* the next vertex: a cosine-weighted ray, whose light the surface
         * reflects by its albedo */
        weight *= diffuse_color(&m);
        /* its direction's numbers apart from the next vertex's emitter stream */
        seed = rng_hash(seed + 0x9e3779b9u);
        const uint s1 = rng_hash(seed ^ 0x85ebca6bu), s2 = rng_hash(s1);
        float3 t, b;
        basis_of(n, &t, &b);
        d = normalize(cosine_dir(n, t, b, (float)(s1 >> 8) * (1.0f / 16777216.0f),
                                 (float)(s2 >> 8) * (1.0f / 16777216.0f)));
        from = p + n * surface_epsilon(&ps->g, p);
        const int found = gather_trace(ps, from, d, INFINITY, &hit);
        if (found == GATHER_MISS)
            return sum + weight * c->ambient.xyz;
        if (found != GATHER_HIT)
            return sum;
    }
}

/* Ray k of m over the hemisphere about unit n (tangents t, b),
 * cosine-weighted: a Fibonacci spiral over the unit disc (radius
 * sqrt((k + 0.5) / m), turned by the golden angle from ray to ray) lifted
 * onto the hemisphere. Every ray stands for the same share of the
 * cosine-weighted hemisphere, and they reach within asin(sqrt(0.5 / m)) of
 * the horizon (5 degrees for 81): the preset's cones, cells about fixed
 * axes, left the last 15 degrees out, where a wall sees the floor at its
 * foot (0.86 of the path tracer's light beside a sunlit strip). */
inline float3 gather_dir(float3 n, float3 t, float3 b, uint k, uint m) {
    const float r2 = ((float)k + 0.5f) / (float)m;
    const float turn = (float)k * 0.618033989f;
    const float2 cs = turn_cos_sin(turn - floor(turn));
    return normalize(sqrt(r2) * (cs.x * t + cs.y * b) + sqrt(fmax(1.0f - r2, 0.0f)) * n);
}

/* The light ray d from `from` brings back (h: what gather_trace found;
 * first: as gather_hit_light takes it), in *open whether it met nothing
 * within `near`. */
inline float3 gather_ray_light(const shading_scene *ps, CONE_POOLS, __global const uint *child,
                               const vct_cone_desc *c, const gather_voxels *gv, float3 from,
                               float3 d, int found, const hit_record *h, float tan_half, uint seed,
                               float near, float3 first, int *open) {
    *open = found == GATHER_MISS || (found == GATHER_HIT && h->t > near);
    if (found == GATHER_MISS)
        return c->ambient.xyz;
#ifdef VCT_INDIRECT
    if (found == GATHER_HIT)
        return gather_hit_light(ps, CONE_POOLS_PASS, child, c, gv, from, d, h, tan_half, seed,
                                first);
#endif
    return (float3)(0.0f);
}

/* The power heuristic's factor (exponent 2) for a ray along d (cosine
 * cos_n with the normal) whose hit lies in voxel v, of m rays by the
 * cosine and k picks, for a ray of either kind (`picked`), over m: 1 for a
 * cosine's ray where no pick can aim there (gather_picks.h). */
inline float gather_mis(const gather_voxels *gv, const vct_cone_desc *c, float3 p, float cos_n,
                        uint v, uint m, uint k, int picked) {
    const float density = k ? pick_density(&gv->picks, c, v, p) : 0.0f;
    if (!(density > 0.0f))
        return picked ? 0.0f : 1.0f;
    const float by_cosine = (float)m * fmax(cos_n, 0.0f) * VCT_INV_PI,
                by_picks = (float)k * density;
    const float both = by_cosine * by_cosine + by_picks * by_picks;
    return (picked ? by_cosine * by_picks : by_cosine * by_cosine) / both;
}

/* For a group of gather rays from `from` (rays, their first segments' hits
 * met/hits; ray_of: each one's index, m of them by the cosine, then k
 * picks aimed at aimed_of): where each ends (found, hits, traced on past
 * glass), the voxel a pick met (voxel_of), and for those whose first
 * surface is their last vertex the light that bounced off its voxel
 * (first; GATHER_UNKNOWN for the others). The voxels are found for all of
 * the group first and their light read after, back to back: a voxel's
 * light lies anywhere in memory, and read ray by ray each ray waited for
 * its own. */
inline void gather_group_first(const shading_scene *ps, __global const uint *child,
                               const vct_cone_desc *c, const gather_voxels *gv, float3 from,
                               const ray_packet *rays, float reach, uint k, uint m,
                               const uint *ray_of, const uint *aimed_of, const int *met,
                               hit_record *hits, int *found, uint *voxel_of, float tan_half,
                               float3 *first) {
    uint voxel[ACCEL_GROUP];
    float3 seen_from[ACCEL_GROUP];
    for (uint j = 0; j < rays->count; ++j) {
        const float3 d = packet_dir(rays, j);
        found[j] = gather_trace_on(ps, from, d, reach, met[j], &hits[j]);
        voxel_of[j] =
            k && found[j] == GATHER_HIT ? pick_voxel_of(child, c, from, d, hits[j].t) : OCT_NULL;
        first[j] = (float3)(GATHER_UNKNOWN);
        voxel[j] = OCT_NULL;
#ifdef VCT_INDIRECT
        float3 p, ng, n;
        int front;
        if (found[j] == GATHER_HIT && (ray_of[j] < m || voxel_of[j] == aimed_of[j]) &&
            gather_last_vertex(c, hits[j].t, 0u) &&
            surface_hit(&ps->g, &hits[j], d, &p, &ng, &n, &front)) {
            seen_from[j] = gather_seen_from(c, p, n, hits[j].t, tan_half);
            voxel[j] = gather_surface_voxel(child, c, p, d);
            first[j] = (float3)(-1.0f);
        }
#endif
    }
    gather_record records[ACCEL_GROUP];
    for (uint j = 0; j < rays->count; ++j)
        if (voxel[j] != OCT_NULL)
            records[j] = gather_load(gv, voxel[j]);
    for (uint j = 0; j < rays->count; ++j)
        if (voxel[j] != OCT_NULL)
            first[j] = gather_record_light(&records[j], c, seen_from[j]);
}

/* The mean light of m gather rays from surface point p (unit normal n,
 * tangents t and b, turned per point by the caller) and of k picks
 * (gather_picks.h), in *open the share of the m that meet nothing within
 * `near`, and in *variance the variance of the mean's luminance by the
 * rays' spread (the indirect filter's guide: a rare ray that met a small
 * bright patch marks its pixel as noisy). Without indirect light
 * (occlusion only), the rays reach `near` alone and nothing is picked. */
inline float3 gather_rays(const shading_scene *ps, CONE_POOLS, __global const uint *child,
                          const vct_cone_desc *c, const gather_voxels *gv, float3 p, float3 n,
                          float3 t, float3 b, uint m, uint k, uint seed, float near, float *open,
                          float *variance) {
    const float3 from = p + n * surface_epsilon(&ps->g, p);
    /* a cone of a ray's share of the hemisphere, where a ray reads bricks */
    const float tan_half = sqrt(2.0f / (float)m);
#ifdef VCT_INDIRECT
    const float reach = INFINITY;
    k = gv->picks.count ? k : 0u;
#else
    const float reach = near;
    k = 0u;
#endif
    float3 sum = (float3)(0.0f);
    /* per kind (by the cosine, picked): the sum of each ray's luminance and
     * of its square */
    float2 lum = (float2)(0.0f), squares = (float2)(0.0f);
    uint open_rays = 0u;
    /* The rays leave one point: their first segments are traced together,
     * ACCEL_GROUP at a time (a packet on CPU devices, the same hits). */
    for (uint r0 = 0; r0 < m + k; r0 += ACCEL_GROUP) {
        const uint group = min(m + k - r0, ACCEL_GROUP);
        ray_packet rays;
        rays.count = 0u;
        uint ray_of[ACCEL_GROUP], aimed_of[ACCEL_GROUP];
        for (uint j = 0; j < group; ++j) {
            const uint r = r0 + j;
            uint aimed = OCT_NULL;
            const float3 d =
                r < m ? gather_dir(n, t, b, r, m)
                      : pick_dir(&gv->picks, c, from, r - m, k, rng_hash(seed ^ r), &aimed);
            if (r >= m && !(dot(d, n) > 0.0f))
                continue; /* below the surface, or a voxel too near */
            ray_of[rays.count] = r;
            aimed_of[rays.count] = aimed;
            packet_set(&rays, rays.count++, from, d, 0.0f, reach);
        }
        hit_record hits[ACCEL_GROUP];
        int met[ACCEL_GROUP];
        accel_trace_packet(&ps->g, &rays, 0, hits, met);
        int found[ACCEL_GROUP];
        uint voxel_of[ACCEL_GROUP];
        float3 first[ACCEL_GROUP];
        gather_group_first(ps, child, c, gv, from, &rays, reach, k, m, ray_of, aimed_of, met, hits,
                           found, voxel_of, tan_half, first);
        for (uint j = 0; j < rays.count; ++j) {
            const uint r = ray_of[j];
            const int by_cosine = r < m;
            const float3 d = packet_dir(&rays, j);
            const float cos_n = dot(d, n);
            const uint v = voxel_of[j];
            if (!by_cosine && v != aimed_of[j])
                continue; /* the picks' light is their voxel's alone */
            int is_open;
            const float3 light =
                gather_ray_light(ps, CONE_POOLS_PASS, child, c, gv, from, d, found[j], &hits[j],
                                 tan_half, rng_hash(seed ^ r), near, first[j], &is_open);
            if (by_cosine)
                open_rays += is_open;
            const float3 share = light * gather_mis(gv, c, from, cos_n, v, m, k, !by_cosine);
            sum += share;
            const float y = side_luminance(share);
            lum += by_cosine ? (float2)(y, 0.0f) : (float2)(0.0f, y);
            squares += by_cosine ? (float2)(y * y, 0.0f) : (float2)(0.0f, y * y);
        }
    }
    *open = (float)open_rays / (float)m;
    /* the variance of the mean's luminance, from the rays' spread: the sum
     * over m of m rays of one kind and k (a pick that missed its voxel
     * adding 0) of the other, each kind's by its own spread */
    const float2 n_kind = (float2)((float)m, (float)max(k, 1u)), mean = lum / n_kind;
    const float2 spread = fmax(squares / n_kind - mean * mean, 0.0f) * n_kind;
    *variance = (spread.x + spread.y) / ((float)m * (float)m);
    return sum / (float)m;
}

#endif
