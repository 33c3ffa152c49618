/* One path of the path tracer, vertex by vertex: where it arrives (the sky,
 * or a surface and what that surface emits), next-event estimation there,
 * and where it leaves to (the BSDF's sample, then Russian roulette after
 * RR_DEPTH bounces). pathtrace.cl walks paths with these; render/pt_lanes.h
 * takes a pixel's paths in vector lanes and falls back on them for the
 * surfaces its lanes do not shade. */
#ifndef VCT_PT_PATH_H
#define VCT_PT_PATH_H

#include "accel/accel.h"
#include "light/nee.h"
#include "scene/bsdf.h"
#include "scene/camera.h"
#include "scene/rng.h"
#include "scene/texture.h"
#include "vct_types.h"

#define RR_DEPTH 3

/* The camera rays of samples first .. first + n - 1 (n <= ACCEL_GROUP) of
 * pixel (x, y), traced together (a packet on CPU devices): each sample's
 * random stream after its jitter, its direction and what it hits. */
inline void pt_camera_rays(const accel_view *g, const vct_camera_desc *cam, uint x, uint y,
                           uint seed, uint first, uint n, uint *rng, float3 *dir, hit_record *hit,
                           int *found) {
    for (uint k = 0; k < n; ++k) {
        rng[k] = rng_start(seed, camera_pixel_id(cam, x, y), first + k);
        const float jx = rng_next(&rng[k]), jy = rng_next(&rng[k]);
        dir[k] = camera_ray_dir(cam, (float)x + jx, (float)camera_row(cam, y) + jy);
    }
    accel_trace_from(g, cam->position.xyz, dir, n, hit, found);
}

/* What every path of a launch shares. */
typedef struct pt_scene {
    accel_view g;
    texture_view tv;
    emitters em;
    __global const vct_material_desc *materials;
    __global const uint *tri_material;
    __global const vct_light_desc *lights;
    uint light_count, max_depth;
    float3 ambient;
    int lit_by_rays;
} pt_scene;

/* A path between its vertices. */
typedef struct pt_path {
    float3 throughput, radiance, direct, org, dir, prev_p;
    float prev_pdf;
    uint rng;
} pt_path;

/* The surface a path arrived at: its point, unit geometric normal ng, the
 * normal n turned towards the arriving ray, the direction back along that
 * ray, whether it arrived on ng's side, and its material (the albedo
 * textured). */
typedef struct pt_vertex {
    float3 p, ng, n, wo;
    int front;
    vct_material_desc m;
} pt_vertex;

/* Vertex `depth` of path q, met by h (found): the sky where nothing was
 * met, else the surface in *v and the light it emits (weighted against
 * next-event estimation where that could have found it). 0 where the path
 * ends here: nothing met, a degenerate hit, or the vertex past the last. */
inline int pt_arrive(const pt_scene *sc, pt_path *q, uint depth, const hit_record *h, int found,
                     pt_vertex *v) {
    if (!found) {
        q->radiance += q->throughput * sc->ambient; /* the environment */
        if (depth == 0)
            q->direct = q->radiance;
        return 0;
    }
    if (!surface_hit(&sc->g, h, q->dir, &v->p, &v->ng, &v->n, &v->front))
        return 0;
    v->wo = -q->dir;
    v->m = sc->materials[sc->tri_material[h->tri]];
    v->m.albedo.xyz = texture_albedo(&sc->tv, &v->m, h->tri, h->u, h->v);
    if (any(v->m.emission.xyz > 0.0f)) {
        float w = 1.0f;
        if (q->prev_pdf > 0.0f && sc->em.view.count > 0) {
            const float3 d = v->p - q->prev_p;
            const float pdf_light = sc->em.inv_area * dot(d, d) / fabs(dot(v->ng, q->dir));
            w = power_heuristic(q->prev_pdf, pdf_light);
        }
        q->radiance += q->throughput * v->m.emission.xyz * w;
        if (depth == 1 && q->prev_pdf > 0.0f) /* the first surface's light, BSDF-sampled */
            q->direct += q->throughput * v->m.emission.xyz * w;
    }
    return depth != sc->max_depth;
}

/* Next-event estimation at v (delta lobes cannot be lit this way); at the
 * first surface, what the path has gathered so far is its direct part. */
inline void pt_nee(const pt_scene *sc, pt_path *q, uint depth, const pt_vertex *v) {
    if (!bsdf_delta_only(&v->m)) {
        q->radiance += q->throughput * nee_punctual(&sc->g, sc->lights, sc->light_count, &v->m,
                                                    v->p, v->n, v->wo, &q->rng);
        q->radiance +=
            q->throughput * nee_emitters(&sc->g, &sc->em, sc->materials, sc->tri_material, &v->m,
                                         v->p, v->n, v->wo, 1, &q->rng);
    }
    if (depth == 0)
        q->direct = q->radiance;
}

/* Whether vertex `depth`'s BSDF sample is worth a ray: the last surface's
 * sample looks for emitters and the sky alone, and where the scene has
 * neither it finds nothing. */
inline int pt_samples_on(const pt_scene *sc, uint depth) {
    return depth + 1 != sc->max_depth || sc->lit_by_rays;
}

/* The BSDF's sample at v and Russian roulette: 1 where the path goes on,
 * its next ray in q->org and q->dir. */
inline int pt_leave(const pt_scene *sc, pt_path *q, uint depth, const pt_vertex *v) {
    if (!pt_samples_on(sc, depth))
        return 0;
    bsdf_sample bs;
    const float u0 = rng_next(&q->rng), u1 = rng_next(&q->rng), u2 = rng_next(&q->rng);
    if (!bsdf_sample_dir(&v->m, v->n, v->wo, v->front, u0, u1, u2, &bs))
        return 0;
    q->throughput *= bs.weight;
    q->prev_pdf = bs.delta ? 0.0f : bs.pdf;
    q->prev_p = v->p;
    /* Leave the surface on the side the new direction points to. */
    const float eps = surface_epsilon(&sc->g, v->p);
    q->org = v->p + (dot(bs.wi, v->n) > 0.0f ? v->n : -v->n) * eps;
    q->dir = bs.wi;
    if (depth + 1 >= RR_DEPTH) {
        const float keep =
            fmin(fmax(q->throughput.x, fmax(q->throughput.y, q->throughput.z)), 0.95f);
        if (!(rng_next(&q->rng) < keep))
            return 0;
        q->throughput /= keep;
    }
    return 1;
}

/* Vertices depth .. last of path q, the first of them met by h (found);
 * 1 where the path goes on past `last` (its next ray in q's org and dir). */
inline int pt_walk(const pt_scene *sc, pt_path *q, uint depth, uint last, hit_record h, int found) {
    for (;; ++depth) {
        pt_vertex v;
        if (!pt_arrive(sc, q, depth, &h, found, &v))
            return 0;
        pt_nee(sc, q, depth, &v);
        if (!pt_leave(sc, q, depth, &v))
            return 0;
        if (depth == last)
            return 1;
        found = accel_trace(&sc->g, q->org, q->dir, 0.0f, INFINITY, 0, &h);
    }
}

#endif
