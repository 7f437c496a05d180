/* "Adopt the current context": the window (ui) makes its own GL context current and hands the
 * renderer its loader. Here an EGL context made by the test plays the window. */
#include "../common/check.h"
#include "render/primitives.h"
#include "render/render.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <string.h>

static void *loader(const char *name)
{
    void *p;
    __extension__ p = (void *)eglGetProcAddress(name);
    return p;
}

int main(void)
{
    PFNEGLGETPLATFORMDISPLAYEXTPROC gpd;
    __extension__ gpd =
        (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    EGLDisplay d =
        gpd ? gpd(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL) : EGL_NO_DISPLAY;
    if (d == EGL_NO_DISPLAY || !eglInitialize(d, NULL, NULL)) {
        fprintf(stderr, "no EGL surfaceless display\n");
        return 1;
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

    rd_context *ctx = NULL;
    CHECK(rd_context_create(&(rd_context_desc){.backend = RD_BACKEND_ADOPT}, &ctx) ==
          RD_ERR_INVALID_ARGUMENT); /* a loader is required */
    rd_result r = rd_context_create(
        &(rd_context_desc){.backend = RD_BACKEND_ADOPT, .get_proc_address = loader}, &ctx);
    CHECK_MSG(r == RD_OK, "%s", rd_last_error());
    if (r == RD_OK) {
        CHECK(rd_context_backend(ctx) == RD_BACKEND_ADOPT);
        rd_mesh_data pd;
        rd_mesh_data_sphere(16, 8, &pd);
        rd_mesh_desc desc = rd_mesh_data_desc(&pd);
        rd_mesh m = rd_mesh_create(ctx, &desc);
        rd_mesh_data_free(&pd);
        rd_scene *s = rd_scene_create(ctx);
        CHECK(rd_scene_add_object(
                  s, &(rd_object_desc){.mesh = m, .material = {.emissive = {9, 0, 0}}}) == RD_OK);
        rd_view v = {.eye = {0, -3, 0}, .target = {0, 0, 0}, .width = 32, .height = 32};
        CHECK(rd_render(ctx, s, &v) == RD_OK);
        unsigned char px[32 * 32 * 4];
        CHECK(rd_read_rgba8(ctx, px, sizeof px) == RD_OK);
        const unsigned char *centre = &px[(16 * 32 + 16) * 4];
        CHECK_MSG(centre[0] > 200 && centre[1] < 20, "centre %d %d %d", centre[0], centre[1],
                  centre[2]);
        CHECK(px[0] == 0); /* the corner sees no sphere */
        rd_scene_destroy(s);
        rd_context_destroy(ctx);
        /* The adopted context stays the caller's: still current and usable. */
        CHECK(eglGetCurrentContext() == c);
    }
    eglMakeCurrent(d, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(d, c);
    eglTerminate(d);
    return check_report("adopt_context");
}
