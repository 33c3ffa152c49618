/* Photon sources: each light's power, the emitters' as one source, the
 * environment (the scene's ambient) as another. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "photon/photon_sources.h"

#define PI 3.14159265358979

/* A light's emitted power summed over channels: what it is picked by. */
static double light_power(const vct_light *l, double bounds_radius) {
    const double c = (double)l->color[0] + l->color[1] + l->color[2];
    switch (l->type) {
    case VCT_LIGHT_SPOT:
        return c * 2.0 * PI * (1.0 - cos((double)l->outer_cone));
    case VCT_LIGHT_DIRECTIONAL:
        return c * PI * bounds_radius * bounds_radius;
    default:
        return c * 4.0 * PI;
    }
}

int vct_photon_sources_make(vct_context *ctx, const vct_scene *s, const char *stage,
                            vct_photon_sources *out, vct_error *err) {
    memset(out, 0, sizeof *out);
    double r2 = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double c = 0.5 * ((double)s->bounds_min[k] + s->bounds_max[k]);
        const double h = 0.5 * ((double)s->bounds_max[k] - s->bounds_min[k]);
        out->bounds.s[k] = (float)c;
        r2 += h * h;
    }
    const double radius = s->triangle_count ? fmax(sqrt(r2), 1e-6) : 1.0;
    out->bounds.s[3] = (float)(radius * 1.01);
    int rc = vct_emitters_build(ctx, s, VCT_EMITTERS_BY_POWER, stage, &out->emitters, err);
    if (rc != VCT_OK)
        return rc;
    const uint32_t n = s->light_count + 2;
    double *w = calloc(n, sizeof *w);
    cl_float4 *table = calloc(n, sizeof *table);
    uint32_t *index = calloc(n, sizeof *index);
    if (!w || !table || !index)
        rc = vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory for the photon sources", stage);
    uint32_t count = 0;
    for (uint32_t i = 0; rc == VCT_OK && i < s->light_count; ++i) {
        const double p = light_power(&s->lights[i], out->bounds.s[3]);
        if (p > 0.0) {
            w[count] = p;
            index[count++] = i;
        }
    }
    if (rc == VCT_OK && out->emitters.count > 0 && out->emitters.power > 0.0) {
        w[count] = out->emitters.power * 2.0 * PI; /* two-sided, cosine: pi per side */
        index[count++] = 0xffffffffu;
    }
    const double sky = (double)s->ambient[0] + s->ambient[1] + s->ambient[2];
    if (rc == VCT_OK && sky > 0.0) {
        /* radiance from every direction through the disk: L 4 pi (pi R^2) */
        w[count] = sky * 4.0 * PI * PI * (double)out->bounds.s[3] * out->bounds.s[3];
        index[count++] = 0xfffffffeu;
    }
    for (int k = 0; k < 3; ++k)
        out->ambient.s[k] = s->ambient[k];
    if (rc == VCT_OK && count == 0)
        rc = vct_fail(err, VCT_ERR_INPUT,
                      "%s: the scene has no lights, nothing emits and it has no sky, so no "
                      "photons can be shot: add a light (--point-light, --dir-light, --ambient) "
                      "or an emissive material",
                      stage);
    double total = 0.0;
    for (uint32_t i = 0; i < count; ++i)
        total += w[i];
    double run = 0.0;
    for (uint32_t i = 0; rc == VCT_OK && i < count; ++i) {
        run += w[i];
        table[i].s[0] = i + 1 == count ? 1.0f : (float)(run / total);
        table[i].s[1] = (float)(total / w[i]);
        memcpy(&table[i].s[2], &index[i], 4);
    }
    out->power = total;
    out->count = count;
    if (rc == VCT_OK) {
        out->table = vct_buffer_create(ctx, stage, "photon sources", sizeof(cl_float4) * count,
                                       CL_MEM_READ_ONLY, table, err);
        rc = out->table ? VCT_OK : (int)err->status;
    }
    free(w);
    free(table);
    free(index);
    if (rc != VCT_OK)
        vct_photon_sources_release(ctx, out);
    return rc;
}

void vct_photon_sources_release(vct_context *ctx, vct_photon_sources *src) {
    vct_buffer_release(ctx, src->table);
    src->table = NULL;
    vct_emitters_release(ctx, &src->emitters);
}
