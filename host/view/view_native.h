/* The X11 and GLX handles behind a GLFW window, kept apart from the files
 * that include libepoxy, whose GL headers must not meet the system's. */
#ifndef VCT_VIEW_NATIVE_H
#define VCT_VIEW_NATIVE_H

typedef struct GLFWwindow GLFWwindow;

void *view_native_glx_context(GLFWwindow *window);
void *view_native_x11_display(void);

#endif
