/* Parts of one render, for hosts that spread a frame over processes or
 * machines (vct render under mpirun does): a band of rows, or a range of
 * the path tracer's samples. Put back together as below, the parts give the
 * image one call would, bit for bit.
 *
 * Bands: every method but the path tracer takes a vct_band (vct/render.h).
 * A band renders more rows than its own where its pixels depend on their
 * neighbours; vct_band_shape says how many. Photon mapping's bands must
 * agree on their gather radii pass by pass: give each band a pass_sync that
 * takes the largest over all bands (vct_band.pass_sync).
 *
 * Samples: the path tracer sums its samples exactly (fixed point, 128 bits
 * per value), so sums of disjoint sample ranges added in any order equal
 * the sums of their union. Render ranges with
 * vct_device_scene_render_samples, add them with vct_sample_sums_add, and
 * turn the total into the image with vct_device_scene_resolve_samples. */
#ifndef VCT_API_PARTIAL_H
#define VCT_API_PARTIAL_H

#include <stddef.h>
#include <stdint.h>

#include "vct/device_scene.h"
#include "vct/export.h"
#include "vct/render.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Rows a band of `job` must align to and render beyond its own so that its
 * pixels equal the whole image's: its own rows start and end on multiples
 * of *align (or end at the image's end); it renders *above rows above them
 * and *below rows below them (within the image), and keeps only its own.
 * With *below 1 and *align above 1 the image's last row, when it is a
 * multiple of *align, belongs to the band above it and is never a band
 * alone. A band whose rendered rows start off the alignment is refused. */
VCT_API void vct_band_shape(const vct_render_job *job, int *align, int *above, int *below);

/* The path tracer's exact per-pixel sums of a range of samples. */
typedef struct vct_sample_sums {
    int width, height;
    uint32_t samples;   /* samples per pixel summed (of every range added) */
    uint32_t discarded; /* samples dropped because they were not finite */
    /* VCT_SAMPLE_SUM_BYTES per pixel, rows top to bottom: 10 values (red,
     * green, blue, samples kept, squared luminance; the direct part's red,
     * green, blue and squared luminance; the indirect part's squared
     * luminance), each a 128-bit two's complement integer as two uint64
     * words, high word first. */
    uint64_t *data;
} vct_sample_sums;
#define VCT_SAMPLE_SUM_BYTES 160

/* data's size in bytes for a width x height image. */
VCT_API size_t vct_sample_sums_bytes(int width, int height);
/* Renders samples [first, first + count) of the job's path tracer
 * (job->method VCT_METHOD_PATHTRACE; its spp and resume are not read) into
 * *sums, allocated here. The device scene's own running sums start over. */
VCT_API vct_status vct_device_scene_render_samples(vct_device_scene *ds, const vct_render_job *job,
                                                   uint32_t first, uint32_t count,
                                                   vct_sample_sums *sums, vct_error *err);
/* into += add: both of one image size. Exact: any order gives the same. */
VCT_API vct_status vct_sample_sums_add(vct_sample_sums *into, const vct_sample_sums *add,
                                       vct_error *err);
/* The words of `add` added into `into`, `pairs` 128-bit values each: the
 * same addition for a host that moves sums as raw memory (an MPI reduction
 * operator, for one). */
VCT_API void vct_sample_sums_add_words(uint64_t *into, const uint64_t *add, size_t pairs);
/* The image of `sums` as the job's path tracer would deliver it (with its
 * variance when job->pathtrace.variance is set). */
VCT_API vct_status vct_device_scene_resolve_samples(vct_device_scene *ds, const vct_render_job *job,
                                                    const vct_sample_sums *sums, vct_image *image,
                                                    vct_error *err);
VCT_API void vct_sample_sums_release(vct_sample_sums *sums);

#ifdef __cplusplus
}
#endif

#endif
