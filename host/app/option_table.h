/* The command-line options as data: every option of every command is one row
 * of a group, and every command names the groups it takes. The parser, each
 * command's --help and the generated reference (doc/cli.md) all read these
 * tables, so they cannot disagree. */
#ifndef VCT_APP_OPTION_TABLE_H
#define VCT_APP_OPTION_TABLE_H

typedef enum cli_option_id {
    OPT_OUTPUT = 1,
    OPT_STATS,
    OPT_EXPOSURE,
    OPT_TONE,
    OPT_AOV,
    OPT_EXR,
    OPT_DENOISE,
    OPT_DEVICE,
    OPT_SIZE,
    OPT_CAMERA_POS,
    OPT_LOOK_AT,
    OPT_UP,
    OPT_FOV,
    OPT_POINT_LIGHT,
    OPT_DIR_LIGHT,
    OPT_LIGHT_RADIUS,
    OPT_AMBIENT,
    OPT_FRAME,
    OPT_FRAMES,
    OPT_FPS,
    OPT_RESUME,
    OPT_VIDEO,
    OPT_ACCEL,
    OPT_BVH_BUILD,
    OPT_BVH_LEVELS,
    OPT_GRID_RES,
    OPT_METHOD,
    OPT_SPP,
    OPT_TIME,
    OPT_MAX_DEPTH,
    OPT_SEED,
    OPT_PLAN,
    OPT_EFFECT,
    OPT_CONES,
    OPT_CONE_STEP,
    OPT_CONE_OFFSET,
    OPT_CONE_LEVELS,
    OPT_DENSE_DIFFUSE,
    OPT_EDGE_SAMPLES,
    OPT_INDIRECT_FILTER,
    OPT_AO_DISTANCE,
    OPT_BOUNCES,
    OPT_LIGHT_CARRY,
    OPT_EXACT_BOUNCES,
    OPT_DENSE_BOUNCES,
    OPT_EMITTERS,
    OPT_COPY_VOXELS,
    OPT_VOXEL_RES,
    OPT_THIN,
    OPT_VOXEL_BOUNDS,
    OPT_BRICKS,
    OPT_ANISOTROPIC,
    OPT_ISOTROPIC,
    OPT_SUBSAMPLE,
    OPT_NO_GUARD,
    OPT_CONTRAST,
    OPT_PHOTONS,
    OPT_FINAL_GATHER,
    OPT_PM_FIXED,
    OPT_PM_DIRECT_PHOTONS,
    OPT_PM_RADIUS,
    OPT_PM_CAUSTIC_RADIUS,
    OPT_PM_ALPHA,
    OPT_PM_KERNEL,
    OPT_PM_NORMAL_FILTER,
    OPT_ERROR_IMAGE,
    OPT_ERROR_SCALE,
    OPT_CAPTURE,
    OPT_KEYS,
    OPT_DISPLAY,
    OPT_HELP,
    OPT_COUNT
} cli_option_id;

/* An option followed by one number or three (--grid-res). */
#define CLI_ONE_OR_THREE (-3)

typedef struct cli_option {
    const char *name; /* long name, without the dashes */
    char short_name;  /* 0: none */
    cli_option_id id;
    int words;           /* values that follow it */
    const char *metavar; /* what the values are, as help shows them */
    const char *help;    /* one paragraph; wrapped when printed */
} cli_option;

typedef struct cli_option_group {
    const char *title;
    const cli_option *options;
    int count;
} cli_option_group;

typedef struct cli_options cli_options;

typedef struct cli_command {
    const char *name;
    const char *operands; /* e.g. "SCENE" */
    int min_operands, max_operands;
    const char *summary;
    const cli_option_group *const *groups; /* NULL-terminated */
    int (*run)(const cli_options *opt);
} cli_command;

/* The groups, shared by the commands of vct and vct-view. */
extern const cli_option_group cli_group_time, cli_group_output, cli_group_denoise, cli_group_tone,
    cli_group_device, cli_group_size, cli_group_scene, cli_group_accel, cli_group_method,
    cli_group_sampling, cli_group_vct, cli_group_voxels, cli_group_whitted, cli_group_pm,
    cli_group_compare, cli_group_view;

/* vct's commands (command_table.c), NULL-terminated, and vct-view's, whose
 * run is the viewer's own main. */
extern const cli_command *const vct_commands[];
extern const cli_command vct_view_command;

#endif
