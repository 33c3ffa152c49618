/* Where photons come from: every light, the emissive triangles and the
 * environment (the scene's ambient radiance), picked in proportion to the
 * power they send (kernels/photon/photon_trace.cl). */
#ifndef VCT_PHOTON_SOURCES_H
#define VCT_PHOTON_SOURCES_H

#include "light/emitters.h"
#include "runtime/runtime.h"

typedef struct vct_photon_sources {
    cl_mem table;          /* float4 per source: cumulative pick, 1 / pick, index bits */
    cl_uint count;         /* lights that send power, plus 1 when something emits */
    vct_emitters emitters; /* picked by power */
    cl_float4 bounds;      /* the scene's bounding sphere, for directional lights */
    cl_float4 ambient;     /* the environment's radiance */
    double power;          /* total emitted power (sum over channels), W */
} vct_photon_sources;

/* Fails with a message when nothing in the scene sends light. */
int vct_photon_sources_make(vct_context *ctx, const vct_scene *s, const char *stage,
                            vct_photon_sources *out, vct_error *err);
void vct_photon_sources_release(vct_context *ctx, vct_photon_sources *src);

#endif
