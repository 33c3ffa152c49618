/* Direct light injected into the leaf voxels: the radiance each voxel sends
 * out, Lambert (albedo / pi times irradiance from every punctual light, with
 * hard shadows from any-hit rays through the acceleration structure) plus emission.
 * The same conventions as the ray caster and the path tracer.
 *
 * Surfaces are two-sided, whatever their winding: each fragment of a voxel
 * (one triangle crossing it) is lit from the side its light is on, and each
 * side of the voxel (about its normal axis) sends out the mean of what its
 * fragments reflect to that side, each weighed by its triangle's area in
 * the voxel (voxel_side.h), over the fragments' sides
 * that do not look into a closed object (fragment_enclosed). A fragment is
 * shaded at the voxel's centre with its triangle's normal (and its albedo
 * averaged over the voxel, fragment_albedo.h), and seen from the light at
 * the point of its triangle nearest that centre, lifted by a relative
 * epsilon off the triangle on the light's side and towards the light. So a
 * wall lit on one face leaves its other face dark, however thin the wall
 * and whichever way it is wound (the dark face's ray starts inside the wall
 * and meets the lit face), and a closed object shadows its own far side.
 * Emissive triangles light the fragments as well (light/emitters.h).
 * Shadow edges move by less than a voxel. The rays of hard point and spot lights test the light's
 * own triangle bins (light_bins.h) when it has them, the acceleration structure otherwise, with
 * the same answer; they end two lifts short of the light. A light with a
 * radius is seen through INJECT_EXTENT_SAMPLES fixed points of its extent
 * (a spiral), so that its penumbrae reach the voxels too. */
#include "light/direct_light.h"
#include "light/emitters.h"
#include "accel/tri_nearest.h"
#include "voxel/clip_area.h"
#include "voxel/fragment_albedo.h"
#include "light/light_bins.h"
#include "voxel/octree.h"
#include "voxel/voxel_carry.h"
#include "scene/tri_normal.h"
#include "voxel/voxel_side.h"
#include "vct_types.h"

#define INJECT_EXTENT_SAMPLES 8u

/* The fraction of light i that p sees, lifted by `lift` along `up`. */
inline float inject_visibility(const accel_view *g, const light_bins_view *bins,
                               __global const vct_light_desc *lights, uint i, float3 p, float3 up,
                               float lift, float3 wi, float dist) {
    if (!light_is_soft(lights, i)) {
        if (isinf(dist)) /* directional */
            return (float)light_visible(g, p, up, lift, wi, dist);
        const float3 o = p + up * lift;
        return (float)(bins->desc[i].info.w ? light_segment_visible_bins(bins, g, i, o, 2.0f * lift)
                                            : light_segment_visible_accel(
                                                  g, o, lights[i].position.xyz, 2.0f * lift));
    }
    uint seen = 0;
    for (uint s = 0; s < INJECT_EXTENT_SAMPLES; ++s) {
        float reach;
        const float u1 = ((float)s + 0.5f) / (float)INJECT_EXTENT_SAMPLES;
        const float u2 = (float)s * 0.618034f;
        const float3 to = light_extent_sample(lights, i, wi, dist, u1, u2 - floor(u2), &reach);
        seen += (uint)light_visible(g, p, up, lift, to, reach);
    }
    return (float)seen / (float)INJECT_EXTENT_SAMPLES;
}

/* Which way a shadow ray towards w leaves a triangle of normal n (either
 * sign): off the triangle on w's side, and towards w, so that a ray from an
 * edge shared with a wall does not start on the wall. */
inline float3 lift_direction(float3 n, float3 w) {
    return normalize((dot(n, w) < 0.0f ? -n : n) + w);
}

/* Fragments of one voxel on one plane (normals within about 8 degrees, of
 * the same sign, and their points within SHARED_PLANE voxels of each
 * other's plane: the two faces of a wall, however thin, are not) share
 * their shadow rays. A dense mesh puts
 * several such fragments in a voxel, and each tracing its own rays made
 * the light update 3x slower. Up to SHARED_LIGHTS lights and emitter
 * samples are kept. */
#define SHARED_LIGHTS 8u
#define SHARED_FACING 0.99f
#define SHARED_PLANE 0.01f

typedef struct shared_rays {
    float3 n, q;               /* the normal and point of the fragment that traced them */
    float seen[SHARED_LIGHTS]; /* per light (or emitter sample), the fraction seen */
    uint trapped;              /* per emitter sample, a bit: its emitter traps its light */
    uint seed;                 /* emitter samples: the stream they came from */
    int valid;
} shared_rays;

/* Whether a fragment of unit normal n at q lies on the plane of the one
 * that traced s (within `plane` of it). */
inline int shared_plane(const shared_rays *s, float3 n, float3 q, float plane) {
    return s->valid && dot(n, s->n) > SHARED_FACING && fabs(dot(q - s->q, n)) < plane;
}

/* Irradiance at centre p from every light onto one fragment: triangle t,
 * unit normal n (either sign), seen from its point q nearest p, or with the
 * visibility `shared` holds when `reuse`; else what it traces is kept there.
 * Returns what arrives on the side n points to, and adds what arrives on
 * the other to *behind. */
inline float3 fragment_irradiance(const accel_view *g, const light_bins_view *bins,
                                  __global const vct_light_desc *lights, uint light_count, float3 p,
                                  float3 q, float3 n, float3 *behind, shared_rays *shared,
                                  int reuse) {
    const float lift = surface_epsilon(g, q);
    const int keep = !reuse && light_count <= SHARED_LIGHTS;
    float3 irradiance = (float3)(0.0f);
    for (uint i = 0; i < light_count; ++i) {
        if (keep)
            shared->seen[i] = 0.0f;
        float3 wi, radiant;
        float dist;
        if (!light_incident(lights, i, p, &wi, &dist, &radiant) || all(radiant == 0.0f))
            continue;
        const float cos_theta = fabs(dot(n, wi));
        float seen;
        if (reuse) {
            seen = shared->seen[i];
        } else {
            float3 wq, unused;
            float dq;
            if (!light_incident(lights, i, q, &wq, &dq, &unused))
                continue;
            const float3 up = lift_direction(n, wq);
            seen = inject_visibility(g, bins, lights, i, q, up, lift, wq, dq);
            if (keep)
                shared->seen[i] = seen;
        }
        if (dot(n, wi) >= 0.0f)
            irradiance += radiant * cos_theta * seen;
        else
            *behind += radiant * cos_theta * seen;
    }
    return irradiance;
}

/* An emitter parallel to a surface and nearer to it than a voxel (a
 * ceiling panel hung just below the ceiling) lights that surface over the
 * panel only in the gap between them, whence the light cannot get out; in a
 * voxel both share, that light would show on the panel's face instead. The
 * same surface beside the emitter sees its face edge-on and lights the room:
 * beyond a voxel from its edge it keeps that light, within a voxel it is
 * taken as trapped and gap_escape sends that band's light. */
#define TRAPPED_PARALLEL 0.95f

/* Whether emitter triangle (a, b, c) traps its light between itself and a
 * fragment of unit normal n at q: parallel, and within `gap` of q. */
inline int emitter_traps(float3 a, float3 b, float3 c, float3 q, float3 n, float gap) {
    const float3 nl = normalize(cross(b - a, c - a));
    return fabs(dot(nl, n)) > TRAPPED_PARALLEL && fabs(dot(q - a, nl)) < gap &&
           length(triangle_nearest(q, a, b, c) - q) < gap;
}

/* Whether emitter triangle (a, b, c) traps its light beside q: it does
 * itself (emitter_traps), or it lies in the plane of one that does (a quad
 * lamp's other triangle, whose light reaches q only through the gap). By
 * the triangle alone, a fragment over one triangle of a lamp hung 0.1 under
 * a ceiling, 0.1 from the other's edge, took the other's light: which
 * fragment of a voxel traced the shared rays first decided it, and wound
 * the other way the ceiling along the lamp's diagonal lit up. Emitters in
 * scenes of more than EMITTER_EXACT_MAX emitter triangles by themselves. */
inline int emitter_traps_in_plane(const accel_view *g, const emitter_view *e, float3 a, float3 b,
                                  float3 c, float3 q, float3 n, float gap) {
    if (emitter_traps(a, b, c, q, n, gap))
        return 1;
    const float3 nl = normalize(cross(b - a, c - a));
    if (e->count > EMITTER_EXACT_MAX || !(fabs(dot(nl, n)) > TRAPPED_PARALLEL) ||
        !(fabs(dot(q - a, nl)) < gap))
        return 0;
    for (uint j = 0u; j < e->count; ++j) {
        float3 x, y, z;
        emitter_vertices(g, e->tris[j], &x, &y, &z);
        if (fabs(dot(x - a, nl)) < 1e-3f * gap && emitter_traps(x, y, z, q, n, gap))
            return 1;
    }
    return 0;
}

/* The light trapped in such a gap leaves through its rim: the surface over
 * the emitter, lit by it, reflects into the slit between them, and what
 * heads out far enough before dropping the gap's height g leaves it. Per
 * unit length of a straight rim, the cosine-weighted share of a point x in
 * from it that gets out, (1 / 2 pi) \int g^2 cos^2 phi / (x^2 + g^2 cos^2 phi)
 * dphi over the half turn facing out, sums over x to g / 2; weighted by the
 * irradiance there (the half plane's, pi L (1 / 2 + x / 2 sqrt(x^2 + g^2)))
 * it is GAP_ESCAPE_SHARE g times pi L. So the surface sends out pi rho L g
 * GAP_ESCAPE_SHARE per unit of rim, into the room. The voxel the rim
 * crosses sends that out on the emitter's side, as radiance over its face.
 * The rim: the trapping triangles' edges that no other trapping triangle
 * shares (a quad's diagonal is no rim), within the voxel's square on the
 * fragment's plane. */
#define GAP_ESCAPE_SHARE 0.40f

/* Length of segment (a, b) (2D) inside the square [-h, h]^2, a segment on
 * the square's +h sides left to the neighbouring square (Liang-Barsky). */
inline float segment_in_square(float2 a, float2 b, float h) {
    const float2 d = b - a;
    float t0 = 0.0f, t1 = 1.0f;
    const float p[4] = {-d.x, d.x, -d.y, d.y}, q[4] = {a.x + h, h - a.x, a.y + h, h - a.y};
    for (int k = 0; k < 4; ++k) {
        if (p[k] == 0.0f) {
            if (q[k] < 0.0f)
                return 0.0f;
        } else {
            const float r = q[k] / p[k];
            if (p[k] < 0.0f)
                t0 = fmax(t0, r);
            else
                t1 = fmin(t1, r);
        }
    }
    if (!(t1 > t0))
        return 0.0f;
    const float2 mid = a + 0.5f * (t0 + t1) * d;
    return mid.x < h && mid.y < h ? (t1 - t0) * length(d) : 0.0f;
}

/* Whether trapping triangle k of traps[0 .. count) shares its edge (u, v). */
inline int rim_shared(const accel_view *g, const emitter_view *e, const uint *traps, uint count,
                      uint k, float3 u, float3 v) {
    for (uint j = 0u; j < count; ++j) {
        if (j == k)
            continue;
        float3 x[3];
        emitter_vertices(g, e->tris[traps[j]], &x[0], &x[1], &x[2]);
        int has_u = 0, has_v = 0;
        for (int i = 0; i < 3; ++i) {
            has_u |= all(x[i] == u);
            has_v |= all(x[i] == v);
        }
        if (has_u && has_v)
            return 1;
    }
    return 0;
}

/* What a fragment at q (unit normal n) of voxel centre p and size `size`
 * sends out through the rims of the emitters that trap their light beside
 * it, per unit albedo, as radiance over the voxel's face; *toward: the
 * side it leaves on (n or -n, towards the emitter). 0 where no rim
 * crosses the voxel or the scene has more than EMITTER_EXACT_MAX emitter
 * triangles. */
inline float3 gap_escape(const accel_view *g, const emitter_view *e,
                         __global const vct_material_desc *materials,
                         __global const uint *tri_material, float3 p, float3 q, float3 n,
                         float size, float3 *toward) {
    if (e->count > EMITTER_EXACT_MAX)
        return (float3)(0.0f);
    uint traps[EMITTER_EXACT_MAX];
    uint count = 0u;
    for (uint i = 0u; i < e->count; ++i) {
        float3 a, b, c;
        emitter_vertices(g, e->tris[i], &a, &b, &c);
        if (emitter_traps_in_plane(g, e, a, b, c, q, n, size))
            traps[count++] = i;
    }
    if (count == 0u)
        return (float3)(0.0f);
    float3 t1, t2;
    basis_of(n, &t1, &t2);
    const float3 centre = p - n * dot(p - q, n);
    float3 rim = (float3)(0.0f); /* per unit albedo, what leaves times the rim's length */
    for (uint k = 0u; k < count; ++k) {
        float3 x[3];
        const uint tri = e->tris[traps[k]];
        emitter_vertices(g, tri, &x[0], &x[1], &x[2]);
        const float gap = fabs(dot(q - x[0], normalize(cross(x[1] - x[0], x[2] - x[0]))));
        float length_in = 0.0f;
        for (int i = 0; i < 3; ++i) {
            const float3 u = x[i], v = x[i == 2 ? 0 : i + 1];
            if (rim_shared(g, e, traps, count, k, u, v))
                continue;
            length_in +=
                segment_in_square((float2)(dot(u - centre, t1), dot(u - centre, t2)),
                                  (float2)(dot(v - centre, t1), dot(v - centre, t2)), 0.5f * size);
        }
        /* and the band beside the rim whose fragments emitter_traps took
         * too (within `size` of the emitter: x < w = sqrt(size^2 - gap^2)
         * out from its edge), which sees the emitter's face edge-on and
         * sends its light straight out: the half plane's irradiance there,
         * pi L / 2 (1 - x / sqrt(x^2 + gap^2)), over pi and integrated over
         * x < w, is L (w + gap - size) / 2 per unit of rim */
        const float band = 0.5f * (sqrt(fmax(size * size - gap * gap, 0.0f)) + gap - size);
        rim += materials[tri_material[tri]].emission.xyz *
               ((GAP_ESCAPE_SHARE * gap + band) * length_in);
    }
    float3 a, b, c;
    emitter_vertices(g, e->tris[traps[0]], &a, &b, &c);
    *toward = dot(a - q, n) >= 0.0f ? n : -n;
    return rim / (size * size);
}

/* Irradiance at centre p onto one fragment (triangle normal n, nearest
 * point q) from the emitters, split by side as fragment_irradiance does,
 * with the estimator the camera's hits use (direct_emitters_part): each
 * side's unoccluded light (the near triangles' exact, by Lambert's formula,
 * where the scene has few; the samples' point weights otherwise) times the
 * share of the samples' weight on that side that the shadow rays see. A
 * ceiling beside a panel hung under it sees the panel edge-on, where point
 * weights of 8 samples fell 20 % short over 156 voxels and 2.8x short in the
 * row nearest it (test_inject). The e->samples samples of stream `seed`
 * are seen from q, lifted off the triangle on the sample's side and towards
 * it; emitters that trap their light within `gap` of the fragment send
 * none. */
inline float3 fragment_emitters(const accel_view *g, const emitter_view *e,
                                __global const vct_material_desc *materials,
                                __global const uint *tri_material, float3 p, float3 q, float3 n,
                                float gap, float3 *behind, uint seed, shared_rays *shared,
                                int reuse) {
    const float lift = surface_epsilon(g, q);
    const int keep = !reuse && e->samples <= SHARED_LIGHTS;
    const int exact = e->count <= EMITTER_EXACT_MAX;
    /* per side (0: the side n faces, 1: the other) */
    float3 unoccluded[2] = {(float3)(0.0f), (float3)(0.0f)};
    float weight[2] = {0.0f, 0.0f}, weight_seen[2] = {0.0f, 0.0f};
    if (exact)
        for (uint i = 0u; i < e->count; ++i) {
            float3 a, b, c;
            emitter_vertices(g, e->tris[i], &a, &b, &c);
            if (emitter_traps_in_plane(g, e, a, b, c, q, n, gap))
                continue;
            for (uint side = 0u; side < 2u; ++side) {
                float area;
                const float3 near = emitter_near_light(g, materials, tri_material, e->tris[i], p,
                                                       side ? -n : n, &area);
                if (near.x >= 0.0f)
                    unoccluded[side] += near * (float)e->samples;
            }
        }
    for (uint s = 0; s < e->samples; ++s) {
        float3 target;
        uint tri;
        const float3 radiant =
            emitter_sample(e, g, materials, tri_material, p, seed, s, &target, &tri);
        float3 a, b, c;
        emitter_vertices(g, tri, &a, &b, &c);
        const int traps = emitter_traps_in_plane(g, e, a, b, c, q, n, gap);
        float seen = 0.0f;
        /* what the shared fragment saw, where it took the sample as this
         * one does: a fragment within a trap's gap and one beside it see
         * the emitter differently */
        if (reuse && ((shared->trapped >> s) & 1u) == (uint)traps) {
            seen = shared->seen[s];
        } else if (any(radiant != 0.0f) && !traps) {
            const float3 wq = normalize(target - q);
            const float3 up = lift_direction(n, wq);
            seen = (float)emitter_visible(g, q + up * lift, target);
        }
        if (keep) {
            shared->seen[s] = seen;
            shared->trapped = (shared->trapped & ~(1u << s)) | ((uint)traps << s);
        }
        if (traps || all(radiant == 0.0f))
            continue;
        const float cos_n = dot(n, normalize(target - p));
        const uint side = cos_n >= 0.0f ? 0u : 1u;
        const float3 point = radiant * fabs(cos_n);
        const float w = point.x + point.y + point.z;
        int is_near;
        if (exact) { /* its light is in the sum already */
            is_near = emitter_is_near(p, a, b, c);
        } else {
            /* the pick's triangle, near: its exact light on both sides, over
             * the pick's probability */
            const float pick = e->scale[emitter_index(e, seed, s)];
            is_near = 0;
            for (uint k = 0u; k < 2u; ++k) {
                float area;
                const float3 near =
                    emitter_near_light(g, materials, tri_material, tri, p, k ? -n : n, &area);
                is_near = near.x >= 0.0f;
                if (is_near && area > 0.0f)
                    unoccluded[k] += near * (pick / area);
            }
        }
        if (!is_near)
            unoccluded[side] += point;
        weight[side] += w;
        weight_seen[side] += w * seen;
    }
    const float inv = 1.0f / (float)e->samples;
    float3 lit[2];
    for (uint side = 0u; side < 2u; ++side)
        lit[side] = weight[side] > 0.0f
                        ? unoccluded[side] * (inv * (weight_seen[side] / weight[side]))
                        : (float3)(0.0f);
    *behind += lit[1];
    return lit[0];
}

/* A fragment's side that looks into a closed object within its voxel (a
 * table top's upper face seen from below, inside the top; a leg's faces
 * seen from within the leg) is hidden: another fragment of the voxel lies
 * parallel to it, in front of that side (more along its normal than across
 * it), more than min_gap (the same plane, to rounding) and less than a
 * voxel away. Such a side sends no light and does not count in the voxel's
 * mean, or a thin closed object's lit faces would be averaged with its
 * hidden inner sides and send out half their light. Bit 0: the side n
 * faces, bit 1: the other. Voxels of more than ENCLOSED_MAX fragments (a
 * dense mesh's) are left open. */
#define ENCLOSED_MAX 24u
#define ENCLOSED_PARALLEL 0.9f
inline uint fragment_enclosed(__global const float4 *tri_vertices,
                              __global const uint *fragment_tri, uint begin, uint end, uint f,
                              float3 p, float3 n, float3 q, float size, float min_gap) {
    uint hidden = 0u;
    if (end - begin > ENCLOSED_MAX)
        return 0u;
    for (uint k = begin; k < end && hidden != 3u; ++k) {
        if (k == f)
            continue;
        const uint t = fragment_tri[k];
        const float3 a = tri_vertices[3u * t].xyz, b = tri_vertices[3u * t + 1u].xyz,
                     c = tri_vertices[3u * t + 2u].xyz;
        const float3 cr = tri_normal(a, b, c);
        const float len = length(cr);
        if (!(len > 0.0f) || fabs(dot(cr / len, n)) < ENCLOSED_PARALLEL)
            continue;
        /* in front: along the normal more than across it (a curved
         * surface's next facet lies beside, not in front) */
        const float3 to = triangle_nearest(p, a, b, c) - q;
        const float d = dot(to, n);
        const float3 across = to - d * n;
        if (fabs(d) > min_gap && fabs(d) < size && dot(across, across) < d * d)
            hidden |= d > 0.0f ? 1u : 2u;
    }
    return hidden;
}

/* Per new voxel, the voxel before at its key whose direct light it keeps
 * (carried_from; the light copied into radiance and side), or
 * VCT_NO_VOXEL where it is new or what moved can reach it (inject_direct
 * lights those). before_*: the direct light of the voxels before. */
__kernel void carry_direct(vct_volume_desc vol, __global const uint *keys, uint voxels,
                           __global const uint *before_keys, uint before_voxels,
                           __global const float4 *before_radiance,
                           __global const float4 *before_side, __global const float4 *boxes,
                           uint box_count, __global const vct_light_desc *lights, uint light_count,
                           float4 emit_lo, float4 emit_hi, __global uint *carried_from,
                           __global float4 *radiance, __global float4 *side) {
    const uint v = get_global_id(0);
    if (v >= voxels)
        return;
    const float size = vol.origin.w / (float)vol.res.x;
    const float3 p = vol.origin.xyz + (convert_float3(morton_decode(keys[v])) + 0.5f) * size;
    uint from = carry_find(before_keys, before_voxels, keys[v]);
    if (from != VCT_NO_VOXEL &&
        carry_dirty(p, 2.0f * size, boxes, box_count, lights, light_count, emit_lo, emit_hi))
        from = VCT_NO_VOXEL;
    carried_from[v] = from;
    if (from == VCT_NO_VOXEL)
        return;
    radiance[v] = before_radiance[from];
    for (uint k = 0; k < VCT_VOXEL_SIDE_FLOAT4S; ++k)
        side[VCT_VOXEL_SIDE_FLOAT4S * v + k] = before_side[VCT_VOXEL_SIDE_FLOAT4S * from + k];
}

/* The area of triangle t inside the voxel of side `size` centred at p, in
 * faces of it. */
inline float fragment_area(__global const float4 *tri_vertices, uint t, float3 p, float size) {
    const float inv = 1.0f / size;
    return triangle_area_in_cube((tri_vertices[3u * t].xyz - p) * inv,
                                 (tri_vertices[3u * t + 1u].xyz - p) * inv,
                                 (tri_vertices[3u * t + 2u].xyz - p) * inv);
}

/* carry 1: voxels with a voxel before (carried_from) keep the light
 * carry_direct copied. */
__kernel void inject_direct(ACCEL_ARGS, LIGHT_BINS_ARGS, vct_volume_desc vol,
                            __global const uint *keys, uint voxels,
                            __global const uint *voxel_start, __global const uint *fragment_tri,
                            uint fragments, __global const vct_material_desc *materials,
                            __global const uint *tri_material, __global const float4 *albedo,
                            __global const float4 *emission, __global const vct_light_desc *lights,
                            uint light_count, EMITTER_ARGS, TEXTURE_ARGS, __global float4 *radiance,
                            __global const float4 *normal, __global float4 *side,
                            __global const uint *carried_from, uint carry) {
    const uint v = get_global_id(0);
    if (v >= voxels || (carry && carried_from[v] != VCT_NO_VOXEL))
        return;
    const accel_view g = ACCEL_VIEW();
    const light_bins_view bins = LIGHT_BINS_VIEW();
    const emitter_view ev = EMITTER_VIEW();
    const texture_view tv = TEXTURE_VIEW();
    const float size = vol.origin.w / (float)vol.res.x;
    const float3 p = vol.origin.xyz + (convert_float3(morton_decode(keys[v])) + 0.5f) * size;
    const uint begin = voxel_start[v], end = v + 1 < voxels ? voxel_start[v + 1] : fragments;
    const float3 axis = normal[v].xyz;
    side_cube sides = side_cube_empty();
    float3 q_sum = (float3)(0.0f);
    uint surfaces = 0;
    float open_sides = 0.0f; /* the fragments' sides not hidden, in halves */
    /* lights and emitters keep apart: each has its own shared rays */
    shared_rays lit = {(float3)(0.0f), (float3)(0.0f), {0}, 0u, 0u, 0},
                glow = {(float3)(0.0f), (float3)(0.0f), {0}, 0u, 0u, 0},
                rim = {(float3)(0.0f), (float3)(0.0f), {0}, 0u, 0u, 0};
    /* what leaves gaps under emitters (gap_escape), and the side it leaves on */
    float3 escape = (float3)(0.0f), escape_side = (float3)(0.0f);
    /* Each fragment weighs by its triangle's area inside the voxel, as the
     * voxel's albedo and opacity do (vox_reduce): a thin closed object's
     * edge, a strip a fifth of a voxel's width along a slat, would send as
     * much as its faces (where fragments only touch the voxel, plain means) */
    float area_total = 0.0f;
    for (uint f = begin; f < end; ++f)
        area_total += fragment_area(tri_vertices, fragment_tri[f], p, size);
    const int by_area = area_total >= CLIP_AREA_WEIGHED_MIN;
    for (uint f = begin; f < end; ++f) {
        const uint t = fragment_tri[f];
        const float3 a = tri_vertices[3u * t].xyz, b = tri_vertices[3u * t + 1u].xyz,
                     c = tri_vertices[3u * t + 2u].xyz;
        const float3 cr = tri_normal(a, b, c);
        const float len = length(cr);
        if (!(len > 0.0f))
            continue; /* zero area: never hit, never lit */
        ++surfaces;
        const float3 q = triangle_nearest(p, a, b, c), n = cr / len;
        q_sum += q;
        if (light_count == 0u && emitter_count == 0u)
            continue; /* nothing to send out: the sides stay dark */
        const uint hidden =
            fragment_enclosed(tri_vertices, fragment_tri, begin, end, f, p, n, q, size,
                              fmax(1e-3f * size, 8.0f * surface_epsilon(&g, q)));
        const float weight = by_area ? fragment_area(tri_vertices, t, p, size) : 1.0f;
        open_sides += 0.5f * weight * (float)(((hidden & 1u) == 0u) + ((hidden & 2u) == 0u));
        float3 behind = (float3)(0.0f);
        const float plane = SHARED_PLANE * size;
        const int reuse_lit = shared_plane(&lit, n, q, plane);
        float3 front =
            fragment_irradiance(&g, &bins, lights, light_count, p, q, n, &behind, &lit, reuse_lit);
        if (!reuse_lit) {
            lit.n = n;
            lit.q = q;
            lit.valid = light_count <= SHARED_LIGHTS;
        }
        const vct_material_desc m = materials[tri_material[t]];
        const float3 rho = fragment_albedo(&tv, &m, t, a, b, c, p, size);
        if (emitter_count > 0u) {
            /* the first fragment's stream: shared samples are the same samples */
            const int reuse_glow = shared_plane(&glow, n, q, plane);
            front += fragment_emitters(&g, &ev, materials, tri_material, p, q, n, size, &behind,
                                       reuse_glow ? glow.seed : f, &glow, reuse_glow);
            if (!reuse_glow) {
                glow.n = n;
                glow.q = q;
                glow.seed = f;
                glow.valid = ev.samples <= SHARED_LIGHTS;
            }
            /* once per plane: the fragments of one surface share its rim */
            const int same_rim =
                shared_plane(&rim, n, q, plane) || shared_plane(&rim, -n, q, plane);
            float3 out_side;
            const float3 out =
                same_rim ? (float3)(0.0f)
                         : gap_escape(&g, &ev, materials, tri_material, p, q, n, size, &out_side);
            if (any(out != 0.0f)) {
                escape += rho * out;
                escape_side = out_side;
                rim.n = n;
                rim.q = q;
                rim.valid = 1;
            }
        }
        if (!(hidden & 1u))
            side_cube_add(&sides, n, weight * rho * front);
        if (!(hidden & 2u))
            side_cube_add(&sides, -n, weight * rho * behind);
    }
    const float scale = open_sides > 0.0f ? VCT_INV_PI / open_sides : 0.0f;
    /* the plane between the sides: across the way most light leaves, else
     * the normal axis (or none) */
    const float lean = length(sides.lean);
    const float3 n = lean > 0.0f ? sides.lean / lean : axis;
    float3 toward, away;
    side_cube_split(&sides, n, &toward, &away);
    /* Emitters sampled as lights light the voxels (and the camera's hits)
     * directly, so the voxels leave their emission out: cones would count
     * it a second time. */
    const float3 glows = emitter_count > 0u ? (float3)(0.0f) : emission[v].xyz;
    const float3 centre =
        ((surfaces > 0u ? q_sum / (float)surfaces : p) - vol.origin.xyz) / vol.origin.w - 0.5f;
    /* w: the opacity, so that re-filtering reads one array */
    const int escape_toward = dot(escape_side, n) >= 0.0f;
    voxel_side_store(toward * scale + glows + (escape_toward ? escape : (float3)(0.0f)),
                     away * scale + glows + (escape_toward ? (float3)(0.0f) : escape), n, centre,
                     albedo[v].w, radiance, side, v);
}
