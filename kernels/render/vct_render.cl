/* Voxel cone tracing into the image buffer, one kernel per effect so that
 * an effect the plan leaves out enqueues nothing:
 *   vct_primary        camera rays through the acceleration structure, direct light
 *                      exactly as the ray caster computes it, emission, and
 *                      refraction through dielectrics (render/primary_sample.h);
 *                      writes the G-buffer
 *   vct_edge_flags, vct_primary_refine  pixels on an edge (of a surface,
 *                      a material or a shadow) traced again with n x n rays
 *                      each ((2 n)^2 on an edge of high contrast, (4 n)^2 on
 *                      an emitter's border), so that the image is the
 *                      pixel's mean as a converged reference's is, not its
 *                      centre's value
 *   vct_soft_shadows   direct light of the lights with a radius, through one
 *                      cone per light as wide as the light
 *   vct_diffuse_cones  indirect diffuse light and ambient occlusion: rays
 *                      spread over the hemisphere by their cosine, their hits
 *                      shaded exactly and by the voxels' bounced light
 *                      (render/diffuse_rays.h)
 *   vct_diffuse_sparse, vct_diffuse_fill  the same, traced at every other
 *                      pixel per axis (over (w + 1) / 2 x (h + 1) / 2
 *                      work-items) and filled in at every pixel
 *   vct_specular_cone  one cone along the mirror direction
 *   vct_glass_reflection  the Fresnel reflection off the first dielectric
 *                      the camera ray enters, one mirror cone
 *   vct_caustics       light through dielectrics onto surfaces, from photons
 * Effects are chosen with -D: VCT_DIRECT, VCT_SHADOWS, VCT_SOFT_SHADOWS,
 * VCT_EMISSION, VCT_REFRACTION, VCT_SPECULAR, VCT_INDIRECT, VCT_AO,
 * VCT_CAUSTICS (and the pool's VCT_BRICK_IMAGE, VCT_ANISOTROPIC); a pass's
 * kernel is compiled only with its effect (VCT_SPARSE_DIFFUSE picks the
 * sparse diffuse kernels, VCT_CONE_PROBE adds cone_probe). VCT_EMITTERS adds
 * the emissive triangles to the direct light, sampled with shadow rays
 * (light/emitters.h).
 *
 * G-buffer, GBUF_SLOTS float4 per pixel: position and material id (as bits);
 * normal facing the viewer and 1 where a surface was found; direction
 * towards the viewer; the throughput of the refractions on the way; the
 * albedo there, the material's times its texture (scene/texture.h), and
 * until the edges are refined the centre's shading (sample_shade); an edge
 * pixel's second surface (second_surface): its point and share of the
 * pixel's samples, its normal and material id (as bits), its albedo. AOVs, AOV_SLOTS
 * float4 per pixel when given: direct, indirect diffuse, specular, (open
 * fraction, the indirect light's variance, the variance of the direct light
 * from emitter samples, 1), position and normal (w 1 where a
 * surface was found, else the slot stays 0), and the denoiser's albedo and
 * normal-depth guides (guide_write). Glass reflections, 3 float4
 * per pixel, when refraction and specular are both planned: (point,
 * weight.x), (normal, weight.y), (mirror direction, weight.z), the weight 0
 * where there is none. */
#include "scene/bsdf.h"
#include "scene/camera.h"
#include "conetrace/cone_frame.h"
#include "conetrace/cone_trace.h"
#include "light/direct_light.h"
#include "light/emitters.h"
#include "scene/texture.h"
#include "accel/accel.h"
#include "conetrace/cone_hit.h"
#include "render/diffuse_rays.h"
#include "render/primary_sample.h"
#include "photon/photon.h"
#include "vct_types.h"

#define AOV_SLOTS 8u
#define GBUF_SLOTS 8u
/* Shadow cones step an eighth as far as the setting says, 1/8 of the
 * diameter at the default step: a thin occluder then falls between samples
 * less often (measured: no leak into the umbra at 1/8 of the diameter, up
 * to 12% at 1/2). */
#define SOFT_STEP_SCALE 0.125f
/* Neighbours on one surface: normals within about 37 degrees, and each
 * point within 0.25 of their distance from the other's plane. */
#define EDGE_NORMAL_COS 0.8f
#define EDGE_PLANE_SLOPE 0.25f
/* Neighbours whose albedos differ by more than this share of the brighter
 * one's luminance (a texture's detail) hold an edge too. */
#define EDGE_ALBEDO_SHARE 0.1f
/* An edge is of high contrast where the shading on its two sides differs
 * by more than this share of the brighter's: through the N x N rays of
 * other edges, its pixels' error reaches 1/N^2 of that difference. */
#define EDGE_CONTRAST 0.75f
/* The 3x3 centres' shading spanning more than this share of the
 * brightest's is an edge too, on one surface: a curved mesh's flat faces,
 * each lit at its own angle, which a pixel's centre alone shows as steps
 * (a faceted ball under a spot light: 30 % of its image's squared error). */
#define SHADING_STEP 0.15f

#define PRIMARY_ARGS                                                                               \
    ACCEL_ARGS, vct_camera_desc cam, __global const vct_material_desc *materials,                  \
        __global const uint *tri_material, TEXTURE_ARGS, __global const vct_light_desc *lights,    \
        uint light_count, EMITTER_ARGS, float4 ambient, __global float4 *gbuf,                     \
        __global float4 *image, __global float4 *aov, __global float4 *reflection

/* What the diffuse gather's rays shade their hits with (render/diffuse_rays.h),
 * after each diffuse kernel's own arguments: the scene's shading inputs,
 * the voxels' light, all of it and the direct part alone, and the picks'
 * running sum over the leaf voxels with their keys (gather_picks.h). */
#define GATHER_ARGS                                                                                \
    __global const uint *tri_material, TEXTURE_ARGS, __global const vct_light_desc *lights,        \
        uint light_count, EMITTER_ARGS, __global const float4 *voxel_total,                        \
        __global const float4 *voxel_total_side, __global const float4 *voxel_direct,              \
        __global const float4 *voxel_direct_side, __global const uint *pick_cdf,                   \
        __global const uint *voxel_keys, uint pick_count, uint pick_total
#define GATHER_VOXELS()                                                                            \
    ((gather_voxels){voxel_total,                                                                  \
                     voxel_total_side,                                                             \
                     voxel_direct,                                                                 \
                     voxel_direct_side,                                                            \
                     {pick_cdf, voxel_keys, pick_count, pick_total}})

inline float albedo_luminance(float3 a) {
    return dot(a, (float3)(0.2126f, 0.7152f, 0.0722f));
}

/* A camera sample's shading, what edges of high contrast are found by: its
 * radiance less the emitter samples' part (noise, not detail), over its
 * albedo where it found a surface (a texture's detail is no contrast). */
inline float sample_shade(const primary_sample *t) {
    const float l = albedo_luminance(t->radiance - t->sampled);
    return t->found ? l / fmax(albedo_luminance(t->galbedo.xyz), 0.02f) : l;
}

/* A sample's surface into the G-buffer, with the throughput given. */
inline void gbuffer_write(__global float4 *gbuf, uint pixel, const primary_sample *s,
                          float3 throughput) {
    gbuf[GBUF_SLOTS * pixel] = s->gpos;
    gbuf[GBUF_SLOTS * pixel + 1u] = s->gnormal;
    gbuf[GBUF_SLOTS * pixel + 2u] = s->gview;
    gbuf[GBUF_SLOTS * pixel + 3u] = (float4)(throughput, 0.0f);
    gbuf[GBUF_SLOTS * pixel + 4u] = s->galbedo;
    gbuf[GBUF_SLOTS * pixel + 5u] = (float4)(0.0f); /* no second surface */
}

inline void reflection_write(__global float4 *reflection, uint pixel, float4 rpos, float4 rnormal,
                             float4 rdir) {
    reflection[3u * pixel] = rpos;
    reflection[3u * pixel + 1u] = rnormal;
    reflection[3u * pixel + 2u] = rdir;
}

/* The denoiser's guides, as render/guides.cl makes them, from the camera
 * samples the pixel took (AOV slots 6 and 7): the mean albedo (1 where a
 * sample found nothing) and w the share of samples on no emitter; the mean
 * normal facing the viewer (shorter at an edge) and the mean distance of
 * the samples that found a surface, 0 where none did. */
typedef struct guide_sum {
    float3 albedo, normal;
    float depth;
    uint hits, glowing;
} guide_sum;

inline void guide_add(guide_sum *g, const primary_sample *t,
                      __global const vct_material_desc *materials, float3 eye) {
    if (!t->found) {
        g->albedo += 1.0f;
        return;
    }
    g->albedo += t->galbedo.xyz;
    g->glowing += any(materials[as_uint(t->gpos.w)].emission.xyz > 0.0f);
    g->normal += t->gnormal.xyz;
    g->depth += distance(eye, t->gpos.xyz);
    ++g->hits;
}

inline void guide_write(__global float4 *aov, uint pixel, const guide_sum *g, uint samples) {
    const float inv = 1.0f / (float)samples;
    aov[AOV_SLOTS * pixel + 6u] = (float4)(g->albedo * inv, (float)(samples - g->glowing) * inv);
    aov[AOV_SLOTS * pixel + 7u] =
        (float4)(g->normal * inv, g->hits ? g->depth / (float)g->hits : 0.0f);
}

/* A pixel whose centre sees the sky, straight, also looks through
 * SKY_PROBES points of it, each on its own quarter of the pixel's rows
 * and of its columns (a rotated grid): geometry thinner than a pixel in
 * front of the sky, a blind's slats seen edge-on or a railing, falls
 * between the centres of whole regions of pixels where its lines and the
 * pixel grid beat, and there no centre meets it (the blinds scene's window
 * showed clear sky where the reference has a quarter of it covered). A
 * surface at any probe sets bit 0 of the pixel's key (keys compare on the
 * others), which makes the pixel an edge. */
#define SKY_PROBES 4u
#define SKY_PROBE_BIT 1u
inline int sky_probes_meet(const shading_scene *ps, const vct_camera_desc *cam, uint x, uint row) {
    for (uint k = 0u; k < SKY_PROBES; ++k) {
        const float u = ((float)k + 0.5f) / (float)SKY_PROBES;
        const float v = ((float)((k * 3u + 1u) % SKY_PROBES) + 0.5f) / (float)SKY_PROBES;
        hit_record h;
        if (accel_trace(&ps->g, cam->position.xyz,
                        camera_ray_dir(cam, (float)x + u, (float)row + v), 0.0f, INFINITY, 1, &h))
            return 1;
    }
    return 0;
}

/* The camera ray through each pixel's centre. keys: what vct_edge_flags
 * compares between neighbours. */
__kernel void vct_primary(PRIMARY_ARGS, __global uint *keys) {
    const uint x = get_global_id(0), y = get_global_id(1);
    if (x >= cam.size.x || y >= cam.size.y)
        return;
    const shading_scene ps = SHADING_SCENE();
    const uint pixel = y * cam.size.x + x;
    const uint row = camera_row(&cam, y);
    const primary_sample s = primary_trace(&ps, &cam, (float)x + 0.5f, (float)row + 0.5f,
                                           camera_pixel_id(&cam, x, y), 0u, 1u);
    gbuffer_write(gbuf, pixel, &s, s.throughput);
    gbuf[GBUF_SLOTS * pixel + 4u].w = sample_shade(&s);
    const int sky = !s.found && all(s.throughput == 1.0f);
    keys[pixel] =
        (s.key & ~SKY_PROBE_BIT) | (sky && sky_probes_meet(&ps, &cam, x, row) ? SKY_PROBE_BIT : 0u);
    image[pixel] = (float4)(s.radiance, 1.0f);
    if (aov) {
        aov[AOV_SLOTS * pixel] = (float4)(s.radiance, 1.0f);
        /* z: the emitter samples' variance (the diffuse pass fills x, y) */
        aov[AOV_SLOTS * pixel + 3u] = (float4)(0.0f, 0.0f, s.sampled_variance, 1.0f);
        aov[AOV_SLOTS * pixel + 4u] = (float4)(s.gpos.xyz, s.gnormal.w);
        aov[AOV_SLOTS * pixel + 5u] = s.gnormal;
    }
    if (reflection)
        reflection_write(reflection, pixel, s.rpos, s.rnormal, s.rdir);
    if (aov) {
        guide_sum g = {(float3)(0.0f), (float3)(0.0f), 0.0f, 0u, 0u};
        guide_add(&g, &s, materials, cam.position.xyz);
        guide_write(aov, pixel, &g, 1u);
    }
}

/* EDGE where a pixel's 3x3 neighbourhood holds an edge: a neighbour with
 * another key (material, dielectrics on the way, lights seen), on another
 * surface (its normal turned, or off this pixel's plane), or of another
 * albedo (a texture's detail). EDGE_EMITTER where the centres of the 5x5
 * pixels around meet both an emitting surface and something else: an
 * emitter's border, which its own key may not tell (centres that miss a
 * small emitter see the same ceiling). EDGE too where those centres meet
 * both a surface and nothing (the sky): geometry thinner than a pixel in
 * front of it, a blind's slats or a railing, is met by few centres, and a
 * pixel it crosses may have none of them within one pixel (the blinds
 * scene's window: NRMSE 0.123 -> 0.117). EDGE_CONTRAST on an edge whose 3x3
 * centres' shading spans more than EDGE_CONTRAST of the brightest's: a
 * hard shadow's, a lit wall's against a dark sky. EDGE too where, on one
 * surface, the 3x3 centres' shading spans more than SHADING_STEP. */
#define EDGE 1u
#define EDGE_EMITTER 2u
#define EDGE_CONTRAST_FLAG 3u
__kernel void vct_edge_flags(__global const float4 *gbuf, __global const uint *keys,
                             __global const vct_material_desc *materials, uint2 size,
                             __global uchar *flags) {
    const uint pixel = get_global_id(0);
    if (pixel >= size.x * size.y)
        return;
    const uint x = pixel % size.x, y = pixel / size.x;
    const uint key = keys[pixel] & ~SKY_PROBE_BIT;
    const float4 n = gbuf[GBUF_SLOTS * pixel + 1u];
    const float3 p = gbuf[GBUF_SLOTS * pixel].xyz;
    const float la = albedo_luminance(gbuf[GBUF_SLOTS * pixel + 4u].xyz);
    int edge = 0;
    for (int dy = -1; dy <= 1 && !edge; ++dy)
        for (int dx = -1; dx <= 1 && !edge; ++dx) {
            const int nx = (int)x + dx, ny = (int)y + dy;
            if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= (int)size.x || ny >= (int)size.y)
                continue;
            const uint q = (uint)ny * size.x + (uint)nx;
            if ((keys[q] & ~SKY_PROBE_BIT) != key) {
                edge = 1;
                continue;
            }
            const float4 nq = gbuf[GBUF_SLOTS * q + 1u];
            if (n.w == 0.0f || nq.w == 0.0f)
                continue;
            const float3 d = gbuf[GBUF_SLOTS * q].xyz - p;
            const float reach = EDGE_PLANE_SLOPE * length(d);
            const float lq = albedo_luminance(gbuf[GBUF_SLOTS * q + 4u].xyz);
            edge = dot(n.xyz, nq.xyz) < EDGE_NORMAL_COS || fabs(dot(n.xyz, d)) > reach ||
                   fabs(dot(nq.xyz, d)) > reach || fabs(la - lq) > EDGE_ALBEDO_SHARE * fmax(la, lq);
        }
    /* the centres within two pixels: emitters' and others'; and the
     * shading of those within one */
    int glow = 0, dark = 0, sky_edge = 0;
    float lo = INFINITY, hi = 0.0f;
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            const int nx = (int)x + dx, ny = (int)y + dy;
            if (nx < 0 || ny < 0 || nx >= (int)size.x || ny >= (int)size.y)
                continue;
            const uint q = (uint)ny * size.x + (uint)nx;
            const int surface = gbuf[GBUF_SLOTS * q + 1u].w != 0.0f;
            const int emits =
                surface && any(materials[as_uint(gbuf[GBUF_SLOTS * q].w)].emission.xyz > 0.0f);
            glow |= emits;
            dark |= !emits;
            /* a surface and a miss: sub-pixel geometry against the sky */
            sky_edge |= (keys[q] & ~SKY_PROBE_BIT) != key && (n.w == 0.0f || !surface);
            if (abs(dx) <= 1 && abs(dy) <= 1) {
                const float shade = gbuf[GBUF_SLOTS * q + 4u].w;
                lo = fmin(lo, shade);
                hi = fmax(hi, shade);
            }
        }
    edge |= sky_edge || (keys[pixel] & SKY_PROBE_BIT);
    const int contrast = edge && hi - lo > EDGE_CONTRAST * hi;
    const int shading = hi - lo > SHADING_STEP * hi;
    flags[pixel] = (uchar)(glow && dark      ? EDGE_EMITTER
                           : contrast        ? EDGE_CONTRAST_FLAG
                           : edge || shading ? EDGE
                                             : 0u);
}

/* A pixel on a sharp edge: its mean radiance over an m x m grid of camera
 * rays. One side of the edge is far brighter than the other, so its share
 * of the pixel decides the pixel. Through the 4 x 4 rays of other edges, a
 * lamp's panel a few pixels wide came out off by up to a fifth of its
 * radiance in the pixels it covers in part, or missed (a hundred times the
 * image's mean there): an emitter's border takes EMITTER_EDGE_SCALE times
 * the rays per axis. A hard shadow's pixels came out off by up to a tenth
 * of the light it stops: edges of high contrast take CONTRAST_EDGE_SCALE
 * times the rays, which leave a third of that error at a quarter of the
 * emitters' cost. */
#define EMITTER_EDGE_SCALE 4u
#define CONTRAST_EDGE_SCALE 2u
inline float3 sharp_edge_radiance(const shading_scene *ps, const vct_camera_desc *cam, uint x,
                                  uint row, uint id, uint m) {
    float3 sum = (float3)(0.0f);
    /* One ray in each cell of the m x m grid, on a column and a row of the
     * m^2 x m^2 grid of its own, their places within the cells shuffled per
     * column and per row (correlated multi-jittered sampling without the
     * jitter): an emitter's corner is met as finely as its edges. */
    for (uint s0 = 0; s0 < m * m; s0 += ACCEL_GROUP) {
        const uint group = min(m * m - s0, ACCEL_GROUP);
        float3 dirs[ACCEL_GROUP];
        hit_record firsts[ACCEL_GROUP];
        int found[ACCEL_GROUP];
        for (uint k = 0; k < group; ++k) {
            const uint s = s0 + k, i = s % m, j = s / m;
            const uint sx = rng_permute(j, m, 0x68bc21ebu ^ i),
                       sy = rng_permute(i, m, 0x02e5be93u ^ j);
            dirs[k] = camera_ray_dir(cam, (float)x + ((float)(i * m + sx) + 0.5f) / (float)(m * m),
                                     (float)row + ((float)(j * m + sy) + 0.5f) / (float)(m * m));
        }
        accel_trace_from(&ps->g, cam->position.xyz, dirs, group, firsts, found); /* a packet */
        for (uint k = 0; k < group; ++k)
            sum += primary_trace_hit(ps, cam, dirs[k], firsts[k], found[k], id, s0 + k, m * m)
                       .radiance;
    }
    return sum / (float)(m * m);
}

/* An edge pixel's samples may lie on two surfaces whose indirect light
 * differs: where a floor meets a wall, the wall's foot sees the sunlit
 * floor close by and the floor the dimmer wall (a long hall's junctions
 * came out with 0.7 of the reference's indirect light, two thirds of the
 * image's squared error in 2 % of its pixels). So the G-buffer keeps, beside
 * the surface it shades, the first other surface its samples met and their
 * share of those that met one, and the diffuse passes give that share of
 * the pixel the second surface's own light. A sample lies on a surface
 * when it is on its plane (on_plane) within MIXED_PLANE_PIXELS of the
 * pixel's footprint. */
#define MIXED_PLANE_PIXELS 1.0f

typedef struct second_surface {
    float3 p, n, albedo;
    uint material, count;
} second_surface;

/* Point q of unit normal m on the surface through p of unit normal n: the
 * normals within about 26 degrees, q within `tolerance` of p's tangent
 * plane (however far along it). What the edge pixels' samples and the
 * sparse fill's cells are told apart by. */
#define PLANE_NORMAL_COS 0.9f
inline int on_plane(float3 p, float3 n, float3 q, float3 m, float tolerance) {
    return dot(n, m) >= PLANE_NORMAL_COS && fabs(dot(n, q - p)) <= tolerance;
}

/* The pixel's footprint at distance d from the camera: a pixel's height there. */
inline float pixel_footprint(const vct_camera_desc *cam, float d) {
    const uint height = cam->size.w ? cam->size.w : cam->size.y;
    return d * 2.0f * cam->position.w / (float)height;
}

/* Pixels on an edge: n x n camera rays over the pixel. The image
 * gets their mean; the G-buffer keeps the centre's surface (or the first
 * sample's that found one) with the mean throughput of the samples that
 * found a surface, so that the cone passes add light in proportion to the
 * pixel's area that has it, and the second surface the samples met.
 * Glass reflections likewise. */
__kernel void vct_primary_refine(PRIMARY_ARGS, __global const uchar *flags, uint n) {
    const uint x = get_global_id(0), y = get_global_id(1);
    if (x >= cam.size.x || y >= cam.size.y)
        return;
    const uint pixel = y * cam.size.x + x;
    if (!flags[pixel])
        return;
    const shading_scene ps = SHADING_SCENE();
    const uint id = camera_pixel_id(&cam, x, y), row = camera_row(&cam, y);
    int found = gbuf[GBUF_SLOTS * pixel + 1u].w != 0.0f; /* the centre's surface */
    int reflected = reflection && any(reflection[3u * pixel + 2u].xyz != 0.0f);
    float3 radiance = (float3)(0.0f), cover = (float3)(0.0f), rweight = (float3)(0.0f);
    float sampled_variance = 0.0f;
    /* The albedo the cone passes shade with: the mean over the samples on
     * the kept surface's material, so that a texture's detail within the
     * pixel is averaged as a converged image averages it. */
    float3 albedo_sum = (float3)(0.0f);
    uint albedo_count = 0u;
    uint material = found ? as_uint(gbuf[GBUF_SLOTS * pixel].w) : 0u;
    /* the kept surface, and the samples that met a surface: on it or on a second */
    float3 kept_p = gbuf[GBUF_SLOTS * pixel].xyz, kept_n = gbuf[GBUF_SLOTS * pixel + 1u].xyz;
    float tolerance =
        MIXED_PLANE_PIXELS * pixel_footprint(&cam, distance(cam.position.xyz, kept_p));
    second_surface second = {(float3)(0.0f), (float3)(0.0f), (float3)(0.0f), 0u, 0u};
    uint met = 0u;
    /* the samples' own contrast: an edge of high contrast between the centres */
    float lo = INFINITY, hi = 0.0f;
    guide_sum guide = {(float3)(0.0f), (float3)(0.0f), 0.0f, 0u, 0u};
    float3 dirs[ACCEL_GROUP];
    hit_record firsts[ACCEL_GROUP];
    int first_found[ACCEL_GROUP];
    for (uint s = 0; s < n * n; ++s) {
        const uint k = s % ACCEL_GROUP;
        if (k == 0u) { /* the next group's camera rays, traced together (a packet) */
            for (uint q = 0; q < min(n * n - s, ACCEL_GROUP); ++q) {
                /* Cell (i, j) of the n x n grid, and within it the sub-cell
                 * (j, i) of an n x n grid of its own: every ray on its own
                 * column and row of the n^2 x n^2 grid, so that an edge
                 * along a pixel row or column is met in n^2 steps, not n. */
                const uint i = (s + q) % n, j = (s + q) / n;
                dirs[q] =
                    camera_ray_dir(&cam, (float)x + ((float)(i * n + j) + 0.5f) / (float)(n * n),
                                   (float)row + ((float)(j * n + i) + 0.5f) / (float)(n * n));
            }
            accel_trace_from(&ps.g, cam.position.xyz, dirs, min(n * n - s, ACCEL_GROUP), firsts,
                             first_found);
        }
        const primary_sample t =
            primary_trace_hit(&ps, &cam, dirs[k], firsts[k], first_found[k], id, s, n * n);
        guide_add(&guide, &t, materials, cam.position.xyz);
        radiance += t.radiance;
        sampled_variance += t.sampled_variance;
        rweight += (float3)(t.rpos.w, t.rnormal.w, t.rdir.w);
        const float shade = sample_shade(&t);
        lo = fmin(lo, shade);
        hi = fmax(hi, shade);
        if (t.found) {
            cover += t.throughput;
            if (!found) {
                found = 1;
                material = as_uint(t.gpos.w);
                gbuffer_write(gbuf, pixel, &t, t.throughput);
                if (aov) {
                    aov[AOV_SLOTS * pixel + 4u] = (float4)(t.gpos.xyz, t.gnormal.w);
                    aov[AOV_SLOTS * pixel + 5u] = t.gnormal;
                }
                kept_p = t.gpos.xyz;
                kept_n = t.gnormal.xyz;
                tolerance =
                    MIXED_PLANE_PIXELS * pixel_footprint(&cam, distance(cam.position.xyz, kept_p));
            }
            ++met;
            if (!on_plane(kept_p, kept_n, t.gpos.xyz, t.gnormal.xyz, tolerance)) {
                if (second.count == 0u)
                    second = (second_surface){t.gpos.xyz, t.gnormal.xyz, t.galbedo.xyz,
                                              as_uint(t.gpos.w), 1u};
                else if (on_plane(second.p, second.n, t.gpos.xyz, t.gnormal.xyz, tolerance)) {
                    second.albedo += t.galbedo.xyz;
                    ++second.count;
                }
            }
            if (as_uint(t.gpos.w) == material) {
                albedo_sum += t.galbedo.xyz;
                ++albedo_count;
            }
        }
        if (reflection && !reflected && any(t.rdir.xyz != 0.0f)) {
            reflected = 1;
            reflection_write(reflection, pixel, t.rpos, t.rnormal, t.rdir);
        }
    }
    const float inv = 1.0f / (float)(n * n);
    if (aov)
        guide_write(aov, pixel, &guide, n * n);
    gbuf[GBUF_SLOTS * pixel + 3u] = (float4)(cover * inv, 0.0f);
    const uint scale = flags[pixel] == EDGE_EMITTER ? EMITTER_EDGE_SCALE
                       : flags[pixel] == EDGE_CONTRAST_FLAG || hi - lo > EDGE_CONTRAST * hi
                           ? CONTRAST_EDGE_SCALE
                           : 1u;
    const float3 mean =
        scale > 1u ? sharp_edge_radiance(&ps, &cam, x, row, id, n * scale) : radiance * inv;
    if (albedo_count > 0u)
        gbuf[GBUF_SLOTS * pixel + 4u] = (float4)(albedo_sum / (float)albedo_count, 0.0f);
    if (second.count > 0u) {
        gbuf[GBUF_SLOTS * pixel + 5u] = (float4)(second.p, (float)second.count / (float)met);
        gbuf[GBUF_SLOTS * pixel + 6u] = (float4)(second.n, as_float(second.material));
        gbuf[GBUF_SLOTS * pixel + 7u] = (float4)(second.albedo / (float)second.count, 0.0f);
    } else {
        gbuf[GBUF_SLOTS * pixel + 5u] = (float4)(0.0f);
    }
    image[pixel] = (float4)(mean, 1.0f);
    if (aov) {
        aov[AOV_SLOTS * pixel] = (float4)(mean, 1.0f);
        /* the mean's: of the n x n samples, or none counted of the finer
         * grid on a sharp edge, whose pixels the filter must keep */
        aov[AOV_SLOTS * pixel + 3u].z = scale > 1u ? 0.0f : sampled_variance * inv * inv;
    }
    if (reflection && reflected) {
        rweight *= inv;
        reflection[3u * pixel].w = rweight.x;
        reflection[3u * pixel + 1u].w = rweight.y;
        reflection[3u * pixel + 2u].w = rweight.z;
    }
}

/* The surface a pixel's camera ray found, from the G-buffer; 0 where it
 * found none (or the pixel lies outside the image). */
typedef struct gbuffer_surface {
    float3 p, n, wo, throughput;
    vct_material_desc m;
} gbuffer_surface;

inline int gbuffer_at(__global const float4 *gbuf, __global const vct_material_desc *materials,
                      uint2 size, uint x, uint y, uint *pixel, gbuffer_surface *s) {
    if (x >= size.x || y >= size.y)
        return 0;
    *pixel = y * size.x + x;
    const float4 gnormal = gbuf[GBUF_SLOTS * *pixel + 1u];
    if (gnormal.w == 0.0f)
        return 0;
    const float4 gpos = gbuf[GBUF_SLOTS * *pixel];
    s->p = gpos.xyz;
    s->n = gnormal.xyz;
    s->wo = gbuf[GBUF_SLOTS * *pixel + 2u].xyz;
    s->throughput = gbuf[GBUF_SLOTS * *pixel + 3u].xyz;
    s->m = materials[as_uint(gpos.w)];
    s->m.albedo.xyz = gbuf[GBUF_SLOTS * *pixel + 4u].xyz; /* textured */
    return 1;
}

/* The G-buffer at this work-item's pixel. */
inline int gbuffer_read(__global const float4 *gbuf, __global const vct_material_desc *materials,
                        uint2 size, uint *pixel, gbuffer_surface *s) {
    return gbuffer_at(gbuf, materials, size, get_global_id(0), get_global_id(1), pixel, s);
}

/* The pixel's second surface (vct_primary_refine) in *s, seen as g is, and
 * its share of the pixel's samples that met a surface; 0 where it has none. */
inline float gbuffer_second(__global const float4 *gbuf,
                            __global const vct_material_desc *materials, uint pixel,
                            const gbuffer_surface *g, gbuffer_surface *s) {
    const float4 at = gbuf[GBUF_SLOTS * pixel + 5u];
    *s = *g;
    if (!(at.w > 0.0f))
        return 0.0f;
    const float4 normal = gbuf[GBUF_SLOTS * pixel + 6u];
    s->p = at.xyz;
    s->n = normal.xyz;
    s->m = materials[as_uint(normal.w)];
    s->m.albedo.xyz = gbuf[GBUF_SLOTS * pixel + 7u].xyz;
    return at.w;
}

/* Adds a cone pass's radiance to the pixel, and to AOV `slot` when AOVs are
 * kept (the buffer starts at 0). */
inline void pixel_add(__global float4 *image, __global float4 *aov, uint pixel, uint slot,
                      float3 add) {
    image[pixel] = (float4)(image[pixel].xyz + add, 1.0f);
    if (aov)
        aov[AOV_SLOTS * pixel + slot] = (float4)(aov[AOV_SLOTS * pixel + slot].xyz + add, 1.0f);
}

/* Lights with a radius: the cone from the surface towards the light's
 * centre, as wide as the light (tan = radius / distance, or the angular
 * radius) and reaching to it, sees opacity alpha; the light is shaded as a
 * point times the fraction 1 - alpha / stop that gets through (0 once the
 * cone counts as opaque). */
#if defined(VCT_SOFT_SHADOWS)
__kernel void vct_soft_shadows(CONE_POOLS, __global const uint *child, vct_cone_desc cd,
                               __global const vct_light_desc *lights, uint light_count,
                               __global const float4 *gbuf,
                               __global const vct_material_desc *materials, uint2 size,
                               __global float4 *image, __global float4 *aov) {
    uint pixel;
    gbuffer_surface g;
    if (!gbuffer_read(gbuf, materials, size, &pixel, &g))
        return;
    float3 r;
    const float e = direct_lobe(&g.m, g.wo, g.n, &r);
    const float3 origin = cone_origin(&cd, g.p, g.n);
    direct_terms sum = {(float3)(0.0f), (float3)(0.0f), 0u, 0u, 0u, 0.0f};
    vct_cone_desc sd = cd;
    sd.march.x *= SOFT_STEP_SCALE;
    for (uint i = 0; i < light_count; ++i) {
        if (!light_is_soft(lights, i))
            continue;
        float3 wi, radiant;
        float dist, cos_theta;
        if (!light_reaches(lights, i, g.p, g.n, &wi, &dist, &radiant, &cos_theta))
            continue;
        const float size_of = lights[i].shape.x;
        const int far = isinf(dist);
        const float tan_half = far ? size_of : fmin(size_of / dist, 1e3f);
        const cone_result c = cone_trace(CONE_POOLS_PASS, child, &sd, origin, wi, tan_half,
                                         far ? INFINITY : dist - size_of);
        direct_add(&sum, radiant, cos_theta, wi, r, e,
                   clamp(1.0f - c.alpha / cd.march.w, 0.0f, 1.0f));
    }
    pixel_add(image, aov, pixel, 0u, g.throughput * direct_shade(&g.m, sum, e));
}
#endif

/* What a pixel's diffuse gather found: the cosine-weighted radiance
 * (which only indirect light uses) and the open fraction within the AO
 * distance. */
typedef struct diffuse_light {
    float3 radiance;
    float open;
    float variance; /* of the radiance's luminance */
} diffuse_light;

inline diffuse_light diffuse_trace(const shading_scene *ps, CONE_POOLS, __global const uint *child,
                                   const vct_cone_desc *cd, const gather_voxels *gv,
                                   uint cone_count, const gbuffer_surface *g) {
    float3 t, b;
    const uint seed = cone_point_seed(cd->volume.xyz, cd->volume.w, cd->res.x, g->p);
    cone_frame(g->n, seed, &t, &b);
    diffuse_light l;
    l.radiance = gather_rays(ps, CONE_POOLS_PASS, child, cd, gv, g->p, g->n, t, b,
                             cone_count * GATHER_RAYS_PER_CONE, cone_count * GATHER_PICKS_PER_CONE,
                             seed, cd->march.z, &l.open, &l.variance);
    return l;
}

/* What the diffuse gather's light l sends to the camera off surface g, and
 * in *variance the variance of its luminance. */
inline float3 diffuse_reflected(const gbuffer_surface *g, diffuse_light l, float3 ambient,
                                float *variance) {
    *variance = 0.0f;
#if defined(VCT_INDIRECT)
    const float3 reflect = diffuse_color(&g->m) * g->throughput;
    *variance = l.variance * albedo_luminance(reflect) * albedo_luminance(reflect);
    return reflect * l.radiance;
#elif defined(VCT_AO)
    return diffuse_color(&g->m) * g->throughput * ambient * l.open;
#else
    return (float3)(0.0f);
#endif
}

/* Adds what the diffuse gather found, reflected by the pixel's surface g,
 * and where the pixel has a second surface g2 (a share of its samples),
 * that share of what g2's gather l2 found reflected by g2. */
inline void diffuse_write(__global float4 *image, __global float4 *aov, uint pixel,
                          const gbuffer_surface *g, diffuse_light l, const gbuffer_surface *g2,
                          diffuse_light l2, float share, float3 ambient) {
    float variance;
    float3 add = diffuse_reflected(g, l, ambient, &variance);
    float open = l.open;
    if (share > 0.0f) {
        float variance2;
        const float3 add2 = diffuse_reflected(g2, l2, ambient, &variance2);
        const float keep = 1.0f - share;
        add = keep * add + share * add2;
        open = keep * open + share * l2.open;
        variance = keep * keep * variance + share * share * variance2;
    }
    pixel_add(image, aov, pixel, 1u, add);
    if (aov) /* z: the primary pass's */
        aov[AOV_SLOTS * pixel + 3u] = (float4)(open, variance, aov[AOV_SLOTS * pixel + 3u].z, 1.0f);
}

#if (defined(VCT_INDIRECT) || defined(VCT_AO)) && !defined(VCT_SPARSE_DIFFUSE)
__kernel void vct_diffuse_cones(ACCEL_ARGS, CONE_POOLS, __global const uint *child,
                                vct_cone_desc cd, __global const vct_cone_dir *cones,
                                uint cone_count, __global const float4 *gbuf,
                                __global const vct_material_desc *materials, uint2 size,
                                __global float4 *image, __global float4 *aov, GATHER_ARGS) {
    const float4 ambient = cd.ambient;
    const shading_scene ps = SHADING_SCENE();
    const gather_voxels gv = GATHER_VOXELS();
    uint pixel;
    gbuffer_surface g;
    if (!gbuffer_read(gbuf, materials, size, &pixel, &g))
        return;
    const diffuse_light l = diffuse_trace(&ps, CONE_POOLS_PASS, child, &cd, &gv, cone_count, &g);
    gbuffer_surface g2;
    const float share = gbuffer_second(gbuf, materials, pixel, &g, &g2);
    const diffuse_light l2 =
        share > 0.0f ? diffuse_trace(&ps, CONE_POOLS_PASS, child, &cd, &gv, cone_count, &g2) : l;
    diffuse_write(image, aov, pixel, &g, l, &g2, l2, share, cd.ambient.xyz);
}
#endif

/* Diffuse light traced sparsely: vct_diffuse_sparse traces the cones of
 * every other pixel per axis, pixel (2i, 2j) into cell (i, j) of `sparse`
 * (two float4 each: radiance and open fraction; the variance of the
 * radiance's luminance, 0, 0, 0), and
 * vct_diffuse_fill gives every pixel the mean of the cells around it (itself
 * at (2i, 2j), else the 2 or 4 nearest) whose surface agrees with its own:
 * on the pixel's plane (on_plane), the cell's point within
 * SPARSE_PLANE_VOXELS of the pixel's tangent plane. The cells are the
 * pixel's neighbours on the screen, so on one plane the pixel's point lies
 * between theirs, however far apart a grazing view puts them: the fill
 * interpolates along the surface at the image's own rate (a Cornell box's
 * ceiling and walls seen aslant had every other row trace its own cones
 * when the cells had to lie within the cone offset: 2021 of 16384 pixels
 * at 128^2, half the diffuse pass's time, for the same error). Where
 * any of them does not agree, the pixel lies on an edge, in a thin part or
 * beside a junction, and the light of a cell on one side is not its own:
 * it changes fast towards a junction (the foot of a hall's wall over a
 * sunlit floor took the light of the cell two rows up, 0.7 of its own;
 * taking the mean where two of four cells agreed, the suite's mean NRMSE
 * was 0.0421, with every one agreeing 0.0417 for a few milliseconds more
 * at 128^2). There the pixel traces its own rays, a third of
 * the gather's (FILL_CONES), whose noise the indirect filter's variance
 * guide weighs (the hall's NRMSE 0.086 -> 0.076 at 6 ms; with all the
 * rays 0.073 at 20 ms; the suite's mean 0.048 -> 0.045 with the second
 * surfaces below). A pixel with a second surface (vct_primary_refine)
 * takes its light from the cells around that lie on it, one further each
 * way, else, where it holds at least SECOND_TRACE_SHARE of the pixel, from
 * rays of its own (thinner parts take the first surface's light).
 * vct_diffuse_sparse takes image and aov only to share every cone pass's
 * signature. */
#define SPARSE_PLANE_VOXELS 0.25f
#define FILL_CONES(n) max((n) / 3u, 1u)
#define SECOND_TRACE_SHARE 0.25f

#if (defined(VCT_INDIRECT) || defined(VCT_AO)) && defined(VCT_SPARSE_DIFFUSE)
__kernel void vct_diffuse_sparse(ACCEL_ARGS, CONE_POOLS, __global const uint *child,
                                 vct_cone_desc cd, __global const vct_cone_dir *cones,
                                 uint cone_count, __global const float4 *gbuf,
                                 __global const vct_material_desc *materials, uint2 size,
                                 __global float4 *image, __global float4 *aov,
                                 __global float4 *sparse, GATHER_ARGS) {
    const float4 ambient = cd.ambient;
    const shading_scene ps = SHADING_SCENE();
    const gather_voxels gv = GATHER_VOXELS();
    const uint i = get_global_id(0), j = get_global_id(1);
    const uint2 cells = (size + 1u) / 2u;
    if (i >= cells.x || j >= cells.y)
        return;
    uint pixel;
    gbuffer_surface g;
    diffuse_light l = {(float3)(0.0f), 0.0f, 0.0f};
    if (gbuffer_at(gbuf, materials, size, 2u * i, 2u * j, &pixel, &g))
        l = diffuse_trace(&ps, CONE_POOLS_PASS, child, &cd, &gv, cone_count, &g);
    const uint cell = j * cells.x + i;
    sparse[2u * cell] = (float4)(l.radiance, l.open);
    sparse[2u * cell + 1u] = (float4)(l.variance, 0.0f, 0.0f, 0.0f);
}
#endif

inline int sparse_agrees(const vct_cone_desc *cd, const gbuffer_surface *g,
                         const gbuffer_surface *cell) {
    const float voxel = cd->volume.w / (float)cd->res.x;
    return on_plane(g->p, g->n, cell->p, cell->n, SPARSE_PLANE_VOXELS * voxel);
}

/* The mean light of the cells (i, j), i0 <= i <= i1 and j0 <= j <= j1,
 * whose surface agrees with g, in *l; how many agree. */
inline float sparse_mean(const vct_cone_desc *cd, __global const float4 *gbuf,
                         __global const vct_material_desc *materials, uint2 size,
                         __global const float4 *sparse, int i0, int i1, int j0, int j1,
                         const gbuffer_surface *g, diffuse_light *l) {
    const uint columns = (size.x + 1u) / 2u;
    diffuse_light sum = {(float3)(0.0f), 0.0f, 0.0f};
    float agree = 0.0f;
    for (int j = max(j0, 0); j <= j1; ++j)
        for (int i = max(i0, 0); i <= i1; ++i) {
            uint at;
            gbuffer_surface q;
            if (!gbuffer_at(gbuf, materials, size, 2u * (uint)i, 2u * (uint)j, &at, &q) ||
                !sparse_agrees(cd, g, &q))
                continue;
            const uint cell = (uint)j * columns + (uint)i;
            const float4 a = sparse[2u * cell];
            sum.radiance += a.xyz;
            sum.open += a.w;
            sum.variance += sparse[2u * cell + 1u].x;
            agree += 1.0f;
        }
    if (agree > 0.0f) {
        sum.radiance /= agree;
        sum.open /= agree;
        sum.variance /= agree * agree; /* the mean's, of independent cells */
    }
    *l = sum;
    return agree;
}

#if (defined(VCT_INDIRECT) || defined(VCT_AO)) && defined(VCT_SPARSE_DIFFUSE)
__kernel void vct_diffuse_fill(ACCEL_ARGS, CONE_POOLS, __global const uint *child, vct_cone_desc cd,
                               __global const vct_cone_dir *cones, uint cone_count,
                               __global const float4 *gbuf,
                               __global const vct_material_desc *materials, uint2 size,
                               __global float4 *image, __global float4 *aov,
                               __global const float4 *sparse, GATHER_ARGS) {
    const float4 ambient = cd.ambient;
    const shading_scene ps = SHADING_SCENE();
    const gather_voxels gv = GATHER_VOXELS();
    uint pixel;
    gbuffer_surface g;
    if (!gbuffer_read(gbuf, materials, size, &pixel, &g))
        return;
    const int x = (int)get_global_id(0), y = (int)get_global_id(1);
    const int i = x / 2, j = y / 2, i1 = i + ((x & 1) && 2 * i + 2 < (int)size.x),
              j1 = j + ((y & 1) && 2 * j + 2 < (int)size.y);
    const float needed = (float)((i1 - i + 1) * (j1 - j + 1));
    diffuse_light l;
    if (sparse_mean(&cd, gbuf, materials, size, sparse, i, i1, j, j1, &g, &l) < needed)
        l = diffuse_trace(&ps, CONE_POOLS_PASS, child, &cd, &gv, FILL_CONES(cone_count), &g);
    gbuffer_surface g2;
    const float share = gbuffer_second(gbuf, materials, pixel, &g, &g2);
    diffuse_light l2 = l;
    if (share > 0.0f &&
        !sparse_mean(&cd, gbuf, materials, size, sparse, i - 1, i + 1, j - 1, j + 1, &g2, &l2))
        l2 = share >= SECOND_TRACE_SHARE
                 ? diffuse_trace(&ps, CONE_POOLS_PASS, child, &cd, &gv, FILL_CONES(cone_count), &g2)
                 : l;
    diffuse_write(image, aov, pixel, &g, l, &g2, l2, share, cd.ambient.xyz);
}
#endif

/* The picks' weights (gather_picks.h; host/src/conetrace/gather_picks.c
 * chooses them): each leaf voxel's by the luminance l of its direct light
 * (the brighter side's), min(l scale, cap) unit rounded where l is at
 * least floor_l and above 0, else 0. gather_pick_peak finds the brightest
 * (its bits, into peak[0], which must start at 0): luminances are not
 * negative, so their bits order as integers do. */
#if defined(VCT_INDIRECT)
__kernel void gather_pick_peak(__global const float4 *direct, uint voxels, __global int *peak) {
    const uint first = get_global_id(0) * VCT_PICK_SPAN;
    float brightest = 0.0f;
    for (uint v = first; v < min(first + VCT_PICK_SPAN, voxels); ++v)
        brightest = fmax(brightest, side_luminance(direct[v].xyz));
    if (brightest > 0.0f)
        atomic_max(peak, as_int(brightest));
}

__kernel void gather_pick_weights(__global const float4 *direct, uint voxels, float scale,
                                  float floor_l, float cap, uint unit, __global uint *weights) {
    const uint v = get_global_id(0);
    if (v >= voxels)
        return;
    const float l = side_luminance(direct[v].xyz);
    weights[v] = l > 0.0f && l >= floor_l ? (uint)(fmin(l * scale, cap) * (float)unit + 0.5f) : 0u;
}
#endif

/* Half-angle of a Phong lobe cos^e: the cone that holds half its energy. */
inline float specular_tan_half(float e) {
    const float c = pow(0.5f, 1.0f / (e + 1.0f));
    return sqrt(fmax(1.0f - c * c, 0.0f)) / c;
}

#if defined(VCT_SPECULAR)
__kernel void vct_specular_cone(CONE_POOLS, __global const uint *child, vct_cone_desc cd,
                                __global const float4 *gbuf,
                                __global const vct_material_desc *materials, uint2 size,
                                __global float4 *image, __global float4 *aov) {
    uint pixel;
    gbuffer_surface g;
    if (!gbuffer_read(gbuf, materials, size, &pixel, &g))
        return;
    const vct_material_desc m = g.m;
    if (!(glossy_probability(&m) > 0.0f) || is_dielectric(&m))
        return; /* nothing glossy here: the pixel is left as it is */
    const float3 n = g.n;
    const float3 r = reflect_dir(g.wo, n);
    const int mirror = is_mirror(&m);
    const float e = phong_exponent(m.emission.w);
    const float3 origin = cone_origin(&cd, g.p, n);
    const cone_result c = cone_trace(CONE_POOLS_PASS, child, &cd, origin, r,
                                     mirror ? 0.0f : specular_tan_half(e), INFINITY);
    float3 weight = glossy_color(&m) * g.throughput;
    if (!mirror)
        weight *= (e + 2.0f) / (e + 1.0f) * fmax(dot(n, r), 0.0f);
    pixel_add(image, aov, pixel, 2u, weight * c.radiance);
}
#endif

/* Caustics: light that reached a surface through dielectrics, which shadow
 * rays stop at and voxels let through unlit. Photons traced from the lights
 * (photon/photon_trace.cl, kept when their specular bounces met a
 * dielectric) are gathered at each pixel's G-buffer surface; the estimate
 * (power times the BSDF over pi r^2 and the photons emitted) is added to the
 * pixel and its direct AOV, through the throughput of the dielectrics and
 * mirrors the camera ray passed. */

#define CAUSTIC_PI 3.14159265f
/* Photons whose surface normal is within about 60 degrees of the pixel's. */
#define CAUSTIC_NORMAL_COS 0.5f
/* A pixel's radius: the base radius doubled, up to CAUSTIC_WIDENINGS times,
 * until a pilot pass finds CAUSTIC_MIN_PHOTONS within it. A focus keeps its
 * sharpness and the sparse photons of a faint caustic are spread, not left
 * as blotches; the pilot's photons are not the estimate's, so choosing by
 * their count does not bias it. 0: no photon within the widest. */
#define CAUSTIC_MIN_PHOTONS 16u
#define CAUSTIC_WIDENINGS 2

#if defined(VCT_CAUSTICS)
__kernel void vct_caustic_radius(PHOTON_GRID_ARGS(c), float radius, __global const float4 *gbuf,
                                 __global const vct_material_desc *materials, uint2 size,
                                 __global float *radii) {
    uint pixel;
    gbuffer_surface g;
    if (!gbuffer_read(gbuf, materials, size, &pixel, &g)) {
        if (get_global_id(0) < size.x && get_global_id(1) < size.y)
            radii[get_global_id(1) * size.x + get_global_id(0)] = 0.0f;
        return;
    }
    const photon_grid grid = PHOTON_GRID_VIEW(c);
    /* The widest first: most pixels have no caustic near them at all. */
    const float widest = radius * (float)(1 << CAUSTIC_WIDENINGS);
    uint found;
    photon_estimate(&grid, g.p, g.n, g.wo, widest, &g.m, 0u, CAUSTIC_NORMAL_COS, &found);
    float chosen = found > 0u ? widest : 0.0f;
    for (float r = radius; found > 0u && r < widest; r *= 2.0f) {
        uint within;
        photon_estimate(&grid, g.p, g.n, g.wo, r, &g.m, 0u, CAUSTIC_NORMAL_COS, &within);
        if (within >= CAUSTIC_MIN_PHOTONS) {
            chosen = r;
            break;
        }
    }
    radii[pixel] = chosen;
}
#endif

#if defined(VCT_CAUSTICS)
__kernel void vct_caustics(PHOTON_GRID_ARGS(c), __global const float *radii, float inv_emitted,
                           __global const float4 *gbuf, __global const vct_material_desc *materials,
                           uint2 size, __global float4 *image, __global float4 *aov) {
    uint pixel;
    gbuffer_surface g;
    if (!gbuffer_read(gbuf, materials, size, &pixel, &g))
        return;
    const float r = radii[pixel];
    if (!(r > 0.0f))
        return;
    const photon_grid grid = PHOTON_GRID_VIEW(c);
    uint found;
    const float3 sum = photon_estimate(&grid, g.p, g.n, g.wo, r, &g.m, PHOTON_EPANECHNIKOV,
                                       CAUSTIC_NORMAL_COS, &found);
    if (found > 0u)
        pixel_add(image, aov, pixel, 0u, g.throughput * sum * (inv_emitted / (CAUSTIC_PI * r * r)));
}
#endif

/* The Fresnel reflection vct_primary recorded, through a mirror cone.
 * gbuf and materials are unused: the signature is every cone pass's. */
#if defined(VCT_REFRACTION) && defined(VCT_SPECULAR)
__kernel void vct_glass_reflection(CONE_POOLS, __global const uint *child, vct_cone_desc cd,
                                   __global const float4 *reflection, uint per_pixel,
                                   __global const float4 *gbuf,
                                   __global const vct_material_desc *materials, uint2 size,
                                   __global float4 *image, __global float4 *aov) {
    const uint x = get_global_id(0), y = get_global_id(1);
    if (x >= size.x || y >= size.y)
        return;
    const uint pixel = y * size.x + x;
    const float4 rpos = reflection[per_pixel * pixel];
    const float4 rnormal = reflection[per_pixel * pixel + 1u];
    const float4 rdir = reflection[per_pixel * pixel + 2u];
    const float3 weight = (float3)(rpos.w, rnormal.w, rdir.w);
    if (!(weight.x > 0.0f || weight.y > 0.0f || weight.z > 0.0f))
        return;
    const float3 origin = cone_origin(&cd, rpos.xyz, rnormal.xyz);
    const cone_result c = cone_trace(CONE_POOLS_PASS, child, &cd, origin, rdir.xyz, 0.0f, INFINITY);
    pixel_add(image, aov, pixel, 2u, weight * c.radiance);
}
#endif

/* Cones given one by one (for tests and tools): 2 float4 in, origin and
 * tan(half-angle), direction and reach; 2 float4 out, radiance and opacity,
 * then AO opacity, level sum, samples and 1 if it left the volume. */
#if defined(VCT_CONE_PROBE)
__kernel void cone_probe(CONE_POOLS, __global const uint *child, vct_cone_desc cd,
                         __global const float4 *cones, uint n, __global float4 *out) {
    const uint i = get_global_id(0);
    if (i >= n)
        return;
    const float4 a = cones[2u * i], b = cones[2u * i + 1u];
    const cone_result r = cone_trace(CONE_POOLS_PASS, child, &cd, a.xyz, b.xyz, a.w, b.w);
    out[2u * i] = (float4)(r.radiance, r.alpha);
    out[2u * i + 1u] = (float4)(r.ao_alpha, r.level_sum, (float)r.samples, (float)r.left);
}
#endif
