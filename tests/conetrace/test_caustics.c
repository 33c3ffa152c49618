/* Cone tracing's caustics: sunlight through a glass slab onto a floor.
 *
 * Shadow rays stop at the glass and voxels let the light through unlit, so
 * without photons the floor under the slab is black. With them it gets the
 * sun's light times what a parallel plate transmits at normal incidence,
 * every internal reflection summed: (1 - F)^2 (1 + F^2 + F^4 + ...) =
 * (1 - F) / (1 + F), F = ((n - 1) / (n + 1))^2. The camera sits between the
 * slab and the floor and sees the floor alone.
 *
 * Also: the plan turns caustics on only for a transmissive material with
 * light to send through it, and no caustic kernel runs otherwise. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "mesh_gen.h"
#include "vct_case.h"

#define W 48
#define H 48
#define IOR 1.5
#define SUN 3.0
#define ALBEDO 0.8

static vct_context *ctx;

/* A floor at y = 0 (half-size 3) and a glass slab from y = 1 to 1.2 (half-size 2). */
static vct_scene *slab_scene(float transmission) {
    const float quads[] = {-3, 0,    -3, 3, 0,    -3, 3, 0,    3, -3, 0,    3,
                           -2, 1.2f, -2, 2, 1.2f, -2, 2, 1.2f, 2, -2, 1.2f, 2,
                           -2, 1.0f, -2, 2, 1.0f, -2, 2, 1.0f, 2, -2, 1.0f, 2};
    test_mesh t = mesh_quads(quads, 3);
    uint32_t mat[6] = {0, 0, 1, 1, 1, 1};
    vct_material m[2] = {vct_material_default(), vct_material_default()};
    m[0].albedo[0] = m[0].albedo[1] = m[0].albedo[2] = (float)ALBEDO;
    m[1].albedo[0] = m[1].albedo[1] = m[1].albedo[2] = 1.0f;
    m[1].roughness = 0.0f;
    m[1].transmission = transmission;
    m[1].ior = (float)IOR;
    vct_error err = {0};
    vct_scene *s = vct_scene_from_arrays(t.pos, t.nv, t.tri, t.nt, mat, m, 2, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    mesh_free(&t);
    vct_light sun = {0};
    sun.type = VCT_LIGHT_DIRECTIONAL;
    sun.direction[1] = -1.0f;
    sun.color[0] = sun.color[1] = sun.color[2] = (float)SUN;
    REQUIRE_OK(vct_scene_add_light(s, &sun, &err), err);
    s->camera = (vct_camera){{0.0f, 0.6f, 0.0f}, {0, 0, 0}, {0, 0, -1}, 60.0f};
    return s;
}

static void slab(void) {
    vct_scene *s = slab_scene(1.0f);
    vct_plan plan;
    vct_plan_make(s, NULL, &plan);
    CHECK(plan.on[VCT_EFFECT_CAUSTICS] && strstr(plan.why[VCT_EFFECT_CAUSTICS], "transmits"),
          "a glass slab in the sun plans caustics: %s", plan.why[VCT_EFFECT_CAUSTICS]);
    vct_image im = vct_case_render(ctx, s, &plan, 32, W, H, 1, NULL);
    CHECK(vct_kernel_launches(ctx, "vct_caustics") > 0, "no caustic pass ran");
    const double F = pow((IOR - 1.0) / (IOR + 1.0), 2.0);
    const double expected = ALBEDO / CHECK_PI * SUN * (1.0 - F) / (1.0 + F);
    double sum = 0.0;
    int n = 0, far = 0;
    for (int p = 0; p < W * H; ++p)
        for (int k = 0; k < 3; ++k) {
            const double v = im.rgba[4 * p + k];
            sum += v;
            ++n;
            far += fabs(v / expected - 1.0) > 0.3;
        }
    const double mean = sum / n;
    CHECK(fabs(mean / expected - 1.0) < 0.03 && far < n / 20,
          "floor under the slab: mean %.4f against %.4f (sun through the plate), %d of %d "
          "values off by more than 30 %%",
          mean, expected, far, n);
    vct_image_release(&im);

    /* Forced off, the floor under the slab is in the slab's shadow. */
    vct_plan off;
    vct_case_plan_forcing(s, VCT_EFFECT_CAUSTICS, VCT_FORCE_OFF, VCT_FORCE_AUTO, &off);
    im = vct_case_render(ctx, s, &off, 32, W, H, 1, NULL);
    double worst = 0.0;
    for (int p = 0; p < 4 * W * H; ++p)
        worst = fmax(worst, p % 4 == 3 ? 0.0 : im.rgba[p]);
    CHECK(vct_kernel_launches(ctx, "vct_caustics") == 0 && worst < 1e-3 * expected,
          "caustics off: %llu caustic passes, floor up to %g",
          (unsigned long long)vct_kernel_launches(ctx, "vct_caustics"), worst);
    vct_image_release(&im);
    vct_scene_release(s);

    /* An opaque slab sends nothing through: no caustics planned. */
    s = slab_scene(0.0f);
    vct_plan_make(s, NULL, &plan);
    CHECK(!plan.on[VCT_EFFECT_CAUSTICS], "an opaque slab plans caustics: %s",
          plan.why[VCT_EFFECT_CAUSTICS]);
    vct_scene_release(s);
}

int main(void) {
    ctx = check_context();
    slab();
    vct_context_release(ctx);
    return check_exit("test_caustics");
}
