/* An edge-avoiding à-trous wavelet filter with variance guidance (after
 * Schied et al. 2017, "Spatiotemporal Variance-Guided Filtering", on one
 * frame): the image is divided by the first hit's albedo, filtered in
 * DENOISE_ITERATIONS passes of a 5x5 B3-spline kernel whose taps spread
 * 2^i pixels apart (after bright outliers are clamped to their
 * neighbourhood), each tap weighted by how alike its normal, depth and
 * luminance are to the centre's, the luminance judged against the centre's
 * standard deviation (each pass allowing 0.8 of the difference the one
 * before allowed: the host scales sigma.x), and multiplied by the albedo
 * again, or replaced by denoise/edge_fit.cl's fit on a geometric edge.
 * Every pass reads one buffer and writes another, in a fixed order: the
 * result does not depend on scheduling.
 *
 * Buffers, one element per pixel, rows top to bottom:
 *   color          float4 linear radiance
 *   albedo         float4 (rgb; w: the share of the pixel not on an
 *                  emitter), render_guides' albedo
 *   normal_depth   float4 (normal, not normalised; distance, 0: no surface)
 *   variance       float, the variance of each pixel's mean luminance
 *   signal         float4 (demodulated rgb, its luminance variance)
 *   guide, slope   float4 (unit normal, distance; -1 where an emitter is
 *                  seen), float2 depth change per pixel along x and y:
 *                  normal_depth prepared once
 *
 * An emitter seen directly is no noise, and far brighter than what lies
 * beside it: its pixels (albedo.w below 1) are left as they are and lend
 * nothing to their neighbours. Spread, a ceiling panel's light lit the
 * ceiling around it at 30 to 90 times the image's mean. */
#include "denoise/denoise.h"

/* Without the estimator's variance: the smallest luminance variance of the
 * four 3x3 windows that hold the pixel in a corner (Kuwahara's choice), so
 * that an edge beside a pixel does not pass for noise: one window lies on
 * the pixel's side of it. Each window's variance is the mean squared
 * deviation from its mean, not the mean square less the squared mean, whose
 * cancellation leaves rounding noise where the window is nearly flat. */
__kernel void denoise_estimate_variance(__global const float4 *color, uint2 size,
                                        __global float *variance) {
    const int x = (int)get_global_id(0), y = (int)get_global_id(1);
    if (x >= (int)size.x || y >= (int)size.y)
        return;
    float l[5][5]; /* luminance around the pixel; -infinity: outside the image */
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            const int qx = x + dx, qy = y + dy;
            const int inside = qx >= 0 && qy >= 0 && qx < (int)size.x && qy < (int)size.y;
            l[dy + 2][dx + 2] =
                inside ? denoise_luminance(color[qy * (int)size.x + qx].xyz) : -INFINITY;
        }
    float least = INFINITY;
    for (int wy = 0; wy <= 2; wy += 2)
        for (int wx = 0; wx <= 2; wx += 2) {
            float sum = 0.0f, count = 0.0f;
            for (int dy = wy; dy <= wy + 2; ++dy)
                for (int dx = wx; dx <= wx + 2; ++dx)
                    if (l[dy][dx] > -INFINITY) {
                        sum += l[dy][dx];
                        count += 1.0f;
                    }
            const float mean = sum / count; /* the pixel itself is in every window */
            float squares = 0.0f;
            for (int dy = wy; dy <= wy + 2; ++dy)
                for (int dx = wx; dx <= wx + 2; ++dx)
                    if (l[dy][dx] > -INFINITY)
                        squares += (l[dy][dx] - mean) * (l[dy][dx] - mean);
            least = fmin(least, squares / count);
        }
    variance[y * (int)size.x + x] = least;
}

/* Each pixel's guide and depth slope, once for all passes. */
__kernel void denoise_guides(__global const float4 *normal_depth, uint2 size,
                             __global float4 *guide, __global float2 *slope,
                             __global const float4 *albedo) {
    const int x = (int)get_global_id(0), y = (int)get_global_id(1);
    if (x >= (int)size.x || y >= (int)size.y)
        return;
    const int p = y * (int)size.x + x;
    const float4 v = normal_depth[p];
    const float len = length(v.xyz);
    guide[p] = (float4)(len > 0.0f ? v.xyz / len : (float3)(0.0f),
                        albedo[p].w < 1.0f ? DENOISE_EMITTER : v.w);
    slope[p] = (float2)(denoise_slope(v.w, denoise_depth_at(normal_depth, size, x - 1, y),
                                      denoise_depth_at(normal_depth, size, x + 1, y)),
                        denoise_slope(v.w, denoise_depth_at(normal_depth, size, x, y - 1),
                                      denoise_depth_at(normal_depth, size, x, y + 1)));
}

/* The signal the passes filter: radiance over albedo, and its variance. */
__kernel void denoise_demodulate(__global const float4 *color, __global const float4 *albedo,
                                 __global const float *variance, uint pixels,
                                 __global float4 *signal) {
    const uint i = get_global_id(0);
    if (i >= pixels)
        return;
    const float3 a = denoise_safe_albedo(albedo[i].xyz);
    const float la = denoise_luminance(a);
    signal[i] = (float4)(color[i].xyz / a, variance[i] / (la * la));
}

/* One pass with taps `step` pixels apart. */
__kernel void denoise_atrous(__global const float4 *in, __global const float4 *guide,
                             __global const float2 *slope, uint2 size, int step, float4 sigma,
                             __global float4 *out) {
    const int x = (int)get_global_id(0), y = (int)get_global_id(1);
    if (x >= (int)size.x || y >= (int)size.y)
        return;
    const int w = (int)size.x, h = (int)size.y;
    const int p = y * w + x;
    const float4 centre = in[p];
    const float4 gp = guide[p];
    const float2 sp = slope[p];
    /* the first pass trusts each pixel's own variance; later ones blur it */
    const float var_c = step == 1 ? centre.w : denoise_variance_blurred(in, size, x, y);
    const float lp = denoise_luminance(centre.xyz);
    const float kernel_weights[3] = {0.375f, 0.25f, 0.0625f};
    float3 sum = (float3)(0.0f);
    float weights = 0.0f, variance = 0.0f;
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            const int qx = x + dx * step, qy = y + dy * step;
            if (qx < 0 || qy < 0 || qx >= w || qy >= h)
                continue;
            const float4 q = in[qy * w + qx];
            const float k = kernel_weights[abs(dx)] * kernel_weights[abs(dy)];
            /* the centre always counts: its normal may be 0 where its rays' cancel */
            const float wq =
                dx == 0 && dy == 0
                    ? k
                    : k * denoise_edge_weight(gp, sp, guide[qy * w + qx], dx * step, dy * step, lp,
                                              denoise_luminance(q.xyz), var_c, q.w, sigma);
            sum += wq * q.xyz;
            weights += wq;
            variance += wq * wq * q.w;
        }
    /* The centre's own weight, k(0, 0) > 0, keeps weights above 0. */
    out[p] = (float4)(sum / weights, variance / (weights * weights));
}

/* Fireflies: a pixel whose luminance lies above its 3x3 neighbours' mean by
 * more than k of their standard deviation is brought down to that bound
 * (k <= 0: none is). Rare bright paths otherwise spread into blotches that
 * the passes cannot tell from light. */
__kernel void denoise_clamp(__global const float4 *in, uint2 size, float k, __global float4 *out) {
    const int x = (int)get_global_id(0), y = (int)get_global_id(1);
    if (x >= (int)size.x || y >= (int)size.y)
        return;
    const int w = (int)size.x;
    float around[8]; /* the neighbours' luminance */
    int n = 0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int qx = x + dx, qy = y + dy;
            if ((dx == 0 && dy == 0) || qx < 0 || qy < 0 || qx >= w || qy >= (int)size.y)
                continue;
            around[n++] = denoise_luminance(in[qy * w + qx].xyz);
        }
    const float4 c = in[y * w + x];
    const float l = denoise_luminance(c.xyz);
    float sum = 0.0f, squares = 0.0f;
    for (int i = 0; i < n; ++i)
        sum += around[i];
    const float mean = n > 0 ? sum / (float)n : l;
    /* squared deviations from the mean: no cancellation where the
     * neighbours are nearly alike */
    for (int i = 0; i < n; ++i)
        squares += (around[i] - mean) * (around[i] - mean);
    const float bound = mean + k * sqrt(n > 0 ? squares / (float)n : 0.0f);
    out[y * w + x] = k > 0.0f && l > bound ? (float4)(c.xyz * (bound / l), c.w) : c;
}

/* The filtered signal times the albedo again, or an edge pixel's fit
 * (denoise/edge_fit.cl, w 1); an emitter's pixels keep their colour. */
__kernel void denoise_remodulate(__global const float4 *signal, __global const float4 *albedo,
                                 __global const float4 *fit, uint pixels, __global float4 *color) {
    const uint i = get_global_id(0);
    if (i >= pixels || albedo[i].w < 1.0f)
        return;
    color[i] = fit[i].w > 0.0f ? fit[i]
                               : (float4)(signal[i].xyz * denoise_safe_albedo(albedo[i].xyz), 1.0f);
}
