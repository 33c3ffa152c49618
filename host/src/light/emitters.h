/* Emissive triangles as lights (kernels/light/emitters.h): the table of
 * emitters with the CDF they are picked by, for the path tracer's
 * next-event estimation and the direct light of the other methods. */
#ifndef VCT_EMITTERS_HOST_H
#define VCT_EMITTERS_HOST_H

#include "runtime/runtime.h"
#include "scene/scene_resident.h"

/* Emitter samples per shading point for the direct-light methods (ray
 * casting, cone tracing's primary hit) and per voxel fragment for light
 * injection. */
#define VCT_EMITTER_SAMPLES 16u
#define VCT_EMITTER_INJECT_SAMPLES 8u

/* How an emitter is picked: by its area (the path tracer, whose MIS then
 * needs one density, 1 / total area), or by its power, area times the sum
 * of its emitted radiance (direct light: bright lamps get the samples). */
typedef enum vct_emitter_weight { VCT_EMITTERS_BY_AREA, VCT_EMITTERS_BY_POWER } vct_emitter_weight;

typedef struct vct_emitters {
    cl_mem tris;  /* emissive triangles of positive area */
    cl_mem cdf;   /* cumulative weight, normalised, the last exactly 1 */
    cl_mem scale; /* per emitter: its area over its pick probability */
    cl_uint count;
    float inv_area; /* 1 / total emissive area */
    double area, power;
    int borrowed; /* 1: a committed scene's (scene/scene_resident.h); release leaves it */
} vct_emitters;

/* Builds the table (count 0 when nothing emits: the buffers then hold one
 * unused element, so that kernels can take them), or borrows a committed
 * scene's, built at its first use. */
int vct_emitters_build(vct_context *ctx, const vct_scene *s, vct_emitter_weight weight,
                       const char *stage, vct_emitters *e, vct_error *err);
/* The emitter table's five kernel arguments from `first` (tris, cdf, scale,
 * count, samples). */
int vct_emitters_set_args(cl_kernel k, int first, const vct_emitters *e, cl_uint samples,
                          const char *stage, vct_error *err);
void vct_emitters_release(vct_context *ctx, vct_emitters *e);
/* Releases a committed scene's tables (at a change that affects them). */
void vct_emitters_release_resident(vct_context *ctx, vct_resident *r);
/* How many triangles of s emit (of positive area or not). */
uint32_t vct_scene_emissive_triangles(const vct_scene *s);

#endif
