/* SH9 ambient (RENDERING.md section 7; seed 001 eqs. 8-12 with Ramamoorthi and Hanrahan's
 * c5 = 0.247708): a small probe at the centre of the box proxy sees the room; its 8 x 8 mip is
 * read back and projected on the CPU onto nine coefficients (rd_ref_sh9_project), which every
 * lit program turns into irradiance per pixel. */
#include "gl_funcs.h"
#include "probe.h"

#include "render/cube_data.h"
#include "render/reflect_ref.h"

#include <math.h>
#include <string.h>
#include <stdlib.h>

#define AMBIENT_PROBE_SIZE 32
#define AMBIENT_READ_SIZE 8

static rd_result project_sh9(rd_scene *s, rd_probe *p)
{
    int level = 0;
    while ((AMBIENT_PROBE_SIZE >> level) > AMBIENT_READ_SIZE)
        level++;
    glBindTexture(GL_TEXTURE_CUBE_MAP, p->capture);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, level);
    glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
    rd_cube_data cube;
    rd_result r = rd_cube_data_alloc(AMBIENT_READ_SIZE, &cube);
    if (r != RD_OK) {
        glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
        return r;
    }
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    for (int f = 0; f < 6; f++)
        glGetTexImage(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, level, GL_RGBA, GL_FLOAT,
                      cube.faces[f]);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    rd_sh9 sh;
    rd_ref_sh9_project(&cube, &sh);
    rd_cube_data_free(&cube);
    memcpy(s->sh9, sh.coeff, sizeof s->sh9);
    return rd_gl_drain_errors() == GL_NO_ERROR ? RD_OK
                                               : rd_fail(RD_ERR_GL, "reading the ambient probe");
}

rd_result rd_scene_prepare_ambient(rd_context *ctx, rd_scene *scene)
{
    if (!ctx || !scene)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_scene_prepare_ambient: missing argument");
    if (ctx->ops)
        ctx->ops->make_current(ctx->backend_state);
    rd_frame_stats stats = {0};
    rd_result r = rd_ambient_update(ctx, scene, &stats);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glFinish();
    return r;
}

rd_result rd_ambient_update(rd_context *ctx, rd_scene *s, rd_frame_stats *stats)
{
    if (s->reflection.ambient != RD_AMBIENT_SH9)
        return RD_OK;
    rd_probe *p = &s->ambient_probe;
    if (!p->capture) {
        *p = (rd_probe){.key = 0,
                        .owner = -1,
                        .captured_frame = -1,
                        .filtered_level = -1,
                        .size = AMBIENT_PROBE_SIZE,
                        .levels = rd_level_count(AMBIENT_PROBE_SIZE)};
        rd_result r = rd_alloc_cube(&p->capture, p->size, p->levels);
        if (r != RD_OK)
            return r;
    }
    /* The same update policy as the scene's probes: every frame, every n-th, once, or when
     * something changed (time slicing does not apply: the projection needs all six faces). */
    rd_probe_update u = s->reflection.update ? s->reflection.update : RD_PROBE_EVERY_FRAME;
    int every = s->reflection.every_n > 1 ? s->reflection.every_n : 1;
    int due = p->captured_frame < 0 ||
              (u == RD_PROBE_ON_CHANGE && s->change_counter > p->captured_stamp) ||
              ((u == RD_PROBE_EVERY_FRAME || u == RD_PROBE_TIME_SLICED) &&
               s->frame - p->captured_frame >= every);
    /* Under a face budget (a live view, rd_reflection_defaults.max_faces_per_frame) the
     * irradiance waits until the scene has stood still for a frame: a fixture being dragged
     * changes the room's ambient light by little, and the six faces and the read-back of the
     * projection would cost every frame of the drag (RENDERING.md section 7 allows any
     * refresh rate for the SH9 probe; the stills have no budget and are not held back). */
    if (s->change_counter != s->ambient_seen_change) {
        s->ambient_seen_change = s->change_counter;
        s->ambient_seen_frame = s->frame;
    }
    if (due && p->captured_frame >= 0 && u == RD_PROBE_ON_CHANGE &&
        s->reflection.max_faces_per_frame > 0 && s->frame - s->ambient_seen_frame < 2)
        return RD_OK;
    if (!due)
        return RD_OK;
    float bmin[3], bmax[3], far_m = 0.0f;
    rd_effective_proxy(s, bmin, bmax);
    for (int k = 0; k < 3; k++) {
        p->centre[k] = 0.5f * (bmin[k] + bmax[k]);
        far_m += (bmax[k] - bmin[k]) * (bmax[k] - bmin[k]);
    }
    far_m = isfinite(far_m) && far_m > 0.0f ? 2.0f * sqrtf(far_m) : 100.0f;
    if (!isfinite(p->centre[0] + p->centre[1] + p->centre[2]))
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "SH9 ambient needs a scene with bounds");
    p->captured_stamp = s->change_counter;
    /* The capture sees the room lit by its lights alone, as a still's first frame does (no
     * coefficients exist yet) and as the tracer's capture does (ref_scene_set_ambient_sh9):
     * lit with the last frame's coefficients, each capture would add another bounce of
     * ambient to the next, and the room would brighten frame by frame toward a many-bounce
     * ambient that neither a still nor the tracer has. */
    memset(s->sh9, 0, sizeof s->sh9);
    for (int f = 0; f < 6; f++) {
        rd_result r = rd_probe_capture_face(ctx, s, p, f, far_m);
        if (r != RD_OK)
            return r;
        stats->faces_captured++;
    }
    p->captured_frame = s->frame;
    return project_sh9(s, p);
}
