/* The reflection corrections against the ground truth (RENDERING.md sections 4, 10):
 * the GPU renders a scene with every reflective material set to one correction, the tracer
 * (render/ref) traces it once, and the PSNR over the reflective pixels must rank the methods
 * as docs/accuracy.md reports them:
 *
 * - assets/projects/stress-mirror.json (a large flat mirror close to a wall, a lamp and a shelf
 *   off the walls): "box" beats "none" by at least 6 dB and "depth" (distance impostors,
 *   reflect.glsl) beats box by at least 5 dB, margins the measured gaps clear with room to
 *   spare (docs/accuracy.md, "Corrections").
 * - assets/projects/stress-taps.json (glossy chrome before a window of radiance 20): box beats
 *   none and depth beats box. This holds only while the blur levels match their resolution
 *   (prefilter.h): otherwise the window bleeds through the coarse levels of the small tap
 *   probes and box loses to none.
 *
 * GL through TESSERA_GL (EGL unless it says osmesa); a few seconds on two cores. */
#include "../common/check.h"
#include "app/measure/image_compare.h"
#include "app/project/project.h"
#include "app/scene/ref_scene_build.h"
#include "app/scene/scene_build.h"
#include "ref/ref.h"
#include "render/render.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

enum { W = 160, H = 90 };

/* The exposure the truth was resolved with (auto exposure: measured by the tracer), used by
 * every GPU render it is compared with, so the images differ only by the method. */
static float truth_ev;

/* The GPU's PSNR over the mask against the truth with every reflective material set to `c`. */
static double gpu_psnr(rd_context *ctx, app_project *p, int c, const float *truth,
                       const float *mask)
{
    for (int i = 0; i < p->material_count; i++)
        if (p->materials[i].reflectivity > 0.0f || p->materials[i].transparency > 0.0f)
            p->materials[i].correction = c;
    char err[2048];
    app_scene s;
    if (app_scene_build(ctx, p, &s, err, sizeof err) != APP_OK) {
        CHECK_MSG(0, "%s", err);
        return NAN;
    }
    rd_view view;
    CHECK(app_view_from_camera(p, NULL, W, H, &view, err, sizeof err) == APP_OK);
    view.supersample = 1;
    view.auto_exposure = 0;
    view.exposure_ev = truth_ev;
    float *img = malloc((size_t)W * H * 4 * sizeof *img);
    double psnr = NAN;
    if (img && rd_render(ctx, s.scene, &view) == RD_OK &&
        rd_read_linear(ctx, img, (size_t)W * H * 4) == RD_OK) {
        app_image_metrics m;
        CHECK(app_image_metrics_compute(img, truth, W, H, mask, &m) == 0);
        psnr = m.psnr;
    } else {
        CHECK_MSG(0, "render: %s", rd_last_error());
    }
    free(img);
    app_scene_release(ctx, &s);
    return psnr;
}

/* PSNR over the reflective pixels for none, box and depth, in that order. */
static void measure(rd_context *ctx, const char *project, double out[3])
{
    char err[2048];
    app_project p;
    out[0] = out[1] = out[2] = NAN;
    if (app_project_read(project, &p, err, sizeof err) != APP_OK) {
        CHECK_MSG(0, "%s", err);
        return;
    }
    ref_scene *rs = NULL;
    CHECK_MSG(app_ref_scene_build(&p, &rs, err, sizeof err) == APP_OK, "%s", err);
    rd_view view;
    CHECK(app_view_from_camera(&p, NULL, W, H, &view, err, sizeof err) == APP_OK);
    view.supersample = 1;
    ref_image truth = {0};
    float *mask = malloc((size_t)W * H * sizeof *mask);
    if (rs && mask &&
        ref_render(rs, &(ref_render_desc){.view = view, .samples = 16}, &truth) == REF_OK) {
        for (int i = 0; i < W * H; i++)
            mask[i] = truth.mask[i] ? 1.0f : 0.0f;
        truth_ev = truth.exposure_ev;
        const int modes[3] = {APP_CORRECTION_NONE, APP_CORRECTION_BOX, APP_CORRECTION_DEPTH};
        for (int k = 0; k < 3; k++)
            out[k] = gpu_psnr(ctx, &p, modes[k], truth.linear, mask);
    } else {
        CHECK_MSG(0, "reference: %s", ref_last_error());
    }
    printf("%s: reflective PSNR none %.2f, box %.2f, depth %.2f dB\n", project, out[0], out[1],
           out[2]);
    free(mask);
    ref_image_free(&truth);
    ref_scene_destroy(rs);
    app_project_free(&p);
}

int main(void)
{
    rd_context *ctx = NULL;
    if (rd_context_create(&(rd_context_desc){.backend = RD_BACKEND_DEFAULT}, &ctx) != RD_OK) {
        fprintf(stderr, "no GL context: %s\n", rd_last_error());
        return 1;
    }
    double m[3];
    measure(ctx, TESSERA_SOURCE_DIR "/assets/projects/stress-mirror.json", m);
    CHECK_MSG(m[1] >= m[0] + 6.0, "mirror: box %.2f dB is not 6 dB above none %.2f", m[1], m[0]);
    CHECK_MSG(m[2] >= m[1] + 5.0, "mirror: depth %.2f dB is not 5 dB above box %.2f", m[2], m[1]);
    measure(ctx, TESSERA_SOURCE_DIR "/assets/projects/stress-taps.json", m);
    CHECK_MSG(m[1] > m[0], "taps: box %.2f dB is not above none %.2f", m[1], m[0]);
    CHECK_MSG(m[2] > m[1], "taps: depth %.2f dB is not above box %.2f", m[2], m[1]);
    rd_context_destroy(ctx);
    return check_report("test_depth_correction");
}
