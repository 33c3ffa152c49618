/* The area of a triangle inside an axis-aligned cube: the triangle clipped
 * by the cube's six planes (Sutherland-Hodgman), then its polygon's area.
 * Coordinates are relative to the cube's centre in units of its side, so the
 * cube is [-0.5, 0.5]^3 and the area comes out as a share of one face. */
#ifndef VCT_CLIP_AREA_H
#define VCT_CLIP_AREA_H

/* Below this area (in faces) a voxel's fragments only touch it: its means
 * are plain, not weighted by area. */
#define CLIP_AREA_WEIGHED_MIN 1e-6f

/* A triangle clipped by six planes has at most 3 + 6 corners. */
#define CLIP_AREA_MAX 9

/* Clips poly (n corners) to the half-space s * p[axis] <= 0.5 into out;
 * returns the new corner count. */
inline int clip_half_space(const float3 *poly, int n, int axis, float s, float3 *out) {
    int m = 0;
    for (int i = 0; i < n; ++i) {
        const float3 p = poly[i], q = poly[i + 1 < n ? i + 1 : 0];
        const float dp = s * (axis == 0 ? p.x : (axis == 1 ? p.y : p.z)) - 0.5f;
        const float dq = s * (axis == 0 ? q.x : (axis == 1 ? q.y : q.z)) - 0.5f;
        if (dp <= 0.0f)
            out[m++] = p;
        /* crossing: the point where the edge meets the plane */
        if ((dp < 0.0f && dq > 0.0f) || (dp > 0.0f && dq < 0.0f))
            out[m++] = p + (q - p) * (dp / (dp - dq));
    }
    return m;
}

/* Whether p comes before q in x, then y, then z. */
inline int clip_before(float3 p, float3 q) {
    return p.x < q.x || (p.x == q.x && (p.y < q.y || (p.y == q.y && p.z < q.z)));
}

/* Area of triangle (a, b, c), given in the cube's frame, inside the cube.
 * The corners are taken in one fixed order, so that the triangle wound
 * either way gives the same area bit for bit. */
inline float triangle_area_in_cube(float3 a, float3 b, float3 c) {
    float3 poly[CLIP_AREA_MAX + 1], next[CLIP_AREA_MAX + 1];
    if (clip_before(b, a)) {
        const float3 t = a;
        a = b;
        b = t;
    }
    if (clip_before(c, b)) {
        const float3 t = b;
        b = c;
        c = t;
    }
    if (clip_before(b, a)) {
        const float3 t = a;
        a = b;
        b = t;
    }
    poly[0] = a;
    poly[1] = b;
    poly[2] = c;
    int n = 3;
    /* only the planes the triangle crosses: a triangle inside the cube
     * (most fragments of fine meshes) is not clipped at all */
    const float3 lo = fmin(fmin(a, b), c), hi = fmax(fmax(a, b), c);
    for (int axis = 0; axis < 3 && n > 0; ++axis) {
        const float top = axis == 0 ? hi.x : (axis == 1 ? hi.y : hi.z);
        const float bottom = axis == 0 ? lo.x : (axis == 1 ? lo.y : lo.z);
        if (top > 0.5f) {
            n = clip_half_space(poly, n, axis, 1.0f, next);
            for (int i = 0; i < n; ++i)
                poly[i] = next[i];
        }
        if (bottom < -0.5f) {
            n = clip_half_space(poly, n, axis, -1.0f, next);
            for (int i = 0; i < n; ++i)
                poly[i] = next[i];
        }
    }
    if (n < 3)
        return 0.0f;
    /* a fan from the first corner: the polygon is convex */
    float3 twice = (float3)(0.0f);
    for (int i = 1; i + 1 < n; ++i)
        twice += cross(poly[i] - poly[0], poly[i + 1] - poly[0]);
    return 0.5f * length(twice);
}

#endif
