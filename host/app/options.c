/* Command-line parsing: getopt_long over the command's groups of options
 * (option_table.c); every value is checked, and every error names the
 * option. */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "options.h"

/* getopt_long's return for an option: past every character it returns. */
#define LONG_ID_BASE 256
#define MAX_LONG_OPTIONS 96

typedef struct parse_state {
    const char *who;  /* "vct render", named in every message */
    const char *name; /* the option being read, with its dashes */
} parse_state;

static int fail(const parse_state *ps, const char *fmt, const char *a, const char *b) {
    fprintf(stderr, "%s: ", ps->who);
    fprintf(stderr, fmt, a, b);
    fputc('\n', stderr);
    return 2;
}

static int to_float(const parse_state *ps, const char *word, float *out) {
    char *end = NULL;
    *out = strtof(word, &end);
    if (!end || *end || end == word || !isfinite(*out))
        return fail(ps, "%s: \"%s\" is not a finite number", ps->name, word);
    return 0;
}

static int to_floats(const parse_state *ps, char **words, int count, float *out) {
    for (int k = 0; k < count; ++k)
        if (to_float(ps, words[k], &out[k]))
            return 2;
    return 0;
}

static int to_int(const parse_state *ps, const char *word, int lo, int hi, int *out) {
    char *end = NULL;
    long v = strtol(word, &end, 10);
    if (!end || *end || end == word || v < lo || v > hi) {
        fprintf(stderr, "%s: %s: \"%s\" is not an integer in %d..%d\n", ps->who, ps->name, word, lo,
                hi);
        return 2;
    }
    *out = (int)v;
    return 0;
}

/* The index of word in a |-separated list of choices, or a message. */
static int choose(const parse_state *ps, const char *word, const char *choices, int *out) {
    const size_t len = strlen(word);
    int index = 0;
    for (const char *c = choices; *c; ++index) {
        const char *bar = strchr(c, '|');
        const size_t n = bar ? (size_t)(bar - c) : strlen(c);
        if (n == len && strncmp(c, word, n) == 0) {
            *out = index;
            return 0;
        }
        c += n + (bar != NULL);
    }
    /* "a|b|c" read out as "a, b or c" */
    fprintf(stderr, "%s: %s takes ", ps->who, ps->name);
    for (const char *c = choices; *c; ++c) {
        if (*c == '|')
            fputs(strchr(c + 1, '|') ? ", " : " or ", stderr);
        else
            fputc(*c, stderr);
    }
    fprintf(stderr, ", not \"%s\"\n", word);
    return 2;
}

static int add_light(const parse_state *ps, cli_options *opt, vct_light_type type,
                     const float v[6]) {
    if (opt->light_count == MAX_CLI_LIGHTS) {
        fprintf(stderr, "%s: at most %d lights on the command line\n", ps->who, MAX_CLI_LIGHTS);
        return 2;
    }
    if (type == VCT_LIGHT_DIRECTIONAL && v[0] == 0.0f && v[1] == 0.0f && v[2] == 0.0f)
        return fail(ps, "%s: the direction must not be zero%s", ps->name, "");
    vct_light *l = &opt->lights[opt->light_count++];
    memset(l, 0, sizeof *l);
    l->type = type;
    for (int k = 0; k < 3; ++k) {
        if (type == VCT_LIGHT_DIRECTIONAL)
            l->direction[k] = v[k];
        else
            l->position[k] = v[k];
        l->color[k] = v[3 + k];
    }
    return 0;
}

/* NAME=on|off */
static int apply_effect(const parse_state *ps, const char *arg, cli_options *opt) {
    char name[32];
    const char *eq = strchr(arg, '=');
    const size_t len = eq ? (size_t)(eq - arg) : 0;
    int e = -1;
    if (eq && len < sizeof name) {
        memcpy(name, arg, len);
        name[len] = '\0';
        e = vct_effect_from_name(name);
    }
    const char *value = eq ? eq + 1 : "";
    const int on = strcmp(value, "on") == 0, off = strcmp(value, "off") == 0;
    if (e < 0 || !(on || off)) {
        fprintf(stderr, "%s: --effect takes NAME=on or NAME=off, NAME one of:", ps->who);
        for (int k = 0; k < VCT_EFFECTS; ++k)
            fprintf(stderr, " %s", vct_effect_name((vct_effect)k));
        fprintf(stderr, " (got \"%s\")\n", arg);
        return 2;
    }
    opt->force[e] = on ? VCT_FORCE_ON : VCT_FORCE_OFF;
    return 0;
}

static int positive(const parse_state *ps, char **w, float *out, const char *what) {
    if (to_float(ps, w[0], out))
        return 2;
    return *out > 0.0f ? 0 : fail(ps, "%s must be %s", ps->name, what);
}

/* Photon mapping's options. */
static int apply_pm(const parse_state *ps, cli_option_id id, char **w, cli_pm *pm) {
    int choice = 0;
    switch (id) {
    case OPT_PHOTONS:
        return to_int(ps, w[0], 1, 1 << 30, &pm->photons);
    case OPT_FINAL_GATHER:
        return to_int(ps, w[0], 1, 1024, &pm->final_gather_rays);
    case OPT_PM_FIXED:
        pm->fixed = 1;
        return 0;
    case OPT_PM_DIRECT_PHOTONS:
        pm->direct_photons = 1;
        return 0;
    case OPT_PM_RADIUS:
        return positive(ps, w, &pm->radius, "a positive distance");
    case OPT_PM_CAUSTIC_RADIUS:
        return positive(ps, w, &pm->caustic_radius, "a positive distance");
    case OPT_PM_ALPHA:
        pm->has_alpha = 1;
        if (to_float(ps, w[0], &pm->alpha))
            return 2;
        return pm->alpha > 0.0f && pm->alpha <= 1.0f
                   ? 0
                   : fail(ps, "%s must be in (0, 1]%s", ps->name, "");
    case OPT_PM_KERNEL:
        if (choose(ps, w[0], "box|epanechnikov", &choice))
            return 2;
        pm->kernel_box = choice == 0;
        return 0;
    case OPT_PM_NORMAL_FILTER:
        pm->has_normal_cos = 1;
        if (strcmp(w[0], "off") == 0) {
            pm->normal_cos = -2.0f;
            return 0;
        }
        if (to_float(ps, w[0], &pm->normal_cos))
            return 2;
        return pm->normal_cos >= -1.0f && pm->normal_cos <= 1.0f
                   ? 0
                   : fail(ps, "%s takes a cosine in [-1, 1] or off%s", ps->name, "");
    default:
        return -1;
    }
}

/* Cone tracing's and the voxels' options. */
static int apply_vct(const parse_state *ps, cli_option_id id, char **w, cli_options *opt) {
    int choice = 0;
    switch (id) {
    case OPT_PLAN:
        opt->print_plan = 1;
        return 0;
    case OPT_EFFECT:
        return apply_effect(ps, w[0], opt);
    case OPT_CONES:
        return to_int(ps, w[0], 1, 16, &opt->diffuse_cones);
    case OPT_CONE_STEP:
        return to_float(ps, w[0], &opt->cones.step); /* the library names a bad step */
    case OPT_CONE_OFFSET:
        return to_float(ps, w[0], &opt->cones.offset);
    case OPT_CONE_LEVELS:
        return choose(ps, w[0], "blend|nearest", &opt->cones.nearest_level);
    case OPT_DENSE_DIFFUSE:
        opt->sparse_diffuse = 0;
        return 0;
    case OPT_INDIRECT_FILTER:
        return to_int(ps, w[0], 0, (int)VCT_INDIRECT_PASSES_MAX, &opt->indirect_passes);
    case OPT_EDGE_SAMPLES:
        return to_int(ps, w[0], 1, (int)VCT_EDGE_SAMPLES_MAX, &opt->edge_samples);
    case OPT_AO_DISTANCE:
        return to_float(ps, w[0], &opt->cones.ao_distance);
    case OPT_BOUNCES:
        return to_int(ps, w[0], 1, 4, &opt->bounces);
    case OPT_DENSE_BOUNCES:
        opt->dense_bounces = 1;
        return 0;
    case OPT_EXACT_BOUNCES:
        opt->exact_bounces = 1;
        return 0;
    case OPT_LIGHT_CARRY:
        opt->light_carry = 1;
        return 0;
    case OPT_EMITTERS:
        return choose(ps, w[0], "rays|cones", &opt->emitters_by_cones);
    case OPT_COPY_VOXELS:
        opt->copy_voxels = 1;
        return 0;
    case OPT_VOXEL_RES:
        if (to_int(ps, w[0], 2, 1024, &opt->voxel_res))
            return 2;
        return opt->voxel_res & (opt->voxel_res - 1)
                   ? fail(ps, "%s must be a power of two (2, 4, ..., 1024)%s", ps->name, "")
                   : 0;
    case OPT_THIN:
        opt->thin_voxels = 1;
        return 0;
    case OPT_VOXEL_BOUNDS:
        opt->has_voxel_bounds = 1;
        if (to_floats(ps, w, 4, opt->voxel_bounds))
            return 2;
        return opt->voxel_bounds[3] > 0.0f
                   ? 0
                   : fail(ps, "%s: the size must be positive%s", ps->name, "");
    case OPT_BRICKS:
        if (choose(ps, w[0], "auto|buffer|image", &choice))
            return 2;
        opt->bricks = choice == 0   ? VCT_BRICKS_AUTO
                      : choice == 1 ? VCT_BRICKS_BUFFER
                                    : VCT_BRICKS_IMAGE;
        return 0;
    case OPT_ANISOTROPIC:
    case OPT_ISOTROPIC:
        opt->anisotropic = id == OPT_ANISOTROPIC;
        return 0;
    default:
        return apply_pm(ps, id, w, &opt->pm);
    }
}

/* Ray tracing's options: acceleration, sampling, subsampling. */
static int apply_rays(const parse_state *ps, cli_option_id id, char **w, int nw, cli_options *opt) {
    int choice = 0;
    switch (id) {
    case OPT_ACCEL:
        if (choose(ps, w[0], "bvh|grid", &choice))
            return 2;
        opt->accel.kind = (vct_accel_kind)vct_accel_kind_from_name(w[0]);
        return 0;
    case OPT_BVH_BUILD:
        if (choose(ps, w[0], "clustered|linear", &choice))
            return 2;
        opt->accel.bvh_builder = choice == 0 ? VCT_BVH_PLOC : VCT_BVH_LINEAR;
        return 0;
    case OPT_BVH_LEVELS:
        if (choose(ps, w[0], "auto|one|two", &choice))
            return 2;
        opt->accel.bvh_levels = (vct_bvh_levels)choice;
        return 0;
    case OPT_GRID_RES:
        for (int k = 0; k < 3; ++k) {
            int r = 0;
            if (to_int(ps, w[nw == 1 ? 0 : k], 1, 1024, &r))
                return 2;
            opt->accel.grid_res[k] = (uint32_t)r;
        }
        return 0;
    case OPT_SPP:
        return to_int(ps, w[0], 1, 1 << 24, &opt->spp);
    case OPT_TIME:
        return positive(ps, w, &opt->time_limit, "positive (seconds)");
    case OPT_MAX_DEPTH:
        return to_int(ps, w[0], 1, 1024, &opt->max_depth);
    case OPT_SEED:
        return to_int(ps, w[0], 0, 2147483647, &opt->seed);
    case OPT_SUBSAMPLE:
        return to_int(ps, w[0], 0, 16384, &opt->subsample);
    case OPT_NO_GUARD:
        opt->subsample_plain = 1;
        return 0;
    case OPT_CONTRAST:
        if (to_float(ps, w[0], &opt->contrast))
            return 2;
        return opt->contrast >= 0.0f ? 0 : fail(ps, "%s must be 0 or more%s", ps->name, "");
    default:
        return apply_vct(ps, id, w, opt);
    }
}

/* One option with its nw words. */
static int apply(const parse_state *ps, cli_option_id id, char **w, int nw, cli_options *opt) {
    float v[6];
    int choice = 0;
    switch (id) {
    case OPT_OUTPUT:
        opt->output = w[0];
        return 0;
    case OPT_STATS:
        opt->stats = 1;
        return 0;
    case OPT_EXPOSURE:
        opt->tone.auto_exposure = 0;
        return to_float(ps, w[0], &opt->tone.exposure);
    case OPT_TONE:
        if (choose(ps, w[0], "filmic|clip", &choice))
            return 2;
        opt->tone.curve = choice == 0 ? VCT_TONE_FILMIC : VCT_TONE_CLIP;
        return 0;
    case OPT_AOV:
        opt->aov = 1;
        return 0;
    case OPT_DENOISE:
        opt->denoise = 1;
        return 0;
    case OPT_EXR:
        return choose(ps, w[0], "half|float", &opt->exr_float);
    case OPT_DEVICE:
        opt->device = w[0];
        return 0;
    case OPT_SIZE:
        return to_int(ps, w[0], 1, 16384, &opt->width) || to_int(ps, w[1], 1, 16384, &opt->height)
                   ? 2
                   : 0;
    case OPT_CAMERA_POS:
        opt->has_camera_pos = 1;
        return to_floats(ps, w, 3, opt->camera_pos);
    case OPT_LOOK_AT:
        opt->has_look_at = 1;
        return to_floats(ps, w, 3, opt->look_at);
    case OPT_UP:
        opt->has_up = 1;
        return to_floats(ps, w, 3, opt->up);
    case OPT_FOV:
        opt->has_fov = 1;
        if (to_float(ps, w[0], &opt->fov))
            return 2;
        return opt->fov > 0.0f && opt->fov < 179.0f
                   ? 0
                   : fail(ps, "%s must lie in (0, 179) degrees%s", ps->name, "");
    case OPT_POINT_LIGHT:
    case OPT_DIR_LIGHT:
        return to_floats(ps, w, 6, v) ||
                       add_light(ps, opt,
                                 id == OPT_POINT_LIGHT ? VCT_LIGHT_POINT : VCT_LIGHT_DIRECTIONAL, v)
                   ? 2
                   : 0;
    case OPT_LIGHT_RADIUS:
        opt->has_light_radius = 1;
        return to_float(ps, w[0], &opt->light_radius);
    case OPT_AMBIENT:
        opt->has_ambient = 1;
        return to_floats(ps, w, 3, opt->ambient);
    case OPT_FRAME:
        return to_int(ps, w[0], 0, 1000000, &opt->frame);
    case OPT_FRAMES: {
        int a = -1, b = -1, used = 0;
        if (sscanf(w[0], "%d:%d%n", &a, &b, &used) != 2 || w[0][used] || a < 0 || b < a)
            return fail(ps, "%s takes A:B, two frame numbers from 0 with A <= B, not %s", ps->name,
                        w[0]);
        opt->frames[0] = a;
        opt->frames[1] = b;
        return 0;
    }
    case OPT_FPS:
        if (to_float(ps, w[0], &opt->fps))
            return 2;
        if (!(opt->fps > 0.0f))
            return fail(ps, "%s takes frames per second above 0, not %s", ps->name, w[0]);
        return 0;
    case OPT_RESUME:
        opt->resume_frames = 1;
        return 0;
    case OPT_VIDEO:
        opt->video = w[0];
        return 0;
    case OPT_METHOD:
        opt->method = w[0];
        return 0;
    case OPT_ERROR_IMAGE:
        opt->error_image = w[0];
        return 0;
    case OPT_ERROR_SCALE:
        return to_float(ps, w[0], &opt->error_scale);
    case OPT_CAPTURE:
        opt->capture = w[0];
        return 0;
    case OPT_KEYS:
        opt->keys = w[0];
        return 0;
    case OPT_DISPLAY:
        opt->display = w[0];
        return choose(ps, w[0], "auto|interop|host", &choice);
    default:
        return apply_rays(ps, id, w, nw, opt);
    }
}

static void defaults(cli_options *opt) {
    memset(opt, 0, sizeof *opt);
    opt->width = opt->height = 512;
    opt->tone = vct_tone_default();
    opt->method = "vct";
    opt->diffuse_cones = 9;
    opt->sparse_diffuse = 1;
    opt->edge_samples = (int)VCT_EDGE_SAMPLES_DEFAULT;
    opt->indirect_passes = (int)VCT_INDIRECT_PASSES_DEFAULT;
    opt->bounces = (int)VCT_DEFAULT_BOUNCES;
    opt->frame = -1;
    opt->frames[0] = opt->frames[1] = -1;
    opt->fps = 24.0f;
    opt->anisotropic = -1; /* the library's choice unless given */
    opt->cones = vct_cone_settings_default();
    opt->contrast = VCT_SUBSAMPLE_CONTRAST_DEFAULT;
}

static const cli_option help_option = {"help", 'h', OPT_HELP, 0, NULL, "this help"};

/* The command's rows by getopt's id, and getopt's table of them. */
typedef struct option_index {
    const cli_option *rows[OPT_COUNT];
    struct option longs[MAX_LONG_OPTIONS + 1];
} option_index;

static void index_command(const cli_command *cmd, option_index *ix) {
    memset(ix, 0, sizeof *ix);
    int n = 0;
    ix->rows[OPT_HELP] = &help_option;
    ix->longs[n++] = (struct option){"help", no_argument, NULL, LONG_ID_BASE + OPT_HELP};
    for (const cli_option_group *const *g = cmd->groups; g && *g; ++g)
        for (int i = 0; i < (*g)->count && n < MAX_LONG_OPTIONS; ++i) {
            const cli_option *o = &(*g)->options[i];
            ix->rows[o->id] = o;
            ix->longs[n++] = (struct option){o->name, o->words ? required_argument : no_argument,
                                             NULL, LONG_ID_BASE + o->id};
        }
}

/* The name of the command that takes an option this one does not. */
static const char *taken_by(const char *name) {
    for (const cli_command *const *c = vct_commands; *c; ++c)
        for (const cli_option_group *const *g = (*c)->groups; g && *g; ++g)
            for (int i = 0; i < (*g)->count; ++i)
                if (strcmp((*g)->options[i].name, name) == 0)
                    return (*c)->name;
    return NULL;
}

static int unknown_option(const parse_state *ps, const char *word) {
    char name[64];
    const char *dashes = strncmp(word, "--", 2) == 0 ? word + 2 : "";
    snprintf(name, sizeof name, "%.*s", (int)strcspn(dashes, "="), dashes);
    const char *other = *name ? taken_by(name) : NULL;
    if (other)
        fprintf(stderr, "%s: --%s is not an option of this command (it is one of vct %s's)\n",
                ps->who, name, other);
    else
        fprintf(stderr, "%s: unknown option %s (see %s --help)\n", ps->who, word, ps->who);
    return 2;
}

int cli_parse(const cli_command *cmd, const char *program, int argc, char **argv,
              cli_options *opt) {
    defaults(opt);
    opt->command = cmd;
    char who[96];
    snprintf(who, sizeof who, "%s%s%s", program, cmd->name[0] ? " " : "", cmd->name);
    parse_state ps = {who, NULL};
    option_index ix;
    index_command(cmd, &ix);
    opterr = 0;
    optind = 0; /* glibc: a full reset, as for a first call */
    for (;;) {
        /* -o only where the command writes an image */
        const int c = getopt_long(argc, argv, ix.rows[OPT_OUTPUT] ? ":ho:" : ":h", ix.longs, NULL);
        if (c == -1)
            break;
        if (c == '?')
            return unknown_option(&ps, optopt ? (char[3]){'-', (char)optopt, 0} : argv[optind - 1]);
        if (c == ':') {
            if (optopt >= LONG_ID_BASE)
                fprintf(stderr, "%s: --%s needs a value: %s\n", who,
                        ix.rows[optopt - LONG_ID_BASE]->name,
                        ix.rows[optopt - LONG_ID_BASE]->metavar);
            else
                fprintf(stderr, "%s: -%c needs a value\n", who, optopt);
            return 2;
        }
        const cli_option_id id = c == 'h'   ? OPT_HELP
                                 : c == 'o' ? OPT_OUTPUT
                                            : (cli_option_id)(c - LONG_ID_BASE);
        if (id == OPT_HELP) {
            cli_print_help(stdout, program, cmd);
            return -1;
        }
        const cli_option *row = ix.rows[id];
        char name[72];
        snprintf(name, sizeof name, "--%s", row->name);
        ps.name = name;
        /* getopt hands over the first word; the rest follow it. */
        char *words[6] = {optarg};
        int nw = row->words ? 1 : 0;
        const int more = row->words == CLI_ONE_OR_THREE ? 2 : row->words - 1;
        for (int k = 0; k < more; ++k) {
            const char *next = optind < argc ? argv[optind] : NULL;
            if (row->words == CLI_ONE_OR_THREE && !(next && next[0] >= '0' && next[0] <= '9'))
                break;
            if (!next) {
                fprintf(stderr, "%s: %s needs %d values: %s\n", who, name, row->words,
                        row->metavar);
                return 2;
            }
            words[nw++] = argv[optind++];
        }
        if (row->words == CLI_ONE_OR_THREE && nw == 2)
            return fail(&ps, "%s takes one number or three%s", name, "");
        const int rc = apply(&ps, id, words, nw, opt);
        if (rc)
            return rc < 0 ? fail(&ps, "internal: %s has no handler%s", name, "") : rc;
    }
    for (int i = optind; i < argc; ++i) {
        if (opt->input_count == 2 || opt->input_count == cmd->max_operands) {
            fprintf(stderr, "%s: unexpected argument \"%s\" (see %s --help)\n", who, argv[i], who);
            return 2;
        }
        opt->inputs[opt->input_count++] = argv[i];
    }
    if (opt->input_count < cmd->min_operands) {
        fprintf(stderr, "%s: give %s (see %s --help)\n", who, cmd->operands, who);
        return 2;
    }
    return 0;
}
