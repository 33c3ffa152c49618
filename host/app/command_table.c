/* vct's commands and vct-view's: their operands and the groups of options
 * each takes. */
#include <stddef.h>

#include "commands.h"

static const cli_option_group *const no_groups[] = {NULL};
static const cli_option_group *const info_groups[] = {&cli_group_device, &cli_group_scene,
                                                      &cli_group_accel, NULL};
static const cli_option_group *const render_groups[] = {
    &cli_group_output,   &cli_group_denoise, &cli_group_tone,
    &cli_group_device,   &cli_group_size,    &cli_group_scene,
    &cli_group_time,     &cli_group_method,  &cli_group_accel,
    &cli_group_sampling, &cli_group_vct,     &cli_group_voxels,
    &cli_group_whitted,  &cli_group_pm,      NULL};
static const cli_option_group *const voxelize_groups[] = {&cli_group_output,
                                                          &cli_group_tone,
                                                          &cli_group_device,
                                                          &cli_group_size,
                                                          &cli_group_scene,
                                                          &cli_group_voxels,
                                                          NULL};
static const cli_option_group *const compile_groups[] = {
    &cli_group_device, &cli_group_scene, &cli_group_accel, &cli_group_vct, &cli_group_voxels, NULL};
static const cli_option_group *const compare_groups[] = {&cli_group_compare, NULL};
static const cli_option_group *const view_groups[] = {&cli_group_view,     &cli_group_denoise,
                                                      &cli_group_tone,     &cli_group_device,
                                                      &cli_group_size,     &cli_group_scene,
                                                      &cli_group_method,   &cli_group_accel,
                                                      &cli_group_sampling, &cli_group_vct,
                                                      &cli_group_voxels,   &cli_group_whitted,
                                                      &cli_group_pm,       NULL};

static const cli_command devices = {
    "devices", "", 0, 0, "list the OpenCL devices and their limits", no_groups, cmd_devices};
static const cli_command info = {
    "info",
    "SCENE",
    1,
    1,
    "load and validate a scene, print what it holds and the acceleration structure built for it",
    info_groups,
    cmd_info};
static const cli_command render = {
    "render",      "SCENE",   1, 1, "render an image of the scene by one of five methods",
    render_groups, cmd_render};
static const cli_command voxelize = {
    "voxelize",
    "SCENE",
    1,
    1,
    "voxelize, build the sparse voxel octree and its filtered bricks, inject light; report "
    "counts, memory and time; -o renders the voxels",
    voxelize_groups,
    cmd_voxelize};
static const cli_command compile = {
    "compile",
    "SCENE",
    1,
    1,
    "compile the kernel programs that rendering the scene needs, by every method, into the "
    "kernel cache, so that no render waits for the compiler (once per device and driver)",
    compile_groups,
    cmd_compile};
static const cli_command compare = {
    "compare",
    "TEST.pfm REFERENCE.pfm",
    2,
    2,
    "NRMSE, RMSE, relative MSE, PSNR, mean absolute error and the ratio of the means of two "
    "linear images (PFM or EXR)",
    compare_groups,
    cmd_compare};

const cli_command *const vct_commands[] = {&devices, &info,    &render, &voxelize,
                                           &compile, &compare, NULL};

const cli_command vct_view_command = {
    "",
    "SCENE",
    1,
    1,
    "an interactive window on the scene, rendered by any method (vct render's options); keys "
    "switch methods and effects, H lists them",
    view_groups,
    NULL};
