/* The GPU side of the tests that hold a render against the tracer (render/ref): one project
 * rendered as the tracer sees it, with shadows and glazes off (it has neither), a preset and
 * one change to the scene's reflection defaults. Header-only, so its CHECKs count in the
 * test that includes it (check.h). */
#ifndef TESTS_REF_GPU_RENDER_H
#define TESTS_REF_GPU_RENDER_H

#include "../common/check.h"
#include "app/project/project.h"
#include "app/scene/quality.h"
#include "app/scene/scene_build.h"
#include "render/render.h"

/* Changes the reflection defaults after the preset (room probe off, lamps in the probes...). */
typedef void (*gpu_render_tweak)(rd_reflection_defaults *d, int arg);

/* p's scene under `preset` (NULL: the project's own settings), `tweak(d, arg)` applied when
 * given, rendered for view into img (width x height linear RGBA) with the frame's stats. */
static int gpu_render(rd_context *ctx, app_project *p, const rd_view *view, const char *preset,
                      gpu_render_tweak tweak, int arg, float *img, rd_frame_stats *stats)
{
    char err[2048];
    app_scene s;
    if (app_scene_build(ctx, p, &s, err, sizeof err) != APP_OK) {
        CHECK_MSG(0, "%s", err);
        return 0;
    }
    if (preset)
        app_quality_apply(app_quality_find(preset), s.scene);
    rd_shadow_settings sh = rd_scene_shadows(s.scene);
    sh.mode = RD_SHADOWS_OFF;
    rd_scene_set_shadows(s.scene, &sh);
    /* Glazes off: the direct-only tracer (bounces 0) reflects nothing off a surface without a
     * reflectivity, where a glaze reflects the room (docs/rendering.md, "Glazes"). */
    rd_reflection_defaults d = rd_scene_reflection_defaults(s.scene);
    d.glaze = RD_SWITCH_OFF;
    if (tweak)
        tweak(&d, arg);
    rd_scene_set_reflection_defaults(s.scene, &d);
    size_t n = (size_t)view->width * (size_t)view->height * 4;
    int ok = rd_render(ctx, s.scene, view) == RD_OK && rd_read_linear(ctx, img, n) == RD_OK;
    CHECK_MSG(ok, "render: %s", rd_last_error());
    if (stats)
        *stats = rd_last_frame_stats(ctx);
    app_scene_release(ctx, &s);
    return ok;
}

#endif
