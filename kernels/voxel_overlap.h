/* Exact triangle / voxel overlap on integer coordinates.
 *
 * Vertices are integers (VCT_VOLUME_UNITS_LOG2 bits per cube side, within
 * one side outside the cube), voxels are closed boxes [b, b + q]^3. Every
 * product stays below 2^63, so the tests are exact: no rounding, no
 * tolerance, the same answer on every device.
 *
 * Conservative (26-separating): the separating axis theorem with the plane
 * normal and the 9 edge x axis products (the box normals are covered by the
 * caller, which only visits voxels inside the triangle's bounding box).
 * Thin (6-separating, Schwarz & Seidel 2010): the plane passes within half a
 * voxel of the centre along the dominant axis, and in each axis-aligned
 * projection the triangle overlaps the diamond inscribed in the voxel. */
#ifndef VCT_VOXEL_OVERLAP_H
#define VCT_VOXEL_OVERLAP_H

inline long vox_dot(long3 a, long3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

inline long3 vox_cross(long3 a, long3 b) {
    return (long3)(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

inline long vox_abs(long v) { return v < 0 ? -v : v; }

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

/* Edge x axis separating tests, the vertex side precomputed per triangle. */
typedef struct vox_sat {
    long3 axis[9];
    long lo[9], hi[9];
} vox_sat;

inline void vox_sat_init(const vox_triangle *t, vox_sat *s) {
    const long3 e[3] = {t->b - t->a, t->c - t->b, t->a - t->c};
    for (int i = 0; i < 3; ++i) {
        s->axis[3 * i + 0] = (long3)(0, -e[i].z, e[i].y);
        s->axis[3 * i + 1] = (long3)(e[i].z, 0, -e[i].x);
        s->axis[3 * i + 2] = (long3)(-e[i].y, e[i].x, 0);
    }
    for (int k = 0; k < 9; ++k) {
        const long pa = vox_dot(s->axis[k], t->a), pb = vox_dot(s->axis[k], t->b),
                   pc = vox_dot(s->axis[k], t->c);
        s->lo[k] = min(pa, min(pb, pc));
        s->hi[k] = max(pa, max(pb, pc));
    }
}

/* 26-separating: the closed box [b, b + q]^3 meets the triangle. */
inline int vox_overlaps_conservative(const vox_triangle *t, const vox_sat *s, long3 b, long q) {
    const long2 plane = vox_box_interval(t->n, b, q);
    if (t->d < plane.x || t->d > plane.y)
        return 0;
    for (int k = 0; k < 9; ++k) {
        const long2 box = vox_box_interval(s->axis[k], b, q);
        if (s->hi[k] < box.x || s->lo[k] > box.y)
            return 0;
    }
    return 1;
}

/* One projection of the thin test: `r` rotates the axes so that the
 * projection axis is z; p2 is twice the voxel centre. */
inline int vox_thin_projection(long3 a, long3 b, long3 c, long nz, long3 p2, long q) {
    const long sign = nz < 0 ? -1 : 1;
    const long3 v[3] = {a, b, c};
    for (int i = 0; i < 3; ++i) {
        const long3 e = v[(i + 1) % 3] - v[i];
        const long nx = -e.y * sign, ny = e.x * sign;
        const long f = nx * (p2.x - 2 * v[i].x) + ny * (p2.y - 2 * v[i].y) +
                       q * max(vox_abs(nx), vox_abs(ny));
        if (f < 0)
            return 0;
    }
    return 1;
}

/* 6-separating: see the file comment. */
inline int vox_overlaps_thin(const vox_triangle *t, long3 b, long q) {
    const long3 p2 = 2 * b + q;
    const long plane = vox_dot(t->n, p2) - 2 * t->d;
    const long nmax = max(vox_abs(t->n.x), max(vox_abs(t->n.y), vox_abs(t->n.z)));
    if (vox_abs(plane) > q * nmax)
        return 0;
    return vox_thin_projection(t->a, t->b, t->c, t->n.z, p2, q) &&
           vox_thin_projection(t->a.yzx, t->b.yzx, t->c.yzx, t->n.x, p2.yzx, q) &&
           vox_thin_projection(t->a.zxy, t->b.zxy, t->c.zxy, t->n.y, p2.zxy, q);
}

#endif
