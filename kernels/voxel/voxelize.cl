/* Triangle-parallel voxelization: chunks -> scan -> count -> scan -> write,
 * then (on the host) a stable sort by Morton key and a per-voxel reduction.
 *
 * Each triangle is projected along its dominant normal axis; its work is the
 * set of voxel columns over its bounding rectangle there, cut into chunks of
 * VOX_COLUMNS_PER_CHUNK columns so that a huge triangle spreads over many
 * work-items. In each column the plane's exact range of z leaves at most
 * three voxels; the exact integer tests (voxel_overlap.h) decide. Counting and
 * writing share one walk, so they cannot disagree, and fragments come out in
 * (triangle, column, voxel) order whatever the schedule. */
#include "voxel/octree.h"
#include "vct_types.h"
#include "voxel/voxel_overlap.h"
#include "voxel/fragment_albedo.h"
#include "voxel/clip_area.h"

#define VOX_COLUMNS_PER_CHUNK 32u

/* A triangle rotated so that its dominant normal axis is z. */
typedef struct vox_setup {
    vox_triangle tri;
    int3 lo, hi; /* voxel range of the bounding box, clamped to the volume */
    uint axis;   /* the dominant axis in the original frame */
} vox_setup;

inline long3 vox_rotate(long3 v, uint axis) {
    return axis == 0u ? v.yzx : (axis == 1u ? v.zxy : v);
}

inline int3 vox_unrotate(int3 v, uint axis) {
    return axis == 0u ? v.zxy : (axis == 1u ? v.yzx : v);
}

inline long3 vox_vertex(__global const int4 *tris, uint i) {
    return convert_long3(tris[i].xyz);
}

/* 0 for a zero-area triangle or one that misses the volume. */
inline int vox_setup_make(__global const int4 *tris, uint t, vct_volume_desc vol, vox_setup *s) {
    long3 a = vox_vertex(tris, 3 * t), b = vox_vertex(tris, 3 * t + 1),
          c = vox_vertex(tris, 3 * t + 2);
    const long3 n = vox_cross(b - a, c - b);
    if (n.x == 0 && n.y == 0 && n.z == 0)
        return 0;
    const long ax = vox_abs(n.x), ay = vox_abs(n.y), az = vox_abs(n.z);
    s->axis = (ax >= ay && ax >= az) ? 0u : (ay >= az ? 1u : 2u);
    a = vox_rotate(a, s->axis);
    b = vox_rotate(b, s->axis);
    c = vox_rotate(c, s->axis);
    s->tri = vox_triangle_make(a, b, c);
    const long q = vol.res.z, last = (long)vol.res.x - 1;
    const long3 mn = min(a, min(b, c)), mx = max(a, max(b, c));
    /* Voxel i's closed box [iq, (i+1)q] meets [mn, mx] iff (mn-1) div q <= i <= mx div q. */
    const long3 lo =
        (long3)(vox_floor_div(mn.x - 1, q), vox_floor_div(mn.y - 1, q), vox_floor_div(mn.z - 1, q));
    const long3 hi =
        (long3)(vox_floor_div(mx.x, q), vox_floor_div(mx.y, q), vox_floor_div(mx.z, q));
    if (any(hi < 0) || any(lo > last))
        return 0;
    s->lo = convert_int3(clamp(lo, 0L, last));
    s->hi = convert_int3(clamp(hi, 0L, last));
    return 1;
}

inline uint vox_columns(const vox_setup *s) {
    return (uint)(s->hi.x - s->lo.x + 1) * (uint)(s->hi.y - s->lo.y + 1);
}

/* Walks the voxels of chunk `first / VOX_COLUMNS_PER_CHUNK` of triangle t;
 * with `write` stores (Morton key, t) from keys[out]. Returns the count.
 * Per column: the projection test along z (the same for every voxel of the
 * column), then the plane's exact range of z; columns wholly inside the
 * projection need no more tests, the others test each voxel's remaining axes. */
inline uint vox_visit(__global const int4 *tris, uint t, uint first, vct_volume_desc vol, int thin,
                      int write, __global uint *keys, __global uint *ids, uint out) {
    vox_setup s;
    if (!vox_setup_make(tris, t, vol, &s))
        return 0;
    vox_sat sat;
    if (!thin)
        vox_sat_init(&s.tri, &sat);
    const long q = vol.res.z;
    const uint width = (uint)(s.hi.x - s.lo.x + 1);
    const uint end = min(first + VOX_COLUMNS_PER_CHUNK, vox_columns(&s));
    uint n = 0;
    for (uint col = first; col < end; ++col) {
        const int u = s.lo.x + (int)(col % width), v = s.lo.y + (int)(col / width);
        const long uq = (long)u * q, vq = (long)v * q;
        int column;
        long2 z;
        if (thin) {
            column = vox_thin_column(&s.tri, uq, vq, q) ? VOX_COLUMN_CROSSES : VOX_COLUMN_MISSES;
            z = vox_thin_z_range(&s.tri, uq, vq, q);
        } else {
            column = vox_column_test(&sat, uq, vq, q);
            z = vox_plane_z_range(&s.tri, uq, vq, q);
        }
        const int z_lo = (int)max(z.x, (long)s.lo.z), z_hi = (int)min(z.y, (long)s.hi.z);
        if (column == VOX_COLUMN_MISSES || z_lo > z_hi)
            continue;
        for (int zi = z_lo; zi <= z_hi; ++zi) {
            const long3 corner = (long3)(uq, vq, (long)zi * q);
            if (column != VOX_COLUMN_INSIDE &&
                !(thin ? vox_thin_sides(&s.tri, corner, q) : vox_edges_overlap(&sat, corner, q)))
                continue;
            if (write) {
                keys[out + n] =
                    morton_encode(convert_uint3(vox_unrotate((int3)(u, v, zi), s.axis)));
                ids[out + n] = t;
            }
            ++n;
        }
    }
    return n;
}

/* Chunks per triangle, and its unit normal with the material index in w
 * (as a float: exact below 2^24, and not a denormal that could be flushed). */
/* Triangles first_tri .. first_tri + vol.res.w - 1 (all of them, or the
 * ones that moved): chunks is indexed from first_tri, the rest by triangle. */
__kernel void vox_chunks(__global const int4 *tris, vct_volume_desc vol, uint first_tri,
                         __global uint *chunks, __global float4 *tri_normals) {
    const uint i = get_global_id(0), t = first_tri + i;
    if (i >= vol.res.w)
        return;
    vox_setup s;
    chunks[i] = vox_setup_make(tris, t, vol, &s)
                    ? (vox_columns(&s) + VOX_COLUMNS_PER_CHUNK - 1) / VOX_COLUMNS_PER_CHUNK
                    : 0u;
    const long3 a = vox_vertex(tris, 3 * t), b = vox_vertex(tris, 3 * t + 1),
                c = vox_vertex(tris, 3 * t + 2);
    const float3 n = convert_float3(vox_cross(b - a, c - b));
    const float scale = fmax(fabs(n.x), fmax(fabs(n.y), fabs(n.z)));
    tri_normals[t] =
        (float4)(scale > 0.0f ? normalize(n / scale) : (float3)(0.0f), (float)tris[3 * t].w);
}

/* The triangle owning chunk c: the last t with chunk_start[t] <= c. */
inline uint vox_chunk_owner(__global const uint *chunk_start, uint triangles, uint c) {
    uint lo = 0, hi = triangles;
    while (hi - lo > 1) {
        const uint mid = (lo + hi) / 2;
        if (chunk_start[mid] <= c)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

__kernel void vox_count(__global const int4 *tris, vct_volume_desc vol, uint first_tri, int thin,
                        __global const uint *chunk_start, uint chunks, __global uint *counts) {
    const uint c = get_global_id(0);
    if (c >= chunks)
        return;
    const uint i = vox_chunk_owner(chunk_start, vol.res.w, c);
    const uint first = (c - chunk_start[i]) * VOX_COLUMNS_PER_CHUNK;
    counts[c] = vox_visit(tris, first_tri + i, first, vol, thin, 0, counts, counts, 0);
}

__kernel void vox_write(__global const int4 *tris, vct_volume_desc vol, uint first_tri, int thin,
                        __global const uint *chunk_start, uint chunks, __global const uint *offsets,
                        __global uint *keys, __global uint *ids) {
    const uint c = get_global_id(0);
    if (c >= chunks)
        return;
    const uint i = vox_chunk_owner(chunk_start, vol.res.w, c);
    const uint first = (c - chunk_start[i]) * VOX_COLUMNS_PER_CHUNK;
    vox_visit(tris, first_tri + i, first, vol, thin, 1, keys, ids, offsets[c]);
}

/* The fragments before that stay: each fragment's voxel key (from its
 * voxel's), and 1 where its triangle is outside [moved_lo, moved_hi). */
__kernel void vox_kept(__global const uint *voxel_keys, __global const uint *voxel_start,
                       uint voxels, uint fragments, __global const uint *ids, uint moved_lo,
                       uint moved_hi, __global uint *keys, __global uint *keep) {
    const uint v = get_global_id(0);
    if (v >= voxels)
        return;
    const uint end = v + 1u < voxels ? voxel_start[v + 1u] : fragments;
    for (uint f = voxel_start[v]; f < end; ++f) {
        keys[f] = voxel_keys[v];
        keep[f] = ids[f] < moved_lo || ids[f] >= moved_hi;
    }
}

/* Scatters the kept fragments to their places in order (index: the
 * exclusive scan of keep). */
__kernel void vox_compact(__global const uint *keys, __global const uint *ids,
                          __global const uint *keep, __global const uint *index, uint n,
                          __global uint *kept_keys, __global uint *kept_ids) {
    const uint f = get_global_id(0);
    if (f < n && keep[f]) {
        kept_keys[index[f]] = keys[f];
        kept_ids[index[f]] = ids[f];
    }
}

/* How many of the n (key, id) pairs sort before (key, id), by key then id. */
inline uint vox_rank(__global const uint *keys, __global const uint *ids, uint n, uint key,
                     uint id) {
    uint lo = 0u, hi = n;
    while (lo < hi) {
        const uint mid = lo + (hi - lo) / 2u;
        if (keys[mid] < key || (keys[mid] == key && ids[mid] < id))
            lo = mid + 1u;
        else
            hi = mid;
    }
    return lo;
}

/* Two lists sorted by (key, triangle), a kept one and one of the moved
 * triangles (no triangle in both), merged into one so sorted: the order a
 * full voxelization gives. Work-items 0 .. a - 1 place a's pairs, the
 * rest b's. */
__kernel void vox_merge(__global const uint *a_keys, __global const uint *a_ids, uint a,
                        __global const uint *b_keys, __global const uint *b_ids, uint b,
                        __global uint *keys, __global uint *ids) {
    const uint i = get_global_id(0);
    if (i < a) {
        const uint at = i + vox_rank(b_keys, b_ids, b, a_keys[i], a_ids[i]);
        keys[at] = a_keys[i];
        ids[at] = a_ids[i];
    } else if (i < a + b) {
        const uint j = i - a, at = j + vox_rank(a_keys, a_ids, a, b_keys[j], b_ids[j]);
        keys[at] = b_keys[j];
        ids[at] = b_ids[j];
    }
}

/* 1 where a sorted key starts a new voxel. */
__kernel void vox_heads(__global const uint *keys, uint n, __global uint *heads) {
    const uint i = get_global_id(0);
    if (i < n)
        heads[i] = i == 0 || keys[i] != keys[i - 1];
}

/* index: exclusive scan of the heads. Records each voxel's key and first fragment. */
__kernel void vox_starts(__global const uint *keys, uint n, __global const uint *index,
                         __global uint *voxel_keys, __global uint *voxel_start) {
    const uint i = get_global_id(0);
    if (i < n && (i == 0 || keys[i] != keys[i - 1])) {
        voxel_keys[index[i]] = keys[i];
        voxel_start[index[i]] = i;
    }
}

/* The sum of n n^T over a voxel's fragment normals, symmetric: xx yy zz in
 * d, xy yz zx in o. A normal and its negation add the same bits to it. */
typedef struct normal_tensor {
    float3 d, o;
} normal_tensor;

inline float3 tensor_apply(normal_tensor m, float3 v) {
    return (float3)(m.d.x * v.x + m.o.x * v.y + m.o.z * v.z,
                    m.o.x * v.x + m.d.y * v.y + m.o.y * v.z,
                    m.o.z * v.x + m.o.y * v.y + m.d.z * v.z);
}

/* m^2 over its trace (which keeps it bounded; the eigenvectors stay). */
inline normal_tensor tensor_square(normal_tensor m) {
    const float3 cx = (float3)(m.d.x, m.o.x, m.o.z), cy = (float3)(m.o.x, m.d.y, m.o.y),
                 cz = (float3)(m.o.z, m.o.y, m.d.z);
    normal_tensor r;
    r.d = (float3)(dot(cx, cx), dot(cy, cy), dot(cz, cz));
    r.o = (float3)(dot(cx, cy), dot(cy, cz), dot(cz, cx));
    const float trace = r.d.x + r.d.y + r.d.z;
    r.d /= trace;
    r.o /= trace;
    return r;
}

/* The axis that fits the normals best: the principal eigenvector of their
 * tensor, found as m^256 times m's column of largest diagonal (power
 * iteration by squaring), canonical in sign. Where two eigenvalues tie (two
 * perpendicular walls), a fixed vector of their plane. 0 without normals. */
inline float3 tensor_axis(normal_tensor m) {
    if (!(m.d.x + m.d.y + m.d.z > 0.0f))
        return (float3)(0.0f);
    normal_tensor p = m;
    for (int i = 0; i < 8; ++i)
        p = tensor_square(p);
    const float3 e = p.d.x >= p.d.y && p.d.x >= p.d.z ? (float3)(1.0f, 0.0f, 0.0f)
                     : p.d.y >= p.d.z                 ? (float3)(0.0f, 1.0f, 0.0f)
                                                      : (float3)(0.0f, 0.0f, 1.0f);
    const float3 v = tensor_apply(p, e);
    const float len = length(v);
    return len > 0.0f ? axis_canonical(v / len) : e;
}

/* Sums each voxel's fragments in sorted order (deterministic), each weighed
 * by the area of its triangle inside the voxel (clip_area.h), in voxel
 * faces: albedo (each fragment's mean over its part of the voxel where its
 * material has a texture, fragment_albedo.h) and emission are means by area;
 * opacity is the area's opaque share (1 - transmission, times the share an
 * alpha mask keeps), at most 1. A wall across the voxel makes it opaque;
 * a bead or a slat a fraction of a voxel wide covers, blocks and sends light
 * in proportion to its surface, not as a whole voxel. Fragments that only
 * touch the voxel (no area) give plain means and no opacity.
 * Surfaces are two-sided, so a fragment's normal counts for its line, not its sign: the voxel's
 * normal is the axis that fits its fragments' normals best (tensor_axis), and a surface wound
 * either way, or a mix, gives it bit for bit. normal.w: how well it fits, sqrt(mean of (n .
 * axis)^2), 1 when all fragments lie along it. emission.w holds the fragment count. */
__kernel void vox_reduce(__global const uint *ids, __global const uint *voxel_start, uint voxels,
                         uint fragments, __global const float4 *tri_normals,
                         __global const vct_material_desc *materials, __global const uint *keys,
                         __global const int4 *tris, vct_volume_desc vol, TEXTURE_ARGS,
                         __global float4 *albedo_out, __global float4 *normal_out,
                         __global float4 *emission_out) {
    const uint v = get_global_id(0);
    if (v >= voxels)
        return;
    const texture_view tv = TEXTURE_VIEW();
    const float voxel = vol.origin.w / (float)vol.res.x;
    const float unit = vol.origin.w / (float)(1u << VCT_VOLUME_UNITS_LOG2);
    const uint3 cell = morton_decode(keys[v]);
    const float3 centre = vol.origin.xyz + (convert_float3(cell) + 0.5f) * voxel;
    const int q = (int)((1u << VCT_VOLUME_UNITS_LOG2) / vol.res.x);
    const int3 centre_units = convert_int3(cell) * q + q / 2;
    const float voxels_per_unit = 1.0f / (float)q; /* a power of two: exact */
    const uint begin = voxel_start[v], end = v + 1 < voxels ? voxel_start[v + 1] : fragments;
    /* area-weighted sums (the surface's area inside the voxel, in faces),
     * and plain ones for voxels whose fragments only touch it */
    float3 albedo_area = 0.0f, albedo_plain = 0.0f, emission_area = 0.0f, emission_plain = 0.0f;
    float area_sum = 0.0f, opacity_area = 0.0f;
    normal_tensor m = {(float3)(0.0f), (float3)(0.0f)};
    for (uint f = begin; f < end; ++f) {
        const uint t = ids[f];
        const float4 tn = tri_normals[t];
        const vct_material_desc mat = materials[(uint)tn.w];
        const int3 ia = tris[3u * t].xyz, ib = tris[3u * t + 1u].xyz, ic = tris[3u * t + 2u].xyz;
        /* corners relative to the voxel's centre from the integer units:
         * exact, however far the triangle reaches */
        const float area =
            triangle_area_in_cube(convert_float3(ia - centre_units) * voxels_per_unit,
                                  convert_float3(ib - centre_units) * voxels_per_unit,
                                  convert_float3(ic - centre_units) * voxels_per_unit);
        float3 fragment_albedo;
        float kept;
        if ((uint)mat.extra.y != 0u) {
            uint inside;
            /* world corners, for the texture's samples */
            const float3 a = vol.origin.xyz + convert_float3(ia) * unit;
            const float3 b = vol.origin.xyz + convert_float3(ib) * unit;
            const float3 c = vol.origin.xyz + convert_float3(ic) * unit;
            const float3 sum =
                fragment_albedo_sum(&tv, &mat, t, a, b, c, centre, voxel, &inside, &kept);
            fragment_albedo = inside > 0u ? sum / (float)inside : sum;
        } else {
            kept = fragment_kept(&mat, (float4)(1.0f)) ? 1.0f : 0.0f;
            fragment_albedo = mat.albedo.xyz;
        }
        albedo_area += area * fragment_albedo;
        albedo_plain += fragment_albedo;
        emission_area += area * mat.emission.xyz;
        emission_plain += mat.emission.xyz;
        area_sum += area;
        opacity_area += area * (1.0f - mat.specular.w) * kept;
        m.d += tn.xyz * tn.xyz;
        m.o += tn.xyz * tn.yzx;
    }
    const float inv = 1.0f / (float)(end - begin);
    /* one fragment (most voxels): its own normal is the axis exactly, and
     * the eight squarings are saved (they cost the reduction 2x) */
    const float3 single = tri_normals[ids[begin]].xyz;
    const float3 axis = end - begin == 1u ? (all(single == 0.0f) ? single : axis_canonical(single))
                                          : tensor_axis(m);
    const int weighed = area_sum > CLIP_AREA_WEIGHED_MIN;
    albedo_out[v] =
        (float4)(weighed ? albedo_area / area_sum : albedo_plain * inv, fmin(opacity_area, 1.0f));
    normal_out[v] = (float4)(axis, sqrt(fmax(dot(axis, tensor_apply(m, axis)), 0.0f) * inv));
    emission_out[v] =
        (float4)(weighed ? emission_area / area_sum : emission_plain * inv, (float)(end - begin));
}
