/* The denoiser in plain C, written from its description (vct/denoise.h,
 * kernels/denoise/atrous.cl's and edge_fit.cl's comments): demodulation by
 * the albedo, an optional 5x5 variance estimate, à-trous passes of the B3
 * spline with normal, depth and luminance weights (each pass's luminance
 * sigma 0.8 of the one before), remodulation, and the edge pixels' colour
 * fitted by least squares on their neighbours' normals and depths. Single
 * precision, as the device computes, so the two agree to rounding. */
#ifndef VCT_TEST_DENOISE_REF_H
#define VCT_TEST_DENOISE_REF_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define LOG2E_F 1.44269504088896340736f

typedef struct ref_px {
    float r, g, b, w;
} ref_px;

static float ref_lum(float r, float g, float b) {
    return 0.2126f * r + 0.7152f * g + 0.0722f * b;
}

static float ref_safe(float a) {
    return a > 0.01f ? a : 1.0f;
}

static int ref_inside(int w, int h, int x, int y) {
    return x >= 0 && y >= 0 && x < w && y < h;
}

static float ref_depth(const ref_px *nd, int w, int h, int x, int y) {
    return ref_inside(w, h, x, y) ? nd[y * w + x].w : 0.0f;
}

static float ref_slope(float z, float before, float after) {
    const float a = before > 0.0f ? fabsf(z - before) : INFINITY;
    const float b = after > 0.0f ? fabsf(after - z) : INFINITY;
    const float s = fminf(a, b);
    return isinf(s) ? 0.0f : s;
}

static void ref_unit(const ref_px *p, float n[3]) {
    const float len = sqrtf(p->r * p->r + p->g * p->g + p->b * p->b);
    n[0] = len > 0 ? p->r / len : 0.0f;
    n[1] = len > 0 ? p->g / len : 0.0f;
    n[2] = len > 0 ? p->b / len : 0.0f;
}

/* One pass over `in` (rgb demodulated, w variance) into `out`; a pixel whose
 * albedo's w is below 1 (an emitter seen) takes nothing from the others and
 * gives them nothing. */
static void ref_atrous(const ref_px *in, const ref_px *nd, const ref_px *albedo, int w, int h,
                       int step, const float sigma[3], ref_px *out) {
    static const float k1[3] = {0.375f, 0.25f, 0.0625f};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const ref_px c = in[y * w + x], cnd = nd[y * w + x];
            float nc[3];
            ref_unit(&cnd, nc);
            const float gx =
                ref_slope(cnd.w, ref_depth(nd, w, h, x - 1, y), ref_depth(nd, w, h, x + 1, y));
            const float gy =
                ref_slope(cnd.w, ref_depth(nd, w, h, x, y - 1), ref_depth(nd, w, h, x, y + 1));
            float vs = 0.0f, vw = 0.0f;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    if (!ref_inside(w, h, x + dx, y + dy))
                        continue;
                    const float k = (dx ? 0.125f : 0.25f) * (dy ? 0.125f : 0.25f) * 4.0f;
                    vs += k * in[(y + dy) * w + x + dx].w;
                    vw += k;
                }
            const float var_c = step == 1 ? c.w : vs / vw, lc = ref_lum(c.r, c.g, c.b);
            float sr = 0, sg = 0, sb = 0, weights = 0, var = 0;
            for (int dy = -2; dy <= 2; ++dy)
                for (int dx = -2; dx <= 2; ++dx) {
                    const int qx = x + dx * step, qy = y + dy * step;
                    if (!ref_inside(w, h, qx, qy))
                        continue;
                    const ref_px q = in[qy * w + qx], qnd = nd[qy * w + qx];
                    const float k = k1[abs(dx)] * k1[abs(dy)];
                    float e = 1.0f;
                    if ((dx || dy) &&
                        (albedo[y * w + x].w < 1.0f || albedo[qy * w + qx].w < 1.0f)) {
                        e = 0.0f;
                    } else if (dx || dy) {
                        /* a Gaussian in standard deviations */
                        const float u = fabsf(lc - ref_lum(q.r, q.g, q.b)) /
                                        (sigma[0] * sqrtf(var_c + q.w) + 1e-6f),
                                    l = 0.5f * u * u;
                        const int sc = cnd.w > 0.0f, sq = qnd.w > 0.0f;
                        float nq[3];
                        ref_unit(&qnd, nq);
                        const float cosine = nc[0] * nq[0] + nc[1] * nq[1] + nc[2] * nq[2];
                        if (!sc || !sq) {
                            e = sc == sq ? exp2f(-l * LOG2E_F) : 0.0f;
                        } else if (!(cosine > 0.0f)) {
                            e = 0.0f;
                        } else {
                            const float slope =
                                fabsf(gx * (float)(dx * step)) + fabsf(gy * (float)(dy * step));
                            const float z =
                                fabsf(cnd.w - qnd.w) / (sigma[2] * slope + 1e-3f * cnd.w);
                            e = exp2f(sigma[1] * log2f(cosine) - (l + z) * LOG2E_F);
                        }
                    }
                    const float wq = k * e;
                    sr += wq * q.r;
                    sg += wq * q.g;
                    sb += wq * q.b;
                    weights += wq;
                    var += wq * wq * q.w;
                }
            out[y * w + x] =
                (ref_px){sr / weights, sg / weights, sb / weights, var / (weights * weights)};
        }
}

/* Clamps each pixel above its 3x3 neighbours' mean + k sd. */
static void ref_clamp(const ref_px *in, int w, int h, float k, ref_px *out) {
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double s = 0, s2 = 0, n = 0; /* in double: no cancellation below */
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    if ((!dx && !dy) || !ref_inside(w, h, x + dx, y + dy))
                        continue;
                    const ref_px q = in[(y + dy) * w + x + dx];
                    const float l = ref_lum(q.r, q.g, q.b);
                    s += l;
                    s2 += l * l;
                    n += 1.0f;
                }
            const ref_px c = in[y * w + x];
            const float l = ref_lum(c.r, c.g, c.b);
            const double mean = n > 0 ? s / n : l;
            const float bound = (float)(mean + k * sqrt(fmax(n > 0 ? s2 / n - mean * mean : 0, 0)));
            const float f = k > 0 && l > bound ? bound / l : 1.0f;
            out[y * w + x] = f < 1.0f ? (ref_px){c.r * f, c.g * f, c.b * f, c.w} : c;
        }
}

/* Edge pixels: the rays' mean normal shorter than 0.995, a surface, no
 * emitter. */
static int ref_is_edge(ref_px nd, float albedo_w) {
    return nd.w > 0.0f && albedo_w >= 1.0f &&
           nd.r * nd.r + nd.g * nd.g + nd.b * nd.b < 0.995f * 0.995f;
}

/* Solves a x = b for 5 unknowns and 3 right-hand sides by Gaussian
 * elimination with partial pivoting, in double (another route than the
 * device's Cholesky factorisation); returns 0 if a is singular. */
static int ref_solve5(double a[5][5], double b[5][3]) {
    for (int c = 0; c < 5; ++c) {
        int pivot = c;
        for (int r = c + 1; r < 5; ++r)
            if (fabs(a[r][c]) > fabs(a[pivot][c]))
                pivot = r;
        if (a[pivot][c] == 0.0)
            return 0;
        for (int k = 0; k < 5; ++k) {
            const double t = a[c][k];
            a[c][k] = a[pivot][k];
            a[pivot][k] = t;
        }
        for (int k = 0; k < 3; ++k) {
            const double t = b[c][k];
            b[c][k] = b[pivot][k];
            b[pivot][k] = t;
        }
        for (int r = c + 1; r < 5; ++r) {
            const double f = a[r][c] / a[c][c];
            for (int k = c; k < 5; ++k)
                a[r][k] -= f * a[c][k];
            for (int k = 0; k < 3; ++k)
                b[r][k] -= f * b[c][k];
        }
    }
    for (int r = 4; r >= 0; --r)
        for (int k = 0; k < 3; ++k) {
            double s = b[r][k];
            for (int j = r + 1; j < 5; ++j)
                s -= a[r][j] * b[j][k];
            b[r][k] = s / a[r][r];
        }
    return 1;
}

/* An edge pixel's colour: the weighted least-squares fit over the 5x5
 * pixels around (weights exp(-d^2 / 4.5), emitters left out) of the
 * clamped radiance (signal times albedo) as 1, the normal's change and the
 * depth's relative change, with a ridge of 1e-3 of the weights' sum on the
 * last four, at the pixel's own guide; negative channels become 0. Returns
 * 0 where the pixel is no edge. */
static int ref_edge_fit(const ref_px *signal, const ref_px *albedo, const ref_px *nd, int w, int h,
                        int x, int y, ref_px *out) {
    const ref_px c = nd[y * w + x];
    if (!ref_is_edge(c, albedo[y * w + x].w))
        return 0;
    double a[5][5] = {{0}}, b[5][3] = {{0}};
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            if (!ref_inside(w, h, x + dx, y + dy))
                continue;
            const int q = (y + dy) * w + x + dx;
            if (albedo[q].w < 1.0f)
                continue;
            const ref_px g = nd[q];
            const double t[5] = {1.0, g.r - c.r, g.g - c.g, g.b - c.b, (g.w - c.w) / c.w};
            const double k = exp(-(dx * dx + dy * dy) / 4.5);
            const double y3[3] = {signal[q].r * ref_safe(albedo[q].r),
                                  signal[q].g * ref_safe(albedo[q].g),
                                  signal[q].b * ref_safe(albedo[q].b)};
            for (int i = 0; i < 5; ++i) {
                for (int j = 0; j < 5; ++j)
                    a[i][j] += k * t[i] * t[j];
                for (int m = 0; m < 3; ++m)
                    b[i][m] += k * t[i] * y3[m];
            }
        }
    for (int i = 1; i < 5; ++i)
        a[i][i] += 1e-3 * a[0][0];
    if (!ref_solve5(a, b))
        return 0;
    *out = (ref_px){(float)fmax(b[0][0], 0.0), (float)fmax(b[0][1], 0.0), (float)fmax(b[0][2], 0.0),
                    1.0f};
    return 1;
}

/* The whole filter; variance NULL: the least of the four 3x3 windows'. sigma:
 * luminance, normal, depth, fireflies. */
static void ref_denoise(const ref_px *color, const ref_px *albedo, const ref_px *nd,
                        const float *variance, int w, int h, int iterations, const float sigma[4],
                        ref_px *out) {
    const size_t n = (size_t)w * h;
    ref_px *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int i = y * w + x;
            float v;
            if (variance) {
                v = variance[i];
            } else {
                v = INFINITY;
                for (int wy = -2; wy <= 0; wy += 2)
                    for (int wx = -2; wx <= 0; wx += 2) {
                        double s = 0, s2 = 0, cnt = 0; /* in double: no cancellation */
                        for (int dy = wy; dy <= wy + 2; ++dy)
                            for (int dx = wx; dx <= wx + 2; ++dx) {
                                if (!ref_inside(w, h, x + dx, y + dy))
                                    continue;
                                const ref_px q = color[(y + dy) * w + x + dx];
                                const float l = ref_lum(q.r, q.g, q.b);
                                s += l;
                                s2 += l * l;
                                cnt += 1.0f;
                            }
                        const double mean = s / cnt;
                        v = fminf(v, (float)fmax(s2 / cnt - mean * mean, 0.0));
                    }
            }
            const float ar = ref_safe(albedo[i].r), ag = ref_safe(albedo[i].g),
                        ab = ref_safe(albedo[i].b), la = ref_lum(ar, ag, ab);
            a[i] = (ref_px){color[i].r / ar, color[i].g / ag, color[i].b / ab, v / (la * la)};
        }
    ref_clamp(a, w, h, sigma[3], b);
    ref_px *t0 = a;
    a = b;
    b = t0;
    ref_px *fit = malloc(n * sizeof *fit);
    char *fitted = malloc(n);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            fitted[y * w + x] = (char)ref_edge_fit(a, albedo, nd, w, h, x, y, &fit[y * w + x]);
    float pass_sigma[3] = {sigma[0], sigma[1], sigma[2]};
    for (int it = 0; it < iterations; ++it, pass_sigma[0] *= 0.8f) {
        ref_atrous(a, nd, albedo, w, h, 1 << it, pass_sigma, b);
        ref_px *t = a;
        a = b;
        b = t;
    }
    for (size_t i = 0; i < n; ++i) /* an emitter's pixels keep their colour */
        out[i] = albedo[i].w < 1.0f ? color[i]
                 : fitted[i]
                     ? fit[i]
                     : (ref_px){a[i].r * ref_safe(albedo[i].r), a[i].g * ref_safe(albedo[i].g),
                                a[i].b * ref_safe(albedo[i].b), 1.0f};
    free(fit);
    free(fitted);
    free(a);
    free(b);
}

#endif
