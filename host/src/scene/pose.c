/* Posing: an animation evaluated at a time into its nodes' transforms, and
 * the instances under the nodes it moves placed again. Unmoved nodes keep
 * the transforms loading gave them, bit for bit (the same float products). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "scene/instances.h"

/* Where t falls among n key times: key *i and the fraction *f towards the
 * next; held before the first key and after the last. */
static void key_at(const float *times, uint32_t n, float t, uint32_t *i, float *f) {
    *i = 0;
    *f = 0.0f;
    if (n == 0 || t <= times[0])
        return;
    if (t >= times[n - 1]) {
        *i = n - 1;
        return;
    }
    while (*i + 1 < n && times[*i + 1] <= t)
        ++*i;
    const float span = times[*i + 1] - times[*i];
    *f = span > 0.0f ? (t - times[*i]) / span : 0.0f;
}

/* glTF's cubic Hermite spline between keys i and i+1 at fraction f, for
 * component c of n: the values and the out-tangent of i and in-tangent of
 * i+1, scaled by the keys' spacing (tangents: in, out per key). */
static float hermite(const float *times, const float *values, const float *tangents, uint32_t i,
                     float f, int n, int c) {
    const double s = f, s2 = s * s, s3 = s2 * s, span = (double)times[i + 1] - times[i];
    const double out_i = tangents[2 * n * i + n + c], in_next = tangents[2 * n * (i + 1) + c];
    return (float)((2 * s3 - 3 * s2 + 1) * values[n * i + c] + span * (s3 - 2 * s2 + s) * out_i +
                   (-2 * s3 + 3 * s2) * values[n * (i + 1) + c] + span * (s3 - s2) * in_next);
}

static void sample_vec3(const float *times, const float *values, const float *tangents, uint32_t n,
                        float t, int step, float out[3]) {
    uint32_t i;
    float f;
    key_at(times, n, t, &i, &f);
    if (step)
        f = 0.0f;
    for (int k = 0; k < 3; ++k)
        out[k] = !(f > 0.0f) ? values[3 * i + k]
                 : tangents  ? hermite(times, values, tangents, i, f, 3, k)
                             : values[3 * i + k] + f * (values[3 * i + 3 + k] - values[3 * i + k]);
}

/* Spherical interpolation of unit quaternions (x y z w), the shorter way. */
static void sample_quat(const float *times, const float *values, const float *tangents, uint32_t n,
                        float t, int step, float out[4]) {
    uint32_t i;
    float f;
    key_at(times, n, t, &i, &f);
    if (step)
        f = 0.0f;
    const float *a = &values[4 * i];
    /* equal keys hold exactly: a blend of a with itself, normalised, may
     * round to another float and turn the node by an ulp */
    if (!(f > 0.0f) || memcmp(a, a + 4, 4 * sizeof(float)) == 0) {
        memcpy(out, a, 4 * sizeof(float));
        return;
    }
    if (tangents) { /* the spline, then normalised (glTF 2.0, appendix C) */
        double q[4], len = 0.0;
        for (int k = 0; k < 4; ++k) {
            q[k] = hermite(times, values, tangents, i, f, 4, k);
            len += q[k] * q[k];
        }
        if (!(len > 1e-12)) { /* tangents that pass through no rotation: hold the key */
            memcpy(out, a, 4 * sizeof(float));
            return;
        }
        for (int k = 0; k < 4; ++k)
            out[k] = (float)(q[k] / sqrt(len));
        return;
    }
    const float *b = &values[4 * i + 4];
    double d = 0.0, sb = 1.0;
    for (int k = 0; k < 4; ++k)
        d += (double)a[k] * b[k];
    if (d < 0.0) {
        d = -d;
        sb = -1.0;
    }
    double wa = 1.0 - f, wb = f;
    if (d < 0.9995) { /* else nearly equal: a straight blend, normalised */
        const double angle = acos(d), s = sin(angle);
        wa = sin((1.0 - f) * angle) / s;
        wb = sin(f * angle) / s;
    }
    double q[4], len = 0.0;
    for (int k = 0; k < 4; ++k) {
        q[k] = wa * a[k] + wb * sb * b[k];
        len += q[k] * q[k];
    }
    len = len > 0.0 ? sqrt(len) : 1.0;
    for (int k = 0; k < 4; ++k)
        out[k] = (float)(q[k] / len);
}

/* T * R * S as a row-major 3x4, in double, rounded once. */
static void compose(const float t[3], const float q[4], const float s[3], float m[12]) {
    const double x = q[0], y = q[1], z = q[2], w = q[3];
    const double r[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
                         2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                         2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
    for (int row = 0; row < 3; ++row) {
        for (int c = 0; c < 3; ++c)
            m[4 * row + c] = (float)(r[3 * row + c] * s[c]);
        m[4 * row + 3] = t[row];
    }
}

/* parent * local for 3x4 transforms, as loading multiplies 4x4 floats (the
 * same terms in the same order, so that unmoved chains agree bit for bit). */
static void multiply(const float a[12], const float b[12], float out[12]) {
    const float x[16] = {a[0], a[1], a[2],  a[3],  a[4], a[5], a[6], a[7],
                         a[8], a[9], a[10], a[11], 0,    0,    0,    1};
    const float y[16] = {b[0], b[1], b[2],  b[3],  b[4], b[5], b[6], b[7],
                         b[8], b[9], b[10], b[11], 0,    0,    0,    1};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j)
            out[4 * i + j] = x[4 * i] * y[j] + x[4 * i + 1] * y[4 + j] + x[4 * i + 2] * y[8 + j] +
                             x[4 * i + 3] * y[12 + j];
}

/* m's point p (w 1) or direction d (w 0, normalised). */
static void transform(const float m[12], const float v[3], float w, float out[3]) {
    for (int r = 0; r < 3; ++r)
        out[r] = m[4 * r] * v[0] + m[4 * r + 1] * v[1] + m[4 * r + 2] * v[2] + m[4 * r + 3] * w;
    if (w == 0.0f) {
        const float len = sqrtf(out[0] * out[0] + out[1] * out[1] + out[2] * out[2]);
        for (int k = 0; len > 0.0f && k < 3; ++k)
            out[k] /= len;
    }
}

/* The camera and the lights that moved nodes carry, moved with them. */
static void carry_attachments(vct_scene *s, const float *world, const uint8_t *moved) {
    const vct_attachment *c = &s->camera_attachment;
    if (c->node < s->node_count && moved[c->node]) {
        const float *m = &world[12 * c->node];
        float forward[3];
        transform(m, c->position, 1.0f, s->camera.position);
        transform(m, c->direction, 0.0f, forward);
        transform(m, c->up, 0.0f, s->camera.up);
        const float d = c->look_distance > 0.0f ? c->look_distance : 1.0f;
        for (int k = 0; k < 3; ++k)
            s->camera.look_at[k] = s->camera.position[k] + d * forward[k];
    }
    for (uint32_t i = 0; i < s->light_attachment_count && i < s->light_count; ++i) {
        const vct_attachment *a = &s->light_attachments[i];
        if (a->node >= s->node_count || !moved[a->node])
            continue;
        transform(&world[12 * a->node], a->position, 1.0f, s->lights[i].position);
        transform(&world[12 * a->node], a->direction, 0.0f, s->lights[i].direction);
    }
}

vct_status vct_scene_pose(vct_scene *s, uint32_t animation, double seconds, vct_error *err) {
    if (animation >= s->animation_count)
        return vct_fail(err, VCT_ERR_INPUT, "scene %s: no animation %u (it has %u)",
                        vct_scene_name(s), animation, s->animation_count);
    if (!isfinite(seconds))
        return vct_fail(err, VCT_ERR_INPUT, "scene %s: posing at a time that is not finite",
                        vct_scene_name(s));
    const vct_animation_info *an = &s->animations[animation];
    float *local = malloc(sizeof(float) * 12 * (s->node_count + 1));
    float *world = malloc(sizeof(float) * 12 * (s->node_count + 1));
    uint8_t *moved = calloc(s->node_count + 1, 1);
    if (!local || !world || !moved) {
        free(local);
        free(world);
        free(moved);
        return vct_fail(err, VCT_ERR_MEMORY, "scene: out of host memory");
    }
    for (uint32_t n = 0; n < s->node_count; ++n)
        memcpy(&local[12 * n], s->nodes[n].rest, sizeof s->nodes[n].rest);
    const float t = (float)seconds;
    for (uint32_t c = 0; c < an->channels; ++c) {
        const vct_animation_channel *ch = &an->channel[c];
        if (ch->node >= s->node_count)
            continue;
        const vct_node *node = &s->nodes[ch->node];
        float tr[3], q[4], sc[3];
        memcpy(tr, node->translation, sizeof tr);
        memcpy(q, node->rotation, sizeof q);
        memcpy(sc, node->scale, sizeof sc);
        if (ch->translation_keys)
            sample_vec3(ch->translation_times, ch->translations, ch->translation_tangents,
                        ch->translation_keys, t, ch->translation_step, tr);
        if (ch->rotation_keys)
            sample_quat(ch->rotation_times, ch->rotations, ch->rotation_tangents, ch->rotation_keys,
                        t, ch->rotation_step, q);
        if (ch->scale_keys)
            sample_vec3(ch->scale_times, ch->scales, ch->scale_tangents, ch->scale_keys, t,
                        ch->scale_step, sc);
        compose(tr, q, sc, &local[12 * ch->node]);
        moved[ch->node] = 1;
    }
    static const float identity[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    for (uint32_t n = 0; n < s->node_count; ++n) { /* parents come first */
        const uint32_t p = s->nodes[n].parent;
        multiply(p < n ? &world[12 * p] : identity, &local[12 * n], &world[12 * n]);
        moved[n] |= p < n && moved[p];
    }
    vct_status rc = VCT_OK;
    /* bad keys (not finite) are refused before anything moves */
    for (uint32_t n = 0; rc == VCT_OK && n < s->node_count; ++n)
        for (int k = 0; rc == VCT_OK && moved[n] && k < 12; ++k)
            if (!isfinite(world[12 * n + k]))
                rc = vct_fail(err, VCT_ERR_INPUT,
                              "scene %s: animation \"%s\" at %g s gives node %u a transform "
                              "that is not finite: its keys hold a bad value",
                              vct_scene_name(s), an->name, seconds, n);
    for (uint32_t i = 0; rc == VCT_OK && i < s->instance_count; ++i) {
        const uint32_t n = s->instances[i].node;
        if (n < s->node_count && moved[n])
            rc = vct_instance_place(s, i, &world[12 * n], err);
    }
    if (rc == VCT_OK)
        carry_attachments(s, world, moved);
    free(local);
    free(world);
    free(moved);
    return rc == VCT_OK ? vct_scene_validate(s, err) : rc;
}
