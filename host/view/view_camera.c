/* Fly camera arithmetic (view_camera.h). */
#include <math.h>
#include <string.h>

#include <cglm/cglm.h>

#include "view_camera.h"

#define LOOK_RADIANS_PER_PIXEL 0.004f
#define PITCH_LIMIT 1.55f /* just short of straight up, where yaw loses meaning */

static void forward_of(const view_camera *c, vec3 out) {
    vec3 flat, lift;
    glm_vec3_scale((float *)c->ahead, cosf(c->yaw), flat);
    glm_vec3_muladds((float *)c->side, sinf(c->yaw), flat);
    glm_vec3_scale(flat, cosf(c->pitch), out);
    glm_vec3_scale((float *)c->up, sinf(c->pitch), lift);
    glm_vec3_add(out, lift, out);
}

void view_camera_init(view_camera *c, const vct_camera *start, float extent) {
    memset(c, 0, sizeof *c);
    c->start = *start;
    memcpy(c->position, start->position, sizeof c->position);
    vec3 up = {start->up[0], start->up[1], start->up[2]}, f;
    glm_vec3_normalize(up);
    glm_vec3_sub((float *)start->look_at, (float *)start->position, f);
    glm_vec3_normalize(f);
    const float lift = glm_vec3_dot(f, up);
    vec3 ahead;
    glm_vec3_copy(f, ahead);
    glm_vec3_muladds(up, -lift, ahead);
    if (glm_vec3_norm(ahead) < 1e-6f) /* looking straight along up: pick any heading */
        glm_vec3_ortho(up, ahead);
    glm_vec3_normalize(ahead);
    glm_vec3_copy(up, c->up);
    glm_vec3_copy(ahead, c->ahead);
    glm_vec3_crossn(ahead, up, c->side);
    c->pitch = fmaxf(-PITCH_LIMIT, fminf(PITCH_LIMIT, asinf(fmaxf(-1.0f, fminf(1.0f, lift)))));
    c->speed = extent > 0.0f ? 0.25f * extent : 1.0f;
}

void view_camera_look(view_camera *c, float dx, float dy) {
    if (dx == 0.0f && dy == 0.0f)
        return;
    c->yaw += dx * LOOK_RADIANS_PER_PIXEL;
    c->pitch = fmaxf(-PITCH_LIMIT, fminf(PITCH_LIMIT, c->pitch - dy * LOOK_RADIANS_PER_PIXEL));
    c->moved = 1;
}

void view_camera_move(view_camera *c, float forward, float right, float up, float dt) {
    if (forward == 0.0f && right == 0.0f && up == 0.0f)
        return;
    vec3 f, r;
    forward_of(c, f);
    glm_vec3_crossn(f, c->up, r);
    const float d = c->speed * dt;
    glm_vec3_muladds(f, forward * d, c->position);
    glm_vec3_muladds(r, right * d, c->position);
    glm_vec3_muladds(c->up, up * d, c->position);
    c->moved = 1;
}

void view_camera_scroll(view_camera *c, float notches) {
    c->speed *= powf(1.25f, notches);
}

void view_camera_get(const view_camera *c, vct_camera *out) {
    *out = c->start;
    if (!c->moved)
        return;
    vec3 f;
    forward_of(c, f);
    for (int k = 0; k < 3; ++k) {
        out->position[k] = c->position[k];
        out->look_at[k] = c->position[k] + f[k];
        out->up[k] = c->up[k];
    }
}
