/* Exact triangle / voxel overlap on integer coordinates.
 *
 * Vertices are integers (VCT_VOLUME_UNITS_LOG2 bits per cube side, within
 * one side outside the cube), voxels are closed boxes [b, b + q]^3. Every
 * product stays below 2^63, so the tests are exact: no rounding, no
 * tolerance, the same answer on every device.
 *
 * Conservative (26-separating): the separating axis theorem with the plane
 * normal and the 9 edge x axis products (the box normals are covered by the
 * caller, which only visits voxels inside the triangle's bounding box), the
 * triangle rotated so that z is its dominant normal axis.
 * Thin (6-separating, Schwarz & Seidel 2010): the plane passes within half a
 * voxel of the centre along the dominant axis, and in each axis-aligned
 * projection the triangle overlaps the diamond inscribed in the voxel. */
#ifndef VCT_VOXEL_OVERLAP_H
#define VCT_VOXEL_OVERLAP_H

inline long vox_dot(long3 a, long3 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

inline long3 vox_cross(long3 a, long3 b) {
    return (long3)(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

inline long vox_abs(long v) {
    return v < 0 ? -v : v;
}

/* The box [b, b + q]^3 projected onto axis: (min, max). */
inline long2 vox_box_interval(long3 axis, long3 b, long q) {
    const long base = vox_dot(axis, b);
    const long neg = min(axis.x, 0L) + min(axis.y, 0L) + min(axis.z, 0L);
    const long pos = max(axis.x, 0L) + max(axis.y, 0L) + max(axis.z, 0L);
    return (long2)(base + q * neg, base + q * pos);
}

typedef struct vox_triangle {
    long3 a, b, c;
    long3 n; /* (b - a) x (c - b): zero for a zero-area triangle */
    long d;  /* n . a: the plane is n . p = d */
} vox_triangle;

inline vox_triangle vox_triangle_make(long3 a, long3 b, long3 c) {
    vox_triangle t;
    t.a = a;
    t.b = b;
    t.c = c;
    t.n = vox_cross(b - a, c - b);
    t.d = vox_dot(t.n, a);
    return t;
}

/* Edge x axis separating tests, the vertex side precomputed per triangle.
 * Axes 0-2 are edge x z: they do not depend on z, so a whole column of
 * voxels is tested against them at once. */
typedef struct vox_sat {
    long3 axis[9];
    long lo[9], hi[9];
} vox_sat;

inline void vox_sat_init(const vox_triangle *t, vox_sat *s) {
    const long3 e[3] = {t->b - t->a, t->c - t->b, t->a - t->c};
    for (int i = 0; i < 3; ++i) {
        s->axis[i] = (long3)(-e[i].y, e[i].x, 0);
        s->axis[3 + 2 * i] = (long3)(0, -e[i].z, e[i].y);
        s->axis[4 + 2 * i] = (long3)(e[i].z, 0, -e[i].x);
    }
    for (int k = 0; k < 9; ++k) {
        const long pa = vox_dot(s->axis[k], t->a), pb = vox_dot(s->axis[k], t->b),
                   pc = vox_dot(s->axis[k], t->c);
        s->lo[k] = min(pa, min(pb, pc));
        s->hi[k] = max(pa, max(pb, pc));
    }
}

#define VOX_COLUMN_MISSES 0
#define VOX_COLUMN_CROSSES 1
#define VOX_COLUMN_INSIDE 2

/* The column over the square [u, u + q] x [v, v + q] (u, v in units)
 * against the triangle's projection along z: missed, crossed by an edge, or
 * wholly inside. The three edge x z slabs intersect in exactly the
 * projected triangle, so inside all three means inside the triangle. */
inline int vox_column_test(const vox_sat *s, long u, long v, long q) {
    int inside = 1;
    for (int k = 0; k < 3; ++k) {
        const long3 a = s->axis[k];
        const long base = a.x * u + a.y * v;
        const long box_lo = base + q * (min(a.x, 0L) + min(a.y, 0L));
        const long box_hi = base + q * (max(a.x, 0L) + max(a.y, 0L));
        if (s->hi[k] < box_lo || s->lo[k] > box_hi)
            return VOX_COLUMN_MISSES;
        inside &= s->lo[k] <= box_lo && box_hi <= s->hi[k];
    }
    return inside ? VOX_COLUMN_INSIDE : VOX_COLUMN_CROSSES;
}

inline long vox_floor_div(long a, long b) {
    return a >= 0 ? a / b : -((-a + b - 1) / b);
}

/* The z with lo <= step * z <= hi (step != 0), as (first, last). */
inline long2 vox_z_solve(long lo, long hi, long step) {
    if (step < 0) {
        const long t = lo;
        lo = -hi;
        hi = -t;
        step = -step;
    }
    return (long2)(-vox_floor_div(-lo, step), vox_floor_div(hi, step));
}

/* Voxels z of column (u, v) (in units) whose closed box the plane meets:
 * n.b + q * sum(min(n, 0)) <= d <= n.b + q * sum(max(n, 0)). */
inline long2 vox_plane_z_range(const vox_triangle *t, long u, long v, long q) {
    const long3 n = t->n;
    const long base = t->d - n.x * u - n.y * v;
    const long neg = min(n.x, 0L) + min(n.y, 0L) + min(n.z, 0L);
    const long pos = max(n.x, 0L) + max(n.y, 0L) + max(n.z, 0L);
    return vox_z_solve(base - q * pos, base - q * neg, n.z * q);
}

/* 26-separating, for a box the plane meets in a column the triangle's
 * projection crosses: the six edge x axis tests that depend on z. */
inline int vox_edges_overlap(const vox_sat *s, long3 b, long q) {
    for (int k = 3; k < 9; ++k) {
        const long2 box = vox_box_interval(s->axis[k], b, q);
        if (s->hi[k] < box.x || s->lo[k] > box.y)
            return 0;
    }
    return 1;
}

/* One projection of the thin test, along the third axis of the arguments;
 * p2 is twice the voxel centre. */
inline int vox_thin_projection(long3 a, long3 b, long3 c, long nz, long3 p2, long q) {
    const long sign = nz < 0 ? -1 : 1;
    const long3 v[3] = {a, b, c};
    for (int i = 0; i < 3; ++i) {
        const long3 e = v[(i + 1) % 3] - v[i];
        const long nx = -e.y * sign, ny = e.x * sign;
        const long f =
            nx * (p2.x - 2 * v[i].x) + ny * (p2.y - 2 * v[i].y) + q * max(vox_abs(nx), vox_abs(ny));
        if (f < 0)
            return 0;
    }
    return 1;
}

/* 6-separating plane condition |n.(2b + q) - 2d| <= q max|n| solved for the
 * voxels z of column (u, v). */
inline long2 vox_thin_z_range(const vox_triangle *t, long u, long v, long q) {
    const long3 n = t->n;
    const long nmax = max(vox_abs(n.x), max(vox_abs(n.y), vox_abs(n.z)));
    const long base = 2 * t->d - 2 * (n.x * u + n.y * v) - q * (n.x + n.y + n.z);
    return vox_z_solve(base - q * nmax, base + q * nmax, 2 * n.z * q);
}

/* The thin test's projection along z, the same for a whole column. */
inline int vox_thin_column(const vox_triangle *t, long u, long v, long q) {
    const long3 p2 = (long3)(2 * u + q, 2 * v + q, 0);
    return vox_thin_projection(t->a, t->b, t->c, t->n.z, p2, q);
}

/* The thin test's projections along x and y, for a voxel inside the plane
 * slab of a column that passed vox_thin_column. */
inline int vox_thin_sides(const vox_triangle *t, long3 b, long q) {
    const long3 p2 = 2 * b + q;
    return vox_thin_projection(t->a.yzx, t->b.yzx, t->c.yzx, t->n.x, p2.yzx, q) &&
           vox_thin_projection(t->a.zxy, t->b.zxy, t->c.zxy, t->n.y, p2.zxy, q);
}

#endif
