/* Headless EGL: Mesa's surfaceless platform first (llvmpipe here), then the EGL device
 * platform where a driver offers one. No window system is touched. */
#include "render_internal.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <stdlib.h>

typedef struct egl_state {
    EGLDisplay display;
    EGLContext context;
} egl_state;

static void egl_make_current(void *s)
{
    egl_state *st = s;
    eglMakeCurrent(st->display, EGL_NO_SURFACE, EGL_NO_SURFACE, st->context);
}

static void egl_destroy(void *s)
{
    egl_state *st = s;
    if (!st)
        return;
    if (st->display != EGL_NO_DISPLAY) {
        eglMakeCurrent(st->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (st->context != EGL_NO_CONTEXT)
            eglDestroyContext(st->display, st->context);
        eglTerminate(st->display);
    }
    free(st);
}

static const rd_backend_ops egl_ops = {egl_make_current, egl_destroy};

static void *egl_proc(const char *name)
{
    void *p;
    __extension__ p = (void *)eglGetProcAddress(name);
    return p;
}

static EGLDisplay open_display(void)
{
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display;
    __extension__ get_platform_display =
        (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    if (!get_platform_display)
        return EGL_NO_DISPLAY;

    EGLDisplay d = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    if (d != EGL_NO_DISPLAY && eglInitialize(d, NULL, NULL))
        return d;

    PFNEGLQUERYDEVICESEXTPROC query_devices;
    __extension__ query_devices =
        (PFNEGLQUERYDEVICESEXTPROC)eglGetProcAddress("eglQueryDevicesEXT");
    if (!query_devices)
        return EGL_NO_DISPLAY;
    EGLDeviceEXT devices[8];
    EGLint count = 0;
    if (!query_devices(8, devices, &count))
        return EGL_NO_DISPLAY;
    for (EGLint i = 0; i < count; i++) {
        d = get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], NULL);
        if (d != EGL_NO_DISPLAY && eglInitialize(d, NULL, NULL))
            return d;
    }
    return EGL_NO_DISPLAY;
}

rd_result rd_backend_egl_create(void **state, const rd_backend_ops **ops,
                                void *(**gpa)(const char *))
{
    egl_state *st = calloc(1, sizeof *st);
    if (!st)
        return rd_fail(RD_ERR_OUT_OF_MEMORY, "out of memory");
    st->display = open_display();
    if (st->display == EGL_NO_DISPLAY) {
        free(st);
        return rd_fail(
            RD_ERR_BACKEND_UNAVAILABLE,
            "EGL: no surfaceless or device display (EGL error 0x%x); try --backend osmesa",
            (unsigned)eglGetError());
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
        egl_destroy(st);
        return rd_fail(RD_ERR_BACKEND_UNAVAILABLE, "EGL: desktop OpenGL API not available");
    }
    const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = NULL;
    EGLint n = 0;
    eglChooseConfig(st->display, config_attribs, &config, 1, &n);
    const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                      3,
                                      EGL_CONTEXT_MINOR_VERSION,
                                      3,
                                      EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                      EGL_NONE};
    st->context = eglCreateContext(st->display, n > 0 ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT,
                                   context_attribs);
    if (st->context == EGL_NO_CONTEXT) {
        EGLint e = eglGetError();
        egl_destroy(st);
        return rd_fail(RD_ERR_BACKEND_UNAVAILABLE,
                       "EGL: cannot create an OpenGL 3.3 core context (EGL error 0x%x)",
                       (unsigned)e);
    }
    if (!eglMakeCurrent(st->display, EGL_NO_SURFACE, EGL_NO_SURFACE, st->context)) {
        EGLint e = eglGetError();
        egl_destroy(st);
        return rd_fail(RD_ERR_BACKEND_UNAVAILABLE,
                       "EGL: cannot make the context current without a surface (EGL error 0x%x)",
                       (unsigned)e);
    }
    *state = st;
    *ops = &egl_ops;
    *gpa = egl_proc;
    return RD_OK;
}
