/* turn_cos_sin (kernels/scene/turn.h), which sampling uses for the cosine
 * and sine of 2 pi u, against the C library in double precision: a dense
 * sweep of [0, 1), each eighth of a turn's edges and the floats next to
 * them, and the last float below 1. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "runtime/runtime.h"

int main(void) {
    vct_error err = {0};
    vct_context *ctx = check_context();
    enum { SWEEP = 1 << 16, EDGES = 9 * 3 };
    const uint32_t n = SWEEP + EDGES + 1;
    float *u = malloc(4ull * n), *out = malloc(8ull * n);
    for (uint32_t i = 0; i < SWEEP; ++i)
        u[i] = (float)i / SWEEP + 0.37f / SWEEP;
    for (int e = 0; e < 9; ++e) {
        const float edge = (float)e / 8.0f;
        u[SWEEP + 3 * e] = edge;
        u[SWEEP + 3 * e + 1] = nextafterf(edge, 0.0f);
        u[SWEEP + 3 * e + 2] = nextafterf(edge, 2.0f);
    }
    u[n - 1] = nextafterf(1.0f, 0.0f);
    cl_program p;
    REQUIRE_OK(vct_program_get(ctx, "scene/turn_probe.cl", "", &p, &err), err);
    cl_mem in = vct_buffer_create(ctx, "turn", "u", 4ull * n,
                                  CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, u, &err);
    REQUIRE_OK(in ? VCT_OK : err.status, err);
    cl_mem res = vct_buffer_create(ctx, "turn", "cos sin", 8ull * n, CL_MEM_WRITE_ONLY, NULL, &err);
    REQUIRE_OK(res ? VCT_OK : err.status, err);
    cl_uint count = n;
    REQUIRE_OK(vct_run_kernel(ctx, p, "turn_probe", "turn", n, &err, 3, VCT_ARG(u, in),
                              VCT_ARG(n, count), VCT_ARG(out, res)),
               err);
    REQUIRE_OK(vct_buffer_read(ctx, "turn", res, 0, 8ull * n, out, &err), err);
    double worst = 0.0, worst_norm = 0.0;
    uint32_t worst_at = 0;
    for (uint32_t i = 0; i < n; ++i) {
        const double a = 6.283185307179586477 * (double)u[i];
        const double dc = fabs(out[2 * i] - cos(a)), ds = fabs(out[2 * i + 1] - sin(a));
        if (fmax(dc, ds) > worst)
            worst = fmax(dc, ds), worst_at = i;
        const double norm = hypot(out[2 * i], out[2 * i + 1]);
        worst_norm = fmax(worst_norm, fabs(norm - 1.0));
    }
    /* a few float roundings of unit values (2^-24 each) */
    CHECK(worst < 4e-7, "cos and sin off by %.3g at u = %.9g", worst, u[worst_at]);
    CHECK(worst_norm < 4e-7, "cos^2 + sin^2 off 1 by %.3g", worst_norm);
    CHECK(out[0] == 1.0f || fabs(out[0] - 1.0) < 1e-7, "u = 0 gives cos %.9g", out[0]);
    printf("turn_cos_sin: worst error %.3g (at u = %.9g) over %u values, |(c, s)| - 1 at most "
           "%.3g\n",
           worst, u[worst_at], n, worst_norm);
    vct_buffer_release(ctx, in);
    vct_buffer_release(ctx, res);
    vct_context_release(ctx);
    free(u);
    free(out);
    return check_exit("test_turn");
}
