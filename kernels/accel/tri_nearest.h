/* Nearest points on triangles, barycentric coordinates, and normals as
 * axes. */
#ifndef VCT_TRI_NEAREST_H
#define VCT_TRI_NEAREST_H

/* The point of triangle (a, b, c) nearest p: by the region of the
 * triangle's plane that p projects into (a vertex, an edge, or inside). */
inline float3 triangle_nearest(float3 p, float3 a, float3 b, float3 c) {
    const float3 ab = b - a, ac = c - a;
    const float a_ab = dot(ab, p - a), a_ac = dot(ac, p - a);
    if (a_ab <= 0.0f && a_ac <= 0.0f)
        return a;
    const float b_ab = dot(ab, p - b), b_ac = dot(ac, p - b);
    if (b_ab >= 0.0f && b_ac <= b_ab)
        return b;
    const float c_ab = dot(ab, p - c), c_ac = dot(ac, p - c);
    if (c_ac >= 0.0f && c_ab <= c_ac)
        return c;
    const float w_c = a_ab * b_ac - b_ab * a_ac; /* p's weight of c, unnormalised */
    if (w_c <= 0.0f && a_ab >= 0.0f && b_ab <= 0.0f)
        return a + ab * (a_ab / (a_ab - b_ab));
    const float w_b = c_ab * a_ac - a_ab * c_ac;
    if (w_b <= 0.0f && a_ac >= 0.0f && c_ac <= 0.0f)
        return a + ac * (a_ac / (a_ac - c_ac));
    const float w_a = b_ab * c_ac - c_ab * b_ac;
    if (w_a <= 0.0f && b_ac - b_ab >= 0.0f && c_ab - c_ac >= 0.0f)
        return b + (c - b) * ((b_ac - b_ab) / ((b_ac - b_ab) + (c_ab - c_ac)));
    const float inv = 1.0f / (w_a + w_b + w_c);
    const float3 q = a + ab * (w_b * inv) + ac * (w_c * inv);
    return all(isfinite(q)) ? q : a;
}

/* A surface's normal as an axis: the sign that makes its largest component
 * positive (the first such component on ties). A surface and its copy wound
 * the other way give the same axis bit for bit. */
inline float3 axis_canonical(float3 n) {
    const float3 a = fabs(n);
    const float lead = a.x >= a.y && a.x >= a.z ? n.x : a.y >= a.z ? n.y : n.z;
    return lead < 0.0f ? -n : n;
}

/* Barycentrics (u, v) of point q of triangle (a, b, c)'s plane: q = a +
 * u (b - a) + v (c - a); (0, 0) for a degenerate triangle. */
inline float2 triangle_barycentrics(float3 q, float3 a, float3 b, float3 c) {
    const float3 e1 = b - a, e2 = c - a, d = q - a;
    const float d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2);
    const float d1 = dot(d, e1), d2 = dot(d, e2);
    const float det = d11 * d22 - d12 * d12;
    if (!(det > 0.0f))
        return (float2)(0.0f);
    return (float2)(d22 * d1 - d12 * d2, d11 * d2 - d12 * d1) / det;
}

#endif
