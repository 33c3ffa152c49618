/* Watertight ray / triangle intersection (Woop, Benthin and Wald, JCGT 2013).
 *
 * The ray is sheared so that it runs along +z through the origin; the
 * triangle's 2D edge functions U, V, W are then evaluated on vertices that
 * every triangle sharing them transforms identically. With contraction off,
 * an edge shared by two triangles gets exactly opposite edge values, so a ray
 * through the edge or a shared vertex hits at least one of them: nothing leaks
 * through a closed mesh. Zero edge values are re-evaluated in double where the
 * device has it. */
#ifndef VCT_RAY_TRI_H
#define VCT_RAY_TRI_H

#pragma OPENCL FP_CONTRACT OFF
#ifdef cl_khr_fp64
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
#endif

typedef struct ray_shear {
    float3 org;
    int kx, ky, kz;
    float sx, sy, sz;
} ray_shear;

inline float axis_of(float3 v, int k) {
    return k == 0 ? v.x : (k == 1 ? v.y : v.z);
}

inline ray_shear ray_shear_make(float3 org, float3 dir) {
    ray_shear r;
    float3 ad = fabs(dir);
    r.kz = (ad.x > ad.y) ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
    r.kx = r.kz == 2 ? 0 : r.kz + 1;
    r.ky = r.kx == 2 ? 0 : r.kx + 1;
    if (axis_of(dir, r.kz) < 0.0f) { /* keep the winding */
        int t = r.kx;
        r.kx = r.ky;
        r.ky = t;
    }
    float dz = axis_of(dir, r.kz);
    r.sx = axis_of(dir, r.kx) / dz;
    r.sy = axis_of(dir, r.ky) / dz;
    r.sz = 1.0f / dz;
    r.org = org;
    return r;
}

/* On a hit in (tmin, tmax]: returns 1 with t and barycentrics of v1 (u), v2 (v). */
inline int ray_triangle(const ray_shear *r, float3 v0, float3 v1, float3 v2, float tmin,
                        float tmax, float *t_out, float *u_out, float *v_out) {
    const float3 A = v0 - r->org, B = v1 - r->org, C = v2 - r->org;
    const float Az = axis_of(A, r->kz), Bz = axis_of(B, r->kz), Cz = axis_of(C, r->kz);
    const float Ax = axis_of(A, r->kx) - r->sx * Az, Ay = axis_of(A, r->ky) - r->sy * Az;
    const float Bx = axis_of(B, r->kx) - r->sx * Bz, By = axis_of(B, r->ky) - r->sy * Bz;
    const float Cx = axis_of(C, r->kx) - r->sx * Cz, Cy = axis_of(C, r->ky) - r->sy * Cz;
    float U = Cx * By - Cy * Bx;
    float V = Ax * Cy - Ay * Cx;
    float W = Bx * Ay - By * Ax;
#ifdef cl_khr_fp64
    if (U == 0.0f || V == 0.0f || W == 0.0f) {
        U = (float)((double)Cx * (double)By - (double)Cy * (double)Bx);
        V = (float)((double)Ax * (double)Cy - (double)Ay * (double)Cx);
        W = (float)((double)Bx * (double)Ay - (double)By * (double)Ax);
    }
#endif
    if ((U < 0.0f || V < 0.0f || W < 0.0f) && (U > 0.0f || V > 0.0f || W > 0.0f))
        return 0;
    const float det = U + V + W;
    if (det == 0.0f)
        return 0; /* degenerate triangle, or the ray lies in its plane */
    const float T = U * (r->sz * Az) + V * (r->sz * Bz) + W * (r->sz * Cz);
    const float inv = 1.0f / det;
    const float t = T * inv;
    if (!(t > tmin && t <= tmax))
        return 0;
    *t_out = t;
    *u_out = V * inv;
    *v_out = W * inv;
    return 1;
}

#endif
