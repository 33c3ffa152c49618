/* A triangle's normal, not normalised, that turns exactly into its negation
 * when the triangle is wound the other way. */
#ifndef VCT_TRI_NORMAL_H
#define VCT_TRI_NORMAL_H

/* The cross product of the edges less the cross product in the other order,
 * halved. One cross product is antisymmetric only where a * b - c * d is
 * rounded twice: a device that fuses it into one rounding (NVIDIA's OpenCL
 * does) leaves a component that should be 0 at +-1 ulp of the products,
 * with a sign that follows the winding, and bsdf.h's basis_of, which
 * branches on a component's sign, turned the tangent frame of a triangle
 * wound the other way over. */
inline float3 tri_normal(float3 a, float3 b, float3 c) {
    const float3 e1 = b - a, e2 = c - a;
    return 0.5f * (cross(e1, e2) - cross(e2, e1));
}

#endif
