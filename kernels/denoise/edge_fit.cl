/* Pixels on a geometric edge (a crease, a silhouette: the guide's normal,
 * the mean of the pixel's rays', shorter than DENOISE_EDGE_NORMAL) mix the
 * surfaces either side, so their normals are like none of their
 * neighbours' and the à-trous passes leave them nearly as noisy as they
 * came. Their colour is instead fitted, by weighted least squares over the
 * 5x5 pixels around, as a linear function of the normal and the relative
 * depth: a pixel covering a share f of one surface and 1 - f of another has
 * f of each one's normal and f of each one's radiance, so the fit at the
 * pixel's own guide recovers the mixture from its neighbours on both sides
 * (first-order feature regression, as NFOR and BMFR do over whole windows).
 *
 * Buffers, one element per pixel, rows top to bottom:
 *   signal         float4 (demodulated rgb, fireflies clamped; variance)
 *   albedo         float4 render_guides' albedo (w below 1: an emitter)
 *   normal_depth   float4 render_guides' normal (not normalised), distance
 *   fit            float4: an edge pixel's fitted radiance, w 1; w 0 at
 *                  every other pixel (denoise_remodulate reads it)
 * Taps on an emitter are left out: their light is no mixture of the
 * surfaces. */
#include "denoise/denoise.h"

/* The Gaussian's sigma, in pixels, of the taps' weights. */
#define EDGE_FIT_SIGMA 1.5f
/* Ridge on the slopes, relative to the sum of the weights: where the
 * neighbours' guides do not vary, the fit is their weighted mean. */
#define EDGE_FIT_RIDGE 1e-3f
#define EDGE_FIT_TERMS 5

/* Solves the symmetric positive definite a x = b (a: row-major, overwritten
 * by its Cholesky factor) for three right-hand sides; returns 0 where a
 * pivot is not positive. */
inline int edge_fit_solve(float a[EDGE_FIT_TERMS][EDGE_FIT_TERMS], float3 b[EDGE_FIT_TERMS]) {
    for (int j = 0; j < EDGE_FIT_TERMS; ++j) {
        float d = a[j][j];
        for (int k = 0; k < j; ++k)
            d -= a[j][k] * a[j][k];
        if (!(d > 0.0f))
            return 0;
        a[j][j] = sqrt(d);
        for (int i = j + 1; i < EDGE_FIT_TERMS; ++i) {
            float s = a[i][j];
            for (int k = 0; k < j; ++k)
                s -= a[i][k] * a[j][k];
            a[i][j] = s / a[j][j];
        }
    }
    for (int i = 0; i < EDGE_FIT_TERMS; ++i) { /* L y = b */
        float3 s = b[i];
        for (int k = 0; k < i; ++k)
            s -= a[i][k] * b[k];
        b[i] = s / a[i][i];
    }
    for (int i = EDGE_FIT_TERMS - 1; i >= 0; --i) { /* L^T x = y */
        float3 s = b[i];
        for (int k = i + 1; k < EDGE_FIT_TERMS; ++k)
            s -= a[k][i] * b[k];
        b[i] = s / a[i][i];
    }
    return 1;
}

__kernel void denoise_edge_fit(__global const float4 *signal, __global const float4 *albedo,
                               __global const float4 *normal_depth, uint2 size,
                               __global float4 *fit) {
    const int x = (int)get_global_id(0), y = (int)get_global_id(1);
    if (x >= (int)size.x || y >= (int)size.y)
        return;
    const int w = (int)size.x, p = y * w + x;
    const float4 centre = normal_depth[p];
    fit[p] = (float4)(0.0f);
    if (!denoise_is_edge(centre, albedo[p].w))
        return;
    float a[EDGE_FIT_TERMS][EDGE_FIT_TERMS] = {{0.0f}};
    float3 b[EDGE_FIT_TERMS] = {(float3)(0.0f)};
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            const int qx = x + dx, qy = y + dy;
            if (qx < 0 || qy < 0 || qx >= w || qy >= (int)size.y)
                continue;
            const int q = qy * w + qx;
            const float4 aq = albedo[q];
            if (aq.w < 1.0f)
                continue;
            const float4 g = normal_depth[q];
            const float t[EDGE_FIT_TERMS] = {1.0f, g.x - centre.x, g.y - centre.y, g.z - centre.z,
                                             (g.w - centre.w) / centre.w};
            const float k =
                exp(-(float)(dx * dx + dy * dy) / (2.0f * EDGE_FIT_SIGMA * EDGE_FIT_SIGMA));
            const float3 radiance = signal[q].xyz * denoise_safe_albedo(aq.xyz);
            for (int i = 0; i < EDGE_FIT_TERMS; ++i) {
                for (int j = 0; j <= i; ++j)
                    a[i][j] += k * t[i] * t[j];
                b[i] += k * t[i] * radiance;
            }
        }
    for (int i = 1; i < EDGE_FIT_TERMS; ++i)
        a[i][i] += EDGE_FIT_RIDGE * a[0][0];
    /* the centre's own tap keeps a[0][0] >= 1 and the ridge the rest positive */
    if (edge_fit_solve(a, b))
        fit[p] = (float4)(fmax(b[0], (float3)(0.0f)), 1.0f);
}
