/* vct: OpenCL global illumination engine — public C API.
 *
 * Shape: an opaque context (one OpenCL device, queue, program cache and stage
 * statistics), a host scene of flat arrays, and stages that take both. Every
 * call reports failure through a vct_error the caller owns; there is no global
 * state. This header includes every topic's header:
 *
 *   vct/version.h   library and kernel-interface versions
 *   vct/error.h     status codes and vct_error
 *   vct/device.h    devices, contexts, statistics
 *   vct/opencl.h    contexts on the caller's cl_context and queue
 *   vct/scene.h     the host scene
 *   vct/parallel.h  scan, compaction, sort, segmented reduction
 *   vct/accel.h     the triangle grid and ray queries
 *   vct/voxels.h    voxels, octree, bricks, light injection, cones
 *   vct/render.h    renderers, the effect plan, the frame, OpenGL display
 *   vct/device_scene.h  a scene committed to a context: upload once, render many times
 *   vct/image.h     images, files, error metrics
 *   vct/denoise.h   the denoiser
 *   vct/multi.h     one frame on several devices */
#ifndef VCT_VCT_H
#define VCT_VCT_H

#include "vct/version.h"
#include "vct/error.h"
#include "vct/device.h"
#include "vct/opencl.h"
#include "vct/scene.h"
#include "vct/parallel.h"
#include "vct/accel.h"
#include "vct/voxels.h"
#include "vct/render.h"
#include "vct/device_scene.h"
#include "vct/image.h"
#include "vct/denoise.h"
#include "vct/multi.h"
#include "vct/partial.h"

#endif
