/* GLFW's native handles (view_native.h). */
#define GLFW_EXPOSE_NATIVE_X11
#define GLFW_EXPOSE_NATIVE_GLX
#include <GLFW/glfw3.h>
#include <GLFW/glfw3native.h>

#include "view_native.h"

void *view_native_glx_context(GLFWwindow *window) {
    return (void *)glfwGetGLXContext(window);
}

void *view_native_x11_display(void) {
    return (void *)glfwGetX11Display();
}
