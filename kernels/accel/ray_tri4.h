/* The watertight ray / triangle test of ray_tri.h on up to four triangles at
 * once: the same operations in the same order, one float4 lane per triangle,
 * so every lane's t, u and v are bit for bit what ray_triangle gives for it
 * (zero edge values re-evaluated in double per lane, as there). */
#ifndef VCT_RAY_TRI4_H
#define VCT_RAY_TRI4_H

#include "accel/ray_tri.h"

typedef struct tri4_hits {
    float4 t, u, v;
    int4 hit; /* -1 in lanes whose triangle the ray meets in (tmin, tmax] */
} tri4_hits;

/* Sheared coordinates of four vertices given as x, y, z lanes. */
inline void ray_sheared4(const ray_shear *r, float4 x, float4 y, float4 z, float4 *sx, float4 *sy,
                         float4 *sz) {
    const float4 px = x - r->org.x, py = y - r->org.y, pz = z - r->org.z;
    *sx = (px * r->col[0].x + py * r->col[1].x) + pz * r->col[2].x;
    *sy = (px * r->col[0].y + py * r->col[1].y) + pz * r->col[2].y;
    *sz = (px * r->col[0].z + py * r->col[1].z) + pz * r->col[2].z;
}

/* Lane k of v replaced by x. */
inline float4 lane_set(float4 v, int k, float x) {
    return k == 0 ? (float4)(x, v.yzw)
                  : (k == 1 ? (float4)(v.x, x, v.zw)
                            : (k == 2 ? (float4)(v.xy, x, v.w) : (float4)(v.xyz, x)));
}

inline float lane_get(float4 v, int k) {
    return k == 0 ? v.x : (k == 1 ? v.y : (k == 2 ? v.z : v.w));
}

inline int lane_geti(int4 v, int k) {
    return k == 0 ? v.x : (k == 1 ? v.y : (k == 2 ? v.z : v.w));
}

/* Triangles (a, b, c) by lanes: ax is the four first vertices' x, ... */
__attribute__((always_inline)) inline tri4_hits
ray_triangle4(const ray_shear *r, float4 ax, float4 ay, float4 az, float4 bx, float4 by, float4 bz,
              float4 cx, float4 cy, float4 cz, float tmin, float tmax) {
    float4 Ax, Ay, Az, Bx, By, Bz, Cx, Cy, Cz;
    ray_sheared4(r, ax, ay, az, &Ax, &Ay, &Az);
    ray_sheared4(r, bx, by, bz, &Bx, &By, &Bz);
    ray_sheared4(r, cx, cy, cz, &Cx, &Cy, &Cz);
    float4 U = Cx * By - Cy * Bx;
    float4 V = Ax * Cy - Ay * Cx;
    float4 W = Bx * Ay - By * Ax;
#ifdef cl_khr_fp64
    const int4 zero = U == 0.0f || V == 0.0f || W == 0.0f;
    if (any(zero))
        for (int k = 0; k < 4; ++k)
            if (lane_geti(zero, k)) {
                const double ax_ = lane_get(Ax, k), ay_ = lane_get(Ay, k), bx_ = lane_get(Bx, k),
                             by_ = lane_get(By, k), cx_ = lane_get(Cx, k), cy_ = lane_get(Cy, k);
                U = lane_set(U, k, (float)(cx_ * by_ - cy_ * bx_));
                V = lane_set(V, k, (float)(ax_ * cy_ - ay_ * cx_));
                W = lane_set(W, k, (float)(bx_ * ay_ - by_ * ax_));
            }
#endif
    const int4 outside = (U < 0.0f || V < 0.0f || W < 0.0f) && (U > 0.0f || V > 0.0f || W > 0.0f);
    const float4 det = U + V + W;
    const float4 T = U * (r->sz * Az) + V * (r->sz * Bz) + W * (r->sz * Cz);
    const float4 inv = 1.0f / det;
    tri4_hits h;
    h.t = T * inv;
    h.u = V * inv;
    h.v = W * inv;
    h.hit = !outside && det != 0.0f && h.t > tmin && h.t <= tmax;
    return h;
}

#endif
