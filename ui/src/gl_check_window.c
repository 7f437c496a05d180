/* TESSERA_GL_CHECK=1: the window counts every OpenGL error of its context, the renderer's and
 * Dear ImGui's backend's alike (render/gl_check.h), asks GLFW for a debug context so the
 * driver reports them, and says at exit how many frames it drew and how many errors it saw;
 * any error makes the exit code 1. The window's soak (tests/ui/soak_session.sh) runs so. */
#include "planner.h"

#include "render/gl_check.h"

#include <GLFW/glfw3.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int enabled(void)
{
    const char *v = getenv("TESSERA_GL_CHECK");
    return v && *v && strcmp(v, "0");
}

void planner_gl_check_hint(void)
{
    if (enabled())
        glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
}

static void *proc(const char *name)
{
    __extension__ void *p = (void *)glfwGetProcAddress(name);
    return p;
}

void planner_gl_check_start(void)
{
    if (!enabled())
        return;
    rd_gl_check_mode m = rd_gl_check_begin(proc, 0);
    fprintf(stderr, "tessera: gl-check: counting GL errors (%s)\n",
            m == RD_GL_CHECK_CALLBACK ? "KHR_debug callback"
            : m == RD_GL_CHECK_POLL   ? "glGetError once a frame"
                                      : "not available");
}

void planner_gl_check_frame(void)
{
    rd_gl_check_poll();
}

int planner_gl_check_finish(long frames)
{
    if (!enabled())
        return 0;
    rd_gl_check_poll();
    unsigned long errors = rd_gl_check_errors();
    rd_gl_check_end();
    fprintf(stderr, "tessera: gl-check: %ld frames, %lu GL errors\n", frames, errors);
    return errors > 0;
}
