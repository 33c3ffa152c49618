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

/* The shear as a matrix: row x = e_kx - sx e_kz, row y = e_ky - sy e_kz,
 * row z = e_kz, stored by columns. Multiplying by it gives exactly the
 * permuted, sheared components (every other term is an exact zero, as the
 * scene loader accepts finite vertices only) without a run-time shuffle,
 * which CPU devices do through memory. */
typedef struct ray_shear {
    float3 org;
    float3 col[3];
    float sz;
} ray_shear;

inline float axis_of(float3 v, int k) {
    return k == 0 ? v.x : (k == 1 ? v.y : v.z);
}

inline float3 unit_axis(int k) {
    return (float3)(k == 0 ? 1.0f : 0.0f, k == 1 ? 1.0f : 0.0f, k == 2 ? 1.0f : 0.0f);
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
    const float sx = axis_of(dir, kx) / dz, sy = axis_of(dir, ky) / dz;
    const float3 row_x = unit_axis(kx) - sx * unit_axis(kz);
    const float3 row_y = unit_axis(ky) - sy * unit_axis(kz);
    const float3 row_z = unit_axis(kz);
    r.col[0] = (float3)(row_x.x, row_y.x, row_z.x);
    r.col[1] = (float3)(row_x.y, row_y.y, row_z.y);
    r.col[2] = (float3)(row_x.z, row_y.z, row_z.z);
    r.sz = 1.0f / dz;
    r.org = org;
    return r;
}

/* Vertex v relative to the origin in the sheared frame: (x, y) across the
 * ray, z along it (unscaled). */
inline float3 ray_sheared(const ray_shear *r, float3 v) {
    const float3 p = v - r->org;
    return (p.x * r->col[0] + p.y * r->col[1]) + p.z * r->col[2];
}

/* On a hit in (tmin, tmax]: returns 1 with t and barycentrics of v1 (u), v2 (v). */
__attribute__((always_inline)) inline int ray_triangle(const ray_shear *r, float3 v0, float3 v1,
                                                       float3 v2, float tmin, float tmax,
                                                       float *t_out, float *u_out, float *v_out) {
    const float3 A = ray_sheared(r, v0), B = ray_sheared(r, v1), C = ray_sheared(r, v2);
    const float Az = A.z, Bz = B.z, Cz = C.z;
    const float Ax = A.x, Ay = A.y, Bx = B.x, By = B.y, Cx = C.x, Cy = C.y;
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
