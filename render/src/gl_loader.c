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
    void *storage = get_proc_address("glTexStorage2D");
    memcpy(&rd_glTexStorage2D, &storage, sizeof storage);
    return 1;
}

PFNGLTEXSTORAGE2DPROC rd_glTexStorage2D;

int rd_gl_has_tex_storage(void)
{
    /* GL 4.2 core (ARB_texture_storage); a get-proc-address may name functions the context
     * does not support, so the version decides. */
    GLint major = 0, minor = 0;
    rd_glGetIntegerv(GL_MAJOR_VERSION, &major);
    rd_glGetIntegerv(GL_MINOR_VERSION, &minor);
    return rd_glTexStorage2D && (major > 4 || (major == 4 && minor >= 2));
}
