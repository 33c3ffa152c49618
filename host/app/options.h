/* Command-line options shared by the vct commands. */
#ifndef VCT_APP_OPTIONS_H
#define VCT_APP_OPTIONS_H

#include <stdio.h>

#include "option_table.h"
#include "vct/vct.h"

#define MAX_CLI_LIGHTS 16

/* --method pm's options; 0 where not given (the library's defaults). */
typedef struct cli_pm {
    int photons, final_gather_rays, fixed, direct_photons, kernel_box;
    float radius, caustic_radius, alpha, normal_cos;
    int has_alpha, has_normal_cos;
} cli_pm;

struct cli_options {
    const cli_command *command;
    const char *inputs[2];
    int input_count;
    const char *output;
    const char *device;
    const char *method;
    const char *error_image;
    float error_scale;
    int width, height;
    int spp, max_depth, seed;
    int subsample;       /* whitted: --subsample N, 0 off */
    int subsample_plain; /* whitted: --no-guard */
    float contrast;      /* whitted: --contrast C */
    float time_limit;
    int stats;
    vct_tone tone;           /* PNG: exposure and curve */
    vct_accel_options accel; /* --accel, --grid-res */
    int has_camera_pos, has_look_at, has_up, has_fov;
    float camera_pos[3], look_at[3], up[3], fov;
    vct_light lights[MAX_CLI_LIGHTS];
    int light_count;
    int has_light_radius;
    float light_radius;
    int voxel_res, thin_voxels, has_voxel_bounds;
    int exact_bounces;     /* no rest of the bounces after the last one */
    int dense_bounces;     /* every voxel gathers each bounce */
    int light_carry;       /* --light-carry (vct_render_job.light_carry) */
    float voxel_bounds[4]; /* x, y, z, size */
    vct_brick_storage bricks;
    int anisotropic;
    int has_ambient;
    float ambient[3];
    int frame;     /* -1: the file's rest pose; else the first animation at frame / fps */
    int frames[2]; /* --frames A:B; frames[1] < 0: none */
    float fps;
    int resume_frames; /* --resume: skip the frames whose files exist */
    const char *video; /* --video FILE: the frames encoded by ffmpeg, or NULL */
    /* vct method */
    int print_plan;
    vct_effect_force force[VCT_EFFECTS];
    int diffuse_cones, bounces, sparse_diffuse, edge_samples;
    int indirect_passes;   /* --indirect-filter N */
    int copy_voxels;       /* several devices: one builds the voxels, the others copy them */
    int emitters_by_cones; /* --emitters cones */
    vct_cone_settings cones;
    int aov;       /* --aov */
    int exr_float; /* --exr float */
    int denoise;   /* --denoise */
    cli_pm pm;
    /* vct-view */
    const char *capture, *keys, *display;
};

/* Parses a command's words (argv[0] is the command's name) into opt, with
 * the command's groups of options. Returns 0, or 2 after printing the reason
 * (an option the command does not take, a bad value, a missing operand), or
 * -1 after printing the command's help for --help. */
int cli_parse(const cli_command *cmd, const char *program, int argc, char **argv, cli_options *opt);
/* The command's usage and options (--help). */
void cli_print_help(FILE *out, const char *program, const cli_command *cmd);
/* vct's usage: its commands and global options. */
void cli_print_commands(FILE *out);
/* Every command's options as Markdown (doc/cli.md is generated from this). */
void cli_print_reference(FILE *out);
/* Applies camera and light overrides to a loaded scene. */
int cli_apply_scene_overrides(const cli_options *opt, vct_scene *scene, vct_error *err);

#endif
