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
    float4 org;
    uint4 perm; /* (kx, ky, kz, 3): vertex components in sheared order */
    float sx, sy, sz;
} ray_shear;

inline float axis_of(float3 v, int k) {
    return k == 0 ? v.x : (k == 1 ? v.y : v.z);
}

inline ray_shear ray_shear_make(float3 org, float3 dir) {
    ray_shear r;
    const float3 ad = fabs(dir);
    const int kz = (ad.x > ad.y) ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
    int kx = kz == 2 ? 0 : kz + 1;
    int ky = kx == 2 ? 0 : kx + 1;
    if (axis_of(dir, kz) < 0.0f) { /* keep the winding */
        const int t = kx;
        kx = ky;
        ky = t;
    }
    const float dz = axis_of(dir, kz);
    r.sx = axis_of(dir, kx) / dz;
    r.sy = axis_of(dir, ky) / dz;
    r.sz = 1.0f / dz;
    r.perm = (uint4)((uint)kx, (uint)ky, (uint)kz, 3u);
    r.org = (float4)(org, 0.0f);
    return r;
}

/* On a hit in (tmin, tmax]: returns 1 with t and barycentrics of v1 (u), v2 (v). */
__attribute__((always_inline)) inline int ray_triangle(const ray_shear *r, float3 v0, float3 v1,
                                                       float3 v2, float tmin, float tmax,
                                                       float *t_out, float *u_out, float *v_out) {
    /* Vertices relative to the origin, components permuted to (kx, ky, kz). */
    const float4 A = shuffle((float4)(v0, 0.0f) - r->org, r->perm);
    const float4 B = shuffle((float4)(v1, 0.0f) - r->org, r->perm);
    const float4 C = shuffle((float4)(v2, 0.0f) - r->org, r->perm);
    const float Az = A.z, Bz = B.z, Cz = C.z;
    const float Ax = A.x - r->sx * Az, Ay = A.y - r->sy * Az;
    const float Bx = B.x - r->sx * Bz, By = B.y - r->sy * Bz;
    const float Cx = C.x - r->sx * Cz, Cy = C.y - r->sy * Cz;
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
