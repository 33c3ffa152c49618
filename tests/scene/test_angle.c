/* angle_of (kernels/scene/angle.h), which Lambert's formula takes each edge's
 * angle from, against the C library's atan2 in double precision: a dense
 * sweep of the half turn [0, pi] at several magnitudes (unit, tiny, huge),
 * the octant borders (s == |c|) and the floats beside them, the axes, and
 * both zero. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "runtime/runtime.h"

enum { SWEEP = 1 << 15, SCALES = 3, BORDERS = 4 * 3, AXES = 3 };

int main(void) {
    vct_error err = {0};
    vct_context *ctx = check_context();
    const float scales[SCALES] = {1.0f, 1e-30f, 1e30f};
    const uint32_t n = SWEEP * SCALES + BORDERS + AXES + 1;
    float *sc = malloc(8ull * n), *out = malloc(4ull * n);
    uint32_t k = 0;
    for (int s = 0; s < SCALES; ++s)
        for (uint32_t i = 0; i < SWEEP; ++i) {
            const double a = 3.14159265358979324 * ((double)i + 0.5) / SWEEP;
            sc[2 * k] = (float)(sin(a) * scales[s]);
            sc[2 * k + 1] = (float)(cos(a) * scales[s]);
            ++k;
        }
    /* s == |c| on either side of the +c and -c axes, and one float off */
    for (int side = 0; side < 2; ++side)
        for (int off = -1; off <= 1; off += 1)
            for (int big = 0; big < 2; ++big) {
                const float c = (side ? -1.0f : 1.0f) * (big ? 3.0e5f : 0.7f);
                float s = fabsf(c);
                if (off < 0)
                    s = nextafterf(s, 0.0f);
                else if (off > 0)
                    s = nextafterf(s, INFINITY);
                sc[2 * k] = s;
                sc[2 * k + 1] = c;
                ++k;
            }
    const float axes[AXES][2] = {{1.0f, 0.0f}, {0.0f, 1.0f}, {0.0f, -1.0f}};
    for (int i = 0; i < AXES; ++i, ++k) {
        sc[2 * k] = axes[i][0];
        sc[2 * k + 1] = axes[i][1];
    }
    sc[2 * k] = 0.0f; /* both zero: a point of no angle */
    sc[2 * k + 1] = 0.0f;
    cl_program p;
    REQUIRE_OK(vct_program_get(ctx, "scene/angle_probe.cl", "", &p, &err), err);
    cl_mem in = vct_buffer_create(ctx, "angle", "sine, cosine", 8ull * n,
                                  CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sc, &err);
    REQUIRE_OK(in ? VCT_OK : err.status, err);
    cl_mem res = vct_buffer_create(ctx, "angle", "angles", 4ull * n, CL_MEM_WRITE_ONLY, NULL, &err);
    REQUIRE_OK(res ? VCT_OK : err.status, err);
    cl_uint count = n;
    REQUIRE_OK(vct_run_kernel(ctx, p, "angle_probe", "angle", n, &err, 3, VCT_ARG(sc, in),
                              VCT_ARG(n, count), VCT_ARG(out, res)),
               err);
    REQUIRE_OK(vct_buffer_read(ctx, "angle", res, 0, 4ull * n, out, &err), err);
    double worst = 0.0;
    uint32_t worst_at = 0;
    for (uint32_t i = 0; i + 1 < n; ++i) {
        const double want = atan2((double)sc[2 * i], (double)sc[2 * i + 1]);
        /* as a share of pi: Lambert's formula sums the angles */
        const double off = fabs(out[i] - want) / 3.14159265358979324;
        if (!(off <= worst) || isnan(out[i]))
            worst = isnan(out[i]) ? INFINITY : off, worst_at = i;
    }
    /* a few float roundings of the polynomial's terms and of the octant's
     * pi / 2 or pi (2^-24 each) */
    CHECK(worst < 4.0 * FLT_EPSILON, "angle off by %.3g of pi at (s, c) = (%.9g, %.9g)", worst,
          sc[2 * worst_at], sc[2 * worst_at + 1]);
    CHECK(out[n - 1] == 0.0f, "(0, 0) gives %.9g, not 0", out[n - 1]);
    CHECK(out[n - 2] == 3.14159265f, "(0, -1) gives %.9g, not pi", out[n - 2]);
    CHECK(out[n - 3] == 0.0f, "(0, 1) gives %.9g, not 0", out[n - 3]);
    printf("angle_of: worst error %.3g of pi (at s = %.9g, c = %.9g) over %u pairs\n", worst,
           sc[2 * worst_at], sc[2 * worst_at + 1], n);
    vct_buffer_release(ctx, in);
    vct_buffer_release(ctx, res);
    vct_context_release(ctx);
    free(sc);
    free(out);
    return check_exit("test_angle");
}
