/* Self-reflections (render/src/self_trace.c, self_trace.glsl) against the ground
 * truth. A probe leaves its own product out and holds its neighbours as its centre sees them;
 * under the print preset each fixture's lookups trace its own parts and the fixtures beside
 * it, which its probe then leaves out.
 *
 * - assets/projects/stress-taps.json (chrome taps on a ceramic counter before a bright window:
 *   a spout reflects its body and the counter), print preset, 160 x 90 at 4 x 4: on beats off
 *   by at least 8 dB over the reflective pixels, and reaches 28 dB.
 * - only what the scene needs: each of the five taps' probes is traced with the print preset;
 *   none when it is turned off, none under the interactive preset.
 * - a moved neighbour is traced where it now is: the counter moved 10 cm down after a first
 *   frame gives the image of a scene built with it there (within 50 dB).
 * - a reflective part shows what it reflects: tests/data/scenes/chrome-behind-glass.json (a
 *   chrome ball behind a clear pane, which traces it as a neighbour), print: the ball seen
 *   through the pane is as bright as the same ball without the pane, times the pane's
 *   transmission, within a third (drawn plain, chrome is its dark diffuse colour: a quarter).
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

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { W = 160, H = 90 };

/* on: the preset's self-reflections; off: none. */
static void set_self(rd_reflection_defaults *d, int on)
{
    if (!on)
        d->self_reflections = 0;
}

static double psnr(const float *img, const float *truth, const float *mask)
{
    app_image_metrics m;
    CHECK(app_image_metrics_compute(img, truth, W, H, mask, &m) == 0);
    return m.psnr;
}

static int find_object(const app_project *p, const char *name)
{
    for (int i = 0; i < p->object_count; i++)
        if (!strcmp(p->objects[i].name, name))
            return i;
    return -1;
}

static void against_tracer(rd_context *ctx, app_project *p, const rd_view *view, float *on,
                           float *off, float *mask)
{
    char err[2048];
    ref_scene *rs = NULL;
    ref_image truth = {0};
    int ok = app_ref_scene_build(p, &rs, err, sizeof err) == APP_OK &&
             ref_render(rs, &(ref_render_desc){.view = *view, .samples = 16}, &truth) == REF_OK;
    CHECK_MSG(ok, "reference: %s %s", err, ref_last_error());
    rd_frame_stats st_on, st_off, st_live;
    if (ok && gpu_render(ctx, p, view, "print", set_self, 1, on, &st_on) &&
        gpu_render(ctx, p, view, "print", set_self, 0, off, &st_off)) {
        for (int i = 0; i < W * H; i++)
            mask[i] = truth.mask[i] ? 1.0f : 0.0f;
        double a = psnr(on, truth.linear, mask), b = psnr(off, truth.linear, mask);
        printf("stress-taps, print, %dx%d: reflective PSNR self-reflections on %.2f dB, off "
               "%.2f dB; %d probes traced, %d triangles\n",
               W, H, a, b, st_on.self_traced_probes, st_on.self_triangles);
        CHECK_MSG(a >= b + 8.0, "self-reflections on %.2f dB is not 8 dB above off %.2f", a, b);
        CHECK_MSG(a >= 28.0, "self-reflections on: %.2f dB (expected 28)", a);
        CHECK_MSG(st_on.self_traced_probes == 5 && st_on.self_triangles > 0 &&
                      st_off.self_traced_probes == 0 && st_off.self_triangles == 0,
                  "probes traced: %d on (expected the 5 taps), %d off", st_on.self_traced_probes,
                  st_off.self_traced_probes);
    }
    if (gpu_render(ctx, p, view, "interactive", NULL, 0, on, &st_live))
        CHECK_MSG(st_live.self_traced_probes == 0, "the interactive preset traced %d probes",
                  st_live.self_traced_probes);
    ref_image_free(&truth);
    ref_scene_destroy(rs);
}

/* The counter moved down by `drop_m` in a scene that has rendered a frame already. */
static int render_moved(rd_context *ctx, app_project *p, const rd_view *view, int counter,
                        float drop_m, float *img)
{
    char err[2048];
    app_scene s;
    if (app_scene_build(ctx, p, &s, err, sizeof err) != APP_OK) {
        CHECK_MSG(0, "%s", err);
        return 0;
    }
    app_quality_apply(app_quality_find("print"), s.scene);
    rd_shadow_settings sh = rd_scene_shadows(s.scene);
    sh.mode = RD_SHADOWS_OFF;
    rd_scene_set_shadows(s.scene, &sh);
    size_t n = (size_t)W * H * 4;
    int ok = rd_render(ctx, s.scene, view) == RD_OK;
    if (ok) {
        double at[3] = {p->objects[counter].position_mm[0], p->objects[counter].position_mm[1],
                        p->objects[counter].position_mm[2] - drop_m * 1e3};
        ok = app_scene_move_object(&s, p, counter, at) == APP_OK &&
             rd_render(ctx, s.scene, view) == RD_OK && rd_read_linear(ctx, img, n) == RD_OK;
    }
    CHECK_MSG(ok, "moved render: %s", rd_last_error());
    app_scene_release(ctx, &s);
    return ok;
}

/* The print preset's glazes, which gpu_render leaves out for the tracer: the moved scene keeps
 * them, so the room probe they read must follow the move as well. */
static void keep_glazes(rd_reflection_defaults *d, int on)
{
    d->glaze = on ? RD_SWITCH_ON : RD_SWITCH_OFF;
}

static void moved_neighbour(rd_context *ctx, app_project *p, const rd_view *view, float *moved,
                            float *fresh, float *all)
{
    int counter = find_object(p, "counter");
    CHECK_MSG(counter >= 0, "stress-taps.json has no \"counter\"");
    if (counter < 0 || !render_moved(ctx, p, view, counter, 0.1f, moved))
        return; /* the counter stays moved in the document: the fresh build draws it there */
    if (!gpu_render(ctx, p, view, "print", keep_glazes, 1, fresh, NULL))
        return;
    for (int i = 0; i < W * H; i++)
        all[i] = 1.0f;
    double same = psnr(moved, fresh, all);
    printf("the counter moved 10 cm down after a frame against a scene built so: %.2f dB\n", same);
    CHECK_MSG(same >= 50.0, "moved counter: %.2f dB from the scene built with it there", same);
}

/* The mean linear luminance of the w x h pixels at (x0, y0) of a width-wide RGBA image. */
static double window_mean(const float *img, int width, int x0, int y0, int w, int h)
{
    double sum = 0.0;
    for (int y = y0; y < y0 + h; y++)
        for (int x = x0; x < x0 + w; x++) {
            const float *px = img + 4 * ((size_t)y * width + x);
            sum += (px[0] + px[1] + px[2]) / 3.0;
        }
    return sum / (w * h);
}

static void chrome_behind_glass(rd_context *ctx, float *through, float *bare)
{
    char err[2048];
    app_project p;
    if (app_project_read(TESSERA_SOURCE_DIR "/tests/data/scenes/chrome-behind-glass.json", &p, err,
                         sizeof err) != APP_OK) {
        CHECK_MSG(0, "%s", err);
        return;
    }
    rd_view view;
    CHECK(app_view_from_camera(&p, NULL, W, H, &view, err, sizeof err) == APP_OK);
    view.supersample = 4;
    int pane = find_object(&p, "screen");
    CHECK_MSG(pane == p.object_count - 1, "the pane is not the scene's last object");
    rd_frame_stats st;
    int ok =
        pane == p.object_count - 1 && gpu_render(ctx, &p, &view, "print", NULL, 0, through, &st);
    if (ok) {
        p.object_count--; /* the same room without the pane */
        ok = gpu_render(ctx, &p, &view, "print", NULL, 0, bare, NULL);
        p.object_count++;
    }
    if (ok) {
        /* The ball's lower half (the coloured bands behind the camera), clear of the lamp's
         * highlight: the ball's centre projects 3 pixels below the image's centre, 45 pixels
         * across. */
        double t = window_mean(through, W, 74, 47, 12, 8), b = window_mean(bare, W, 74, 47, 12, 8);
        float transmission = p.materials[p.objects[pane].material].transparency;
        printf("chrome ball behind a pane, print: %.4f through the pane, %.4f without it "
               "(ratio %.2f, the pane's transparency %.2f); %d probes traced\n",
               t, b, b > 0.0 ? t / b : 0.0, transmission, st.self_traced_probes);
        CHECK_MSG(st.self_traced_probes >= 1, "the pane traced nothing");
        CHECK_MSG(t >= 0.67 * transmission * b && t <= 1.33 * b,
                  "the ball through the pane %.4f against %.4f without it", t, b);
    }
    app_project_free(&p);
}

int main(void)
{
    rd_context *ctx = NULL;
    if (rd_context_create(&(rd_context_desc){.backend = RD_BACKEND_DEFAULT}, &ctx) != RD_OK) {
        fprintf(stderr, "no GL context: %s\n", rd_last_error());
        return 1;
    }
    char err[2048];
    app_project p;
    if (app_project_read(TESSERA_SOURCE_DIR "/assets/projects/stress-taps.json", &p, err,
                         sizeof err) != APP_OK) {
        CHECK_MSG(0, "%s", err);
        rd_context_destroy(ctx);
        return check_report("test_self_reflections");
    }
    rd_view view;
    CHECK(app_view_from_camera(&p, NULL, W, H, &view, err, sizeof err) == APP_OK);
    view.supersample = 4; /* the print preset's 4 x 4 */
    float *a = malloc((size_t)W * H * 4 * sizeof *a), *b = malloc((size_t)W * H * 4 * sizeof *b);
    float *mask = malloc((size_t)W * H * sizeof *mask);
    CHECK(a && b && mask);
    if (a && b && mask) {
        against_tracer(ctx, &p, &view, a, b, mask);
        moved_neighbour(ctx, &p, &view, a, b, mask);
        chrome_behind_glass(ctx, a, b);
    }
    free(a);
    free(b);
    free(mask);
    app_project_free(&p);
    rd_context_destroy(ctx);
    return check_report("test_self_reflections");
}
