/* Small images for a user interface drawn in the same OpenGL context as the renderer (the
 * planner's catalog thumbnails): RGBA8 pixels uploaded into a plain GL texture
 * whose name the caller hands to its widget toolkit (Dear ImGui's ImTextureID). Only for an
 * adopted context (RD_BACKEND_ADOPT), whose GL context is the window's and current. */
#ifndef RENDER_UI_TEXTURE_H
#define RENDER_UI_TEXTURE_H

#include "render/render.h"

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Uploads width x height RGBA8 texels (top row first, sRGB bytes shown as they are) into a new
 * texture with linear filtering and clamped edges; *gl_name gets its GL name. */
rd_result rd_ui_texture_upload(rd_context *ctx, int width, int height, const uint8_t *rgba,
                               unsigned *gl_name);
/* Deletes a texture made by rd_ui_texture_upload (0 is ignored). */
void rd_ui_texture_delete(rd_context *ctx, unsigned gl_name);
/* Binds the window (framebuffer 0) again with a width x height viewport after off-screen work
 * in the frame (a thumbnail's rd_render), so the caller's widgets draw into the window.
 * Implemented in present.c. */
rd_result rd_bind_window(rd_context *ctx, int width, int height);
/* The framebuffer draws go to now: 0 is the window, anything else a target off-screen work
 * left bound. */
unsigned rd_draw_framebuffer(rd_context *ctx);

#ifdef __cplusplus
}
#endif
#endif
