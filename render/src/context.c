#include "gl_funcs.h"
#include "render_internal.h"

#include <stdio.h>
#include <stdlib.h>

rd_result rd_backend_parse(const char *name, rd_backend *out)
{
    if (!name)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "no backend name");
    if (!strcmp(name, "egl"))
        *out = RD_BACKEND_EGL;
    else if (!strcmp(name, "osmesa"))
        *out = RD_BACKEND_OSMESA;
    else if (!strcmp(name, "adopt"))
        *out = RD_BACKEND_ADOPT;
    else
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "unknown backend \"%s\" (use egl or osmesa)", name);
    return RD_OK;
}

const char *rd_backend_name(rd_backend b)
{
    switch (b) {
    case RD_BACKEND_EGL:
        return "egl";
    case RD_BACKEND_OSMESA:
        return "osmesa";
    case RD_BACKEND_ADOPT:
        return "adopt";
    default:
        return "default";
    }
}

static rd_result open_backend(rd_context *ctx, rd_backend b, void *(**gpa)(const char *))
{
    ctx->backend = b;
    if (b == RD_BACKEND_EGL)
        return rd_backend_egl_create(&ctx->backend_state, &ctx->ops, gpa);
    return rd_backend_osmesa_create(&ctx->backend_state, &ctx->ops, gpa);
}

static rd_result choose_and_open(rd_context *ctx, const rd_context_desc *desc,
                                 void *(**gpa)(const char *))
{
    if (desc->backend == RD_BACKEND_ADOPT) {
        if (!desc->get_proc_address)
            return rd_fail(RD_ERR_INVALID_ARGUMENT,
                           "adopting the current context needs get_proc_address");
        ctx->backend = RD_BACKEND_ADOPT;
        *gpa = desc->get_proc_address;
        return RD_OK;
    }
    if (desc->backend != RD_BACKEND_DEFAULT)
        return open_backend(ctx, desc->backend, gpa);

    const char *env = getenv("TESSERA_GL");
    if (env && *env) {
        rd_backend b;
        if (rd_backend_parse(env, &b) != RD_OK || b == RD_BACKEND_ADOPT)
            return rd_fail(RD_ERR_INVALID_ARGUMENT,
                           "TESSERA_GL=\"%s\" is not a backend (use egl or osmesa)", env);
        return open_backend(ctx, b, gpa);
    }
    /* Default: EGL, and OSMesa when EGL cannot give a context. */
    if (open_backend(ctx, RD_BACKEND_EGL, gpa) == RD_OK)
        return RD_OK;
    return open_backend(ctx, RD_BACKEND_OSMESA, gpa);
}

static rd_result check_version(rd_context *ctx)
{
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    const char *renderer = (const char *)glGetString(GL_RENDERER);
    const char *version = (const char *)glGetString(GL_VERSION);
    snprintf(ctx->description, sizeof ctx->description, "%s; %s", renderer ? renderer : "?",
             version ? version : "?");
    if (major * 10 + minor < 33)
        return rd_fail(RD_ERR_BACKEND_UNAVAILABLE, "OpenGL 3.3 core is required, got %d.%d (%s)",
                       major, minor, ctx->description);
    GLint tex = 0, rb = 0, vp[2] = {0, 0};
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &tex);
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &rb);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, vp);
    int m = tex;
    if (rb < m)
        m = rb;
    if (vp[0] < m)
        m = vp[0];
    if (vp[1] < m)
        m = vp[1];
    ctx->max_size = m;
    return RD_OK;
}

rd_result rd_context_create(const rd_context_desc *desc, rd_context **out)
{
    static const rd_context_desc defaults = {0};
    if (!out)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_context_create: out is NULL");
    *out = NULL;
    if (!desc)
        desc = &defaults;
    rd_context *ctx = calloc(1, sizeof *ctx);
    if (!ctx)
        return rd_fail(RD_ERR_OUT_OF_MEMORY, "out of memory");
    void *(*gpa)(const char *) = NULL;
    rd_result r = choose_and_open(ctx, desc, &gpa);
    if (r == RD_OK && !rd_gl_load(gpa))
        r = RD_ERR_BACKEND_UNAVAILABLE;
    if (r == RD_OK)
        r = check_version(ctx);
    if (r == RD_OK)
        r = rd_programs_create(ctx);
    if (r != RD_OK) {
        rd_context_destroy(ctx);
        return r;
    }
    glGenVertexArrays(1, &ctx->empty_vao);
    glGenFramebuffers(1, &ctx->probe_fbo);
    /* One sampling rule for every cube map: filter across face edges (RENDERING.md 3). */
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    rd_gl_drain_errors();
    *out = ctx;
    return RD_OK;
}

void rd_context_destroy(rd_context *ctx)
{
    if (!ctx)
        return;
    if ((ctx->lit[0] && ctx->lit[0]->id) || ctx->backend_state ||
        ctx->backend == RD_BACKEND_ADOPT) {
        if (ctx->ops)
            ctx->ops->make_current(ctx->backend_state);
        if (rd_glDeleteProgram) {
            rd_resources_destroy_all(ctx);
            rd_programs_destroy(ctx);
            rd_target_destroy(&ctx->hdr);
            rd_adaptive_destroy(ctx);
            if (ctx->isotropic_sampler)
                glDeleteSamplers(1, &ctx->isotropic_sampler);
            rd_target_destroy(&ctx->display);
            rd_target_destroy(&ctx->composed);
            rd_target_destroy(&ctx->linear);
            rd_target_destroy(&ctx->meter);
            if (ctx->empty_vao)
                glDeleteVertexArrays(1, &ctx->empty_vao);
        }
    }
    if (ctx->ops)
        ctx->ops->destroy(ctx->backend_state);
    for (int v = 0; v < RD_LIT_VARIANTS; v++)
        free(ctx->lit[v]); /* what rd_programs_destroy left: a context whose GL is gone */
    free(ctx->meshes);
    free(ctx->textures);
    free(ctx->cubemaps);
    free(ctx);
}

rd_backend rd_context_backend(const rd_context *ctx)
{
    return ctx ? ctx->backend : RD_BACKEND_DEFAULT;
}

const char *rd_context_description(const rd_context *ctx)
{
    return ctx ? ctx->description : "";
}

int rd_context_max_size(const rd_context *ctx)
{
    return ctx ? ctx->max_size : 0;
}

rd_frame_stats rd_last_frame_stats(const rd_context *ctx)
{
    rd_frame_stats none = {0};
    return ctx ? ctx->stats : none;
}

void rd_finish(rd_context *ctx)
{
    (void)ctx;
    glFinish();
}

unsigned rd_gl_drain_errors(void)
{
    unsigned first = GL_NO_ERROR;
    for (int i = 0; i < 32; i++) {
        GLenum e = glGetError();
        if (e == GL_NO_ERROR)
            break;
        if (first == GL_NO_ERROR)
            first = e;
    }
    return first;
}
