/* Draws a view of a scene: lit pass into a float target, then exposure + tone map + sRGB into
 * an 8-bit target (RENDERING.md sections 1 and 9-HDR). */
#include "camera.h"
#include "draw.h"
#include "probe.h"
#include "probe_planar.h"
#include "gl_funcs.h"
#include "phase_timer.h"
#include "render_internal.h"
#include "scene_internal.h"
#include "shadow.h"

#include <cglm/cglm.h>
#include <math.h>
#include <stdlib.h>

/* Radiance target format: half float is exact enough for 8-bit output after the tone map
 * (11-bit mantissa) and halves the memory traffic of llvmpipe compared with RGBA32F. */
#define HDR_FORMAT GL_RGBA16F
/* The most samples (supersampled pixels) one render may hold: 2^26, a 8192x8192 image. */
#define MAX_SAMPLES (1LL << 26)

static rd_result validate_view(const rd_context *ctx, const rd_view *v, int *samples)
{
    if (!v)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "no view");
    int s = v->supersample <= 0 ? 1 : v->supersample;
    if (s > 4)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "supersampling %d is above the maximum of 4", s);
    if (v->width <= 0 || v->height <= 0)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "image size %dx%d: both sides must be at least 1",
                       v->width, v->height);
    long long sw = (long long)v->width * s, sh = (long long)v->height * s;
    if (sw > ctx->max_size || sh > ctx->max_size || sw * sh > MAX_SAMPLES)
        return rd_fail(RD_ERR_TOO_LARGE,
                       "image size %dx%d (x%d supersampling) is too large: at most %d per side "
                       "and %lld samples in all",
                       v->width, v->height, s, ctx->max_size, MAX_SAMPLES);
    if (v->full_width > 0 && (v->crop_x < 0 || v->crop_y < 0 || v->full_height <= 0 ||
                              (long long)v->crop_x + v->width > v->full_width ||
                              (long long)v->crop_y + v->height > v->full_height))
        return rd_fail(RD_ERR_INVALID_ARGUMENT,
                       "window %dx%d at (%d, %d) is not inside the %dx%d image", v->width,
                       v->height, v->crop_x, v->crop_y, v->full_width, v->full_height);
    if (!(v->exposure_ev > -64.0f && v->exposure_ev < 64.0f))
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "exposure %g EV is outside (-64, 64)",
                       (double)v->exposure_ev);
    if (v->white < 0.0f || !isfinite(v->white))
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "tone map white %g must be >= 0", (double)v->white);
    if (!(v->adaptive_threshold >= 0.0f && v->adaptive_threshold <= 1.0f))
        return rd_fail(RD_ERR_INVALID_ARGUMENT,
                       "adaptive supersampling threshold %g is outside [0, 1]",
                       (double)v->adaptive_threshold);
    if (!(fabsf(v->jitter[0]) < 1.0f && fabsf(v->jitter[1]) < 1.0f))
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "jitter (%g, %g) is not under a pixel",
                       (double)v->jitter[0], (double)v->jitter[1]);
    *samples = s;
    return RD_OK;
}

static void begin_hdr_pass(rd_context *ctx)
{
    glBindFramebuffer(GL_FRAMEBUFFER, ctx->hdr.fbo);
    glViewport(0, 0, ctx->hdr.width, ctx->hdr.height);
    glDisable(GL_CULL_FACE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

/* 1 when a view takes its samples adaptively (renderer_adaptive.c). */
static int adaptive(const rd_view *v, int samples)
{
    return v->adaptive && samples > 1;
}

static rd_result tonemap_pass(rd_context *ctx, const rd_view *v, int samples, unsigned fbo,
                              int linear)
{
    const struct rd_tonemap_program *t = adaptive(v, samples)
                                             ? rd_tonemap_adaptive_program(ctx, samples, linear)
                                             : rd_tonemap_program(ctx, samples, linear);
    if (!t)
        return RD_ERR_SHADER;
    if (adaptive(v, samples)) {
        rd_adaptive_bind_samples(ctx);
        glUseProgram(t->id);
        glUniform1i(t->u_refined, 1);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glViewport(0, 0, v->width, v->height);
    glDisable(GL_DEPTH_TEST);
    glUseProgram(t->id);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, ctx->hdr.color);
    glUniform1i(t->u_source, 0);
    rd_tonemap_uniforms(t, v, ctx->frame_exposure_ev);
    glBindVertexArray(ctx->empty_vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    return RD_OK;
}

static rd_result prepare(rd_context *ctx, rd_scene *scene, const rd_view *v, int *samples,
                         float vp[16], float inv_vp[16], float view_rot[9])
{
    if (!ctx || !scene)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_render: context and scene are required");
    rd_result r = validate_view(ctx, v, samples);
    if (r != RD_OK)
        return r;
    rd_scene_view_input in = {scene};
    r = rd_camera_matrices(ctx, v, &in, vp, inv_vp, view_rot);
    if (r != RD_OK)
        return r;
    if (ctx->ops)
        ctx->ops->make_current(ctx->backend_state);
    int scale = adaptive(v, *samples) ? 1 : *samples;
    r = rd_target_ensure(&ctx->hdr, v->width * scale, v->height * scale, HDR_FORMAT, true);
    if (r == RD_OK)
        r = rd_target_ensure(&ctx->display, v->width, v->height, GL_RGBA8, false);
    return r;
}

rd_result rd_render(rd_context *ctx, rd_scene *scene, const rd_view *v)
{
    int samples;
    float vp[16], view_rot[9];
    rd_result pr = prepare(ctx, scene, v, &samples, vp, NULL, view_rot);
    if (pr != RD_OK)
        return pr;
    rd_frame_stats stats = {0};
    /* A tile's probes are as sharp as the whole image's (renderer_tiled.c). */
    float pixels_per_tan = 0.5f * (float)(v->full_width > 0 ? v->full_height : v->height) /
                           tanf(0.5f * glm_rad(v->fov_y_deg > 0.0f ? v->fov_y_deg : 60.0f));
    /* SH9 ambient first: the probes' captures light what they see with its coefficients
     * (RENDERING.md section 7), and a still's one frame must not capture them without any. */
    rd_phase_mark("targets");
    rd_result r = rd_ambient_update(ctx, scene, &stats);
    rd_phase_mark("SH9 ambient");
    int shaded = adaptive(v, samples) ? 1 : samples; /* the main pass's samples a pixel side */
    /* An adaptive view's main pass reads a planar capture once a pixel, at its centre, and
     * keeps that for all but the refined edges: a texel a pixel, whose bilinear tap spans about
     * the pixel, as the s x s samples' box filter would. Every other view keeps the capture's
     * 1.5 texels a sample (probe_planar.c). Measured: docs/benchmarks.md, "Print renders". */
    rd_planar_view planar = {vp,
                             {(float)(v->width * shaded), (float)(v->height * shaded)},
                             pixels_per_tan * (float)shaded,
                             adaptive(v, samples) ? 1.0f : 0.0f};
    /* A strip of a split capture (the window's still view) captures for the whole image:
     * its strips are kept only once no probe in the picture waits. */
    float whole_vp[16];
    const float *capture_vp = NULL;
    if (r == RD_OK && scene->reflection.split_captures >= 2 && v->full_width > 0) {
        rd_view whole = *v;
        whole.crop_x = whole.crop_y = whole.full_width = whole.full_height = 0;
        whole.width = v->full_width;
        whole.height = v->full_height;
        rd_scene_view_input in = {scene};
        if (rd_camera_matrices(ctx, &whole, &in, whole_vp, NULL, NULL) == RD_OK)
            capture_vp = whole_vp;
    }
    if (r == RD_OK)
        r = rd_probes_update(ctx, scene, vp, capture_vp, v->eye, pixels_per_tan, samples, &planar,
                             v->live || scene->hold_probe_sizes, &stats);
    if (r == RD_OK)
        r = rd_sphere_maps_update(ctx, scene, view_rot);
    if (r == RD_OK)
        r = rd_shadow_maps_update(ctx, scene);
    /* An adaptive view's main pass takes each pixel's centre as its one sample. */
    rd_shadow_frame(scene, v, shaded);
    if (r != RD_OK)
        return r;
    stats.adaptive = adaptive(v, samples);
    ctx->stats = stats;
    begin_hdr_pass(ctx);
    r = rd_draw_view(ctx, scene, vp, view_rot, v->eye, shaded, v->live, v->all_objects);
    /* The exposure before the adaptive edge mask, which judges pixels in display values. */
    if (r == RD_OK)
        r = rd_exposure_resolve(ctx, v, &ctx->frame_exposure_ev);
    ctx->stats.exposure_ev = ctx->frame_exposure_ev;
    if (r == RD_OK && adaptive(v, samples)) {
        rd_phase_mark("main pass, once per pixel");
        r = rd_adaptive_refine(ctx, scene, v, samples, vp, view_rot);
        rd_phase_mark("adaptive refinement");
    }
    if (r != RD_OK)
        return r;

    r = tonemap_pass(ctx, v, samples, ctx->display.fbo, 0);
    if (r == RD_OK && v->to_window && ctx->backend == RD_BACKEND_ADOPT)
        r = tonemap_pass(ctx, v, samples, 0, 0);
    if (r != RD_OK)
        return r;
    glBindVertexArray(0);
    unsigned err = rd_gl_drain_errors();
    if (err != GL_NO_ERROR)
        return rd_fail(err == GL_OUT_OF_MEMORY ? RD_ERR_OUT_OF_MEMORY : RD_ERR_GL,
                       "OpenGL error 0x%x while rendering", err);
    ctx->out_width = v->width;
    ctx->out_height = v->height;
    ctx->has_frame = 1;
    ctx->frame_view = *v;
    ctx->frame_samples = samples;
    return RD_OK;
}

rd_result rd_render_floor(rd_context *ctx, rd_scene *scene, const rd_view *v)
{
    int samples;
    float vp[16], inv_vp[16];
    rd_result r = prepare(ctx, scene, v, &samples, vp, inv_vp, NULL);
    if (r != RD_OK)
        return r;
    if (!ctx->floor_quad.id) {
        /* A quad on the clip-space plane z = 0; its model matrix (the inverse view-projection)
         * puts it in the world right in front of the camera, covering the whole view. */
        static const float pos[] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
        static const float nrm[] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
        static const uint32_t idx[] = {0, 1, 2, 0, 2, 3};
        ctx->floor_quad = rd_mesh_create(ctx, &(rd_mesh_desc){.positions = pos,
                                                              .normals = nrm,
                                                              .indices = idx,
                                                              .vertex_count = 4,
                                                              .index_count = 6});
        if (!ctx->floor_quad.id)
            return RD_ERR_GL;
    }
    const rd_mesh_slot *m = rd_mesh_lookup(ctx, ctx->floor_quad);
    begin_hdr_pass(ctx);
    /* The same lighting program as the scene's plain objects, SH9 ambient included. */
    const rd_program *p =
        rd_lit_program(ctx, (scene->reflection.ambient == RD_AMBIENT_SH9 ? RD_LIT_SH9 : 0) |
                                (rd_scene_has_area_lights(scene) ? RD_LIT_AREA_LIGHTS : 0));
    rd_set_frame_uniforms(p, scene, vp, v->eye);
    rd_material grey = {.ambient = {0.5f, 0.5f, 0.5f},
                        .diffuse = {0.5f, 0.5f, 0.5f},
                        .specular = {0.2f, 0.2f, 0.2f},
                        .shininess = 32.0f};
    rd_set_object_uniforms(p, inv_vp, &grey);
    glBindVertexArray(m->vao);
    glDisable(GL_CULL_FACE);
    glDrawElements(GL_TRIANGLES, m->index_count, GL_UNSIGNED_INT, 0);
    glBindVertexArray(0);
    unsigned err = rd_gl_drain_errors();
    if (err != GL_NO_ERROR)
        return rd_fail(RD_ERR_GL, "OpenGL error 0x%x in the floor pass", err);
    ctx->has_frame = 0; /* the floor leaves no image to read */
    return RD_OK;
}

static void flip_rows(unsigned char *data, int height, size_t row_bytes)
{
    unsigned char *tmp = malloc(row_bytes);
    if (!tmp)
        return;
    for (int y = 0; y < height / 2; y++) {
        unsigned char *a = data + (size_t)y * row_bytes;
        unsigned char *b = data + (size_t)(height - 1 - y) * row_bytes;
        memcpy(tmp, a, row_bytes);
        memcpy(a, b, row_bytes);
        memcpy(b, tmp, row_bytes);
    }
    free(tmp);
}

rd_result rd_read_rgba8(rd_context *ctx, uint8_t *out, size_t out_size)
{
    if (!ctx || !ctx->has_frame)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_read_rgba8: nothing has been rendered");
    size_t need = (size_t)ctx->out_width * (size_t)ctx->out_height * 4;
    if (!out || out_size < need)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_read_rgba8: buffer of %zu bytes, need %zu",
                       out_size, need);
    glBindFramebuffer(GL_FRAMEBUFFER, ctx->display.fbo);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, ctx->out_width, ctx->out_height, GL_RGBA, GL_UNSIGNED_BYTE, out);
    flip_rows(out, ctx->out_height, (size_t)ctx->out_width * 4);
    return rd_gl_drain_errors() == GL_NO_ERROR ? RD_OK
                                               : rd_fail(RD_ERR_GL, "rd_read_rgba8: read failed");
}

rd_result rd_read_linear(rd_context *ctx, float *out, size_t out_count)
{
    if (!ctx || !ctx->has_frame)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_read_linear: nothing has been rendered");
    size_t need = (size_t)ctx->out_width * (size_t)ctx->out_height * 4;
    if (!out || out_count < need)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_read_linear: buffer of %zu floats, need %zu",
                       out_count, need);
    rd_result r =
        rd_target_ensure(&ctx->linear, ctx->out_width, ctx->out_height, GL_RGBA32F, false);
    if (r != RD_OK)
        return r;
    r = tonemap_pass(ctx, &ctx->frame_view, ctx->frame_samples, ctx->linear.fbo, 1);
    if (r != RD_OK)
        return r;
    glBindVertexArray(0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, ctx->out_width, ctx->out_height, GL_RGBA, GL_FLOAT, out);
    flip_rows((unsigned char *)out, ctx->out_height, (size_t)ctx->out_width * 4 * sizeof(float));
    return rd_gl_drain_errors() == GL_NO_ERROR ? RD_OK
                                               : rd_fail(RD_ERR_GL, "rd_read_linear: read failed");
}
