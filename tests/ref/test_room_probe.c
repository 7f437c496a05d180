/* The room probe (render/src/probe.c, lit.frag's pick_depth_hit) against the ground
 * truth. Under the "depth" correction an object's reflected ray is searched in its own probe
 * and in the room probe, a capture of everything from the room's centre; the room's hit is
 * taken where the own probe's centre cannot see what the ray meets (the basin mixer's rays
 * pass over the basin's rim, which hides the wall from the mixer's centre) or leaves it out
 * (a WC's seat reflects its cistern, a part of its own product).
 *
 * - assets/projects/demo-bathroom.json with the print preset's reflections (shadows off in
 *   both renderers, as the reference has none): the room probe on beats it off by at least
 *   1 dB over the reflective pixels, and over the mixer's pixels alone by at least 3 dB.
 *   Both without the self-reflection trace (render/src/self_trace.c), which finds what the
 *   room probe is searched for and so takes its place in the print preset.
 * - only what the scene needs: the room probe is captured (six more faces) only when something
 *   searches it: with it on, not when it is turned off, not under the print preset (the
 *   self-reflections find what it would), not under the "final" preset (box correction).
 *
 * GL through TESSERA_GL (EGL unless it says osmesa); some seconds on two cores. */
#include "../common/check.h"
#include "app/measure/image_compare.h"
#include "app/project/project.h"
#include "app/scene/quality.h"
#include "app/scene/ref_scene_build.h"
#include "app/scene/scene_build.h"
#include "gpu_render.h"
#include "ref/ref.h"
#include "render/render.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { W = 160, H = 90 };

/* The basin mixer of demo-bathroom.json in a W x H image of its "door" camera: the
 * window where the reflective error concentrates at 640 x 360 (x 120-160, y 200-240), scaled
 * to W x H (`tessera compare --worst N`). */
enum { MIXER_X0 = 30, MIXER_X1 = 40, MIXER_Y0 = 50, MIXER_Y1 = 60 };

/* off: 0 the room probe on, 1 off, both without self-reflections; -1 the preset as it is. */
static void set_room_off(rd_reflection_defaults *d, int off)
{
    if (off < 0)
        return;
    d->room_probe = off ? RD_SWITCH_OFF : RD_SWITCH_ON;
    d->self_reflections = 0;
    /* The direct-only tracer shows reflective objects plain in every reflection, the mirror's
     * too: the mirror's second bounce would be an error common to both renders. */
    d->mirror_bounce = RD_SWITCH_OFF;
}

static int render(rd_context *ctx, app_project *p, const rd_view *view, const char *preset,
                  int room_off, float *img, rd_frame_stats *stats)
{
    return gpu_render(ctx, p, view, preset, set_room_off, room_off, img, stats);
}

static double psnr(const float *img, const float *truth, const float *mask)
{
    app_image_metrics m;
    CHECK(app_image_metrics_compute(img, truth, W, H, mask, &m) == 0);
    return m.psnr;
}

int main(void)
{
    rd_context *ctx = NULL;
    if (rd_context_create(&(rd_context_desc){.backend = RD_BACKEND_DEFAULT}, &ctx) != RD_OK) {
        fprintf(stderr, "no GL context: %s\n", rd_last_error());
        return 1;
    }
    char err[2048];
    app_project project;
    const char *path = TESSERA_SOURCE_DIR "/assets/projects/demo-bathroom.json";
    if (app_project_read(path, &project, err, sizeof err) != APP_OK) {
        CHECK_MSG(0, "%s", err);
        rd_context_destroy(ctx);
        return check_report("test_room_probe");
    }
    rd_view view;
    CHECK(app_view_from_camera(&project, NULL, W, H, &view, err, sizeof err) == APP_OK);
    view.supersample = 4; /* the print preset's 4 x 4, as in docs/accuracy.md */
    ref_scene *rs = NULL;
    CHECK_MSG(app_ref_scene_build(&project, &rs, err, sizeof err) == APP_OK, "%s", err);
    ref_image traced = {0};
    float *mask = malloc((size_t)W * H * sizeof *mask),
          *mixer = calloc((size_t)W * H, sizeof *mixer);
    float *on = malloc((size_t)W * H * 4 * sizeof *on),
          *off = malloc((size_t)W * H * 4 * sizeof *off);
    int ok = rs && mask && mixer && on && off &&
             ref_render(rs, &(ref_render_desc){.view = view, .samples = 16}, &traced) == REF_OK;
    CHECK_MSG(ok, "reference: %s", ref_last_error());
    if (ok) {
        for (int i = 0; i < W * H; i++)
            mask[i] = traced.mask[i] ? 1.0f : 0.0f;
        for (int y = MIXER_Y0; y < MIXER_Y1; y++)
            for (int x = MIXER_X0; x < MIXER_X1; x++)
                mixer[y * W + x] = mask[y * W + x];
        rd_frame_stats st_on, st_off, st_final;
        if (render(ctx, &project, &view, "print", 0, on, &st_on) &&
            render(ctx, &project, &view, "print", 1, off, &st_off)) {
            CHECK_MSG(st_on.room_probe == 1 && st_off.room_probe == 0 &&
                          st_on.faces_captured == st_off.faces_captured + 6,
                      "room probe captured %d / %d, faces %d / %d (on / off)", st_on.room_probe,
                      st_off.room_probe, st_on.faces_captured, st_off.faces_captured);
            double all_on = psnr(on, traced.linear, mask), all_off = psnr(off, traced.linear, mask);
            double mix_on = psnr(on, traced.linear, mixer),
                   mix_off = psnr(off, traced.linear, mixer);
            printf("demo, print, %dx%d: reflective PSNR room probe on %.2f dB, off %.2f dB; "
                   "basin mixer on %.2f dB, off %.2f dB\n",
                   W, H, all_on, all_off, mix_on, mix_off);
            CHECK_MSG(all_on >= all_off + 1.0, "room probe on %.2f dB is not 1 dB above off %.2f",
                      all_on, all_off);
            CHECK_MSG(mix_on >= mix_off + 3.0,
                      "the mixer: room probe on %.2f dB is not 3 dB above off %.2f", mix_on,
                      mix_off);
        }
        /* Which probes a frame captures does not depend on the image: these two, checked on
         * their stats alone, render a small one. */
        rd_view small = view;
        small.width = W / 4;
        small.height = H / 4;
        small.supersample = 1;
        if (render(ctx, &project, &small, "final", 0, on, &st_final))
            CHECK_MSG(st_final.room_probe == 0, "the final preset (box) captured the room probe");
        if (render(ctx, &project, &small, "print", -1, on, &st_final))
            CHECK_MSG(st_final.room_probe == 0 && st_final.self_traced_probes > 0,
                      "the print preset: room probe %d, %d probes self-traced", st_final.room_probe,
                      st_final.self_traced_probes);
    }
    free(mask);
    free(mixer);
    free(on);
    free(off);
    ref_image_free(&traced);
    ref_scene_destroy(rs);
    app_project_free(&project);
    rd_context_destroy(ctx);
    return check_report("test_room_probe");
}
