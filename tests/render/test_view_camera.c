/* The viewer's fly camera against plain vector arithmetic: an untouched
 * camera is the scene's own, bit for bit (so the window matches offline
 * renders); movement goes along the view at the set speed; looking turns
 * about the scene's up axis and never flips over the pole. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "view_camera.h"

static float dot3(const float *a, const float *b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void view_dir(const vct_camera *c, float *d) {
    float len = 0.0f;
    for (int k = 0; k < 3; ++k) {
        d[k] = c->look_at[k] - c->position[k];
        len += d[k] * d[k];
    }
    for (int k = 0; k < 3; ++k)
        d[k] /= sqrtf(len);
}

int main(void) {
    const vct_camera start = {{1.5f, 2.0f, 7.25f}, {0.3f, 1.1f, -2.0f}, {0.0f, 1.0f, 0.0f}, 40.0f};
    view_camera c;
    view_camera_init(&c, &start, 8.0f);
    vct_camera out;
    view_camera_get(&c, &out);
    CHECK(memcmp(&out, &start, sizeof out) == 0, "an untouched camera differs from the scene's");
    CHECK(fabsf(c.speed - 2.0f) < 1e-6f, "speed %g, expected a quarter of the extent", c.speed);

    /* Looking nowhere and moving nowhere leave it untouched. */
    view_camera_look(&c, 0.0f, 0.0f);
    view_camera_move(&c, 0.0f, 0.0f, 0.0f, 1.0f);
    view_camera_get(&c, &out);
    CHECK(memcmp(&out, &start, sizeof out) == 0, "a null move changed the camera");

    /* Forward for half a second at speed 2: one unit along the view. */
    float d0[3], d1[3];
    view_dir(&start, d0);
    view_camera_move(&c, 1.0f, 0.0f, 0.0f, 0.5f);
    view_camera_get(&c, &out);
    view_dir(&out, d1);
    for (int k = 0; k < 3; ++k) {
        CHECK(fabsf(out.position[k] - (start.position[k] + d0[k])) < 1e-5f,
              "axis %d: %g after a unit forward, expected %g", k, out.position[k],
              start.position[k] + d0[k]);
        CHECK(fabsf(d1[k] - d0[k]) < 1e-5f, "moving turned the view (axis %d)", k);
    }
    /* Up (E) moves along the scene's up axis. */
    const float y = out.position[1];
    view_camera_move(&c, 0.0f, 0.0f, 1.0f, 1.0f);
    view_camera_get(&c, &out);
    CHECK(fabsf(out.position[1] - (y + 2.0f)) < 1e-5f, "up: y %g, expected %g", out.position[1],
          y + 2.0f);

    /* Looking right by dx pixels turns about up by dx * 0.004 radians. */
    view_camera_look(&c, 100.0f, 0.0f);
    view_camera_get(&c, &out);
    view_dir(&out, d1);
    const float flat0 = sqrtf(d0[0] * d0[0] + d0[2] * d0[2]);
    const float turn =
        acosf((d0[0] * d1[0] + d0[2] * d1[2]) / (flat0 * sqrtf(d1[0] * d1[0] + d1[2] * d1[2])));
    CHECK(fabsf(turn - 0.4f) < 1e-3f, "turned %g radians, expected 0.4", turn);
    CHECK(fabsf(d1[1] - d0[1]) < 1e-5f, "a turn about up changed the pitch");
    const float cross_y = d0[2] * d1[0] - d0[0] * d1[2];
    CHECK(cross_y < 0.0f, "mouse right turned the view left");

    /* Looking far up stops short of the pole: the view never flips. */
    view_camera_look(&c, 0.0f, -100000.0f);
    view_camera_get(&c, &out);
    view_dir(&out, d1);
    const float up[3] = {0.0f, 1.0f, 0.0f};
    CHECK(dot3(d1, up) > 0.99f && dot3(d1, up) < 1.0f, "looking up: %g", dot3(d1, up));
    CHECK(isfinite(d1[0]) && isfinite(d1[2]), "a NaN at the pole");

    /* Scrolling scales the speed by 1.25 a notch. */
    view_camera_scroll(&c, 2.0f);
    CHECK(fabsf(c.speed - 2.0f * 1.5625f) < 1e-5f, "speed %g after two notches", c.speed);

    /* A camera looking straight down its up axis still gets a frame. */
    const vct_camera down = {{0, 5, 0}, {0, 0, 0}, {0, 1, 0}, 60.0f};
    view_camera_init(&c, &down, 1.0f);
    view_camera_move(&c, 1.0f, 1.0f, 0.0f, 1.0f);
    view_camera_get(&c, &out);
    for (int k = 0; k < 3; ++k)
        CHECK(isfinite(out.position[k]) && isfinite(out.look_at[k]), "NaN looking down");
    return check_exit("test_view_camera");
}
