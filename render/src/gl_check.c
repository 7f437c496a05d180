/* GL error counting for a window's context (render/gl_check.h). The callback follows the
 * KHR_debug specification (OpenGL 4.6 core, section 20.2 "Debug Message Callback"): with
 * DEBUG_OUTPUT_SYNCHRONOUS it runs in the thread and the call that raised the message. */
#include "render/gl_check.h"

#include <GL/glcorearb.h>
#include <stdio.h>
#include <string.h>

enum { PRINTED_MAX = 10 }; /* the first errors are printed; the rest only counted */

static struct {
    rd_gl_check_mode mode;
    unsigned long errors;
    PFNGLGETERRORPROC get_error;
    PFNGLDEBUGMESSAGECALLBACKPROC callback;
    PFNGLDISABLEPROC disable;
} check;

static void *load(void *(*gpa)(const char *), const char *name)
{
    return gpa ? gpa(name) : NULL;
}

static void count(const char *what)
{
    if (check.errors < PRINTED_MAX)
        fprintf(stderr, "tessera: GL error: %s\n", what);
    else if (check.errors == PRINTED_MAX)
        fprintf(stderr, "tessera: GL error: (more errors are counted, not printed)\n");
    check.errors++;
}

static void APIENTRY on_message(GLenum source, GLenum type, GLuint id, GLenum severity,
                                GLsizei length, const GLchar *message, const void *user)
{
    (void)source;
    (void)id;
    (void)severity;
    (void)length;
    (void)user;
    /* Errors and undefined behaviour; performance and portability notes are not faults. */
    if (type == GL_DEBUG_TYPE_ERROR || type == GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR)
        count(message ? message : "(no message)");
}

/* KHR_debug is core from 4.3; below that, the extension string decides. */
static int has_khr_debug(void *(*gpa)(const char *))
{
    PFNGLGETINTEGERVPROC get_integer;
    PFNGLGETSTRINGIPROC get_string_i;
    void *gi = load(gpa, "glGetIntegerv"), *gs = load(gpa, "glGetStringi");
    memcpy(&get_integer, &gi, sizeof gi);
    memcpy(&get_string_i, &gs, sizeof gs);
    if (!get_integer)
        return 0;
    GLint major = 0, minor = 0, n = 0;
    get_integer(GL_MAJOR_VERSION, &major);
    get_integer(GL_MINOR_VERSION, &minor);
    if (major > 4 || (major == 4 && minor >= 3))
        return 1;
    get_integer(GL_NUM_EXTENSIONS, &n);
    for (GLint i = 0; get_string_i && i < n; i++) {
        const char *e = (const char *)get_string_i(GL_EXTENSIONS, (GLuint)i);
        if (e && !strcmp(e, "GL_KHR_debug"))
            return 1;
    }
    return 0;
}

rd_gl_check_mode rd_gl_check_begin(void *(*get_proc_address)(const char *name), int prefer_poll)
{
    memset(&check, 0, sizeof check);
    void *ge = load(get_proc_address, "glGetError");
    memcpy(&check.get_error, &ge, sizeof ge);
    if (!check.get_error)
        return RD_GL_CHECK_OFF;
    while (check.get_error() != GL_NO_ERROR) /* what came before is not ours to count */
        ;
    check.mode = RD_GL_CHECK_POLL;
    if (prefer_poll || !has_khr_debug(get_proc_address))
        return check.mode;
    void *cb = load(get_proc_address, "glDebugMessageCallback");
    void *en = load(get_proc_address, "glEnable"), *dis = load(get_proc_address, "glDisable");
    PFNGLENABLEPROC enable;
    memcpy(&check.callback, &cb, sizeof cb);
    memcpy(&enable, &en, sizeof en);
    memcpy(&check.disable, &dis, sizeof dis);
    if (!check.callback || !enable || !check.disable)
        return check.mode;
    check.callback(on_message, NULL);
    enable(GL_DEBUG_OUTPUT);
    enable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    if (check.get_error() != GL_NO_ERROR) { /* the context refused: poll instead */
        check.callback(NULL, NULL);
        return check.mode;
    }
    check.mode = RD_GL_CHECK_CALLBACK;
    return check.mode;
}

static const char *error_name(GLenum e)
{
    switch (e) {
    case GL_INVALID_ENUM:
        return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE:
        return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
        return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION:
        return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY:
        return "GL_OUT_OF_MEMORY";
    default:
        return "an unknown error code";
    }
}

void rd_gl_check_poll(void)
{
    if (check.mode == RD_GL_CHECK_OFF)
        return;
    /* The flags are set for the callback's errors too; only POLL mode counts them here. A
     * context keeps one flag per error kind, so a frame's errors are bounded. */
    for (int i = 0; i < 16; i++) {
        GLenum e = check.get_error();
        if (e == GL_NO_ERROR)
            break;
        if (check.mode == RD_GL_CHECK_POLL) {
            char what[96];
            snprintf(what, sizeof what, "%s (glGetError at the end of a frame)", error_name(e));
            count(what);
        }
    }
}

unsigned long rd_gl_check_errors(void)
{
    return check.errors;
}

void rd_gl_check_end(void)
{
    if (check.mode == RD_GL_CHECK_CALLBACK) {
        check.disable(GL_DEBUG_OUTPUT);
        check.callback(NULL, NULL);
    }
    check.mode = RD_GL_CHECK_OFF;
}
