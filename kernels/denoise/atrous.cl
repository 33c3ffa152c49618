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

#ifdef VCT_PACKETS
/* Pixels x0 .. x0 + 15 of row y of a float4 image as vectors by component
 * (a, b, c, d); lanes past the row's ends read its nearest pixel. */
inline void atrous_row16(__global const float4 *image, int w, int y, int x0, float16 *a, float16 *b,
                         float16 *c, float16 *d) {
    if (x0 >= 0 && x0 + 16 <= w) {
        __global const float *row = (__global const float *)(image + y * w + x0);
        const float16 p0 = vload16(0, row), p1 = vload16(1, row), p2 = vload16(2, row),
                      p3 = vload16(3, row);
        *a = (float16)(p0.s048c, p1.s048c, p2.s048c, p3.s048c);
        *b = (float16)(p0.s159d, p1.s159d, p2.s159d, p3.s159d);
        *c = (float16)(p0.s26ae, p1.s26ae, p2.s26ae, p3.s26ae);
        *d = (float16)(p0.s37bf, p1.s37bf, p2.s37bf, p3.s37bf);
        return;
    }
    float la[16], lb[16], lc[16], ld[16];
    for (int k = 0; k < 16; ++k) {
        const float4 v = image[y * w + clamp(x0 + k, 0, w - 1)];
        la[k] = v.x;
        lb[k] = v.y;
        lc[k] = v.z;
        ld[k] = v.w;
    }
    *a = vload16(0, la);
    *b = vload16(0, lb);
    *c = vload16(0, lc);
    *d = vload16(0, ld);
}

/* denoise_variance_blurred for 16 pixels of a row; x: their columns. */
inline float16 atrous_variance_blurred16(__global const float4 *signal, int w, int h, int16 x,
                                         int x0, int y) {
    const float k[2] = {0.25f, 0.125f};
    float16 sum = 0.0f, weights = 0.0f;
    for (int dy = -1; dy <= 1; ++dy) {
        const int qy = y + dy;
        if (qy < 0 || qy >= h)
            continue;
        for (int dx = -1; dx <= 1; ++dx) {
            const int16 inside = x + dx >= 0 && x + dx < w;
            float16 unused_a, unused_b, unused_c, v;
            atrous_row16(signal, w, qy, x0 + dx, &unused_a, &unused_b, &unused_c, &v);
            const float wk = k[abs(dx)] * k[abs(dy)] * 4.0f;
            sum = select(sum, sum + wk * v, inside);
            weights = select(weights, weights + wk, inside);
        }
    }
    return sum / weights;
}

/* denoise_atrous for 16 pixels of a row at once, one vector lane each
 * (CPU devices): every tap with the scalar pass's operations, in its
 * order, so the image is the same bit for bit. Work-item (i, y) takes
 * pixels 16 i .. 16 i + 15 of row y. */
__kernel void denoise_atrous16(__global const float4 *in, __global const float4 *guide,
                               __global const float2 *slope, uint2 size, int step, float4 sigma,
                               __global float4 *out) {
    const int x0 = 16 * (int)get_global_id(0), y = (int)get_global_id(1);
    const int w = (int)size.x, h = (int)size.y;
    if (x0 >= w || y >= h)
        return;
    const int16 x = x0 + (int16)(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
    float16 cx, cy, cz, cw, gcx, gcy, gcz, gcw;
    atrous_row16(in, w, y, x0, &cx, &cy, &cz, &cw);
    atrous_row16(guide, w, y, x0, &gcx, &gcy, &gcz, &gcw);
    float sxs[16], sys[16];
    for (int k = 0; k < 16; ++k) {
        const float2 s = slope[y * w + min(x0 + k, w - 1)];
        sxs[k] = s.x;
        sys[k] = s.y;
    }
    const float16 sx = vload16(0, sxs), sy = vload16(0, sys);
    const float16 var_c = step == 1 ? cw : atrous_variance_blurred16(in, w, h, x, x0, y);
    const float16 lp = 0.2126f * cx + 0.7152f * cy + 0.0722f * cz; /* denoise_luminance */
    const float kernel_weights[3] = {0.375f, 0.25f, 0.0625f};
    float16 sum_x = 0.0f, sum_y = 0.0f, sum_z = 0.0f, weights = 0.0f, variance = 0.0f;
    for (int dy = -2; dy <= 2; ++dy) {
        const int qy = y + dy * step;
        if (qy < 0 || qy >= h)
            continue;
        for (int dx = -2; dx <= 2; ++dx) {
            const int16 inside = x + dx * step >= 0 && x + dx * step < w;
            float16 qx, qyc, qz, qw, gqx, gqy, gqz, gqw;
            atrous_row16(in, w, qy, x0 + dx * step, &qx, &qyc, &qz, &qw);
            const float k = kernel_weights[abs(dx)] * kernel_weights[abs(dy)];
            float16 wq = k;
            if (dx != 0 || dy != 0) {
                atrous_row16(guide, w, qy, x0 + dx * step, &gqx, &gqy, &gqz, &gqw);
                const float16 lq = 0.2126f * qx + 0.7152f * qyc + 0.0722f * qz;
                wq = k * denoise_edge_weight16(gcx, gcy, gcz, gcw, sx, sy, gqx, gqy, gqz, gqw,
                                               dx * step, dy * step, lp, lq, var_c, qw, sigma);
            }
            sum_x = select(sum_x, sum_x + wq * qx, inside);
            sum_y = select(sum_y, sum_y + wq * qyc, inside);
            sum_z = select(sum_z, sum_z + wq * qz, inside);
            weights = select(weights, weights + wq, inside);
            variance = select(variance, variance + wq * wq * qw, inside);
        }
    }
    float ox[16], oy[16], oz[16], ow[16];
    vstore16(sum_x / weights, 0, ox);
    vstore16(sum_y / weights, 0, oy);
    vstore16(sum_z / weights, 0, oz);
    vstore16(variance / (weights * weights), 0, ow);
    for (int k = 0; k < 16 && x0 + k < w; ++k)
        out[y * w + x0 + k] = (float4)(ox[k], oy[k], oz[k], ow[k]);
}
#endif

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
