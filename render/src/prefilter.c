/* GPU prefiltering of a probe's cube map: one full-screen pass per face of a mip level. */
#include "prefilter.h"
#include "gl_funcs.h"
#include "phase_timer.h"
#include "probe.h"

#include "render/reflect_ref.h"

#include <math.h>

float rd_gloss_exponent(float g);

/* n(g) = 2^(13 g): g = 0 -> 1 (the cosine lobe), g = 1 -> 8192 (RENDERING.md section 5). */
float rd_gloss_exponent(float g)
{
    g = fminf(fmaxf(g, 0.0f), 1.0f);
    return exp2f(13.0f * g);
}

float rd_level_exponent(int level, int size)
{
    return rd_ref_level_exponent(level, rd_level_count(size));
}

float rd_lobe_level(float glossiness, int size, int levels)
{
    (void)size;
    return rd_ref_gloss_lod(glossiness, levels);
}

/* The mirror level is the capture itself: a framebuffer blit per face, no shading. (The HDR
 * clamp is for blurring; a mirror shows the lamp as it is.) */
static rd_result copy_level0(rd_context *ctx, unsigned source, unsigned dest, int size)
{
    if (!ctx->blit_fbo)
        glGenFramebuffers(1, &ctx->blit_fbo);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, ctx->blit_fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, ctx->probe_fbo);
    glFramebufferRenderbuffer(GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, 0);
    for (int f = 0; f < 6; f++) {
        GLenum face = GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f;
        glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, face, source, 0);
        glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, face, dest, 0);
        glBlitFramebuffer(0, 0, size, size, 0, 0, size, size, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    unsigned e = rd_gl_drain_errors();
    return e == GL_NO_ERROR ? RD_OK : rd_fail(RD_ERR_GL, "OpenGL error 0x%x copying a probe", e);
}

static rd_result prefilter_level(rd_context *ctx, unsigned source, int source_size, unsigned dest,
                                 int dest_size, int level, int levels, float hdr_clamp)
{
    if (!ctx->prefilter_program) {
        rd_result r = rd_prefilter_program_create(ctx);
        if (r != RD_OK)
            return r;
    }
    int size = dest_size >> level;
    if (size < 1)
        size = 1;
    if (level == 0 && source_size == dest_size)
        return copy_level0(ctx, source, dest, size);
    /* Level k holds the lobe matched to its texels (rd_level_exponent); level 0 is the mirror
     * image. */
    (void)levels;
    float exponent = level == 0 ? 0.0f : rd_level_exponent(level, dest_size);
    glBindFramebuffer(GL_FRAMEBUFFER, ctx->probe_fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, 0);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glViewport(0, 0, size, size);
    glUseProgram(ctx->prefilter_program);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_CUBE_MAP, source);
    glUniform1i(ctx->pf_u_source, 0);
    glUniform1f(ctx->pf_u_size, (float)size);
    glUniform1f(ctx->pf_u_exponent, exponent);
    glUniform1f(ctx->pf_u_clamp, hdr_clamp);
    glUniform1f(ctx->pf_u_source_size, (float)source_size);
    /* Twice the square of the lobe's width in texels (4 .. 24): a narrow lobe is a few texels
     * of this level, and the filtered lookups of the source already average those.
     * A level's lobe spans two of its texels (rd_ref_level_exponent), so 8 samples: more
     * samples change the demo's reflective PSNR by a hair and cost a 4K print's prefilter
     * seconds. */
    float half_width = sqrtf(2.0f * 0.6931472f / fmaxf(exponent, 1.0f));
    float texels = half_width / (1.5707963f / (float)size);
    int samples = (int)ceilf(2.0f * texels * texels);
    glUniform1i(ctx->pf_u_samples, samples < 4 ? 4 : samples > 24 ? 24 : samples);
    glBindVertexArray(ctx->empty_vao);
    for (int f = 0; f < 6; f++) {
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                               GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, dest, level);
        glUniform1i(ctx->pf_u_face, f);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glBindVertexArray(0);
    unsigned e = rd_gl_drain_errors();
    return e == GL_NO_ERROR ? RD_OK : rd_fail(RD_ERR_GL, "OpenGL error 0x%x prefiltering", e);
}

rd_result rd_prefilter_level(rd_context *ctx, unsigned source, int source_size, unsigned dest,
                             int dest_size, int level, int levels, float hdr_clamp)
{
    rd_phase_mark("probe captures"); /* TESSERA_PHASES: what came before was capturing */
    rd_result r =
        prefilter_level(ctx, source, source_size, dest, dest_size, level, levels, hdr_clamp);
    rd_phase_mark("prefilter");
    return r;
}
