/* The window and the frame's way into it (view_display.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <epoxy/gl.h>

#include <GLFW/glfw3.h>

#include "view_display.h"
#include "view_native.h"

/* A triangle that covers the viewport, from gl_VertexID alone. */
static const char *const VERTEX_SHADER =
    "#version 330 core\n"
    "void main() {\n"
    "    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);\n"
    "    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);\n"
    "}\n";

/* The frame's pixel under each fragment (rows stored top to bottom), scaled
 * by 2^exposure, through the tone curve and sRGB encoded exactly as the PNG
 * writer does (image/tone.c). */
static const char *const FRAGMENT_SHADER =
    "#version 330 core\n"
    "uniform sampler2D frame;\n"
    "uniform vec2 to_texel;\n"
    "uniform float scale;\n"
    "uniform int filmic;\n"
    "out vec4 colour;\n"
    "float encode(float l) {\n"
    "    if (!(l > 0.0)) return 0.0;\n"
    "    if (filmic != 0) l = l * (2.51 * l + 0.03) / (l * (2.43 * l + 0.59) + 0.14);\n"
    "    if (l >= 1.0) return 1.0;\n"
    "    return l <= 0.0031308 ? 12.92 * l : 1.055 * pow(l, 1.0 / 2.4) - 0.055;\n"
    "}\n"
    "void main() {\n"
    "    ivec2 size = textureSize(frame, 0);\n"
    "    ivec2 p = clamp(ivec2(gl_FragCoord.xy * to_texel), ivec2(0), size - 1);\n"
    "    vec3 l = texelFetch(frame, ivec2(p.x, size.y - 1 - p.y), 0).rgb * scale;\n"
    "    colour = vec4(encode(l.r), encode(l.g), encode(l.b), 1.0);\n"
    "}\n";

static int gl_check(vct_error *err, const char *what) {
    const GLenum e = glGetError();
    if (e == GL_NO_ERROR)
        return VCT_OK;
    err->status = VCT_ERR_IO;
    snprintf(err->message, sizeof err->message,
             "display: OpenGL error 0x%04x while %s: check the GL driver (glxinfo)", e, what);
    return err->status;
}

static GLuint compile(GLenum type, const char *source, char *why, size_t why_size) {
    GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &source, NULL);
    glCompileShader(s);
    GLint ok = GL_FALSE;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[512] = "";
        glGetShaderInfoLog(s, sizeof log, NULL, log);
        snprintf(why, why_size, "display: shader did not compile: %s", log);
        glDeleteShader(s);
        return 0;
    }
    return s;
}

static int build_program(display *d, char *why, size_t why_size) {
    GLuint vs = compile(GL_VERTEX_SHADER, VERTEX_SHADER, why, why_size);
    GLuint fs = vs ? compile(GL_FRAGMENT_SHADER, FRAGMENT_SHADER, why, why_size) : 0;
    if (!fs) {
        glDeleteShader(vs);
        return 1;
    }
    d->program = glCreateProgram();
    glAttachShader(d->program, vs);
    glAttachShader(d->program, fs);
    glLinkProgram(d->program);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = GL_FALSE;
    glGetProgramiv(d->program, GL_LINK_STATUS, &ok);
    if (!ok) {
        snprintf(why, why_size, "display: shader program did not link");
        return 1;
    }
    return 0;
}

static void glfw_error(int code, const char *message) {
    fprintf(stderr, "vct-view: GLFW error 0x%x: %s\n", code, message);
}

int display_open(display *d, int width, int height, char *why, size_t why_size) {
    memset(d, 0, sizeof *d);
    glfwSetErrorCallback(glfw_error);
    if (!glfwInit()) {
        snprintf(why, why_size, "no display could be opened (DISPLAY=%s): run under X11 or Xvfb",
                 getenv("DISPLAY") ? getenv("DISPLAY") : "unset");
        return 1;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    d->window = glfwCreateWindow(width, height, "vct-view", NULL, NULL);
    if (!d->window) {
        snprintf(why, why_size, "no OpenGL 3.3 core context could be created on this display");
        glfwTerminate();
        return 1;
    }
    glfwMakeContextCurrent(d->window);
    glfwSwapInterval(0); /* frames come when the image changes, not on a beat */
    if (epoxy_gl_version() < 33) {
        snprintf(why, why_size, "OpenGL %d.%d found, 3.3 needed", epoxy_gl_version() / 10,
                 epoxy_gl_version() % 10);
        display_close(d);
        return 1;
    }
    if (build_program(d, why, why_size)) {
        display_close(d);
        return 1;
    }
    glGenVertexArrays(1, &d->vao);
    glGenTextures(1, &d->texture);
    glGenBuffers(1, &d->pbo);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    return 0;
}

void display_close(display *d) {
    if (!d->window)
        return;
    glDeleteBuffers(1, &d->pbo);
    glDeleteTextures(1, &d->texture);
    glDeleteVertexArrays(1, &d->vao);
    if (d->program)
        glDeleteProgram(d->program);
    glfwDestroyWindow(d->window);
    glfwTerminate();
    d->window = NULL;
}

vct_context *display_context(display *d, display_mode mode, const char *device, vct_error *err) {
    if (mode != DISPLAY_HOST) {
        vct_context *ctx = vct_context_create_gl(device, view_native_glx_context(d->window),
                                                 view_native_x11_display(), err);
        if (ctx) {
            d->interop = 1;
            snprintf(d->path, sizeof d->path,
                     "display: CL-GL interop (device copy into a GL buffer)");
            return ctx;
        }
        if (mode == DISPLAY_INTEROP)
            return NULL;
        snprintf(d->path, sizeof d->path, "display: host (%.150s)", err->message);
    } else {
        snprintf(d->path, sizeof d->path, "display: host (asked for)");
    }
    d->interop = 0;
    return vct_context_create(device, err);
}

/* Texture and pixel buffer at the frame's size. */
static void resize_targets(display *d, int width, int height) {
    if (d->texture_size[0] == width && d->texture_size[1] == height)
        return;
    glBindTexture(GL_TEXTURE_2D, d->texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, d->pbo);
    glBufferData(GL_PIXEL_UNPACK_BUFFER, 16 * (GLsizeiptr)width * height, NULL, GL_STREAM_DRAW);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    d->texture_size[0] = width;
    d->texture_size[1] = height;
}

int display_upload(display *d, vct_context *ctx, const vct_image *image, int width, int height,
                   vct_error *err) {
    resize_targets(d, width, height);
    const size_t floats = 4 * (size_t)width * (size_t)height;
    int rc = VCT_OK;
    if (image && (!image->rgba || image->width != width || image->height != height)) {
        rc = err->status = VCT_ERR_INPUT;
        snprintf(err->message, sizeof err->message, "display: the frame is not %dx%d", width,
                 height);
    } else if (image) {
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, d->pbo);
        glBufferSubData(GL_PIXEL_UNPACK_BUFFER, 0, (GLsizeiptr)(4 * floats), image->rgba);
    } else if (d->interop) {
        glFinish(); /* GL is done with the buffer before OpenCL acquires it */
        rc = vct_frame_to_gl_buffer(ctx, d->pbo, err);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, d->pbo);
    } else {
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, d->pbo);
        float *mapped = glMapBufferRange(GL_PIXEL_UNPACK_BUFFER, 0, (GLsizeiptr)(4 * floats),
                                         GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT);
        if (!mapped)
            rc = gl_check(err, "mapping the pixel buffer");
        else {
            rc = vct_frame_read(ctx, mapped, floats, err);
            glUnmapBuffer(GL_PIXEL_UNPACK_BUFFER);
        }
    }
    d->applied_stops = d->tone.exposure;
    if (rc == VCT_OK && d->tone.auto_exposure) {
        /* from the frame itself, as the PNG writer takes it */
        float *frame = image ? image->rgba : malloc(4 * floats);
        rc = !frame ? VCT_ERR_MEMORY : image ? VCT_OK : vct_frame_read(ctx, frame, floats, err);
        if (rc == VCT_OK)
            d->applied_stops = vct_tone_exposure(&d->tone, frame, floats / 4);
        else if (!frame)
            snprintf(err->message, sizeof err->message, "display: out of host memory");
        if (!image)
            free(frame);
    }
    if (rc == VCT_OK) {
        glBindTexture(GL_TEXTURE_2D, d->texture);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGBA, GL_FLOAT, NULL);
    }
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    return rc == VCT_OK ? gl_check(err, "uploading the frame") : rc;
}

int display_draw(display *d, vct_error *err) {
    int fw = 0, fh = 0;
    glfwGetFramebufferSize(d->window, &fw, &fh);
    if (fw <= 0 || fh <= 0 || d->texture_size[0] == 0)
        return VCT_OK; /* minimised, or nothing rendered yet */
    glViewport(0, 0, fw, fh);
    glClear(GL_COLOR_BUFFER_BIT);
    glUseProgram(d->program);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, d->texture);
    glUniform1i(glGetUniformLocation(d->program, "frame"), 0);
    glUniform2f(glGetUniformLocation(d->program, "to_texel"), (float)d->texture_size[0] / fw,
                (float)d->texture_size[1] / fh);
    glUniform1f(glGetUniformLocation(d->program, "scale"), exp2f(d->applied_stops));
    glUniform1i(glGetUniformLocation(d->program, "filmic"), d->tone.curve == VCT_TONE_FILMIC);
    glBindVertexArray(d->vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    return gl_check(err, "drawing the frame");
}

int display_read(display *d, unsigned char *rgb, int width, int height, vct_error *err) {
    glReadBuffer(GL_BACK); /* what display_draw drew, before the swap */
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb);
    const int rc = gl_check(err, "reading the framebuffer back");
    /* GL rows run bottom to top. */
    const size_t row = 3 * (size_t)width;
    unsigned char *tmp = malloc(row);
    if (!tmp) {
        err->status = VCT_ERR_MEMORY;
        snprintf(err->message, sizeof err->message, "display: out of host memory");
        return err->status;
    }
    for (int y = 0; rc == VCT_OK && y < height / 2; ++y) {
        unsigned char *a = rgb + (size_t)y * row, *b = rgb + (size_t)(height - 1 - y) * row;
        memcpy(tmp, a, row);
        memcpy(a, b, row);
        memcpy(b, tmp, row);
    }
    free(tmp);
    return rc;
}
