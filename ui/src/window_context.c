/* The planner window's kind of OpenGL context, for the window and for `--backend window`
 * (ui.h): Mesa's shader cache keeps what it compiles per kind of context, so renders that are
 * to warm the window's cache must run in the same kind. */
#include "planner.h"
#include "ui/ui.h"

#include <GLFW/glfw3.h>
#include <stdio.h>
#include <stdlib.h>

static GLFWwindow *hidden;

/* At exit the hidden window and its context are closed, as the planner closes its own. */
static void close_hidden(void)
{
    if (hidden)
        glfwDestroyWindow(hidden);
    hidden = NULL;
    glfwTerminate();
}

void ui_context_hints(void)
{
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    planner_gl_check_hint();
}

void *ui_gl_proc(const char *name)
{
    __extension__ void *p = (void *)glfwGetProcAddress(name);
    return p;
}

int ui_hidden_window_context(void *(**get_proc_address)(const char *name), char *err,
                             size_t err_size)
{
    char why[256];
    if (!ui_display_available(why, sizeof why)) {
        snprintf(err, err_size, "--backend window: %s", why);
        return 1;
    }
    if (!glfwInit()) {
        snprintf(err, err_size, "--backend window: the window system did not start");
        return 1;
    }
    ui_context_hints();
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    /* Kept until the process ends (the session's context lives as long), then closed. */
    hidden = glfwCreateWindow(64, 64, "Tessera", NULL, NULL);
    if (!hidden) {
        snprintf(err, err_size, "--backend window: no OpenGL 3.3 window");
        glfwTerminate();
        return 1;
    }
    atexit(close_hidden);
    glfwMakeContextCurrent(hidden);
    *get_proc_address = ui_gl_proc;
    return 0;
}
