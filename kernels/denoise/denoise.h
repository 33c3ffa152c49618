/* The denoiser's weights (denoise/atrous.cl): what makes a tap count less
 * than the kernel says. Kept in plain float arithmetic that a C reference
 * can follow (tests/denoise/denoise_ref.h). */
#ifndef VCT_DENOISE_H
#define VCT_DENOISE_H

/* guide.w of a pixel where an emitter is seen (denoise/atrous.cl). */
#define DENOISE_EMITTER (-1.0f)

/* Albedo below this is not divided by: the channel is filtered as it is. */
#define DENOISE_MIN_ALBEDO 0.01f

/* A pixel whose rays' mean normal is shorter than this covers surfaces
 * that face different ways (a crease, a silhouette): denoise/edge_fit.cl
 * fits its colour. 0.995: rays that spread over 6 degrees. */
#define DENOISE_EDGE_NORMAL 0.995f

inline float3 denoise_safe_albedo(float3 a) {
    return (float3)(a.x > DENOISE_MIN_ALBEDO ? a.x : 1.0f, a.y > DENOISE_MIN_ALBEDO ? a.y : 1.0f,
                    a.z > DENOISE_MIN_ALBEDO ? a.z : 1.0f);
}

/* On a geometric edge: a surface seen (distance above 0), no emitter, and
 * the normals of the pixel's rays spread. */
inline int denoise_is_edge(float4 normal_depth, float albedo_w) {
    return normal_depth.w > 0.0f && albedo_w >= 1.0f &&
           dot(normal_depth.xyz, normal_depth.xyz) < DENOISE_EDGE_NORMAL * DENOISE_EDGE_NORMAL;
}

inline float denoise_luminance(float3 c) {
    return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

inline float denoise_depth_at(__global const float4 *nd, uint2 size, int x, int y) {
    return x < 0 || y < 0 || x >= (int)size.x || y >= (int)size.y ? 0.0f
                                                                  : nd[y * (int)size.x + x].w;
}

/* The smaller change towards a neighbour with a surface (0: none has one),
 * so that a step in depth beside a pixel does not count as its slope. */
inline float denoise_slope(float z, float before, float after) {
    const float a = before > 0.0f ? fabs(z - before) : INFINITY;
    const float b = after > 0.0f ? fabs(after - z) : INFINITY;
    const float s = fmin(a, b);
    return isinf(s) ? 0.0f : s;
}

/* The variance (signal.w) over the 3x3 pixels around, Gaussian-weighted. */
inline float denoise_variance_blurred(__global const float4 *signal, uint2 size, int x, int y) {
    const float k[2] = {0.25f, 0.125f};
    float sum = 0.0f, weights = 0.0f;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int qx = x + dx, qy = y + dy;
            if (qx < 0 || qy < 0 || qx >= (int)size.x || qy >= (int)size.y)
                continue;
            const float w = k[abs(dx)] * k[abs(dy)] * 4.0f;
            sum += w * signal[qy * (int)size.x + qx].w;
            weights += w;
        }
    return sum / weights;
}

/* 2^x for x <= 0, to about 2e-7 relative: x rounded to a whole power n and
 * a rest f in [-1/2, 1/2], whose 2^f is a Taylor polynomial of degree 6 in
 * f ln 2; 0 below 2^-126. The library's exp2 took 45 % of the passes' time
 * on PoCL, where every tap of every pass takes one. */
__attribute__((always_inline)) inline float denoise_exp2_neg(float x) {
    if (!(x > -126.0f))
        return 0.0f;
    const int n = -(int)(0.5f - x); /* x rounded, by truncation of a positive value */
    const float t = (x - (float)n) * 0.693147181f;
    const float p =
        1.0f +
        t * (1.0f +
             t * (0.5f + t * (1.0f / 6.0f +
                              t * (1.0f / 24.0f + t * (1.0f / 120.0f + t * (1.0f / 720.0f))))));
    return p * as_float((n + 127) << 23);
}

/* c^e for c in (0, 1]: by repeated squaring where e is a whole number
 * below 4096 (the normals' exponent, 128 by default), else exp2(e log2 c). */
__attribute__((always_inline)) inline float denoise_power(float c, float e) {
    if (!(e >= 0.0f && e < 4096.0f && (float)(int)e == e))
        return exp2(e * log2(c));
    const uint n = (uint)e;
    float result = 1.0f, base = c;
    for (uint bit = 0u; bit < 12u; ++bit) { /* a fixed count the compiler unrolls */
        result = (n >> bit) & 1u ? result * base : result;
        base *= base;
    }
    return result;
}

/* A tap (offset ox, oy from the centre c) against the centre, from their
 * guides (unit normal, 0 where a pixel's rays' normals cancel; distance, 0
 * without a surface), the centre's depth slope per pixel, their luminances
 * and variances: normals cos^sigma.y, depth (the difference against the
 * slope times the offset, sigma.z, with a thousandth of the distance for
 * flat surfaces), luminance (a Gaussian of the difference in sigma.x
 * standard deviations of the two: differences the noise explains weigh
 * nearly alike, larger ones fall off fast). Pixels without a surface
 * weigh only by luminance, among themselves; an emitter's pixels with none. */
__attribute__((always_inline)) inline float denoise_edge_weight(float4 gc, float2 slope_c,
                                                                float4 gq, int ox, int oy, float lc,
                                                                float lq, float var_c, float var_q,
                                                                float4 sigma) {
    if (gc.w < 0.0f || gq.w < 0.0f)
        return 0.0f;
    const float u = fabs(lc - lq) / (sigma.x * sqrt(var_c + var_q) + 1e-6f), l = 0.5f * u * u;
    const int surface_c = gc.w > 0.0f, surface_q = gq.w > 0.0f;
    if (!surface_c || !surface_q)
        return surface_c == surface_q ? denoise_exp2_neg(-l * M_LOG2E_F) : 0.0f;
    const float cosine = dot(gc.xyz, gq.xyz);
    if (!(cosine > 0.0f))
        return 0.0f;
    const float slope = fabs(slope_c.x * (float)ox) + fabs(slope_c.y * (float)oy);
    const float z = fabs(gc.w - gq.w) / (sigma.z * slope + 1e-3f * gc.w);
    return denoise_power(cosine, sigma.y) * denoise_exp2_neg(-(l + z) * M_LOG2E_F);
}

#ifdef VCT_PACKETS
/* The weights above for 16 taps at once, one vector lane each (the
 * à-trous pass's lanes, denoise_atrous16): the same operations in the same
 * order, so each lane's weight is the scalar one's bit for bit. */

__attribute__((always_inline)) inline float16 denoise_exp2_neg16(float16 x) {
    const int16 n = -convert_int16(0.5f - x);
    const float16 t = (x - convert_float16(n)) * 0.693147181f;
    const float16 p =
        1.0f +
        t * (1.0f +
             t * (0.5f + t * (1.0f / 6.0f +
                              t * (1.0f / 24.0f + t * (1.0f / 120.0f + t * (1.0f / 720.0f))))));
    return select(p * as_float16((n + 127) << 23), 0.0f, !(x > -126.0f));
}

/* c^e, e the same in every lane. */
__attribute__((always_inline)) inline float16 denoise_power16(float16 c, float e) {
    if (!(e >= 0.0f && e < 4096.0f && (float)(int)e == e)) {
        float lanes[16];
        vstore16(c, 0, lanes);
        for (uint k = 0; k < 16u; ++k)
            lanes[k] = exp2(e * log2(lanes[k]));
        return vload16(0, lanes);
    }
    const uint n = (uint)e;
    float16 result = 1.0f, base = c;
    for (uint bit = 0u; bit < 12u; ++bit) {
        result = (n >> bit) & 1u ? result * base : result;
        base *= base;
    }
    return result;
}

/* denoise_edge_weight with the centres' and taps' guides (gc, gq), the
 * centres' slopes (s), luminances and variances in lanes. */
__attribute__((always_inline)) inline float16
denoise_edge_weight16(float16 gcx, float16 gcy, float16 gcz, float16 gcw, float16 sx, float16 sy,
                      float16 gqx, float16 gqy, float16 gqz, float16 gqw, int ox, int oy,
                      float16 lc, float16 lq, float16 var_c, float16 var_q, float4 sigma) {
    const int16 none = gcw < 0.0f || gqw < 0.0f;
    const float16 u = fabs(lc - lq) / (sigma.x * sqrt(var_c + var_q) + 1e-6f), l = 0.5f * u * u;
    const int16 surface_c = gcw > 0.0f, surface_q = gqw > 0.0f;
    const float16 open =
        select((float16)(0.0f), denoise_exp2_neg16(-l * M_LOG2E_F), surface_c == surface_q);
    /* dot(gc, gq) as the library adds it: no fused steps */
    const float16 cx = gcx * gqx, cy = gcy * gqy, cz = gcz * gqz;
    const float16 cxy = cx + cy;
    const float16 cosine = cxy + cz;
    const float16 slope = fabs(sx * (float)ox) + fabs(sy * (float)oy);
    const float16 z = fabs(gcw - gqw) / (sigma.z * slope + 1e-3f * gcw);
    const float16 both =
        select(denoise_power16(cosine, sigma.y) * denoise_exp2_neg16(-(l + z) * M_LOG2E_F),
               (float16)(0.0f), !(cosine > 0.0f));
    return select(select(both, open, !surface_c || !surface_q), (float16)(0.0f), none);
}
#endif

#endif
