/* Showing the last render in a window the caller owns (RD_BACKEND_ADOPT): the tone-mapped
 * image scaled into framebuffer 0, and reading that framebuffer back for screenshots. The
 * planner renders its 3D view below the window size when the frame budget asks for it
 * (speed for accuracy, live); the blit's linear filter is the upscale. */
#include "render/ui_texture.h"

#include "gl_funcs.h"
#include "render_internal.h"

#include <string.h>

rd_result rd_present(rd_context *ctx, int window_width, int window_height)
{
    if (!ctx || !ctx->has_frame)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_present: nothing has been rendered");
    if (ctx->backend != RD_BACKEND_ADOPT)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_present: only an adopted context has a window");
    if (window_width <= 0 || window_height <= 0)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_present: window size %dx%d", window_width,
                       window_height);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, ctx->display.fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, ctx->out_width, ctx->out_height, 0, 0, window_width, window_height,
                      GL_COLOR_BUFFER_BIT, GL_LINEAR);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, window_width, window_height);
    return rd_gl_drain_errors() == GL_NO_ERROR ? RD_OK
                                               : rd_fail(RD_ERR_GL, "rd_present: blit failed");
}

rd_result rd_present_rect(rd_context *ctx, int window_width, int window_height, int x, int y,
                          int width, int height)
{
    if (!ctx || !ctx->has_frame)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_present_rect: nothing has been rendered");
    if (ctx->backend != RD_BACKEND_ADOPT)
        return rd_fail(RD_ERR_INVALID_ARGUMENT,
                       "rd_present_rect: only an adopted context has a window");
    if (window_width <= 0 || window_height <= 0 || width <= 0 || height <= 0)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_present_rect: window %dx%d, rectangle %dx%d",
                       window_width, window_height, width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, window_width, window_height);
    glClearColor(0.1f, 0.1f, 0.11f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    /* GL's window origin is its bottom-left corner. */
    int y0 = window_height - (y + height);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, ctx->display.fbo);
    glBlitFramebuffer(0, 0, ctx->out_width, ctx->out_height, x, y0, x + width, y0 + height,
                      GL_COLOR_BUFFER_BIT, GL_LINEAR);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return rd_gl_drain_errors() == GL_NO_ERROR ? RD_OK
                                               : rd_fail(RD_ERR_GL, "rd_present_rect: blit failed");
}

rd_result rd_present_rgba8(rd_context *ctx, int width, int height, const uint8_t *rgba,
                           int window_width, int window_height, int x, int y)
{
    if (!ctx || ctx->backend != RD_BACKEND_ADOPT)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_present_rgba8: no adopted window");
    if (width <= 0 || height <= 0 || !rgba)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_present_rgba8: image size %dx%d", width,
                       height);
    rd_result r = rd_target_ensure(&ctx->composed, width, height, GL_RGBA8, false);
    if (r != RD_OK)
        return r;
    /* Uploaded top row first, so the texture stands on its head; the blit turns it back. */
    glBindTexture(GL_TEXTURE_2D, ctx->composed.color);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, window_width, window_height);
    glClearColor(0.1f, 0.1f, 0.11f, 1.0f); /* as rd_present_rect: the rest is the panels' */
    glClear(GL_COLOR_BUFFER_BIT);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, ctx->composed.fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    /* GL's window origin is its bottom-left corner: the pane's top row at window_height - y. */
    int top = window_height - y;
    glBlitFramebuffer(0, 0, width, height, x, top, x + width, top - height, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, window_width, window_height);
    return rd_gl_drain_errors() == GL_NO_ERROR
               ? RD_OK
               : rd_fail(RD_ERR_GL, "rd_present_rgba8: upload or blit failed");
}

rd_result rd_read_window_rgba8(rd_context *ctx, int width, int height, uint8_t *out,
                               size_t out_size)
{
    if (!ctx || ctx->backend != RD_BACKEND_ADOPT)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_read_window_rgba8: no adopted window");
    size_t row = (size_t)width * 4;
    if (width <= 0 || height <= 0 || !out || out_size < row * (size_t)height)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_read_window_rgba8: bad size or buffer");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, out);
    /* GL's rows run bottom-up; images run top-down. */
    for (int y = 0; y < height / 2; y++) {
        uint8_t *a = out + (size_t)y * row, *b = out + (size_t)(height - 1 - y) * row;
        for (size_t i = 0; i < row; i++) {
            uint8_t t = a[i];
            a[i] = b[i];
            b[i] = t;
        }
    }
    return rd_gl_drain_errors() == GL_NO_ERROR
               ? RD_OK
               : rd_fail(RD_ERR_GL, "rd_read_window_rgba8: read failed");
}

rd_result rd_bind_window(rd_context *ctx, int width, int height)
{
    if (!ctx || ctx->backend != RD_BACKEND_ADOPT)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_bind_window: no adopted window");
    if (width <= 0 || height <= 0)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_bind_window: window size %dx%d", width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    return RD_OK;
}

unsigned rd_draw_framebuffer(rd_context *ctx)
{
    (void)ctx; /* the adopted window's context is current */
    GLint bound = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
    return (unsigned)bound;
}
