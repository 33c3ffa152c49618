/* Image metrics against values worked out by hand on small images, and the
 * PFM round trip that `vct compare` reads through. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "check.h"

static vct_image make(int w, int h, float base) {
    vct_image im = {w, h, malloc(16ull * w * h)};
    for (int i = 0; i < w * h; ++i)
        for (int c = 0; c < 4; ++c)
            im.rgba[4 * i + c] = c == 3 ? 1.0f : base + 0.25f * (float)((i + c) % 4);
    return im;
}

static int near(double a, double b) {
    return fabs(a - b) <= 1e-9 * fmax(1.0, fabs(b));
}

int main(void) {
    vct_error err = {0};
    /* Reference values 1, 1.25, 1.5, 1.75 (cycled); test = reference + 0.5. */
    vct_image ref = make(6, 4, 1.0f), test = make(6, 4, 1.5f);
    vct_image_metrics m;
    REQUIRE_OK(vct_image_compare(&test, &ref, &m, &err), err);
    double sum_r2 = 0.0, rel = 0.0, sum_r = 0.0;
    for (int i = 0; i < 24; ++i)
        for (int c = 0; c < 3; ++c) {
            double r = ref.rgba[4 * i + c];
            sum_r2 += r * r;
            sum_r += r;
            rel += 0.25 / (r * r + 0.01);
        }
    CHECK(near(m.rmse, 0.5) && near(m.mae, 0.5) && near(m.mse, 0.25), "rmse %g mae %g", m.rmse,
          m.mae);
    CHECK(near(m.relative_rmse, sqrt(0.25 * 72 / sum_r2)), "relative rmse %g", m.relative_rmse);
    /* NRMSE: the RMSE (0.5) over the reference's mean. */
    CHECK(near(m.nrmse, 0.5 / (sum_r / 72)), "nrmse %g", m.nrmse);
    CHECK(near(m.reference_mean, sum_r / 72) && near(m.test_mean, sum_r / 72 + 0.5), "means %g %g",
          m.reference_mean, m.test_mean);
    CHECK(near(m.relative_mse, rel / 72), "relative mse %g", m.relative_mse);
    CHECK(near(m.psnr, 10 * log10(1.75 * 1.75 / 0.25)), "psnr %g", m.psnr);
    CHECK(m.nonfinite == 0, "nonfinite %zu", m.nonfinite);

    REQUIRE_OK(vct_image_compare(&ref, &ref, &m, &err), err);
    CHECK(m.rmse == 0.0 && isinf(m.psnr), "self comparison: rmse %g psnr %g", m.rmse, m.psnr);

    /* NaN and infinity are counted and left out of the averages. */
    test.rgba[0] = NAN;
    test.rgba[5] = INFINITY;
    REQUIRE_OK(vct_image_compare(&test, &ref, &m, &err), err);
    CHECK(m.nonfinite == 2 && near(m.mae, 0.5), "nonfinite %zu, mae %g", m.nonfinite, m.mae);

    /* Error map: zero error is the ramp's blue end, the largest its red end. */
    vct_image map;
    REQUIRE_OK(vct_image_error_map(&ref, &ref, 0.0, &map, &err), err);
    CHECK(map.rgba[0] == 0.0f && map.rgba[2] == 0.5f, "zero error colour (%g %g %g)", map.rgba[0],
          map.rgba[1], map.rgba[2]);
    vct_image_release(&map);
    REQUIRE_OK(vct_image_error_map(&test, &ref, 0.5, &map, &err), err);
    CHECK(map.rgba[4 * 3 + 0] == 0.9f && map.rgba[4 * 3 + 1] == 0.0f, "full-scale colour");
    vct_image_release(&map);

    vct_image small = make(3, 4, 1.0f);
    CHECK(vct_image_compare(&small, &ref, &m, &err) == VCT_ERR_INPUT &&
              strstr(err.message, "sizes differ"),
          "size mismatch: %s", err.message);

    /* PFM round trip is exact, and rows keep their order. */
    char dir[] = "/tmp/vct-pfm-XXXXXX", path[64];
    if (!mkdtemp(dir))
        return 1;
    snprintf(path, sizeof path, "%s/a.pfm", dir);
    REQUIRE_OK(vct_image_write_pfm(&ref, path, &err), err);
    vct_image back;
    REQUIRE_OK(vct_image_read_pfm(path, &back, &err), err);
    REQUIRE_OK(vct_image_compare(&back, &ref, &m, &err), err);
    CHECK(back.width == 6 && back.height == 4 && m.rmse == 0.0, "PFM round trip: rmse %g", m.rmse);
    unlink(path);
    rmdir(dir);
    vct_image_release(&back);
    vct_image_release(&small);
    vct_image_release(&ref);
    vct_image_release(&test);
    return check_exit("test_compare");
}
