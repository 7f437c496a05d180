/* Auto exposure: the log-average luminance of the main pass (Reinhard et al. 2002, eqs. 1-2;
 * rd_auto_exposure_ev), measured at a grid of at most METER_SIDE x METER_SIDE of its samples
 * by shaders/exposure_meter.frag and summed here. A grid, not every sample: the average of a
 * room's luminance settles long before 9216 samples, and the read-back stays a few kB at any
 * image size. The reference tracer measures its own radiance at the same grid
 * (render/ref/src/ref_render.c), so both resolve a scene with the same EV. */
#include "gl_funcs.h"
#include "render_internal.h"

#include <math.h>
#include <stdlib.h>

#define METER_SIDE 96

void rd_tonemap_uniforms(const struct rd_tonemap_program *t, const rd_view *v, float exposure_ev)
{
    float wb[9];
    rd_white_balance_matrix(v->white_balance_k, wb);
    glUniform1f(t->u_exposure, exp2f(exposure_ev));
    glUniform1f(t->u_white, v->white > 0.0f ? v->white : 4.0f);
    glUniform1i(t->u_mode, (int)v->tonemap);
    glUniformMatrix3fv(t->u_wb, 1, GL_TRUE, wb); /* row-major */
}

rd_result rd_exposure_resolve(rd_context *ctx, const rd_view *v, float *ev)
{
    *ev = v->exposure_ev;
    if (!v->auto_exposure)
        return RD_OK;
    const struct rd_tonemap_program *m = rd_exposure_meter_program(ctx);
    if (!m)
        return RD_ERR_SHADER;
    int w = ctx->hdr.width < METER_SIDE ? ctx->hdr.width : METER_SIDE;
    int h = ctx->hdr.height < METER_SIDE ? ctx->hdr.height : METER_SIDE;
    rd_result r = rd_target_ensure(&ctx->meter, w, h, GL_RGBA32F, false);
    if (r != RD_OK)
        return r;
    float *logs = malloc((size_t)w * (size_t)h * 4 * sizeof(float));
    if (!logs)
        return rd_fail(RD_ERR_OUT_OF_MEMORY, "out of memory for the exposure meter");
    glBindFramebuffer(GL_FRAMEBUFFER, ctx->meter.fbo);
    glViewport(0, 0, w, h);
    glDisable(GL_DEPTH_TEST);
    glUseProgram(m->id);
    rd_tonemap_uniforms(m, v, 0.0f);
    glUniform2i(m->u_samples, w, h);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, ctx->hdr.color);
    glUniform1i(m->u_source, 0);
    glBindVertexArray(ctx->empty_vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, logs);
    double sum = 0.0;
    for (long long i = 0; i < (long long)w * h; i++)
        sum += logs[4 * i];
    free(logs);
    *ev = rd_auto_exposure_ev(sum, (long long)w * h, v->exposure_ev);
    return rd_gl_drain_errors() == GL_NO_ERROR
               ? RD_OK
               : rd_fail(RD_ERR_GL, "OpenGL error while measuring the exposure");
}
