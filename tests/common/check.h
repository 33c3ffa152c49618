/* Minimal test support: CHECK records a failure with file and line and goes on;
 * a test's main returns check_exit() so ctest sees any failure. */
#ifndef VCT_CHECK_H
#define VCT_CHECK_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "vct/debug.h"
#include "vct/vct.h"

#define CHECK_PI 3.14159265358979323846

static int check_failures;
static int check_count;

#define CHECK(cond, ...)                                                                           \
    do {                                                                                           \
        ++check_count;                                                                             \
        if (!(cond)) {                                                                             \
            ++check_failures;                                                                      \
            fprintf(stderr, "%s:%d: check failed: %s: ", __FILE__, __LINE__, #cond);               \
            fprintf(stderr, __VA_ARGS__);                                                          \
            fputc('\n', stderr);                                                                   \
        }                                                                                          \
    } while (0)

/* For calls that must succeed before the test can go on. */
#define REQUIRE_OK(call, err)                                                                      \
    do {                                                                                           \
        if ((call) != VCT_OK) {                                                                    \
            fprintf(stderr, "%s:%d: %s failed: %s\n", __FILE__, __LINE__, #call, (err).message);   \
            exit(1);                                                                               \
        }                                                                                          \
    } while (0)

static inline int check_exit(const char *name) {
    if (check_count == 0) {
        fprintf(stderr, "%s: no checks ran\n", name);
        return 1;
    }
    printf("%s: %d checks, %d failed\n", name, check_count, check_failures);
    return check_failures ? 1 : 0;
}

/* Float values (every channel) that differ bit for bit between two images
 * of one size; SIZE_MAX when the sizes differ. */
static inline size_t check_differing(const vct_image *a, const vct_image *b) {
    if (a->width != b->width || a->height != b->height)
        return (size_t)-1;
    size_t n = 0;
    for (size_t i = 0; i < (size_t)a->width * a->height * 4; ++i)
        n += memcmp(&a->rgba[i], &b->rgba[i], sizeof(float)) != 0;
    return n;
}

static inline vct_context *check_context(void) {
    vct_error err = {0};
    vct_context *ctx = vct_context_create(NULL, &err);
    if (!ctx) {
        fprintf(stderr, "no OpenCL context: %s\n", err.message);
        exit(1);
    }
    return ctx;
}

/* A scene file of the source tree (relative to $VCT_SOURCE_DIR). */
static inline vct_scene *check_scene_file(const char *relative) {
    char path[1024];
    const char *src = getenv("VCT_SOURCE_DIR");
    snprintf(path, sizeof path, "%s/%s", src ? src : ".", relative);
    vct_error err = {0};
    vct_scene *s = vct_scene_load(path, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    return s;
}

/* The shipped Cornell box (glTF, lit by its emissive ceiling). */
static inline vct_scene *check_cornell_box(void) {
    return check_scene_file("scenes/cornell_box.gltf");
}

/* The Cornell box as an OBJ (no lights of its own) under the README's point
 * light below the ceiling, seen through its open side by the glTF's camera
 * (an OBJ has none, and the default one looks at the closed back wall). */
static inline vct_scene *check_cornell_box_point_light(void) {
    vct_scene *s = check_scene_file("scenes/cornell_box.obj");
    const vct_camera camera = {
        {278.0f, 273.0f, -800.0f}, {278.0f, 273.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 39.3076f};
    s->camera = camera;
    vct_light light = {0};
    light.type = VCT_LIGHT_POINT;
    light.position[0] = 278.0f, light.position[1] = 448.8f, light.position[2] = 279.5f;
    light.color[0] = light.color[1] = light.color[2] = 6e5f;
    vct_error err = {0};
    REQUIRE_OK(vct_scene_add_light(s, &light, &err), err);
    return s;
}

/* Deterministic generator for test inputs (xorshift64*). */
static inline uint64_t check_rand(uint64_t *s) {
    *s ^= *s >> 12;
    *s ^= *s << 25;
    *s ^= *s >> 27;
    return *s * 0x2545F4914F6CDD1Dull;
}

static inline float check_randf(uint64_t *s) {
    return (float)(check_rand(s) >> 40) / (float)(1ull << 24);
}

/* Fresnel reflectance of an unpolarised ray, cos_i from the side of
 * refractive index ratio eta = n_incident / n_transmitted (1 past the
 * critical angle). */
static inline double check_fresnel(double cos_i, double eta) {
    const double sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    if (sin2_t >= 1.0)
        return 1.0;
    const double cos_t = sqrt(1.0 - sin2_t);
    const double rs = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    const double rp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return 0.5 * (rs * rs + rp * rp);
}

#endif
