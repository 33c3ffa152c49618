/* A ray's hit as every traversal reports it. */
#ifndef VCT_HIT_H
#define VCT_HIT_H

typedef struct hit_record {
    float t, u, v; /* distance; barycentrics of the second and third vertex */
    uint tri;      /* the triangle's index in the scene */
} hit_record;

#endif
