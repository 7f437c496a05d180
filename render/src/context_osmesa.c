/* Mesa's off-screen library: the fallback when EGL is not there. The renderer draws into its
 * own framebuffer objects, so OSMesa's buffer is only a token 16x16 one. */
#include "render_internal.h"

#include <GL/osmesa.h>
#include <stdlib.h>

typedef struct osmesa_state {
    OSMesaContext context;
    unsigned char buffer[16 * 16 * 4];
} osmesa_state;

static void osmesa_make_current(void *s)
{
    osmesa_state *st = s;
    OSMesaMakeCurrent(st->context, st->buffer, GL_UNSIGNED_BYTE, 16, 16);
}

static void osmesa_destroy(void *s)
{
    osmesa_state *st = s;
    if (!st)
        return;
    if (st->context)
        OSMesaDestroyContext(st->context);
    free(st);
}

static const rd_backend_ops osmesa_ops = {osmesa_make_current, osmesa_destroy};

static void *osmesa_proc(const char *name)
{
    void *p;
    __extension__ p = (void *)OSMesaGetProcAddress(name);
    return p;
}

rd_result rd_backend_osmesa_create(void **state, const rd_backend_ops **ops,
                                   void *(**gpa)(const char *))
{
    osmesa_state *st = calloc(1, sizeof *st);
    if (!st)
        return rd_fail(RD_ERR_OUT_OF_MEMORY, "out of memory");
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_DEPTH_BITS,
                           24,
                           OSMESA_PROFILE,
                           OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION,
                           3,
                           OSMESA_CONTEXT_MINOR_VERSION,
                           3,
                           0};
    st->context = OSMesaCreateContextAttribs(attribs, NULL);
    if (!st->context) {
        free(st);
        return rd_fail(RD_ERR_BACKEND_UNAVAILABLE,
                       "OSMesa: cannot create an OpenGL 3.3 core context");
    }
    if (!OSMesaMakeCurrent(st->context, st->buffer, GL_UNSIGNED_BYTE, 16, 16)) {
        osmesa_destroy(st);
        return rd_fail(RD_ERR_BACKEND_UNAVAILABLE, "OSMesa: cannot make the context current");
    }
    *state = st;
    *ops = &osmesa_ops;
    *gpa = osmesa_proc;
    return RD_OK;
}
