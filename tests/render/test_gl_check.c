/* GL error counting (render/gl_check.h) in a context made by the test, as the window makes its
 * own: no error counts 0; an invalid enum counts exactly once through KHR_debug's callback
 * (the end-of-frame poll does not count it again) and once through the glGetError poll. */
#include "../common/check.h"
#include "render/gl_check.h"
#include "render/render.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/glcorearb.h>
#include <string.h>

static void *loader(const char *name)
{
    void *p;
    __extension__ p = (void *)eglGetProcAddress(name);
    return p;
}

/* glEnable(0x1234): GL_INVALID_ENUM by the specification. */
static void make_an_error(void)
{
    PFNGLENABLEPROC enable;
    void *p = loader("glEnable");
    memcpy(&enable, &p, sizeof p);
    enable(0x1234);
}

int main(void)
{
    PFNEGLGETPLATFORMDISPLAYEXTPROC gpd;
    __extension__ gpd =
        (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    EGLDisplay d =
        gpd ? gpd(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL) : EGL_NO_DISPLAY;
    if (d == EGL_NO_DISPLAY || !eglInitialize(d, NULL, NULL)) {
        fprintf(stderr, "SKIP: no EGL surfaceless display\n");
        return 77;
    }
    eglBindAPI(EGL_OPENGL_API);
    const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                              3,
                              EGL_CONTEXT_MINOR_VERSION,
                              3,
                              EGL_CONTEXT_OPENGL_PROFILE_MASK,
                              EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                              EGL_NONE};
    EGLContext c = eglCreateContext(d, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
    CHECK(c != EGL_NO_CONTEXT);
    CHECK(eglMakeCurrent(d, EGL_NO_SURFACE, EGL_NO_SURFACE, c));

    CHECK(rd_gl_check_begin(NULL, 0) == RD_GL_CHECK_OFF);

    /* Mesa's core contexts have KHR_debug (core in 4.3). */
    CHECK(rd_gl_check_begin(loader, 0) == RD_GL_CHECK_CALLBACK);
    CHECK(rd_gl_check_errors() == 0);
    rd_gl_check_poll();
    CHECK(rd_gl_check_errors() == 0);
    make_an_error();
    CHECK_MSG(rd_gl_check_errors() == 1, "callback: %lu errors", rd_gl_check_errors());
    rd_gl_check_poll(); /* the flag is taken, not counted twice */
    CHECK_MSG(rd_gl_check_errors() == 1, "callback + poll: %lu errors", rd_gl_check_errors());
    rd_gl_check_end();
    make_an_error(); /* after the end: not counted */
    CHECK(rd_gl_check_errors() == 1);

    CHECK(rd_gl_check_begin(loader, 1) == RD_GL_CHECK_POLL); /* drops the pending flag */
    CHECK(rd_gl_check_errors() == 0);
    make_an_error();
    CHECK(rd_gl_check_errors() == 0); /* counted at the poll */
    rd_gl_check_poll();
    CHECK_MSG(rd_gl_check_errors() == 1, "poll: %lu errors", rd_gl_check_errors());
    rd_gl_check_poll();
    CHECK(rd_gl_check_errors() == 1);
    rd_gl_check_end();

    eglMakeCurrent(d, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(d, c);
    eglTerminate(d);
    return check_report("test_gl_check");
}
