/* Scene data in the kernels' layout: camera, lights and materials. */
#include <math.h>
#include <string.h>

#include "internal.h"
#include "scene_device.h"

static void normalize3(float v[3]) {
    float len = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (len > 0.0f)
        for (int k = 0; k < 3; ++k)
            v[k] /= len;
}

static void cross3(const float a[3], const float b[3], float out[3]) {
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

int vct_camera_desc_make(const vct_camera *cam, int width, int height, vct_camera_desc *d,
                         vct_error *err) {
    float f[3], r[3], u[3];
    for (int k = 0; k < 3; ++k)
        f[k] = cam->look_at[k] - cam->position[k];
    normalize3(f);
    cross3(f, cam->up, r);
    normalize3(r);
    cross3(r, f, u);
    float rl = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
    float fl = f[0] * f[0] + f[1] * f[1] + f[2] * f[2];
    if (!(fl > 0.5f) || !(rl > 0.5f))
        return vct_fail(err, VCT_ERR_INPUT,
                        "camera: position, look-at and up do not define a view (look-at equals "
                        "the position, or up is parallel to the view direction)");
    if (!(cam->fov_y_deg > 0.0f && cam->fov_y_deg < 179.0f))
        return vct_fail(err, VCT_ERR_INPUT, "camera: field of view %g degrees is outside (0, 179)",
                        cam->fov_y_deg);
    if (width <= 0 || height <= 0 || width > 32768 || height > 32768)
        return vct_fail(err, VCT_ERR_INPUT, "camera: image size %dx%d is outside 1..32768", width,
                        height);
    memset(d, 0, sizeof *d);
    for (int k = 0; k < 3; ++k) {
        d->position.s[k] = cam->position[k];
        d->forward.s[k] = f[k];
        d->right.s[k] = r[k];
        d->up.s[k] = u[k];
    }
    d->position.s[3] = tanf(0.5f * cam->fov_y_deg * VCT_PI_F / 180.0f);
    d->forward.s[3] = (float)width / (float)height;
    d->size.s[0] = (cl_uint)width;
    d->size.s[1] = (cl_uint)height;
    return VCT_OK;
}

void vct_light_desc_make(const vct_light *l, vct_light_desc *d) {
    memset(d, 0, sizeof *d);
    float dir[3] = {l->direction[0], l->direction[1], l->direction[2]};
    normalize3(dir);
    for (int k = 0; k < 3; ++k) {
        d->position.s[k] = l->position[k];
        d->direction.s[k] = dir[k];
        d->color.s[k] = l->color[k];
    }
    d->position.s[3] = (float)l->type;
    d->direction.s[3] = cosf(l->outer_cone);
    d->color.s[3] = cosf(l->inner_cone < l->outer_cone ? l->inner_cone : l->outer_cone);
}

void vct_material_desc_make(const vct_material *m, vct_material_desc *d) {
    memset(d, 0, sizeof *d);
    for (int k = 0; k < 3; ++k) {
        d->albedo.s[k] = m->albedo[k];
        d->emission.s[k] = m->emission[k];
        d->specular.s[k] = m->specular[k];
    }
    d->albedo.s[3] = m->metallic;
    d->emission.s[3] = m->roughness;
    d->specular.s[3] = m->transmission;
    d->extra.s[0] = m->ior;
}
