/* Adaptive supersampling for large stills (print-resolution renders with supersampled
 * anti-aliasing in seconds, not minutes). A full s x s render shades every
 * sample of every pixel, though on most of a bathroom's surfaces the samples of a pixel agree
 * with its centre to well under a display step. So (Whitted 1980, section 4: sample at the
 * pixel, subdivide where neighbours differ):
 *   1. the main pass shades each pixel once, at its centre, at output size (renderer.c);
 *   2. the edge mask (edge_mask.frag), drawn over the s x s sample grid, marks in a stencil
 *      the samples of every pixel whose 3 x 3 neighbourhood steps by more than a threshold in
 *      display values;
 *   3. the refinement pass is the full s x s render with the stencil test on: llvmpipe tests
 *      the stencil before it shades, so unmarked blocks cost their rasterisation alone, and
 *      a marked pixel's s x s samples lie side by side, which keeps its SIMD lanes full;
 *   4. the resolve (tonemap.frag, ADAPTIVE) averages a refined pixel's samples after the tone
 *      map, exactly as the full render does, and tone-maps the others' centre sample.
 * A marked pixel's samples are those of the full render (same positions, shadow taps and
 * texture detail); an unmarked one differs from its full-render value by about the
 * neighbourhood's variation, below the threshold. tests/render/test_adaptive_ss.c. */
#include "draw.h"
#include "gl_funcs.h"
#include "phase_timer.h"
#include "render_internal.h"
#include "scene_internal.h"
#include "shadow.h"

#include <math.h>
#include <stdio.h>

/* 4/255: a step below the golden tolerance (5/255), so next to no pixel of the adaptive
 * image differs from the full s x s render by more than a golden test allows, while a
 * lower threshold refines more pixels for a difference no display shows (the threshold's
 * trade, measured: docs/benchmarks.md "Adaptive supersampling"). */
#define DEFAULT_THRESHOLD (4.0f / 255.0f)

void rd_adaptive_destroy(rd_context *ctx)
{
    struct rd_adaptive_target *a = &ctx->adaptive;
    if (a->fbo)
        glDeleteFramebuffers(1, &a->fbo);
    if (a->color)
        glDeleteTextures(1, &a->color);
    if (a->depth_stencil)
        glDeleteRenderbuffers(1, &a->depth_stencil);
    rd_target_destroy(&a->mask);
    memset(a, 0, sizeof *a);
}

static rd_result ensure_target(rd_context *ctx, int width, int height)
{
    struct rd_adaptive_target *a = &ctx->adaptive;
    if (a->fbo && a->width == width && a->height == height)
        return RD_OK;
    rd_target mask = a->mask; /* sized on its own (rd_target_ensure) */
    a->mask = (rd_target){0};
    rd_adaptive_destroy(ctx);
    a->mask = mask;
    rd_gl_drain_errors();
    glGenTextures(1, &a->color);
    glBindTexture(GL_TEXTURE_2D, a->color);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, width, height, 0, GL_RGBA, GL_FLOAT, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
    glGenRenderbuffers(1, &a->depth_stencil);
    glBindRenderbuffer(GL_RENDERBUFFER, a->depth_stencil);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
    glGenFramebuffers(1, &a->fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, a->fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, a->color, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                              a->depth_stencil);
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    unsigned err = rd_gl_drain_errors();
    if (status != GL_FRAMEBUFFER_COMPLETE || err != GL_NO_ERROR) {
        rd_adaptive_destroy(ctx);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        return rd_fail(err == GL_OUT_OF_MEMORY ? RD_ERR_OUT_OF_MEMORY : RD_ERR_GL,
                       "cannot make the %dx%d adaptive supersampling target (status 0x%x, GL "
                       "error 0x%x)",
                       width, height, status, err);
    }
    a->width = width;
    a->height = height;
    return RD_OK;
}

/* Step 2: the edge mask at output size, then the stencil set to 1 on the samples of the
 * marked pixels; returns how many samples that is. The mask is judged once a pixel (nine
 * tone-mapped reads), not once a sample. */
static long long mark_samples(rd_context *ctx, const rd_view *v, int samples,
                              const struct rd_tonemap_program *mask,
                              const struct rd_tonemap_program *stencil)
{
    rd_target *m = &ctx->adaptive.mask;
    glBindFramebuffer(GL_FRAMEBUFFER, m->fbo);
    glViewport(0, 0, v->width, v->height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glUseProgram(mask->id);
    rd_tonemap_uniforms(mask, v, ctx->frame_exposure_ev);
    glUniform1f(mask->u_threshold,
                v->adaptive_threshold > 0.0f ? v->adaptive_threshold : DEFAULT_THRESHOLD);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, ctx->hdr.color);
    glUniform1i(mask->u_source, 0);
    glBindVertexArray(ctx->empty_vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    glBindFramebuffer(GL_FRAMEBUFFER, ctx->adaptive.fbo);
    glViewport(0, 0, ctx->adaptive.width, ctx->adaptive.height);
    glStencilMask(0xff);
    glClearStencil(0);
    glClearColor(0, 0, 0, 0); /* alpha 0: not drawn by the refinement (tonemap.frag) */
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glUseProgram(stencil->id);
    glUniform1i(stencil->u_samples, samples);
    glBindTexture(GL_TEXTURE_2D, m->color);
    glUniform1i(stencil->u_source, 0);
    unsigned query, marked = 0;
    glGenQueries(1, &query);
    glBeginQuery(GL_SAMPLES_PASSED, query);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glEndQuery(GL_SAMPLES_PASSED);
    glGetQueryObjectuiv(query, GL_QUERY_RESULT, &marked);
    glDeleteQueries(1, &query);
    glBindVertexArray(0);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    /* From here on the stencil only selects. */
    glStencilFunc(GL_EQUAL, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glStencilMask(0);
    return (long long)marked;
}

rd_result rd_adaptive_refine(rd_context *ctx, rd_scene *scene, const rd_view *v, int samples,
                             const float vp[16], const float view_rot[9])
{
    const struct rd_tonemap_program *mask = rd_edge_mask_program(ctx);
    const struct rd_tonemap_program *stencil = rd_mask_stencil_program(ctx);
    if (!mask || !stencil)
        return RD_ERR_SHADER;
    rd_result r = ensure_target(ctx, v->width * samples, v->height * samples);
    if (r == RD_OK)
        r = rd_target_ensure(&ctx->adaptive.mask, v->width, v->height, GL_R8, false);
    if (r != RD_OK)
        return r;
    long long marked = mark_samples(ctx, v, samples, mask, stencil);
    ctx->stats.refined_pixels = marked / ((long long)samples * samples);
    if (rd_phase_enabled())
        fprintf(stderr, "adaptive supersampling: %lld of %d pixels refined (%.1f %%), %d x %d\n",
                ctx->stats.refined_pixels, v->width * v->height,
                100.0 * (double)ctx->stats.refined_pixels / ((double)v->width * v->height), samples,
                samples);
    if (marked > 0) {
        /* Step 3: the full render's samples, where the stencil lets them through. */
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDepthMask(GL_TRUE);
        rd_shadow_frame(scene, v, samples);
        r = rd_draw_view(ctx, scene, vp, view_rot, v->eye, samples, v->live, v->all_objects);
    }
    glDisable(GL_STENCIL_TEST);
    glStencilMask(0xff);
    unsigned err = rd_gl_drain_errors();
    if (r == RD_OK && err != GL_NO_ERROR)
        r = rd_fail(err == GL_OUT_OF_MEMORY ? RD_ERR_OUT_OF_MEMORY : RD_ERR_GL,
                    "OpenGL error 0x%x in adaptive supersampling", err);
    return r;
}

void rd_adaptive_bind_samples(rd_context *ctx)
{
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, ctx->adaptive.color);
    glActiveTexture(GL_TEXTURE0);
}
