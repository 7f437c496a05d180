/* Uploading small RGBA8 images for the caller's widgets (render/ui_texture.h). The texture is
 * plain GL: the widget toolkit binds it by name, the renderer never samples it. The binding of
 * texture unit 0 is restored, so neither the renderer's nor the toolkit's state is disturbed. */
#include "render/ui_texture.h"

#include "gl_funcs.h"
#include "render_internal.h"

rd_result rd_ui_texture_upload(rd_context *ctx, int width, int height, const uint8_t *rgba,
                               unsigned *gl_name)
{
    if (gl_name)
        *gl_name = 0;
    if (!ctx || ctx->backend != RD_BACKEND_ADOPT)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_ui_texture_upload: no adopted window context");
    if (width <= 0 || height <= 0 || width > 4096 || height > 4096 || !rgba || !gl_name)
        return rd_fail(RD_ERR_INVALID_ARGUMENT,
                       "rd_ui_texture_upload: bad size %dx%d (1..4096) or no pixels", width,
                       height);
    /* Errors pending from before are not drained here: they surface below rather than hide. */
    GLint previous = 0;
    glActiveTexture(GL_TEXTURE0);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &previous);
    GLuint t = 0;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    /* Top row first, as GL's v = 0 row: the widget maps uv (0,0) to the image's top left. */
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glBindTexture(GL_TEXTURE_2D, (GLuint)previous);
    if (rd_gl_drain_errors() != GL_NO_ERROR) {
        glDeleteTextures(1, &t);
        return rd_fail(RD_ERR_GL, "rd_ui_texture_upload: the %dx%d upload failed", width, height);
    }
    *gl_name = t;
    return RD_OK;
}

void rd_ui_texture_delete(rd_context *ctx, unsigned gl_name)
{
    if (!ctx || ctx->backend != RD_BACKEND_ADOPT || !gl_name)
        return;
    GLuint t = gl_name;
    glDeleteTextures(1, &t);
}
