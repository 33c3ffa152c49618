/* Connected pieces of the mesh by union-find over shared vertices, their
 * boxes projected into the image. */
#include <math.h>
#include <stdlib.h>

#include "raytrace/small_objects.h"

static uint32_t find(uint32_t *parent, uint32_t v) {
    while (parent[v] != v) {
        parent[v] = parent[parent[v]]; /* path halving */
        v = parent[v];
    }
    return v;
}

/* Pixel coordinates of p; 0 when p is not in front of the camera. */
static int project(const vct_camera_desc *c, const double p[3], double *x, double *y) {
    double d[3], z = 0.0, r = 0.0, u = 0.0;
    for (int k = 0; k < 3; ++k)
        d[k] = p[k] - c->position.s[k];
    for (int k = 0; k < 3; ++k) {
        z += d[k] * c->forward.s[k];
        r += d[k] * c->right.s[k];
        u += d[k] * c->up.s[k];
    }
    if (!(z > 1e-6))
        return 0;
    const double tan_half = c->position.s[3], aspect = c->forward.s[3];
    /* A band of a taller image (kernels/scene/camera.h): rows from its first. */
    const double height = c->size.s[3] ? c->size.s[3] : c->size.s[1];
    *x = (r / (z * tan_half * aspect) + 1.0) * 0.5 * c->size.s[0] - 0.5;
    *y = (1.0 - u / (z * tan_half)) * 0.5 * height - 0.5 - c->size.s[2];
    return 1;
}

static void mark(const vct_camera_desc *c, const float lo[3], const float hi[3], uint32_t size,
                 uint16_t *map, int64_t *count) {
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (int corner = 0; corner < 8; ++corner) {
        const double p[3] = {corner & 1 ? hi[0] : lo[0], corner & 2 ? hi[1] : lo[1],
                             corner & 4 ? hi[2] : lo[2]};
        double x, y;
        if (!project(c, p, &x, &y))
            return; /* reaching behind the camera: not small on screen */
        x0 = fmin(x0, x), y0 = fmin(y0, y), x1 = fmax(x1, x), y1 = fmax(y1, y);
    }
    const double extent = fmax(x1 - x0, y1 - y0);
    const int w = (int)c->size.s[0], h = (int)c->size.s[1];
    if (!(extent < 2.0 * size) || x1 < -1.0 || y1 < -1.0 || x0 > w || y0 > h)
        return;
    ++*count;
    const uint16_t v = (uint16_t)fmax(1.0, ceil(extent));
    const int xa = (int)fmax(0.0, floor(x0) - 1.0), xb = (int)fmin(w - 1.0, ceil(x1) + 1.0);
    const int ya = (int)fmax(0.0, floor(y0) - 1.0), yb = (int)fmin(h - 1.0, ceil(y1) + 1.0);
    for (int y = ya; y <= yb; ++y)
        for (int x = xa; x <= xb; ++x)
            if (map[(size_t)y * w + x] > v)
                map[(size_t)y * w + x] = v;
}

int64_t vct_small_object_map(const vct_scene *s, const vct_camera_desc *cam, uint32_t size,
                             uint16_t *map) {
    const size_t pixels = (size_t)cam->size.s[0] * cam->size.s[1];
    for (size_t i = 0; i < pixels; ++i)
        map[i] = VCT_NO_SMALL_OBJECT;
    const uint32_t nv = s->vertex_count;
    uint32_t *parent = malloc(4ull * (nv ? nv : 1));
    float *box = malloc(24ull * (nv ? nv : 1));
    if (!parent || !box) {
        free(parent);
        free(box);
        return -1;
    }
    for (uint32_t v = 0; v < nv; ++v)
        parent[v] = v;
    for (uint32_t t = 0; t < s->triangle_count; ++t) {
        const uint32_t *tr = &s->triangles[3 * t];
        const uint32_t a = find(parent, tr[0]);
        for (int k = 1; k < 3; ++k) {
            const uint32_t b = find(parent, tr[k]);
            if (a != b)
                parent[b] = a;
        }
    }
    for (uint32_t v = 0; v < nv; ++v)
        for (int k = 0; k < 3; ++k) {
            box[6 * v + k] = INFINITY;
            box[6 * v + 3 + k] = -INFINITY;
        }
    for (uint32_t t = 0; t < s->triangle_count; ++t)
        for (int j = 0; j < 3; ++j) {
            const uint32_t v = s->triangles[3 * t + j], root = find(parent, v);
            for (int k = 0; k < 3; ++k) {
                box[6 * root + k] = fminf(box[6 * root + k], s->positions[3 * v + k]);
                box[6 * root + 3 + k] = fmaxf(box[6 * root + 3 + k], s->positions[3 * v + k]);
            }
        }
    int64_t count = 0;
    for (uint32_t v = 0; v < nv; ++v)
        if (parent[v] == v && box[6 * v] <= box[6 * v + 3])
            mark(cam, &box[6 * v], &box[6 * v + 3], size, map, &count);
    free(parent);
    free(box);
    return count;
}
