/* The emitter table: emissive triangles, the CDF they are picked by and
 * each one's area over its pick probability. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "light/emitters.h"

static int emits(const vct_scene *s, uint32_t t) {
    const float *le = s->materials[s->triangle_material[t]].emission;
    return le[0] > 0.0f || le[1] > 0.0f || le[2] > 0.0f;
}

uint32_t vct_scene_emissive_triangles(const vct_scene *s) {
    uint32_t n = 0;
    for (uint32_t t = 0; t < s->triangle_count; ++t)
        n += (uint32_t)emits(s, t);
    return n;
}

static double triangle_area(const vct_scene *s, uint32_t t) {
    const float *a = &s->positions[3 * s->triangles[3 * t]];
    const float *b = &s->positions[3 * s->triangles[3 * t + 1]];
    const float *c = &s->positions[3 * s->triangles[3 * t + 2]];
    double e1[3], e2[3];
    for (int k = 0; k < 3; ++k) {
        e1[k] = (double)b[k] - a[k];
        e2[k] = (double)c[k] - a[k];
    }
    const double cx = e1[1] * e2[2] - e1[2] * e2[1], cy = e1[2] * e2[0] - e1[0] * e2[2],
                 cz = e1[0] * e2[1] - e1[1] * e2[0];
    return 0.5 * sqrt(cx * cx + cy * cy + cz * cz);
}

static int build(vct_context *ctx, const vct_scene *s, vct_emitter_weight weight, const char *stage,
                 vct_emitters *e, vct_error *err) {
    memset(e, 0, sizeof *e);
    const size_t n = (size_t)s->triangle_count + 1;
    uint32_t *tris = malloc(4 * n);
    double *w = malloc(8 * n), *area = malloc(8 * n);
    float *cdf = malloc(4 * n), *scale = malloc(4 * n);
    int rc = tris && w && area && cdf && scale
                 ? VCT_OK
                 : vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory", stage);
    double total = 0.0;
    for (uint32_t t = 0; rc == VCT_OK && t < s->triangle_count; ++t) {
        if (!emits(s, t))
            continue;
        const double ar = triangle_area(s, t);
        if (!(ar > 0.0))
            continue; /* a degenerate emitter cannot be sampled or hit */
        const float *le = s->materials[s->triangle_material[t]].emission;
        const double power = ar * ((double)le[0] + le[1] + le[2]);
        tris[e->count] = t;
        area[e->count] = ar;
        w[e->count] = weight == VCT_EMITTERS_BY_AREA ? ar : power;
        total += w[e->count];
        e->area += ar;
        e->power += power;
        e->count++;
    }
    double run = 0.0;
    for (uint32_t i = 0; rc == VCT_OK && i < e->count; ++i) {
        run += w[i];
        cdf[i] = i + 1 == e->count ? 1.0f : (float)(run / total);
        scale[i] = (float)(area[i] * total / w[i]);
    }
    if (rc == VCT_OK && e->count == 0) {
        tris[0] = 0;
        cdf[0] = scale[0] = 0.0f;
    }
    e->inv_area = e->area > 0.0 ? (float)(1.0 / e->area) : 0.0f;
    const size_t count = e->count ? e->count : 1;
    if (rc == VCT_OK)
        e->tris = vct_buffer_create(ctx, stage, "emissive triangles", 4 * count, CL_MEM_READ_ONLY,
                                    tris, err);
    if (e->tris)
        e->cdf =
            vct_buffer_create(ctx, stage, "emitter CDF", 4 * count, CL_MEM_READ_ONLY, cdf, err);
    if (e->cdf)
        e->scale = vct_buffer_create(ctx, stage, "emitter scales", 4 * count, CL_MEM_READ_ONLY,
                                     scale, err);
    if (rc == VCT_OK && !e->scale)
        rc = err->status;
    free(tris);
    free(w);
    free(area);
    free(cdf);
    free(scale);
    if (rc != VCT_OK)
        vct_emitters_release(ctx, e);
    return rc;
}

int vct_emitters_set_args(cl_kernel k, int first, const vct_emitters *e, cl_uint samples,
                          const char *stage, vct_error *err) {
    return vct_set_args(err, stage, k, first, 5, VCT_ARG(emitter_tris, e->tris),
                        VCT_ARG(emitter_cdf, e->cdf), VCT_ARG(emitter_scale, e->scale),
                        VCT_ARG(emitter_count, e->count), VCT_ARG(emitter_samples, samples));
}

void vct_emitters_release(vct_context *ctx, vct_emitters *e) {
    if (e->borrowed)
        return;
    vct_buffer_release(ctx, e->tris);
    vct_buffer_release(ctx, e->cdf);
    vct_buffer_release(ctx, e->scale);
    e->tris = e->cdf = e->scale = NULL;
}

int vct_emitters_build(vct_context *ctx, const vct_scene *s, vct_emitter_weight weight,
                       const char *stage, vct_emitters *e, vct_error *err) {
    vct_resident *r = vct_resident_find(ctx, s);
    if (!r)
        return build(ctx, s, weight, stage, e, err);
    if (!r->emitters[weight]) {
        vct_emitters *own = calloc(1, sizeof *own);
        if (!own)
            return vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory", stage);
        const uint64_t before = ctx->transfers.uploaded;
        if (build(ctx, s, weight, stage, own, err) != VCT_OK) {
            free(own);
            return err->status;
        }
        r->scene_bytes += ctx->transfers.uploaded - before;
        r->emitters[weight] = own;
    }
    *e = *r->emitters[weight];
    e->borrowed = 1;
    return VCT_OK;
}

void vct_emitters_release_resident(vct_context *ctx, vct_resident *r) {
    for (int w = 0; w < 2; ++w)
        if (r->emitters[w]) {
            vct_emitters_release(ctx, r->emitters[w]);
            free(r->emitters[w]);
            r->emitters[w] = NULL;
        }
}
