/* SH9 ambient in both renderers (RENDERING.md sections 7, 10): the shipped demo,
 * assets/projects/designed-bathroom.json, says "ambient_model": "sh9". The tracer must light
 * with the same nine coefficients the GPU projects from its ambient capture
 * (ref_scene_set_ambient_sh9), and the GPU must capture its reflection probes after those
 * coefficients exist (renderer.c), or a still's reflections miss the ambient term; and every
 * frame must capture the ambient as the first does, or it drifts from frame to frame.
 *
 * At 160 x 90, supersampling 1, 16 samples, the renderer's defaults: with the tracer on a
 * constant I_a instead, or with the probes captured before the coefficients, the reflective
 * pixels fall several dB below 10 dB; with both in order they stay above it, so the bar sits
 * between, at 10 dB (docs/accuracy.md, "Ambient"). Thin chrome parts of the products (rails,
 * handles, lamp housings: model_materials.c) reflect less exactly than big surfaces, which
 * is why the bar is not higher. GL through TESSERA_GL. */
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

int main(void)
{
    rd_context *ctx = NULL;
    if (rd_context_create(&(rd_context_desc){.backend = RD_BACKEND_DEFAULT}, &ctx) != RD_OK) {
        fprintf(stderr, "no GL context: %s\n", rd_last_error());
        return 1;
    }
    const char *path = TESSERA_SOURCE_DIR "/assets/projects/designed-bathroom.json";
    char err[2048];
    app_project p;
    if (app_project_read(path, &p, err, sizeof err) != APP_OK) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    CHECK_MSG(p.render.ambient_model == 1, "%s no longer uses SH9 ambient", path);
    rd_view view;
    CHECK(app_view_from_camera(&p, NULL, W, H, &view, err, sizeof err) == APP_OK);
    view.supersample = 1;

    ref_scene *rs = NULL;
    CHECK_MSG(app_ref_scene_build(&p, &rs, err, sizeof err) == APP_OK, "%s", err);
    ref_image truth = {0};
    CHECK_MSG(rs &&
                  ref_render(rs, &(ref_render_desc){.view = view, .samples = 16}, &truth) == REF_OK,
              "reference: %s", ref_last_error());
    rd_sh9 sh;
    CHECK_MSG(rs && ref_scene_ambient_sh9(rs, &sh) && sh.coeff[0][0] > 0.0f,
              "the tracer made no SH9 coefficients");

    app_scene s;
    CHECK_MSG(app_scene_build(ctx, &p, &s, err, sizeof err) == APP_OK, "%s", err);
    float *img = malloc((size_t)W * H * 4 * sizeof *img);
    float *plain = malloc((size_t)W * H * sizeof *plain);
    float *refl = malloc((size_t)W * H * sizeof *refl);
    CHECK(img && plain && refl && truth.linear);
    if (img && plain && refl && truth.linear && rd_render(ctx, s.scene, &view) == RD_OK &&
        rd_read_linear(ctx, img, (size_t)W * H * 4) == RD_OK) {
        for (int i = 0; i < W * H; i++) {
            refl[i] = truth.mask[i] ? 1.0f : 0.0f;
            plain[i] = 1.0f - refl[i];
        }
        app_image_metrics mp, mr;
        CHECK(app_image_metrics_compute(img, truth.linear, W, H, plain, &mp) == 0);
        CHECK(app_image_metrics_compute(img, truth.linear, W, H, refl, &mr) == 0);
        printf("designed demo, SH9 ambient: PSNR plain pixels %.2f dB, reflective %.2f dB\n",
               mp.psnr, mr.psnr);
        CHECK_MSG(mp.psnr >= 30.0, "plain pixels %.2f dB: the ambient terms differ", mp.psnr);
        CHECK_MSG(mr.psnr >= 10.0, "reflective pixels %.2f dB: the probes' ambient differs",
                  mr.psnr);
        /* Frames after the first light the room as the first does: the ambient capture sees
         * the lights alone every frame (ambient_sh.c), never the last frame's ambient. */
        for (int f = 0; f < 4; f++)
            CHECK(rd_render(ctx, s.scene, &view) == RD_OK);
        app_image_metrics later;
        if (rd_read_linear(ctx, img, (size_t)W * H * 4) == RD_OK &&
            app_image_metrics_compute(img, truth.linear, W, H, plain, &later) == 0) {
            printf("the fifth frame: PSNR plain pixels %.2f dB\n", later.psnr);
            CHECK_MSG(later.psnr >= 30.0,
                      "plain pixels of the fifth frame %.2f dB: the ambient "
                      "drifts from frame to frame",
                      later.psnr);
        } else {
            CHECK_MSG(0, "fifth frame: %s", rd_last_error());
        }
    } else {
        CHECK_MSG(0, "render: %s", rd_last_error());
    }
    free(img);
    free(plain);
    free(refl);
    app_scene_release(ctx, &s);
    ref_image_free(&truth);
    ref_scene_destroy(rs);
    app_project_free(&p);
    rd_context_destroy(ctx);
    return check_report("test_sh9_ambient");
}
