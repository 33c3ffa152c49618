/* The effect plan: what a scene calls for, read from its lights, materials
 * and ambient light, each decision with its reason. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "runtime/runtime.h"
#include "light/emitters.h"

static const char *const effect_names[VCT_EFFECTS] = {"direct",   "shadows",      "indirect",
                                                      "specular", "refraction",   "emission",
                                                      "ao",       "soft_shadows", "caustics"};

const char *vct_effect_name(vct_effect effect) {
    return effect >= 0 && effect < VCT_EFFECTS ? effect_names[effect] : "unknown";
}

int vct_effect_from_name(const char *name) {
    for (int e = 0; e < VCT_EFFECTS; ++e)
        if (strcmp(name, effect_names[e]) == 0)
            return e;
    return -1;
}

static int positive3(const float *v) {
    return v[0] > 0.0f || v[1] > 0.0f || v[2] > 0.0f;
}

/* The same lobes as kernels/scene/bsdf.h: metals reflect their albedo glossily. */
static int is_metal(const vct_material *m) {
    return m->metallic > 0.5f;
}

static int is_transmissive(const vct_material *m) {
    return m->transmission > 0.0f;
}

static int is_diffuse(const vct_material *m) {
    return !is_metal(m) && !is_transmissive(m) && positive3(m->albedo);
}

static int is_glossy(const vct_material *m) {
    return !is_transmissive(m) && positive3(is_metal(m) ? m->albedo : m->specular);
}

/* The first material used by a triangle that `has` holds, or -1. */
static int first_used(const vct_scene *s, const unsigned char *used,
                      int (*has)(const vct_material *)) {
    for (uint32_t m = 0; m < s->material_count; ++m)
        if (used[m] && has(&s->materials[m]))
            return (int)m;
    return -1;
}

static int is_emissive(const vct_material *m) {
    return positive3(m->emission);
}

static void say(vct_plan *p, vct_effect e, int on, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

static void say(vct_plan *p, vct_effect e, int on, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(p->why[e], sizeof p->why[e], fmt, ap);
    va_end(ap);
    p->on[e] = on;
}

void vct_plan_make(const vct_scene *s, const vct_effect_force *force, vct_plan *p) {
    memset(p, 0, sizeof *p);
    unsigned char *used = calloc(s->material_count + 1, 1);
    for (uint32_t t = 0; used && t < s->triangle_count; ++t)
        used[s->triangle_material[t]] = 1;
    uint32_t lights = 0, soft = 0;
    for (uint32_t l = 0; l < s->light_count; ++l) {
        lights += positive3(s->lights[l].color);
        soft += positive3(s->lights[l].color) && s->lights[l].radius > 0.0f;
    }
    const int diffuse = used ? first_used(s, used, is_diffuse) : -1;
    const int glossy = used ? first_used(s, used, is_glossy) : -1;
    const int clear = used ? first_used(s, used, is_transmissive) : -1;
    const int emissive = used ? first_used(s, used, is_emissive) : -1;
    const int ambient = positive3(s->ambient);
    free(used);
    const uint32_t emitters = emissive >= 0 ? vct_scene_emissive_triangles(s) : 0; /* area lights */
    char sources[96];
    snprintf(sources, sizeof sources, "%u light%s", lights, lights == 1 ? "" : "s");
    if (emitters)
        snprintf(sources, sizeof sources, "%u light%s and %u emissive triangle%s", lights,
                 lights == 1 ? "" : "s", emitters, emitters == 1 ? "" : "s");

    if (lights || emitters)
        say(p, VCT_EFFECT_DIRECT, 1, "%s%s", sources,
            emitters ? " (the triangles sampled as area lights)" : "");
    else
        say(p, VCT_EFFECT_DIRECT, 0, "no lights and no emissive triangles");
    if (lights || emitters)
        say(p, VCT_EFFECT_SHADOWS, 1, "shadow rays towards %s", sources);
    else
        say(p, VCT_EFFECT_SHADOWS, 0, "no lights to cast them");
    const int lit = lights || emissive >= 0 || ambient;
    if (diffuse >= 0 && lit)
        say(p, VCT_EFFECT_INDIRECT, 1, "diffuse material \"%s\", lit by %s",
            s->materials[diffuse].name,
            lights          ? "lights"
            : emissive >= 0 ? "emissive surfaces"
                            : "ambient light");
    else
        say(p, VCT_EFFECT_INDIRECT, 0, "%s",
            diffuse < 0 ? "no diffuse material" : "nothing emits light");
    if (glossy >= 0)
        say(p, VCT_EFFECT_SPECULAR, 1, "glossy material \"%s\" (roughness %g)",
            s->materials[glossy].name, s->materials[glossy].roughness);
    else if (clear >= 0)
        say(p, VCT_EFFECT_SPECULAR, 1, "dielectric \"%s\" reflects (Fresnel)",
            s->materials[clear].name);
    else
        say(p, VCT_EFFECT_SPECULAR, 0, "no glossy, metallic or transmissive material");
    if (clear >= 0)
        say(p, VCT_EFFECT_REFRACTION, 1, "material \"%s\" transmits %g", s->materials[clear].name,
            s->materials[clear].transmission);
    else
        say(p, VCT_EFFECT_REFRACTION, 0, "no transmissive material");
    if (emissive >= 0)
        say(p, VCT_EFFECT_EMISSION, 1, "material \"%s\" emits", s->materials[emissive].name);
    else
        say(p, VCT_EFFECT_EMISSION, 0, "no emissive material");
    if (ambient)
        say(p, VCT_EFFECT_AO, 1, "ambient light (%g %g %g) is occluded by geometry", s->ambient[0],
            s->ambient[1], s->ambient[2]);
    else
        say(p, VCT_EFFECT_AO, 0, "no ambient light");

    if (soft)
        say(p, VCT_EFFECT_SOFT_SHADOWS, 1, "%u light%s with a radius: one cone as wide as each",
            soft, soft == 1 ? "" : "s");
    else
        say(p, VCT_EFFECT_SOFT_SHADOWS, 0, "%s", lights ? "no light has a radius" : "no lights");

    if (clear >= 0 && (lights || emitters || ambient))
        say(p, VCT_EFFECT_CAUSTICS, 1,
            "light through material \"%s\" (transmits %g): photons gathered where it lands",
            s->materials[clear].name, s->materials[clear].transmission);
    else
        say(p, VCT_EFFECT_CAUSTICS, 0, "%s",
            clear >= 0 ? "nothing sends light through it" : "no transmissive material");

    for (int e = 0; force && e < VCT_EFFECTS; ++e) {
        if (force[e] == VCT_FORCE_AUTO)
            continue;
        char scene_said[160];
        snprintf(scene_said, sizeof scene_said, "%s", p->why[e]);
        const int on = force[e] == VCT_FORCE_ON;
        say(p, (vct_effect)e, on, "forced %s (the scene alone: %s, %s)", on ? "on" : "off",
            p->on[e] ? "on" : "off", scene_said);
        p->forced[e] = 1;
    }
    /* Soft shadows replace shadow rays: nothing to soften without them. */
    if (p->on[VCT_EFFECT_SOFT_SHADOWS] && !(p->on[VCT_EFFECT_SHADOWS] && p->on[VCT_EFFECT_DIRECT]))
        say(p, VCT_EFFECT_SOFT_SHADOWS, 0, "%s is off",
            p->on[VCT_EFFECT_DIRECT] ? "shadows" : "direct light");
}

int vct_plan_needs_voxels(const vct_plan *p) {
    return p->on[VCT_EFFECT_INDIRECT] || p->on[VCT_EFFECT_SPECULAR] || p->on[VCT_EFFECT_AO] ||
           p->on[VCT_EFFECT_SOFT_SHADOWS];
}

int vct_plan_needs_voxel_light(const vct_plan *p) {
    return p->on[VCT_EFFECT_INDIRECT] || p->on[VCT_EFFECT_SPECULAR];
}
