/* Self-reflections (render/src/self_trace.c) in a scene of primitives: a glass pane and a chrome
 * ball seen directly (tests/data/scenes/mirror-glass-room.json, a camera looking away from its
 * mirror). Primitive shapes are baked meshes, whose vertices are wider than a plain mesh's; the
 * trace must read their triangles where the rasteriser draws them. Baked as the CLI bakes.
 *
 * - print with self-reflections on against print with them off, 128 x 72 at 4 x 4: the scene
 *   holds no concave fixture, so the traced neighbours (the ball, the bands behind the pane)
 *   show what the probes show without the trace: within 30 dB over the whole image, and over
 *   the ball's and the pane's pixels.
 * - the trace does run: at least one probe is traced.
 * - the pane seen in the mirror (the scene's camera): on against off within 30 dB, as a
 *   mirror's capture traces glass though not the other fixtures.
 *
 * GL through TESSERA_GL (EGL unless it says osmesa); a few seconds on two cores. */
#include "../common/check.h"
#include "app/measure/image_compare.h"
#include "app/project/project.h"
#include "app/scene/scene_bake.h"
#include "app/scene/scene_build.h"
#include "gpu_render.h"
#include "render/render.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { W = 128, H = 72 };

static void set_self(rd_reflection_defaults *d, int on)
{
    if (!on)
        d->self_reflections = 0;
}

/* The PSNR of img against truth over the pixels of [x0, x1) x [y0, y1) (image rows from the
 * top, as rd_read_linear gives them). */
static double psnr_box(const float *img, const float *truth, float *mask, int x0, int y0, int x1,
                       int y1)
{
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
            mask[y * W + x] = x >= x0 && x < x1 && y >= y0 && y < y1 ? 1.0f : 0.0f;
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
    app_project p;
    if (app_project_read(TESSERA_SOURCE_DIR "/tests/data/scenes/mirror-glass-room.json", &p, err,
                         sizeof err) != APP_OK) {
        CHECK_MSG(0, "%s", err);
        rd_context_destroy(ctx);
        return check_report("test_self_trace_primitives");
    }
    /* The scene's camera, at the mirror: the pane appears in it at about x 0.55-0.76, y
     * 0.22-0.75 of the frame. */
    rd_view mirror_view;
    CHECK(app_view_from_camera(&p, NULL, W, H, &mirror_view, err, sizeof err) == APP_OK);
    mirror_view.supersample = 4;
    /* Look away from the mirror, at the pane (left) and the ball (right). */
    CHECK(p.camera_count >= 1);
    if (p.camera_count >= 1) {
        app_camera *c = &p.cameras[0];
        const double eye[3] = {1500, 300, 1300}, target[3] = {1500, 2500, 1100};
        memcpy(c->position_mm, eye, sizeof eye);
        memcpy(c->target_mm, target, sizeof target);
        c->fov_deg = 60.0;
    }
    /* Baked, as the CLI renders by default (--bake on): what gives primitives their wider
     * vertices. A coarse bake: the picture's light is not under test. */
    app_bake_configure(&(app_bake_settings){.on = 1, .samples = 16, .bounces = 1});
    rd_view view;
    CHECK(app_view_from_camera(&p, NULL, W, H, &view, err, sizeof err) == APP_OK);
    view.supersample = 4; /* the print preset's 4 x 4 */
    float *on = malloc((size_t)W * H * 4 * sizeof *on),
          *off = malloc((size_t)W * H * 4 * sizeof *off);
    float *mask = malloc((size_t)W * H * sizeof *mask);
    rd_frame_stats st;
    CHECK(on && off && mask);
    if (on && off && mask && gpu_render(ctx, &p, &view, "print", set_self, 1, on, &st) &&
        gpu_render(ctx, &p, &view, "print", set_self, 0, off, NULL)) {
        double all = psnr_box(on, off, mask, 0, 0, W, H);
        /* The pane covers about x 0.15-0.45, y 0.05-0.75 of the frame, the ball x 0.63-0.78,
         * y 0.38-0.68 (the camera above). */
        double pane =
            psnr_box(on, off, mask, W * 18 / 100, H * 10 / 100, W * 42 / 100, H * 70 / 100);
        double ball =
            psnr_box(on, off, mask, W * 65 / 100, H * 40 / 100, W * 76 / 100, H * 66 / 100);
        printf("mirror-glass-room, print, %dx%d: self-reflections on against off %.2f dB (pane "
               "%.2f, ball %.2f); %d probes traced, %d triangles\n",
               W, H, all, pane, ball, st.self_traced_probes, st.self_triangles);
        CHECK_MSG(all >= 30.0 && pane >= 30.0 && ball >= 30.0,
                  "on against off: %.2f dB, pane %.2f, ball %.2f (expected 30 each)", all, pane,
                  ball);
        CHECK_MSG(st.self_traced_probes >= 1, "no probe traced");
    }
    /* In the mirror's capture glass still traces what its probe leaves out (the red band). */
    if (on && off && mask && gpu_render(ctx, &p, &mirror_view, "print", set_self, 1, on, NULL) &&
        gpu_render(ctx, &p, &mirror_view, "print", set_self, 0, off, NULL)) {
        double pane =
            psnr_box(on, off, mask, W * 58 / 100, H * 26 / 100, W * 74 / 100, H * 72 / 100);
        printf("the pane in the mirror: self-reflections on against off %.2f dB\n", pane);
        CHECK_MSG(pane >= 30.0, "the pane in the mirror, on against off: %.2f dB (expected 30)",
                  pane);
    }
    free(on);
    free(off);
    free(mask);
    app_project_free(&p);
    rd_context_destroy(ctx);
    return check_report("test_self_trace_primitives");
}
