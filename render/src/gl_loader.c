#include "gl_funcs.h"
#include "render_internal.h"

#define RD_GL_DEFINE(type, name) type rd_##name;
RD_GL_FUNCTIONS(RD_GL_DEFINE)
#undef RD_GL_DEFINE

int rd_gl_load(void *(*get_proc_address)(const char *name))
{
    /* ISO C forbids converting void* to a function pointer; memcpy is the portable way. */
#define RD_GL_LOAD(type, name)                                                                     \
    {                                                                                              \
        void *p = get_proc_address(#name);                                                         \
        if (!p) {                                                                                  \
            rd_set_error("OpenGL entry point %s is missing", #name);                               \
            return 0;                                                                              \
        }                                                                                          \
        memcpy(&rd_##name, &p, sizeof p);                                                          \
    }
    RD_GL_FUNCTIONS(RD_GL_LOAD)
#undef RD_GL_LOAD
    return 1;
}
