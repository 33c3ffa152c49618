/* A pixel's paths in vector lanes, where rays go in packets (VCT_PACKETS,
 * CPU devices): PACKET_RAYS samples go through their vertices together,
 * one float16 lane each. At each vertex every path arrives and gets its
 * next-event estimate by itself (render/pt_path.h); the paths at surfaces
 * that only reflect diffusely then take their BSDF sample, Russian
 * roulette and next ray in the lanes at once, the others one by one with
 * pt_leave. The lanes repeat pt_leave's operations in its order and each
 * path draws from its own random stream in its own order, so every path is
 * the one pt_walk traces, bit for bit. The first surfaces' shadow rays and
 * the first bounce's rays (all from one spot of the scene) go as packets,
 * the later ones one by one (as packets they ran no faster). */
#ifndef VCT_PT_LANES_H
#define VCT_PT_LANES_H

/* Shared headers outside the branch: the host's include expansion takes
 * each file once, wherever it first appears. */
#include "accel/accel.h"
#include "light/direct_light.h"
#include "render/pt_path.h"
#include "scene/bsdf.h"
#include "scene/camera.h"
#include "scene/rng.h"

#ifdef VCT_PACKETS

/* The group's paths by component, one lane each; going: -1 where the path
 * goes on, 0 where it has ended (or the lane holds none). */
typedef struct pt_lanes {
    float tr[PACKET_RAYS], tg[PACKET_RAYS], tb[PACKET_RAYS]; /* throughput */
    float lr[PACKET_RAYS], lg[PACKET_RAYS], lb[PACKET_RAYS]; /* radiance */
    float er[PACKET_RAYS], eg[PACKET_RAYS], eb[PACKET_RAYS]; /* its direct part */
    float ox[PACKET_RAYS], oy[PACKET_RAYS], oz[PACKET_RAYS]; /* the next ray */
    float dx[PACKET_RAYS], dy[PACKET_RAYS], dz[PACKET_RAYS];
    float px[PACKET_RAYS], py[PACKET_RAYS], pz[PACKET_RAYS]; /* the last vertex */
    float prev_pdf[PACKET_RAYS];
    uint rng[PACKET_RAYS];
    int going[PACKET_RAYS];
} pt_lanes;

/* The diffuse surfaces of one vertex: point, normal (towards the arriving
 * ray), diffuse colour (the albedo, textured) and material; lambert: -1 in
 * their lanes. */
typedef struct pt_diffuse {
    float px[PACKET_RAYS], py[PACKET_RAYS], pz[PACKET_RAYS];
    float nx[PACKET_RAYS], ny[PACKET_RAYS], nz[PACKET_RAYS];
    float ar[PACKET_RAYS], ag[PACKET_RAYS], ab[PACKET_RAYS];
    uint material[PACKET_RAYS];
    int lambert[PACKET_RAYS];
} pt_diffuse;

inline pt_path pt_lane_get(const pt_lanes *l, uint k) {
    pt_path q;
    q.throughput = (float3)(l->tr[k], l->tg[k], l->tb[k]);
    q.radiance = (float3)(l->lr[k], l->lg[k], l->lb[k]);
    q.direct = (float3)(l->er[k], l->eg[k], l->eb[k]);
    q.org = (float3)(l->ox[k], l->oy[k], l->oz[k]);
    q.dir = (float3)(l->dx[k], l->dy[k], l->dz[k]);
    q.prev_p = (float3)(l->px[k], l->py[k], l->pz[k]);
    q.prev_pdf = l->prev_pdf[k];
    q.rng = l->rng[k];
    return q;
}

inline void pt_lane_set(pt_lanes *l, uint k, const pt_path *q) {
    l->tr[k] = q->throughput.x;
    l->tg[k] = q->throughput.y;
    l->tb[k] = q->throughput.z;
    l->lr[k] = q->radiance.x;
    l->lg[k] = q->radiance.y;
    l->lb[k] = q->radiance.z;
    l->er[k] = q->direct.x;
    l->eg[k] = q->direct.y;
    l->eb[k] = q->direct.z;
    l->ox[k] = q->org.x;
    l->oy[k] = q->org.y;
    l->oz[k] = q->org.z;
    l->dx[k] = q->dir.x;
    l->dy[k] = q->dir.y;
    l->dz[k] = q->dir.z;
    l->px[k] = q->prev_p.x;
    l->py[k] = q->prev_p.y;
    l->pz[k] = q->prev_p.z;
    l->prev_pdf[k] = q->prev_pdf;
    l->rng[k] = q->rng;
}

/* The radiance (lr, lg, lb) a vertex leaves the lanes in mask with; at the
 * first vertex it is their direct part too (pt_arrive, pt_nee). The other
 * lanes keep theirs. */
inline void pt_lanes_radiance(pt_lanes *l, uint depth, int16 mask, float16 lr, float16 lg,
                              float16 lb) {
    vstore16(select(vload16(0, l->lr), lr, mask), 0, l->lr);
    vstore16(select(vload16(0, l->lg), lg, mask), 0, l->lg);
    vstore16(select(vload16(0, l->lb), lb, mask), 0, l->lb);
    if (depth == 0u) {
        vstore16(select(vload16(0, l->er), lr, mask), 0, l->er);
        vstore16(select(vload16(0, l->eg), lg, mask), 0, l->eg);
        vstore16(select(vload16(0, l->eb), lb, mask), 0, l->eb);
    }
}

/* A surface the lanes shade: it emits nothing and its BSDF sample is pure
 * Lambert (bsdf_sample_dir's last branch: no glass, no glossy or mirror
 * lobe). Its albedo, textured, is then its diffuse colour. */
inline int pt_lambert_only(const vct_material_desc *m) {
    return !any(m->emission.xyz > 0.0f) && !is_dielectric(m) && !(glossy_probability(m) > 0.0f);
}

/* Vertex `depth` of every going path, met by hits[k] (found[k]): paths
 * that met nothing take the sky, in the lanes; diffuse surfaces are left in
 * *d for the lanes; the rest arrive, get their next-event estimate and
 * leave one by one. 1 if any surface is left in *d. */
inline int pt_arrive_lanes(const pt_scene *sc, pt_lanes *l, uint depth, const hit_record *hits,
                           const int *found, pt_diffuse *d) {
    int any_left = 0, any_missed = 0;
    int missed[PACKET_RAYS];
    for (uint k = 0; k < PACKET_RAYS; ++k) {
        d->lambert[k] = missed[k] = 0;
        if (!l->going[k])
            continue;
        if (!found[k]) {
            missed[k] = -1;
            any_missed = 1;
            l->going[k] = 0;
            continue;
        }
        const float3 dir = (float3)(l->dx[k], l->dy[k], l->dz[k]);
        float3 p, ng, n;
        int front;
        if (!surface_hit(&sc->g, &hits[k], dir, &p, &ng, &n, &front)) {
            l->going[k] = 0;
            continue;
        }
        const uint mi = sc->tri_material[hits[k].tri];
        vct_material_desc m = sc->materials[mi];
        m.albedo.xyz = texture_albedo(&sc->tv, &m, hits[k].tri, hits[k].u, hits[k].v);
        if (depth != sc->max_depth && pt_lambert_only(&m)) {
            d->px[k] = p.x;
            d->py[k] = p.y;
            d->pz[k] = p.z;
            d->nx[k] = n.x;
            d->ny[k] = n.y;
            d->nz[k] = n.z;
            const float3 a = diffuse_color(&m);
            d->ar[k] = a.x;
            d->ag[k] = a.y;
            d->ab[k] = a.z;
            d->material[k] = mi;
            d->lambert[k] = -1;
            any_left = 1;
            continue;
        }
        pt_path q = pt_lane_get(l, k);
        pt_vertex v;
        int on = pt_arrive(sc, &q, depth, &hits[k], 1, &v);
        if (on) {
            pt_nee(sc, &q, depth, &v);
            on = pt_leave(sc, &q, depth, &v);
        }
        pt_lane_set(l, k, &q);
        l->going[k] = on ? -1 : 0;
    }
    if (any_missed) /* pt_arrive's sky */
        pt_lanes_radiance(l, depth, vload16(0, missed),
                          vload16(0, l->lr) + vload16(0, l->tr) * sc->ambient.x,
                          vload16(0, l->lg) + vload16(0, l->tg) * sc->ambient.y,
                          vload16(0, l->lb) + vload16(0, l->tb) * sc->ambient.z);
    return any_left;
}

/* pt_nee for the diffuse surfaces in *d, in the lanes: each punctual
 * light's direction, distance and Lambert term at once, the shadow rays
 * (and the points of lights with a radius) one by one, then one emitter
 * sample each. */
inline void pt_nee_lambert(const pt_scene *sc, pt_lanes *l, uint depth, const pt_diffuse *d) {
    const int16 mine = vload16(0, d->lambert);
    const float16 px = vload16(0, d->px), py = vload16(0, d->py), pz = vload16(0, d->pz);
    const float16 nx = vload16(0, d->nx), ny = vload16(0, d->ny), nz = vload16(0, d->nz);
    const float16 ar = vload16(0, d->ar), ag = vload16(0, d->ag), ab = vload16(0, d->ab);
    float16 sr = 0.0f, sg = 0.0f, sb = 0.0f;
    for (uint i = 0; i < sc->light_count; ++i) {
        float16 wx, wy, wz, dist, rr, rg, rb;
        int16 lit =
            light_incident16(sc->lights, i, px, py, pz, &wx, &wy, &wz, &dist, &rr, &rg, &rb) & mine;
        /* bsdf_eval's Lambert term: dot(n, wi) as the library adds it, a
         * statement a step so that nothing is fused */
        const float16 cx = nx * wx, cy = ny * wy, cz = nz * wz;
        const float16 cxy = cx + cy;
        const float16 cos_i = cxy + cz;
        const float16 lambert = select(cos_i / BSDF_PI, (float16)(0.0f), cos_i <= 0.0f);
        const float16 fr = ar * lambert, fg = ag * lambert, fb = ab * lambert;
        lit &= (fr != 0.0f || fg != 0.0f || fb != 0.0f) && (rr != 0.0f || rg != 0.0f || rb != 0.0f);
        if (!any(lit))
            continue;
        int seen[PACKET_RAYS];
        float wxs[PACKET_RAYS], wys[PACKET_RAYS], wzs[PACKET_RAYS], dists[PACKET_RAYS];
        int lits[PACKET_RAYS];
        vstore16(lit, 0, lits);
        vstore16(wx, 0, wxs);
        vstore16(wy, 0, wys);
        vstore16(wz, 0, wzs);
        vstore16(dist, 0, dists);
        const int soft = light_is_soft(sc->lights, i);
        /* The first surfaces' shadow rays, from one spot of the scene
         * towards one light, as one packet; later ones one by one. */
        ray_packet rays;
        rays.count = 0u;
        uint lane_of[PACKET_RAYS];
        for (uint k = 0; k < PACKET_RAYS; ++k) {
            seen[k] = 0;
            if (!lits[k])
                continue;
            const float3 p = (float3)(d->px[k], d->py[k], d->pz[k]),
                         n = (float3)(d->nx[k], d->ny[k], d->nz[k]);
            float3 towards = (float3)(wxs[k], wys[k], wzs[k]);
            float reach = dists[k];
            if (soft) {
                const float u1 = rng_next(&l->rng[k]), u2 = rng_next(&l->rng[k]);
                towards = light_extent_sample(sc->lights, i, towards, reach, u1, u2, &reach);
            }
            const float eps = surface_epsilon(&sc->g, p);
            if (depth == 0u) {
                lane_of[rays.count] = k;
                packet_set(&rays, rays.count++, p + n * eps, towards, 0.0f,
                           light_reach(reach, eps));
            } else {
                seen[k] = light_visible(&sc->g, p, n, eps, towards, reach) ? -1 : 0;
            }
        }
        if (rays.count > 0u) {
            hit_record blocker[PACKET_RAYS];
            int blocked[PACKET_RAYS];
            accel_trace_packet(&sc->g, &rays, 1, blocker, blocked);
            for (uint j = 0; j < rays.count; ++j)
                seen[lane_of[j]] = blocked[j] ? 0 : -1;
        }
        const int16 visible = vload16(0, seen);
        sr = select(sr, sr + rr * fr, visible);
        sg = select(sg, sg + rg * fg, visible);
        sb = select(sb, sb + rb * fb, visible);
    }
    const float16 tr = vload16(0, l->tr), tg = vload16(0, l->tg), tb = vload16(0, l->tb);
    float16 lr = vload16(0, l->lr) + tr * sr, lg = vload16(0, l->lg) + tg * sg,
            lb = vload16(0, l->lb) + tb * sb;
    if (sc->em.view.count > 0) { /* nee_emitters, one by one */
        float er[PACKET_RAYS], eg[PACKET_RAYS], eb[PACKET_RAYS];
        for (uint k = 0; k < PACKET_RAYS; ++k) {
            er[k] = eg[k] = eb[k] = 0.0f;
            if (!d->lambert[k])
                continue;
            vct_material_desc m = sc->materials[d->material[k]];
            m.albedo.xyz = (float3)(d->ar[k], d->ag[k], d->ab[k]); /* as textured */
            const float3 n = (float3)(d->nx[k], d->ny[k], d->nz[k]);
            const float3 e = nee_emitters(&sc->g, &sc->em, sc->materials, sc->tri_material, &m,
                                          (float3)(d->px[k], d->py[k], d->pz[k]), n,
                                          -(float3)(l->dx[k], l->dy[k], l->dz[k]), 1, &l->rng[k]);
            er[k] = e.x;
            eg[k] = e.y;
            eb[k] = e.z;
        }
        lr = lr + tr * vload16(0, er);
        lg = lg + tg * vload16(0, eg);
        lb = lb + tb * vload16(0, eb);
    } else { /* what pt_nee adds: nee_emitters' zero */
        lr = lr + tr * 0.0f;
        lg = lg + tg * 0.0f;
        lb = lb + tb * 0.0f;
    }
    pt_lanes_radiance(l, depth, mine, lr, lg, lb);
}

/* pt_leave for the diffuse surfaces in *d, in the lanes at once. */
inline void pt_leave_lambert(const pt_scene *sc, pt_lanes *l, uint depth, const pt_diffuse *d) {
    const int16 mine = vload16(0, d->lambert);
    int16 on = mine;
    if (!pt_samples_on(sc, depth))
        on = (int16)(0);
    uint16 rng = vload16(0, l->rng);
    rng_next16(&rng); /* u0: one lobe, nothing to choose */
    const float16 u1 = rng_next16(&rng), u2 = rng_next16(&rng);
    const float16 px = vload16(0, d->px), py = vload16(0, d->py), pz = vload16(0, d->pz);
    const float16 nx = vload16(0, d->nx), ny = vload16(0, d->ny), nz = vload16(0, d->nz);
    float16 wx, wy, wz;
    const float16 pdf = bsdf_lambert16(nx, ny, nz, u1, u2, &wx, &wy, &wz);
    on &= pdf > 0.0f;
    float16 tr = vload16(0, l->tr) * vload16(0, d->ar), tg = vload16(0, l->tg) * vload16(0, d->ag),
            tb = vload16(0, l->tb) * vload16(0, d->ab);
    const float16 eps = surface_epsilon16(&sc->g, px, py, pz);
    /* dot(wi, n) as the library adds it: no fused steps */
    const float16 wnx = wx * nx, wny = wy * ny, wnz = wz * nz;
    const float16 wn_xy = wnx + wny;
    const int16 up = wn_xy + wnz > 0.0f;
    const float16 ox = px + select(-nx, nx, up) * eps, oy = py + select(-ny, ny, up) * eps,
                  oz = pz + select(-nz, nz, up) * eps;
    if (depth + 1 >= RR_DEPTH) {
        const float16 keep = fmin(fmax(tr, fmax(tg, tb)), 0.95f);
        on &= rng_next16(&rng) < keep;
        tr /= keep;
        tg /= keep;
        tb /= keep;
    }
    /* Lanes left out keep what they hold. */
#define PT_LANE_STORE(value, field) vstore16(select(vload16(0, l->field), value, mine), 0, l->field)
    PT_LANE_STORE(tr, tr);
    PT_LANE_STORE(tg, tg);
    PT_LANE_STORE(tb, tb);
    PT_LANE_STORE(pdf, prev_pdf);
    PT_LANE_STORE(px, px);
    PT_LANE_STORE(py, py);
    PT_LANE_STORE(pz, pz);
    PT_LANE_STORE(ox, ox);
    PT_LANE_STORE(oy, oy);
    PT_LANE_STORE(oz, oz);
    PT_LANE_STORE(wx, dx);
    PT_LANE_STORE(wy, dy);
    PT_LANE_STORE(wz, dz);
    PT_LANE_STORE(rng, rng);
    PT_LANE_STORE(on, going);
#undef PT_LANE_STORE
}

/* The next hits of the going paths: the first bounce's rays (all from one
 * spot of the scene) as one packet, later ones one by one. 0 when no path
 * goes on. */
inline int pt_trace_lanes(const pt_scene *sc, const pt_lanes *l, uint depth, hit_record *hits,
                          int *found) {
    if (depth == 0u) {
        ray_packet rays;
        rays.count = 0u;
        uint lane_of[PACKET_RAYS];
        for (uint k = 0; k < PACKET_RAYS; ++k)
            if (l->going[k]) {
                lane_of[rays.count] = k;
                packet_set(&rays, rays.count++, (float3)(l->ox[k], l->oy[k], l->oz[k]),
                           (float3)(l->dx[k], l->dy[k], l->dz[k]), 0.0f, INFINITY);
            }
        hit_record met[PACKET_RAYS];
        int met_found[PACKET_RAYS];
        accel_trace_packet(&sc->g, &rays, 0, met, met_found);
        for (uint j = 0; j < rays.count; ++j) {
            hits[lane_of[j]] = met[j];
            found[lane_of[j]] = met_found[j];
        }
        return rays.count > 0u;
    }
    int any_going = 0;
    for (uint k = 0; k < PACKET_RAYS; ++k)
        if (l->going[k]) {
            any_going = 1;
            found[k] =
                accel_trace(&sc->g, (float3)(l->ox[k], l->oy[k], l->oz[k]),
                            (float3)(l->dx[k], l->dy[k], l->dz[k]), 0.0f, INFINITY, 0, &hits[k]);
        }
    return any_going;
}

/* Samples first .. first + n - 1 of pixel (x, y): each one's radiance and
 * its direct part. */
inline void pt_group_lanes(const pt_scene *sc, const vct_camera_desc *cam, uint x, uint y,
                           uint seed, uint first, uint n, float3 *radiance, float3 *direct) {
    pt_lanes l;
    /* pt_camera_rays in the lanes: streams, jitter and directions */
    const uint16 lane =
        (uint16)(0u, 1u, 2u, 3u, 4u, 5u, 6u, 7u, 8u, 9u, 10u, 11u, 12u, 13u, 14u, 15u);
    uint16 rng = rng_start16(seed, camera_pixel_id(cam, x, y), first + lane);
    const float16 jx = rng_next16(&rng), jy = rng_next16(&rng);
    float16 dx, dy, dz;
    camera_ray_dir16(cam, (float)x + jx, (float)camera_row(cam, y) + jy, &dx, &dy, &dz);
    vstore16(rng, 0, l.rng);
    vstore16(dx, 0, l.dx);
    vstore16(dy, 0, l.dy);
    vstore16(dz, 0, l.dz);
    const float16 one = 1.0f, zero = 0.0f;
    const float16 cx = cam->position.x, cy = cam->position.y, cz = cam->position.z;
    vstore16(one, 0, l.tr);
    vstore16(one, 0, l.tg);
    vstore16(one, 0, l.tb);
    vstore16(zero, 0, l.lr);
    vstore16(zero, 0, l.lg);
    vstore16(zero, 0, l.lb);
    vstore16(zero, 0, l.er);
    vstore16(zero, 0, l.eg);
    vstore16(zero, 0, l.eb);
    vstore16(cx, 0, l.ox);
    vstore16(cy, 0, l.oy);
    vstore16(cz, 0, l.oz);
    vstore16(cx, 0, l.px);
    vstore16(cy, 0, l.py);
    vstore16(cz, 0, l.pz);
    vstore16(zero, 0, l.prev_pdf); /* 0: camera ray or delta bounce, emission counts fully */
    vstore16(as_int16(lane < n), 0, l.going);
    ray_packet rays;
    rays.count = n;
    for (uint k = 0; k < n; ++k)
        packet_set(&rays, k, cam->position.xyz, (float3)(l.dx[k], l.dy[k], l.dz[k]), 0.0f,
                   INFINITY);
    hit_record hits[PACKET_RAYS];
    int found[PACKET_RAYS];
    accel_trace_packet(&sc->g, &rays, 0, hits, found);
    for (uint depth = 0u;; ++depth) {
        pt_diffuse d;
        if (pt_arrive_lanes(sc, &l, depth, hits, found, &d)) {
            pt_nee_lambert(sc, &l, depth, &d);
            pt_leave_lambert(sc, &l, depth, &d);
        }
        if (!pt_trace_lanes(sc, &l, depth, hits, found))
            break;
    }
    for (uint k = 0; k < n; ++k) {
        radiance[k] = (float3)(l.lr[k], l.lg[k], l.lb[k]);
        direct[k] = (float3)(l.er[k], l.eg[k], l.eb[k]);
    }
}

#endif
#endif
