/* Caustics for cone tracing: light through dielectrics onto the surfaces the
 * camera sees, from photons (kernels/render/vct_render.cl, vct_caustics). */
#ifndef VCT_VCT_CAUSTICS_H
#define VCT_VCT_CAUSTICS_H

#include "accel/accel.h"
#include "scene/scene_device.h"

/* Photon paths traced: a pilot pass that sets the pixels' radii, then
 * VCT_CAUSTIC_PASSES passes, each gathered before the next reuses the slots. */
#define VCT_CAUSTIC_PATHS 65536u
#define VCT_CAUSTIC_PASSES 4u
/* Bounces a photon path follows: enough for a sphere's two surfaces and a
 * reflection inside, or a slab's. */
#define VCT_CAUSTIC_DEPTH 6u
/* The base gather radius, as a share of the scene's extent (photon
 * mapping's default caustic radius); sparse photons widen it. */
#define VCT_CAUSTIC_RADIUS 0.0075f

/* Adds the caustics at the G-buffer's surfaces (`size` pixels, cone
 * tracing's layout) to image and, when given, the direct AOV. program: the
 * frame's vct_render.cl. */
int vct_caustics_add(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                     const vct_scene_buffers *sb, cl_program program, cl_mem gbuf, cl_mem image,
                     cl_mem aov, const cl_uint size[2], vct_error *err);

#endif
