/* Sphere maps (RENDERING.md section 9; seed 000 eqs. 2, 4, 5): for materials that ask for
 * one, the probe's cube map is redrawn every frame as a sphere map for the current view (the
 * map is view-dependent by nature: its centre is the direction back to the viewer). */
#include "gl_funcs.h"
#include "probe.h"

static rd_result ensure_texture(rd_probe *p, int size)
{
    if (p->sphere_map && p->sphere_size == size)
        return RD_OK;
    rd_float_texture_2d(&p->sphere_map, size, size, 1);
    p->sphere_size = size;
    unsigned e = rd_gl_drain_errors();
    return e == GL_NO_ERROR ? RD_OK : rd_fail(RD_ERR_GL, "cannot make a %d sphere map", size);
}

rd_result rd_sphere_maps_update(rd_context *ctx, rd_scene *s, const float view_rot[9])
{
    for (int i = 0; i < s->probe_count; i++) {
        rd_probe *p = &s->probes[i];
        if (!s->objects[p->owner].material.sphere_map)
            continue;
        unsigned cube = rd_probe_texture(s, p);
        if (!cube)
            continue;
        /* Twice the face size: the disc spends its texels unevenly, most near the centre. */
        int size = p->size * 2 > 512 ? 512 : p->size * 2;
        rd_result r = ensure_texture(p, size < 2 ? 2 : size);
        if (r == RD_OK && !ctx->sphere_program)
            r = rd_sphere_program_create(ctx);
        if (r != RD_OK)
            return r;
        glBindFramebuffer(GL_FRAMEBUFFER, ctx->probe_fbo);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, 0);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, p->sphere_map,
                               0);
        glViewport(0, 0, p->sphere_size, p->sphere_size);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_CULL_FACE);
        glUseProgram(ctx->sphere_program);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
        glUniform1i(ctx->sm_u_source, 0);
        glUniformMatrix3fv(ctx->sm_u_view_rot, 1, GL_FALSE, view_rot);
        glUniform1f(ctx->sm_u_size, (float)p->sphere_size);
        glBindVertexArray(ctx->empty_vao);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindVertexArray(0);
        /* Box mips: the gloss lookup reads the sphere map at the material's level. */
        glBindTexture(GL_TEXTURE_2D, p->sphere_map);
        glGenerateMipmap(GL_TEXTURE_2D);
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    unsigned e = rd_gl_drain_errors();
    return e == GL_NO_ERROR ? RD_OK : rd_fail(RD_ERR_GL, "OpenGL error 0x%x in a sphere map", e);
}
