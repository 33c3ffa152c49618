/* emitter_pick (kernels/light/emitters.h), which every method picks an
 * emitter by, against a plain search in C: the first emitter whose CDF
 * exceeds u, the last where none does. CDFs of 1 to 40 emitters, some of
 * weight 0 (equal neighbours, at the start, the middle and the end), the
 * last exactly 1; u random, exactly each CDF value and the floats either
 * side of it, 0 and the largest float below 1. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "runtime/runtime.h"

static uint32_t pick_ref(const float *cdf, uint32_t count, float u) {
    for (uint32_t i = 0; i < count; ++i)
        if (cdf[i] > u)
            return i;
    return count - 1;
}

int main(void) {
    vct_error err = {0};
    vct_context *ctx = check_context();
    cl_program p;
    REQUIRE_OK(vct_program_get(ctx, "light/emitter_pick_probe.cl", "", &p, &err), err);
    uint64_t seed = 5;
    uint32_t tested = 0, wrong = 0, zero_weight = 0;
    for (uint32_t count = 1; count <= 40; ++count) {
        float cdf[40], u[40 * 3 + 200];
        double run = 0.0, w[40], total = 0.0;
        for (uint32_t i = 0; i < count; ++i) {
            /* every fifth emitter, and the first and last of some tables, weigh nothing */
            const int none = i % 5 == 2 || (count % 3 == 0 && (i == 0 || i == count - 1));
            w[i] = none && count > 1 ? 0.0 : 0.1 + check_randf(&seed);
            total += w[i];
            zero_weight += w[i] == 0.0;
        }
        for (uint32_t i = 0; i < count; ++i) {
            run += w[i];
            cdf[i] = i + 1 == count ? 1.0f : (float)(run / total);
        }
        uint32_t n = 0;
        for (uint32_t i = 0; i < count; ++i) {
            u[n++] = cdf[i];
            u[n++] = nextafterf(cdf[i], 0.0f);
            u[n++] = nextafterf(cdf[i], 2.0f);
        }
        u[n++] = 0.0f;
        u[n++] = nextafterf(1.0f, 0.0f);
        while (n < 40 * 3 + 200)
            u[n++] = check_randf(&seed) * 0.99999994f;
        cl_mem cb = vct_buffer_create(ctx, "pick", "cdf", 4ull * count,
                                      CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, cdf, &err);
        cl_mem ub = cb ? vct_buffer_create(ctx, "pick", "u", 4ull * n,
                                           CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, u, &err)
                       : NULL;
        cl_mem ob =
            ub ? vct_buffer_create(ctx, "pick", "picks", 4ull * n, CL_MEM_WRITE_ONLY, NULL, &err)
               : NULL;
        REQUIRE_OK(ob ? VCT_OK : err.status, err);
        cl_uint c = count, un = n;
        REQUIRE_OK(vct_run_kernel(ctx, p, "emitter_pick_probe", "pick", n, &err, 5,
                                  VCT_ARG(cdf, cb), VCT_ARG(count, c), VCT_ARG(u, ub),
                                  VCT_ARG(n, un), VCT_ARG(out, ob)),
                   err);
        uint32_t got[40 * 3 + 200];
        REQUIRE_OK(vct_buffer_read(ctx, "pick", ob, 0, 4ull * n, got, &err), err);
        for (uint32_t i = 0; i < n; ++i) {
            const uint32_t want = pick_ref(cdf, count, u[i]);
            if (got[i] != want && wrong++ < 5)
                fprintf(stderr, "%u emitters, u = %.9g: picked %u, the search %u\n", count, u[i],
                        got[i], want);
            ++tested;
        }
        vct_buffer_release(ctx, cb);
        vct_buffer_release(ctx, ub);
        vct_buffer_release(ctx, ob);
    }
    CHECK(wrong == 0, "emitter_pick: %u of %u picks differ from the search", wrong, tested);
    CHECK(zero_weight > 100, "only %u emitters of weight 0: a weak test", zero_weight);
    printf("emitter_pick: %u picks over CDFs of 1 to 40 emitters (%u of weight 0), as the search\n",
           tested, zero_weight);
    vct_context_release(ctx);
    return check_exit("test_emitter_pick");
}
