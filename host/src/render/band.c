/* Bands of an image (vct/partial.h): what a band renders beyond its own
 * rows so that they equal the whole image's. */
#include "vct/partial.h"

#include "conetrace/vct_indirect_filter.h"

/* Subsampling refines squares of N rows whose corners lie on the next
 * square's first row, and a row of corners is an edge of the squares above
 * and below it: the finer of the two writes it last. A band therefore also
 * renders the square above it and the corner row below it. Sparse cone
 * tracing fills odd rows from the even row below. Cone tracing finds edges
 * by comparing a pixel with the two rows above and below it. */
void vct_band_shape(const vct_render_job *job, int *align, int *above, int *below) {
    uint32_t subsample = 0;
    if (job->method == VCT_METHOD_WHITTED)
        subsample = job->whitted.subsample;
    else if (job->method == VCT_METHOD_RAYCAST)
        subsample = job->raycast.subsample;
    *align = 1, *above = 0, *below = 0;
    if (subsample > 1)
        *align = (int)subsample, *above = (int)subsample, *below = 1;
    else if (job->method == VCT_METHOD_VCT && job->vct.sparse_diffuse)
        *align = 2, *below = 2;
    if (job->method == VCT_METHOD_VCT && job->vct.edge_samples != 1) {
        /* the edge search reads the centres within two rows (a multiple of
         * the alignment, which keeps the sparse rows' parity); the sparse
         * fill reads a second surface's cells within three rows, whose
         * refined surfaces read the centres two rows further */
        const int reach = job->vct.sparse_diffuse ? 6 : 2;
        *above = *above > reach ? *above : reach;
        *below = *below > reach ? *below : reach;
    }
    if (job->method == VCT_METHOD_VCT && job->vct.indirect_passes) {
        /* the indirect light's filter reads rows that must themselves be
         * whole: beyond those the rows above need, rounded to keep parity */
        const int whole = *above > *below ? *above : *below;
        const int reach = whole + vct_indirect_filter_reach(job->vct.indirect_passes);
        *above = *below = (reach + 1) / 2 * 2;
    }
}
