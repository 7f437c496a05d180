/* Off-screen render targets: a colour texture plus an optional depth buffer, resized lazily. */
#include "gl_funcs.h"
#include "render_internal.h"

void rd_target_destroy(rd_target *t)
{
    if (t->fbo)
        glDeleteFramebuffers(1, &t->fbo);
    if (t->color)
        glDeleteTextures(1, &t->color);
    if (t->depth)
        glDeleteRenderbuffers(1, &t->depth);
    memset(t, 0, sizeof *t);
}

rd_result rd_target_ensure(rd_target *t, int width, int height, unsigned internal_format,
                           bool with_depth)
{
    if (t->fbo && t->width == width && t->height == height &&
        t->color_internal_format == internal_format && (t->depth != 0) == with_depth)
        return RD_OK;
    rd_target_destroy(t);
    rd_gl_drain_errors();
    GLenum type =
        internal_format == GL_RGBA8 || internal_format == GL_R8 ? GL_UNSIGNED_BYTE : GL_FLOAT;
    glGenTextures(1, &t->color);
    glBindTexture(GL_TEXTURE_2D, t->color);
    glTexImage2D(GL_TEXTURE_2D, 0, (GLint)internal_format, width, height, 0, GL_RGBA, type, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
    glGenFramebuffers(1, &t->fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, t->fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t->color, 0);
    if (with_depth) {
        glGenRenderbuffers(1, &t->depth);
        glBindRenderbuffer(GL_RENDERBUFFER, t->depth);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, t->depth);
    }
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    unsigned err = rd_gl_drain_errors();
    if (status != GL_FRAMEBUFFER_COMPLETE || err != GL_NO_ERROR) {
        rd_target_destroy(t);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        return rd_fail(err == GL_OUT_OF_MEMORY ? RD_ERR_OUT_OF_MEMORY : RD_ERR_GL,
                       "cannot make a %dx%d render target (status 0x%x, GL error 0x%x)", width,
                       height, status, err);
    }
    t->width = width;
    t->height = height;
    t->color_internal_format = internal_format;
    return RD_OK;
}
