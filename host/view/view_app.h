/* What the viewer shows and how it is made: the scene, its structures, the
 * method and effect plan, and the frame they render. No window here: the
 * display (view_display.h) takes the frame from the context. */
#ifndef VCT_VIEW_APP_H
#define VCT_VIEW_APP_H

#include "options.h"
#include "view_camera.h"

typedef enum view_method {
    VIEW_RAYCAST,   /* direct light with hard shadows */
    VIEW_VCT,       /* voxel cone tracing (the default) */
    VIEW_PATHTRACE, /* progressive: one sample per pixel per frame, summed */
    VIEW_VOXELS,    /* the voxels of one octree level */
    VIEW_WHITTED,   /* Whitted ray trees */
    VIEW_PM,        /* photon mapping: one pass per frame, progressive */
    VIEW_METHODS
} view_method;

#define VIEW_PT_MAX_SPP 4096u

typedef struct view_app {
    cli_options opt;
    vct_context *ctx;
    /* Several devices (--device 0,1): they hold their own structures and
     * the frame comes back to the host. NULL: ctx alone. */
    vct_group *group;
    /* The frame the display takes from the host (several devices, or a
     * denoised frame); rgba NULL: it stays on the context's device. */
    vct_image host_frame;
    int denoise;                    /* --denoise, or N: filter pt, pm and vct frames */
    vct_image albedo, normal_depth; /* the denoiser's guides for this camera (rgba NULL: none) */
    vct_image variance;             /* the path tracer's, for the last frame */
    vct_aovs aovs;                  /* cone tracing's, whose indirect term is filtered */
    vct_scene *scene;
    /* One device: the scene committed to it, which keeps the structures and
     * rebuilds what a change (a moved light) needs. NULL with a group. */
    vct_device_scene *ds;
    /* A group: whether its devices hold the plan's voxels, lit. */
    int voxels_lit;
    int voxels_for_plan;
    vct_effect_force force[VCT_EFFECTS];
    vct_plan plan;
    view_method method;
    uint32_t voxel_level, voxel_levels;
    view_camera camera;
    int width, height; /* the frame's size */
    int dirty;         /* the frame is out of date */
    int scene_changed; /* a group's structures are out of date (a moved light, a new pose) */
    uint32_t pt_spp;   /* samples (photon mapping: passes) in the progressive frame */
    double frame_ms;
    char stages[256]; /* ms per stage of the last frame */
    /* The scene's first animation: the frame shown (at opt.fps), and
     * whether it plays (a frame further at each frame drawn). */
    int anim_frame;
    int playing;
} view_app;

const char *view_method_name(view_method m);
/* Frame `delta` frames on of the first animation (not before frame 0):
 * the scene posed there; a camera the animation carries is followed. 0
 * when the scene has no animation. */
int view_app_step_animation(view_app *app, int delta, vct_error *err);
/* Space: plays or pauses the animation; 0 when there is none. */
int view_app_toggle_play(view_app *app);
/* Loads the scene and checks the options (before any window opens). */
int view_app_init(view_app *app, const cli_options *opt, vct_error *err);
/* Commits the scene to the caller's context, which renders from now on. */
int view_app_attach(view_app *app, vct_context *ctx, vct_error *err);
/* The same on every device of a group (the caller's), which renders from now on. */
int view_app_attach_group(view_app *app, vct_group *group, vct_error *err);
void view_app_free(view_app *app);
/* Whether another frame is wanted now (changes, or a path tracer still converging). */
int view_app_wants_frame(const view_app *app);
/* The path tracer and photon mapping: frames add to the previous ones. */
int view_app_progressive(const view_app *app);
/* Renders one frame into the context's frame at app->width x app->height. */
int view_app_render(view_app *app, vct_error *err);

void view_app_set_method(view_app *app, view_method m);
/* Flips an effect against the current plan (a forced setting). */
void view_app_toggle_effect(view_app *app, vct_effect e);
void view_app_set_level(view_app *app, int delta);
/* N: the denoiser on or off. */
void view_app_toggle_denoise(view_app *app);
/* Whether the frame shown is denoised. */
int view_app_denoising(const view_app *app);
/* Moves the first light (positions; a directional light turns instead). */
int view_app_move_light(view_app *app, float dx, float dy, float dz);
void view_app_camera_changed(view_app *app);
/* One line: method, plan, ms per stage (the window title). */
void view_app_status(const view_app *app, const char *display_path, char *out, size_t size);

#endif
