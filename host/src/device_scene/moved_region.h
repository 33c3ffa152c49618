/* Where a scene moved since its voxels were built: the world boxes of the
 * instances whose vertices changed, before and after, for light carried
 * over into new voxels (vct_voxel_carry). */
#ifndef VCT_MOVED_REGION_H
#define VCT_MOVED_REGION_H

#include "runtime/runtime.h"
#include "voxel/voxels.h"

typedef struct vct_moved_region {
    uint32_t instance_count;
    uint64_t *hash; /* per instance: a digest of its world vertices */
    float *box;     /* per instance: its world box, lo then hi */
    int everything; /* something moved that no box holds (or out of memory) */
    uint32_t box_count;
    float boxes[VCT_CARRY_BOXES][6];
    uint32_t tri_lo, tri_hi; /* the moved instances' triangles lie in tri_lo .. tri_hi - 1 */
} vct_moved_region;

/* Records s's instances as they are, nothing moved yet. */
void vct_moved_region_init(vct_moved_region *r, const vct_scene *s);
/* A commit found `changed` (VCT_CHANGED_*): adds the boxes of the instances
 * that moved, or marks everything where the change is not one of places. */
void vct_moved_region_note(vct_moved_region *r, const vct_scene *s, unsigned changed);
/* The voxels were built: nothing has moved since. */
void vct_moved_region_clear(vct_moved_region *r);
/* carry's boxes (the moved ones, or one that holds everything) and its
 * range of moved triangles (none where everything moved). */
void vct_moved_region_boxes(const vct_moved_region *r, vct_voxel_carry *carry);
void vct_moved_region_release(vct_moved_region *r);

#endif
