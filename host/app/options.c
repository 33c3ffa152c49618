/* Command-line parsing: every numeric argument is checked, every error names
 * the option. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "options.h"

void cli_usage(void) {
    fputs(
        "usage:\n"
        "  vct devices                      list OpenCL devices and their limits\n"
        "  vct info SCENE                   load and validate a scene, print what it holds\n"
        "  vct render SCENE [-o OUT.png|OUT.pfm] [options]\n"
        "  vct voxelize SCENE [-o VOXELS.png] [--voxel-res N] [--thin] [--voxel-bounds X Y Z S]\n"
        "               [--bricks auto|buffer|image] [--anisotropic]\n"
        "                                   voxelize, build the sparse voxel octree and its\n"
        "                                   filtered bricks, inject light, report counts,\n"
        "                                   memory and time; -o renders the voxels\n"
        "  vct compare TEST.pfm REFERENCE.pfm [--error-image ERR.png] [--error-scale E]\n"
        "                                   RMSE, relative MSE, PSNR and mean absolute error\n"
        "\n"
        "render options:\n"
        "  --method vct                     voxel cone tracing (default): --plan prints the\n"
        "                                   effect plan; --effect NAME=on|off forces one\n"
        "                                   (direct, shadows, indirect, specular, refraction,\n"
        "                                   emission, ao, soft_shadows); --cones 1|5|6|9|16\n"
        "                                   diffuse cones (default 9); --cone-step F\n"
        "                                   (fraction of the diameter, 1); --cone-offset V\n"
        "                                   (voxels, 4); --cone-levels blend|nearest (a\n"
        "                                   sample blends two octree levels, or reads one);\n"
        "                                   --sparse-diffuse: diffuse cones at every other\n"
        "                                   pixel per axis, the rest filled in from the\n"
        "                                   traced neighbours on the same surface;\n"
        "                                   --edge-samples N: N x N camera rays at pixels on\n"
        "                                   an edge (surface, material, hard shadow), which\n"
        "                                   show their mean (default 4; 1: pixel centres);\n"
        "                                   --ao-distance F (of the volume, 0.125);\n"
        "                                   --bounces 1..4 light bounces in the voxels (4),\n"
        "                                   then the rest of the series at the scene's\n"
        "                                   bounce ratio; --exact-bounces: no rest;\n"
        "                                   --isotropic: one radiance per brick sample\n"
        "                                   (default), --anisotropic: six directional values;\n"
        "                                   --aov PREFIX writes PREFIX_direct.pfm, _indirect,\n"
        "                                   _specular, _ao, _level, _position, _normal;\n"
        "                                   --voxel-res, --bricks as for voxelize\n"
        "  --method raycast                 direct light with hard shadows\n"
        "  --method pt                      path tracing (the reference): --spp N or --time S,\n"
        "                                   --max-depth D (default 16), --seed N\n"
        "  --method whitted                 Whitted ray trees: mirrors, Fresnel refraction and\n"
        "                                   total internal reflection, hard shadows;\n"
        "                                   --max-depth D (default 8, at most 16),\n"
        "                                   --subsample N: rays at the corners of N x N squares\n"
        "                                   (a power of two), squares whose corners agree\n"
        "                                   interpolated, the others split (default 0: off);\n"
        "                                   --no-guard: also squares that a piece of the mesh\n"
        "                                   smaller than the square touches (the seed's way);\n"
        "                                   --contrast C: corners whose radiance spreads by more\n"
        "                                   than C of their mean disagree too (default 0)\n"
        "  --method pm                      photon mapping, progressive (SPPM): --spp N passes\n"
        "                                   or --time S; --photons N per pass (131072);\n"
        "                                   --pm-radius R, --pm-caustic-radius R: initial radii\n"
        "                                   (default 1.5 %% of the scene's size; fixed: the\n"
        "                                   caustic radius half that);\n"
        "                                   --pm-alpha A (2/3); --pm-fixed: the seed's fixed\n"
        "                                   radii; --final-gather N: the global map read at the\n"
        "                                   hits of N rays per pixel and pass; "
        "--pm-direct-photons:\n"
        "                                   direct light from photons too (no shadow rays);\n"
        "                                   --pm-kernel box|epanechnikov (default);\n"
        "                                   --pm-normal-filter C|off: photons whose normal's\n"
        "                                   cosine with the surface's is below C are not\n"
        "                                   counted (0: those facing away; the seed: 0.7);\n"
        "                                   --max-depth, --seed as for pt\n"
        "  --size W H                       image size in pixels (default 512 512)\n"
        "  --camera-pos X Y Z  --look-at X Y Z  --up X Y Z  --fov DEGREES (vertical)\n"
        "  --point-light X Y Z R G B        radiant intensity in W/sr (repeatable)\n"
        "  --dir-light DX DY DZ R G B       irradiance, travelling along D (repeatable)\n"
        "  --light-radius R                 every light's size for soft shadows: world units\n"
        "                                   (point, spot), radians (directional); 0 = hard\n"
        "  --ambient R G B                  radiance arriving where nothing is hit\n"
        "  --accel bvh|grid    what rays traverse: the 4-wide BVH (default) or the\n"
        "                      uniform triangle grid\n"
        "  --bvh-build clustered|linear   the BVH's tree: agglomerative clustering (default,\n"
        "                      faster rays) or the linear hierarchy (faster build)\n"
        "  --grid-res N | --grid-res NX NY NZ   triangle grid cells (default: automatic)\n"
        "  --voxel-res N                    voxels per axis, a power of two up to 1024 (default\n"
        "                                   128 for render, 256 for voxelize)\n"
        "  --thin                           6-separating voxels (default: conservative)\n"
        "  --voxel-bounds X Y Z SIZE        voxel cube by hand (default: around the scene)\n"
        "  --bricks auto|buffer|image       brick pool kind (default auto: image3d on GPUs)\n"
        "  --anisotropic                    6 directional radiance values per brick sample\n"
        "  --exposure STOPS                 PNG only: scale by 2^STOPS (default: from the image,\n"
        "                                   its log-average luminance to middle grey)\n"
        "  --tone filmic|clip               PNG only: tone curve after the exposure (default\n"
        "                                   filmic, an ACES fit; clip: 1 and above is white)\n"
        "  --stats                          per-stage device time and memory\n"
        "  --device N|NAME                  OpenCL device (default $VCT_DEVICE, else first GPU,\n"
        "                                   else first CPU)\n"
        "  --device 0,2|all|gpu|cpu         render: several devices, one frame (path tracing\n"
        "                                   split by samples, the others by row bands)\n"
        "  --emitters rays|cones            vct: emissive triangles as lights sampled with shadow\n"
        "                                   rays (default), or through the voxels' cones alone\n"
        "  --copy-voxels                    several devices: the first builds the voxels, the\n"
        "                                   others copy them (default: each builds its own)\n",
        stderr);
}

static int parse_floats(int argc, char **argv, int *i, int count, float *out) {
    const char *name = argv[*i];
    if (*i + count >= argc) {
        fprintf(stderr, "vct: %s needs %d numbers\n", name, count);
        return 1;
    }
    for (int k = 0; k < count; ++k) {
        char *end = NULL;
        const char *arg = argv[*i + 1 + k];
        out[k] = strtof(arg, &end);
        if (!end || *end || end == arg || !isfinite(out[k])) {
            fprintf(stderr, "vct: %s: \"%s\" is not a finite number\n", name, arg);
            return 1;
        }
    }
    *i += count;
    return 0;
}

static int parse_int(int argc, char **argv, int *i, int lo, int hi, int *out) {
    const char *name = argv[*i];
    if (*i + 1 >= argc) {
        fprintf(stderr, "vct: %s needs a number\n", name);
        return 1;
    }
    char *end = NULL;
    long v = strtol(argv[*i + 1], &end, 10);
    if (!end || *end || v < lo || v > hi) {
        fprintf(stderr, "vct: %s: \"%s\" is not an integer in %d..%d\n", name, argv[*i + 1], lo,
                hi);
        return 1;
    }
    *out = (int)v;
    *i += 1;
    return 0;
}

/* --method pm's options: 0 parsed, 1 a bad value, -1 not one of them. */
static int parse_pm_option(int argc, char **argv, int *i, cli_pm *pm) {
    const char *a = argv[*i];
    if (strcmp(a, "--photons") == 0)
        return parse_int(argc, argv, i, 1, 1 << 30, &pm->photons);
    if (strcmp(a, "--final-gather") == 0)
        return parse_int(argc, argv, i, 1, 1024, &pm->final_gather_rays);
    if (strcmp(a, "--pm-fixed") == 0)
        return pm->fixed = 1, 0;
    if (strcmp(a, "--pm-direct-photons") == 0)
        return pm->direct_photons = 1, 0;
    if (strcmp(a, "--pm-radius") == 0 || strcmp(a, "--pm-caustic-radius") == 0) {
        float *r = strcmp(a, "--pm-radius") == 0 ? &pm->radius : &pm->caustic_radius;
        if (parse_floats(argc, argv, i, 1, r))
            return 1;
        if (!(*r > 0.0f)) {
            fprintf(stderr, "vct: %s must be a positive distance\n", a);
            return 1;
        }
        return 0;
    }
    if (strcmp(a, "--pm-alpha") == 0) {
        if (parse_floats(argc, argv, i, 1, &pm->alpha))
            return 1;
        if (!(pm->alpha > 0.0f && pm->alpha <= 1.0f)) {
            fprintf(stderr, "vct: --pm-alpha must be in (0, 1]\n");
            return 1;
        }
        pm->has_alpha = 1;
        return 0;
    }
    if (strcmp(a, "--pm-kernel") == 0) {
        const char *v = *i + 1 < argc ? argv[++*i] : "";
        if (strcmp(v, "box") && strcmp(v, "epanechnikov")) {
            fprintf(stderr, "vct: --pm-kernel takes box or epanechnikov, not '%s'\n", v);
            return 1;
        }
        pm->kernel_box = strcmp(v, "box") == 0;
        return 0;
    }
    if (strcmp(a, "--pm-normal-filter") == 0) {
        pm->has_normal_cos = 1;
        if (*i + 1 < argc && strcmp(argv[*i + 1], "off") == 0) {
            ++*i;
            pm->normal_cos = -2.0f;
            return 0;
        }
        if (parse_floats(argc, argv, i, 1, &pm->normal_cos))
            return 1;
        if (!(pm->normal_cos >= -1.0f && pm->normal_cos <= 1.0f)) {
            fprintf(stderr, "vct: --pm-normal-filter takes a cosine in [-1, 1] or off\n");
            return 1;
        }
        return 0;
    }
    return -1;
}

static int add_light(cli_options *opt, vct_light_type type, const float v[6]) {
    if (opt->light_count == MAX_CLI_LIGHTS) {
        fprintf(stderr, "vct: at most %d lights on the command line\n", MAX_CLI_LIGHTS);
        return 1;
    }
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
    if (type == VCT_LIGHT_DIRECTIONAL && v[0] == 0.0f && v[1] == 0.0f && v[2] == 0.0f) {
        fprintf(stderr, "vct: --dir-light: the direction must not be zero\n");
        return 1;
    }
    return 0;
}

/* --effect NAME=on|off */
static int parse_effect(int argc, char **argv, int *i, cli_options *opt) {
    const char *arg = *i + 1 < argc ? argv[++*i] : "";
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
        fprintf(stderr, "vct: --effect takes NAME=on or NAME=off, NAME one of:");
        for (int k = 0; k < VCT_EFFECTS; ++k)
            fprintf(stderr, " %s", vct_effect_name((vct_effect)k));
        fprintf(stderr, " (got '%s')\n", arg);
        return 1;
    }
    opt->force[e] = on ? VCT_FORCE_ON : VCT_FORCE_OFF;
    return 0;
}

int cli_parse(int argc, char **argv, cli_options *opt) {
    memset(opt, 0, sizeof *opt);
    opt->width = opt->height = 512;
    opt->tone = vct_tone_default();
    opt->method = "vct";
    opt->max_depth = 0; /* each method its own default */
    opt->voxel_res = 0; /* each command's own default */
    opt->diffuse_cones = 9;
    opt->edge_samples = (int)VCT_EDGE_SAMPLES_DEFAULT;
    opt->bounces = (int)VCT_DEFAULT_BOUNCES;
    opt->anisotropic = -1; /* off unless given (--anisotropic) */
    opt->cones = vct_cone_settings_default();
    if (argc < 2) {
        cli_usage();
        return 1;
    }
    opt->command = argv[1];
    for (int i = 2, pm_rc; i < argc; ++i) {
        const char *a = argv[i];
        float v[6];
        int n = 0;
        if (strcmp(a, "-o") == 0 || strcmp(a, "--output") == 0) {
            if (i + 1 >= argc) {
                fprintf(stderr, "vct: %s needs a file name\n", a);
                return 1;
            }
            opt->output = argv[++i];
        } else if (strcmp(a, "--device") == 0 || strcmp(a, "--method") == 0 ||
                   strcmp(a, "--error-image") == 0) {
            if (i + 1 >= argc) {
                fprintf(stderr, "vct: %s needs a value\n", a);
                return 1;
            }
            if (strcmp(a, "--device") == 0)
                opt->device = argv[++i];
            else if (strcmp(a, "--method") == 0)
                opt->method = argv[++i];
            else
                opt->error_image = argv[++i];
        } else if (strcmp(a, "--error-scale") == 0) {
            if (parse_floats(argc, argv, &i, 1, &opt->error_scale))
                return 1;
        } else if (strcmp(a, "--size") == 0) {
            if (parse_int(argc, argv, &i, 1, 16384, &opt->width) ||
                parse_int(argc, argv, &i, 1, 16384, &opt->height))
                return 1;
        } else if (strcmp(a, "--spp") == 0) {
            if (parse_int(argc, argv, &i, 1, 1 << 24, &opt->spp))
                return 1;
        } else if (strcmp(a, "--contrast") == 0) {
            if (parse_floats(argc, argv, &i, 1, &opt->contrast))
                return 1;
            if (!(opt->contrast >= 0.0f)) {
                fprintf(stderr, "vct: --contrast must be 0 or more\n");
                return 1;
            }
        } else if (strcmp(a, "--no-guard") == 0) {
            opt->subsample_plain = 1;
        } else if (strcmp(a, "--subsample") == 0) {
            if (parse_int(argc, argv, &i, 0, 16384, &opt->subsample))
                return 1;
        } else if (strcmp(a, "--max-depth") == 0) {
            if (parse_int(argc, argv, &i, 1, 1024, &opt->max_depth))
                return 1;
        } else if (strcmp(a, "--seed") == 0) {
            if (parse_int(argc, argv, &i, 0, 2147483647, &opt->seed))
                return 1;
        } else if (strcmp(a, "--time") == 0) {
            if (parse_floats(argc, argv, &i, 1, &opt->time_limit))
                return 1;
            if (!(opt->time_limit > 0.0f)) {
                fprintf(stderr, "vct: --time must be positive (seconds)\n");
                return 1;
            }
        } else if (strcmp(a, "--camera-pos") == 0) {
            if (parse_floats(argc, argv, &i, 3, opt->camera_pos))
                return 1;
            opt->has_camera_pos = 1;
        } else if (strcmp(a, "--look-at") == 0) {
            if (parse_floats(argc, argv, &i, 3, opt->look_at))
                return 1;
            opt->has_look_at = 1;
        } else if (strcmp(a, "--up") == 0) {
            if (parse_floats(argc, argv, &i, 3, opt->up))
                return 1;
            opt->has_up = 1;
        } else if (strcmp(a, "--fov") == 0) {
            if (parse_floats(argc, argv, &i, 1, &opt->fov))
                return 1;
            if (!(opt->fov > 0.0f && opt->fov < 179.0f)) {
                fprintf(stderr, "vct: --fov must lie in (0, 179) degrees\n");
                return 1;
            }
            opt->has_fov = 1;
        } else if (strcmp(a, "--point-light") == 0) {
            if (parse_floats(argc, argv, &i, 6, v) || add_light(opt, VCT_LIGHT_POINT, v))
                return 1;
        } else if (strcmp(a, "--dir-light") == 0) {
            if (parse_floats(argc, argv, &i, 6, v) || add_light(opt, VCT_LIGHT_DIRECTIONAL, v))
                return 1;
        } else if (strcmp(a, "--accel") == 0) {
            const int kind = i + 1 < argc ? vct_accel_kind_parse(argv[i + 1]) : -1;
            if (kind < 0) {
                fprintf(stderr, "vct: --accel takes bvh or grid\n");
                return 1;
            }
            opt->accel.kind = (vct_accel_kind)kind;
            ++i;
        } else if (strcmp(a, "--bvh-build") == 0) {
            const char *b = i + 1 < argc ? argv[i + 1] : "";
            if (strcmp(b, "clustered") && strcmp(b, "linear")) {
                fprintf(stderr, "vct: --bvh-build takes clustered or linear\n");
                return 1;
            }
            opt->accel.bvh_builder = strcmp(b, "linear") ? VCT_BVH_PLOC : VCT_BVH_LINEAR;
            ++i;
        } else if (strcmp(a, "--grid-res") == 0) {
            int r[3];
            if (parse_int(argc, argv, &i, 1, 1024, &r[0]))
                return 1;
            /* One number or three. */
            n = 1;
            while (n < 3 && i + 1 < argc && argv[i + 1][0] >= '0' && argv[i + 1][0] <= '9') {
                if (parse_int(argc, argv, &i, 1, 1024, &r[n]))
                    return 1;
                ++n;
            }
            if (n == 2) {
                fprintf(stderr, "vct: --grid-res takes one number or three\n");
                return 1;
            }
            for (int k = 0; k < 3; ++k)
                opt->accel.grid_res[k] = (uint32_t)(n == 1 ? r[0] : r[k]);
        } else if (strcmp(a, "--voxel-res") == 0) {
            if (parse_int(argc, argv, &i, 2, 1024, &opt->voxel_res))
                return 1;
            if (opt->voxel_res & (opt->voxel_res - 1)) {
                fprintf(stderr, "vct: --voxel-res must be a power of two (2, 4, ..., 1024)\n");
                return 1;
            }
        } else if (strcmp(a, "--thin") == 0) {
            opt->thin_voxels = 1;
        } else if (strcmp(a, "--exact-bounces") == 0) {
            opt->exact_bounces = 1;
        } else if (strcmp(a, "--voxel-bounds") == 0) {
            if (parse_floats(argc, argv, &i, 4, opt->voxel_bounds))
                return 1;
            if (!(opt->voxel_bounds[3] > 0.0f)) {
                fprintf(stderr, "vct: --voxel-bounds: the size must be positive\n");
                return 1;
            }
            opt->has_voxel_bounds = 1;
        } else if (strcmp(a, "--bricks") == 0) {
            const char *kind = i + 1 < argc ? argv[++i] : "";
            if (strcmp(kind, "auto") == 0)
                opt->bricks = VCT_BRICKS_AUTO;
            else if (strcmp(kind, "buffer") == 0)
                opt->bricks = VCT_BRICKS_BUFFER;
            else if (strcmp(kind, "image") == 0)
                opt->bricks = VCT_BRICKS_IMAGE;
            else {
                fprintf(stderr, "vct: --bricks takes auto, buffer or image, not '%s'\n", kind);
                return 1;
            }
        } else if (strcmp(a, "--anisotropic") == 0) {
            opt->anisotropic = 1;
        } else if (strcmp(a, "--isotropic") == 0) {
            opt->anisotropic = 0;
        } else if (strcmp(a, "--ambient") == 0) {
            if (parse_floats(argc, argv, &i, 3, opt->ambient))
                return 1;
            opt->has_ambient = 1;
        } else if (strcmp(a, "--light-radius") == 0) {
            if (parse_floats(argc, argv, &i, 1, &opt->light_radius))
                return 1;
            opt->has_light_radius = 1;
        } else if (strcmp(a, "--plan") == 0) {
            opt->print_plan = 1;
        } else if (strcmp(a, "--effect") == 0) {
            if (parse_effect(argc, argv, &i, opt))
                return 1;
        } else if (strcmp(a, "--cones") == 0) {
            if (parse_int(argc, argv, &i, 1, 16, &opt->diffuse_cones))
                return 1;
        } else if (strcmp(a, "--edge-samples") == 0) {
            if (parse_int(argc, argv, &i, 1, (int)VCT_EDGE_SAMPLES_MAX, &opt->edge_samples))
                return 1;
        } else if (strcmp(a, "--bounces") == 0) {
            if (parse_int(argc, argv, &i, 1, 4, &opt->bounces))
                return 1;
        } else if (strcmp(a, "--cone-step") == 0) {
            if (parse_floats(argc, argv, &i, 1, &opt->cones.step))
                return 1;
        } else if (strcmp(a, "--cone-levels") == 0) {
            const char *how = i + 1 < argc ? argv[++i] : "";
            if (strcmp(how, "blend") == 0)
                opt->cones.nearest_level = 0;
            else if (strcmp(how, "nearest") == 0)
                opt->cones.nearest_level = 1;
            else {
                fprintf(stderr, "vct: --cone-levels takes blend or nearest, not '%s'\n", how);
                return 1;
            }
        } else if (strcmp(a, "--emitters") == 0) {
            const char *how = i + 1 < argc ? argv[++i] : "";
            if (strcmp(how, "rays") != 0 && strcmp(how, "cones") != 0) {
                fprintf(stderr, "vct: --emitters takes rays or cones, not '%s'\n", how);
                return 1;
            }
            opt->emitters_by_cones = strcmp(how, "cones") == 0;
        } else if (strcmp(a, "--copy-voxels") == 0) {
            opt->copy_voxels = 1;
        } else if (strcmp(a, "--sparse-diffuse") == 0) {
            opt->sparse_diffuse = 1;
        } else if (strcmp(a, "--cone-offset") == 0) {
            if (parse_floats(argc, argv, &i, 1, &opt->cones.offset))
                return 1;
        } else if (strcmp(a, "--ao-distance") == 0) {
            if (parse_floats(argc, argv, &i, 1, &opt->cones.ao_distance))
                return 1;
        } else if (strcmp(a, "--aov") == 0) {
            if (i + 1 >= argc) {
                fprintf(stderr, "vct: --aov needs a file name prefix\n");
                return 1;
            }
            opt->aov_prefix = argv[++i];
        } else if (strcmp(a, "--exposure") == 0) {
            if (parse_floats(argc, argv, &i, 1, &opt->tone.exposure))
                return 1;
            opt->tone.auto_exposure = 0;
        } else if (strcmp(a, "--tone") == 0) {
            const char *v = i + 1 < argc ? argv[++i] : "";
            if (strcmp(v, "filmic") == 0)
                opt->tone.curve = VCT_TONE_FILMIC;
            else if (strcmp(v, "clip") == 0)
                opt->tone.curve = VCT_TONE_CLIP;
            else {
                fprintf(stderr, "vct: --tone takes filmic or clip, not '%s'\n", v);
                return 1;
            }
        } else if (strcmp(a, "--stats") == 0) {
            opt->stats = 1;
        } else if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0) {
            cli_usage();
            exit(0);
        } else if ((pm_rc = parse_pm_option(argc, argv, &i, &opt->pm)) >= 0) {
            if (pm_rc)
                return 1;
        } else if (a[0] == '-' && a[1] != '\0') {
            fprintf(stderr, "vct: unknown option %s (see vct --help)\n", a);
            return 1;
        } else if (opt->input_count < 2) {
            opt->inputs[opt->input_count++] = a;
        } else {
            fprintf(stderr, "vct: unexpected argument %s\n", a);
            return 1;
        }
    }
    return 0;
}

int cli_apply_scene_overrides(const cli_options *opt, vct_scene *s, vct_error *err) {
    for (int k = 0; k < 3; ++k) {
        if (opt->has_camera_pos)
            s->camera.position[k] = opt->camera_pos[k];
        if (opt->has_look_at)
            s->camera.look_at[k] = opt->look_at[k];
        if (opt->has_up)
            s->camera.up[k] = opt->up[k];
    }
    if (opt->has_fov)
        s->camera.fov_y_deg = opt->fov;
    if (opt->has_ambient) {
        memcpy(s->ambient, opt->ambient, sizeof s->ambient);
        int rc = vct_scene_validate(s, err);
        if (rc)
            return rc;
    }
    for (int i = 0; i < opt->light_count; ++i) {
        int rc = vct_scene_add_light(s, &opt->lights[i], err);
        if (rc)
            return rc;
    }
    for (uint32_t i = 0; opt->has_light_radius && i < s->light_count; ++i)
        s->lights[i].radius = opt->light_radius;
    return opt->has_light_radius ? vct_scene_validate(s, err) : VCT_OK;
}
