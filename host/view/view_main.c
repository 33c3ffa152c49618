/* vct-view: the engine's frame live in a window. Renders when something
 * changes (camera, light, method, effects, size), or keeps adding samples
 * while the path tracer converges. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <GLFW/glfw3.h>
#include <stb/stb_image_write.h>

#include "cli_common.h"
#include "view_app.h"
#include "view_display.h"

/* Exit codes: 1 a render or device failure, 2 bad arguments, 3 no display. */
#define EXIT_NO_DISPLAY 3

typedef struct viewer {
    view_app app;
    display display;
    int dragging;
    double cursor[2];
    int screenshots;
} viewer;

static void help(void) {
    puts(
        "keys: mouse drag look | W A S D move, Q E down/up, scroll speed\n"
        "      1 ray cast, 2 VCT, 3 path tracer (progressive), 4 voxels ([ ] level)\n"
        "      F1 indirect, F2 specular, F3 AO, F4 shadows, F5 soft shadows (forced against\n"
        "      the plan; --light-radius R gives the lights a size)\n"
        "      N denoise (path tracer, photon mapping, cone tracing; one device)\n"
        "      space play/pause the animation, comma/period a frame back/on (--fps F)\n"
        "      arrows, R F move the first light | + - exposure | P screenshot | H help | Esc quit");
}

static void print_plan(const vct_plan *plan) {
    printf("plan:");
    for (int e = 0; e < VCT_EFFECTS; ++e)
        printf(" %s=%s", vct_effect_name((vct_effect)e), plan->on[e] ? "on" : "off");
    putchar('\n');
    fflush(stdout);
}

/* PNG of the frame, tone mapped as the window shows it. */
static void screenshot(viewer *v) {
    vct_error err = {0};
    vct_image im = {0};
    vct_frame_size(v->app.ctx, &im.width, &im.height);
    const size_t floats = 4 * (size_t)im.width * im.height;
    im.rgba = floats ? malloc(4 * floats) : NULL;
    char path[64];
    snprintf(path, sizeof path, "vct-view-%03d.png", v->screenshots++);
    int rc = im.rgba ? vct_frame_read(v->app.ctx, im.rgba, floats, &err) : VCT_ERR_MEMORY;
    /* at the stops the window shows, so that the file shows the same */
    const vct_tone shown = {0, v->display.applied_stops, v->display.tone.curve};
    if (rc == VCT_OK)
        rc = vct_image_write_png_tone(&im, path, &shown, NULL, &err);
    if (rc == VCT_OK)
        printf("wrote %s\n", path);
    else
        fprintf(stderr, "vct-view: screenshot failed: %s\n",
                im.rgba ? err.message : "nothing rendered yet, or out of memory");
    vct_image_release(&im);
}

static void on_key(GLFWwindow *w, int key, int scancode, int action, int mods) {
    viewer *v = glfwGetWindowUserPointer(w);
    view_app *app = &v->app;
    if (action != GLFW_PRESS && action != GLFW_REPEAT)
        return;
    const vct_effect toggles[5] = {VCT_EFFECT_INDIRECT, VCT_EFFECT_SPECULAR, VCT_EFFECT_AO,
                                   VCT_EFFECT_SHADOWS, VCT_EFFECT_SOFT_SHADOWS};
    if (key >= GLFW_KEY_1 && key <= GLFW_KEY_4) {
        view_app_set_method(app, (view_method)(key - GLFW_KEY_1));
    } else if (key >= GLFW_KEY_F1 && key <= GLFW_KEY_F5) {
        view_app_toggle_effect(app, toggles[key - GLFW_KEY_F1]);
        print_plan(&app->plan);
    } else if (key == GLFW_KEY_LEFT_BRACKET || key == GLFW_KEY_RIGHT_BRACKET) {
        view_app_set_level(app, key == GLFW_KEY_LEFT_BRACKET ? -1 : 1);
    } else if (key == GLFW_KEY_LEFT || key == GLFW_KEY_RIGHT || key == GLFW_KEY_UP ||
               key == GLFW_KEY_DOWN || key == GLFW_KEY_R || key == GLFW_KEY_F) {
        const float dx = key == GLFW_KEY_RIGHT ? 1.0f : key == GLFW_KEY_LEFT ? -1.0f : 0.0f;
        const float dy = key == GLFW_KEY_R ? 1.0f : key == GLFW_KEY_F ? -1.0f : 0.0f;
        const float dz = key == GLFW_KEY_DOWN ? 1.0f : key == GLFW_KEY_UP ? -1.0f : 0.0f;
        if (!view_app_move_light(app, dx, dy, dz))
            fprintf(stderr, "vct-view: the scene has no light to move\n");
    } else if (key == GLFW_KEY_EQUAL || key == GLFW_KEY_KP_ADD || key == GLFW_KEY_MINUS ||
               key == GLFW_KEY_KP_SUBTRACT) {
        v->display.tone.exposure +=
            key == GLFW_KEY_MINUS || key == GLFW_KEY_KP_SUBTRACT ? -0.5f : 0.5f;
    } else if (key == GLFW_KEY_P && action == GLFW_PRESS) {
        screenshot(v);
    } else if (key == GLFW_KEY_N && action == GLFW_PRESS) {
        view_app_toggle_denoise(app);
    } else if (key == GLFW_KEY_SPACE && action == GLFW_PRESS) {
        if (!view_app_toggle_play(app))
            fprintf(stderr, "vct-view: the scene has no animation to play\n");
    } else if (key == GLFW_KEY_COMMA || key == GLFW_KEY_PERIOD) {
        vct_error err = {0};
        app->playing = 0;
        if (view_app_step_animation(app, key == GLFW_KEY_PERIOD ? 1 : -1, &err) < 0)
            fprintf(stderr, "vct-view: %s\n", err.message);
    } else if (key == GLFW_KEY_H && action == GLFW_PRESS) {
        help();
    } else if (key == GLFW_KEY_ESCAPE) {
        glfwSetWindowShouldClose(w, GLFW_TRUE);
    }
}

static void on_cursor(GLFWwindow *w, double x, double y) {
    viewer *v = glfwGetWindowUserPointer(w);
    if (v->dragging) {
        view_camera_look(&v->app.camera, (float)(x - v->cursor[0]), (float)(y - v->cursor[1]));
        view_app_camera_changed(&v->app);
    }
    v->cursor[0] = x;
    v->cursor[1] = y;
}

static void on_button(GLFWwindow *w, int button, int action, int mods) {
    viewer *v = glfwGetWindowUserPointer(w);
    if (button == GLFW_MOUSE_BUTTON_LEFT)
        v->dragging = action == GLFW_PRESS;
}

static void on_scroll(GLFWwindow *w, double dx, double dy) {
    viewer *v = glfwGetWindowUserPointer(w);
    view_camera_scroll(&v->app.camera, (float)dy);
}

/* Held movement keys: (forward, right, up) in -1..1; 1 if any is held. */
static int held_motion(GLFWwindow *w, float m[3]) {
    const int keys[6] = {GLFW_KEY_W, GLFW_KEY_S, GLFW_KEY_D, GLFW_KEY_A, GLFW_KEY_E, GLFW_KEY_Q};
    for (int i = 0; i < 3; ++i)
        m[i] = (float)(glfwGetKey(w, keys[2 * i]) == GLFW_PRESS) -
               (float)(glfwGetKey(w, keys[2 * i + 1]) == GLFW_PRESS);
    return m[0] != 0.0f || m[1] != 0.0f || m[2] != 0.0f;
}

static int write_capture(display *d, int width, int height, const char *path, vct_error *err) {
    unsigned char *rgb = malloc(3 * (size_t)width * height);
    if (!rgb) {
        fprintf(stderr, "vct-view: out of host memory for the capture\n");
        return 1;
    }
    int rc = display_read(d, rgb, width, height, err);
    char tmp[4096];
    snprintf(tmp, sizeof tmp, "%s.tmp%d", path, (int)getpid());
    if (rc == VCT_OK &&
        (!stbi_write_png(tmp, width, height, 3, rgb, 3 * width) || rename(tmp, path) != 0)) {
        remove(tmp);
        snprintf(err->message, sizeof err->message, "capture: could not write %s", path);
        rc = VCT_ERR_IO;
    }
    free(rgb);
    if (rc == VCT_OK)
        printf("captured %dx%d framebuffer into %s\n", width, height, path);
    return rc;
}

static const struct {
    const char *name;
    int key;
} KEY_NAMES[] = {{"1", GLFW_KEY_1},
                 {"2", GLFW_KEY_2},
                 {"3", GLFW_KEY_3},
                 {"4", GLFW_KEY_4},
                 {"F1", GLFW_KEY_F1},
                 {"F2", GLFW_KEY_F2},
                 {"F3", GLFW_KEY_F3},
                 {"F4", GLFW_KEY_F4},
                 {"F5", GLFW_KEY_F5},
                 {"[", GLFW_KEY_LEFT_BRACKET},
                 {"]", GLFW_KEY_RIGHT_BRACKET},
                 {"left", GLFW_KEY_LEFT},
                 {"right", GLFW_KEY_RIGHT},
                 {"up", GLFW_KEY_UP},
                 {"down", GLFW_KEY_DOWN},
                 {"r", GLFW_KEY_R},
                 {"f", GLFW_KEY_F},
                 {"+", GLFW_KEY_EQUAL},
                 {"-", GLFW_KEY_MINUS},
                 {"p", GLFW_KEY_P},
                 {"n", GLFW_KEY_N},
                 {"space", GLFW_KEY_SPACE},
                 {"comma", GLFW_KEY_COMMA},
                 {"period", GLFW_KEY_PERIOD}};

/* Renders, takes the frame into the window's texture and puts the status
 * in the title (and on stdout with `print`). A failure keeps the last image
 * and says why; the next change tries again. */
static int render_frame(viewer *v, int print) {
    view_app *app = &v->app;
    vct_error err = {0};
    char title[512];
    int rc = view_app_render(app, &err);
    if (rc == VCT_OK)
        rc = display_upload(&v->display, app->ctx, app->host_frame.rgba ? &app->host_frame : NULL,
                            app->width, app->height, &err);
    if (rc == VCT_OK) {
        view_app_status(app, v->display.path, title, sizeof title);
        if (print)
            printf("%s\n", title);
    } else {
        fprintf(stderr, "vct-view: %s\n", err.message);
        snprintf(title, sizeof title, "vct-view | error: %.400s", err.message);
        app->dirty = 0;
        if (view_app_progressive(app))
            app->pt_spp = VIEW_PT_MAX_SPP;
    }
    glfwSetWindowTitle(v->display.window, title);
    return rc;
}

/* The window at width x height, once the window system has made it so. */
static int resize_window(GLFWwindow *w, int width, int height) {
    glfwSetWindowSize(w, width, height);
    for (int tries = 0; tries < 100; ++tries) {
        int fw = 0, fh = 0;
        glfwWaitEventsTimeout(0.02);
        glfwGetFramebufferSize(w, &fw, &fh);
        if (fw == width && fh == height)
            return 0;
    }
    return 1;
}

/* --keys: each name pressed as the keyboard would; size=WxH resizes;
 * `frame` renders one frame there and then. */
static int press_keys(viewer *v, const char *list) {
    char buf[512];
    snprintf(buf, sizeof buf, "%s", list);
    for (char *save = NULL, *k = strtok_r(buf, ",", &save); k; k = strtok_r(NULL, ",", &save)) {
        int width = 0, height = 0;
        if (sscanf(k, "size=%dx%d", &width, &height) == 2) {
            if (width < 1 || height < 1 || resize_window(v->display.window, width, height)) {
                fprintf(stderr, "vct-view: the window did not take the size %s\n", k + 5);
                return 1;
            }
            continue;
        }
        if (strcmp(k, "frame") == 0) {
            if (render_frame(v, 1) != VCT_OK)
                return 1;
            continue;
        }
        size_t i = 0;
        while (i < sizeof KEY_NAMES / sizeof KEY_NAMES[0] && strcmp(KEY_NAMES[i].name, k) != 0)
            ++i;
        if (i == sizeof KEY_NAMES / sizeof KEY_NAMES[0]) {
            fprintf(stderr, "vct-view: --keys: unknown key \"%s\"\n", k);
            return 1;
        }
        on_key(v->display.window, KEY_NAMES[i].key, 0, GLFW_PRESS, 0);
    }
    return 0;
}

typedef struct view_args {
    const char *capture, *keys;
    display_mode mode;
} view_args;

/* --display's mode (the parser has checked the name). */
static display_mode display_mode_of(const char *name) {
    if (name && strcmp(name, "interop") == 0)
        return DISPLAY_INTEROP;
    if (name && strcmp(name, "host") == 0)
        return DISPLAY_HOST;
    return DISPLAY_AUTO;
}

static int run(viewer *v, const view_args *va);

/* Several devices: their frames reach GL through the host. */
static int run_group(viewer *v, const view_args *va, const cli_options *opt) {
    vct_error err = {0};
    if (va->mode == DISPLAY_INTEROP) {
        fprintf(stderr, "vct-view: --display interop takes one device; several devices "
                        "display through the host\n");
        return 1;
    }
    vct_group *group = vct_group_create(opt->device, &err);
    if (group)
        vct_group_set_log(group, cli_log, NULL);
    int status = 1;
    if (group && view_app_attach_group(&v->app, group, &err) == VCT_OK) {
        const vct_group_device *d;
        const int n = vct_group_devices(group, &d);
        for (int i = 0; i < n; ++i)
            printf("device %d: %s (%s)\n", d[i].info.index, d[i].info.name, d[i].info.platform);
        snprintf(v->display.path, sizeof v->display.path, "display: host (%d devices)", n);
        v->display.interop = 0;
        printf("%s\n", v->display.path);
        print_plan(&v->app.plan);
        if (!va->capture)
            help();
        status = run(v, va);
    } else {
        fprintf(stderr, "vct-view: %s\n", err.message);
    }
    vct_group_release(group);
    return status;
}

static int run(viewer *v, const view_args *va) {
    const char *capture = va->capture;
    display *d = &v->display;
    view_app *app = &v->app;
    glfwSetWindowUserPointer(d->window, v);
    glfwSetKeyCallback(d->window, on_key);
    glfwSetCursorPosCallback(d->window, on_cursor);
    glfwSetMouseButtonCallback(d->window, on_button);
    glfwSetScrollCallback(d->window, on_scroll);
    if (va->keys && press_keys(v, va->keys))
        return 2;
    double last = glfwGetTime();
    int status = 0;
    while (!glfwWindowShouldClose(d->window)) {
        float motion[3];
        if (view_app_wants_frame(app) || held_motion(d->window, motion))
            glfwPollEvents();
        else
            glfwWaitEventsTimeout(0.5);
        const double now = glfwGetTime();
        if (held_motion(d->window, motion)) {
            view_camera_move(&app->camera, motion[0], motion[1], motion[2], (float)(now - last));
            view_app_camera_changed(app);
        }
        last = now;
        int fw = 0, fh = 0;
        glfwGetFramebufferSize(d->window, &fw, &fh);
        if (fw <= 0 || fh <= 0)
            continue; /* minimised: nothing to draw into */
        if (fw != app->width || fh != app->height) {
            app->width = fw;
            app->height = fh;
            view_app_camera_changed(app);
        }
        vct_error err = {0};
        if (app->playing) { /* every frame of the animation, one per frame drawn */
            vct_error step_err = {0};
            if (view_app_step_animation(app, 1, &step_err) < 0) {
                fprintf(stderr, "vct-view: %s\n", step_err.message);
                status = 1;
            }
        }
        if (view_app_wants_frame(app) && render_frame(v, capture != NULL) != VCT_OK)
            status = 1;
        if (display_draw(d, &err) != VCT_OK) {
            fprintf(stderr, "vct-view: %s\n", err.message);
            status = 1;
        }
        if (capture) {
            /* Drawn once more after a swap: a window system may hand the
             * new back buffer of a resized window only at the swap. */
            glfwSwapBuffers(d->window);
            if (status == 0 && display_draw(d, &err) != VCT_OK)
                status = 1;
            if (status == 0 && write_capture(d, fw, fh, capture, &err) != VCT_OK) {
                fprintf(stderr, "vct-view: %s\n", err.message);
                status = 1;
            }
            break;
        }
        status = 0;
        glfwSwapBuffers(d->window);
    }
    return status;
}

int main(int argc, char **argv) {
    cli_options opt;
    const int parsed = cli_parse(&vct_view_command, "vct-view", argc, argv, &opt);
    if (parsed)
        return parsed < 0 ? 0 : parsed;
    const view_args va = {opt.capture, opt.keys, display_mode_of(opt.display)};
    static viewer v;
    vct_error err = {0};
    if (view_app_init(&v.app, &opt, &err) != VCT_OK) {
        fprintf(stderr, "vct-view: %s\n", err.message);
        view_app_free(&v.app);
        return 1;
    }
    char why[512];
    if (display_open(&v.display, opt.width, opt.height, why, sizeof why)) {
        fprintf(stderr, "vct-view: %s\n", why);
        view_app_free(&v.app);
        return EXIT_NO_DISPLAY;
    }
    v.display.tone = opt.tone; /* as `vct render` writes PNG files */
    int status = 1;
    if (cli_device_list(&opt)) {
        status = run_group(&v, &va, &opt);
        view_app_free(&v.app);
        display_close(&v.display);
        return status;
    }
    vct_context *ctx = display_context(&v.display, va.mode, opt.device, &err);
    if (ctx)
        vct_context_set_log(ctx, cli_log, NULL);
    if (ctx && view_app_attach(&v.app, ctx, &err) == VCT_OK) {
        printf("device: %s (%s)\n%s\n", vct_context_device(ctx)->name,
               vct_context_device(ctx)->platform, v.display.path);
        vct_frame_host_copy(ctx, 0); /* the display takes the frame itself */
        print_plan(&v.app.plan);
        if (!va.capture)
            help();
        status = run(&v, &va);
    } else {
        fprintf(stderr, "vct-view: %s\n", err.message);
    }
    view_app_free(&v.app);
    vct_context_release(ctx);
    display_close(&v.display);
    return status;
}
