/* The path tracer against its own converged image (docs/reference.md, "Indirect light"): a
 * Cornell-like room (tests/data/scenes/cornell.json: white, red and green walls, a glossy box,
 * one emitting ceiling panel and no other light) at 64 x 64, traced with N paths a pixel and
 * compared with a golden traced with 64 N (16 x the 4 N of the convergence check below).
 *
 * - The tolerance comes from the noise: two images of N paths with different seeds differ by
 *   RMSE sigma sqrt(2 / N), so an unbiased image of N paths lies sigma sqrt(1 / N + 1 / 64 N)
 *   from the golden; a bias (a lost bounce, light counted twice, a changed lobe) adds to it.
 * - The image's mean brightness is far less noisy than a pixel: it must lie within 4 standard
 *   errors (estimated from the two images as above) of the golden's, which catches a bias of a
 *   fraction of a per cent (light lost or counted twice somewhere).
 * - Convergence: the error falls as 1 / sqrt(paths), so 4 N paths lie closer by
 *   sqrt((1 + 1/64) / (1/4 + 1/64)) = 1.955.
 * TESSERA_UPDATE_GOLDEN=1 re-traces the golden (about a minute on two cores); look at the PNG
 * it writes beside it. */
#include "../common/check.h"
#include "app/project/project.h"
#include "app/scene/ref_scene_build.h"
#include "app/scene/scene_build.h"
#include "render/image_io.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SIDE 64
#define PATHS 8
#define GOLDEN_PATHS (64 * PATHS)

static const char *project_path = TESSERA_SOURCE_DIR "/tests/data/scenes/cornell.json";
static const char *golden_path = TESSERA_SOURCE_DIR "/tests/ref/data/cornell-golden.exr";
static const char *golden_png = TESSERA_SOURCE_DIR "/tests/ref/data/cornell-golden.png";

/* The room traced with `paths` paths a pixel (4 bounces), linear RGBA; NULL on failure. */
static float *trace(int paths, uint32_t seed, unsigned char **rgba8)
{
    app_project p;
    char err[2048];
    if (app_project_read(project_path, &p, err, sizeof err) != APP_OK) {
        fprintf(stderr, "%s\n", err);
        return NULL;
    }
    rd_view view;
    ref_scene *s = NULL;
    float *out = NULL;
    if (app_view_from_camera(&p, NULL, SIDE, SIDE, &view, err, sizeof err) == APP_OK &&
        app_ref_scene_build(&p, &s, err, sizeof err) == APP_OK) {
        view.supersample = 1;
        view.auto_exposure = 0; /* radiance as traced: the golden holds no exposure */
        view.exposure_ev = 0.0f;
        ref_image img;
        ref_render_desc d = {.view = view, .samples = paths, .bounces = 4, .seed = seed};
        if (ref_render(s, &d, &img) == REF_OK) {
            out = img.linear;
            img.linear = NULL;
            if (rgba8) {
                *rgba8 = img.rgba8;
                img.rgba8 = NULL;
            }
            ref_image_free(&img);
        }
    } else {
        fprintf(stderr, "%s\n", err);
    }
    ref_scene_destroy(s);
    app_project_free(&p);
    return out;
}

static double rmse(const float *a, const float *b)
{
    double sum = 0.0;
    for (int i = 0; i < SIDE * SIDE; i++)
        for (int k = 0; k < 3; k++) {
            double d = (double)a[4 * i + k] - (double)b[4 * i + k];
            sum += d * d;
        }
    return sqrt(sum / (3.0 * SIDE * SIDE));
}

/* Per pixel, the mean over RGB of a - b: its mean over the image and its standard deviation. */
static void mean_difference(const float *a, const float *b, double *mean, double *sd)
{
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < SIDE * SIDE; i++) {
        double d = 0.0;
        for (int k = 0; k < 3; k++)
            d += ((double)a[4 * i + k] - (double)b[4 * i + k]) / 3.0;
        sum += d;
        sum2 += d * d;
    }
    *mean = sum / (SIDE * SIDE);
    *sd = sqrt(fmax(sum2 / (SIDE * SIDE) - *mean * *mean, 0.0));
}

static int update_golden(void)
{
    unsigned char *rgba8 = NULL;
    float *g = trace(GOLDEN_PATHS, 1000, &rgba8);
    char err[1024];
    int ok = g && rgba8 &&
             rd_image_write_float(golden_path, SIDE, SIDE, 4, g, err, sizeof err) == RD_IMAGE_OK &&
             rd_image_write_rgba8(golden_png, SIDE, SIDE, rgba8, err, sizeof err) == RD_IMAGE_OK;
    printf("%s %s and %s\n", ok ? "wrote" : "could not write", golden_path, golden_png);
    free(g);
    free(rgba8);
    return ok ? 0 : 1;
}

int main(void)
{
    const char *update = getenv("TESSERA_UPDATE_GOLDEN");
    if (update && !strcmp(update, "1"))
        return update_golden();
    rd_image golden;
    char err[1024];
    CHECK_MSG(rd_image_read(golden_path, &golden, NULL, err, sizeof err) == RD_IMAGE_OK, "%s", err);
    CHECK(golden.width == SIDE && golden.height == SIDE);
    if (check_failures)
        return check_report("test_ref_cornell");
    float *g = malloc(4 * sizeof(float) * SIDE * SIDE);
    rd_image_expand_rgba(&golden, g);
    float *a = trace(PATHS, 1, NULL), *b = trace(PATHS, 2, NULL), *c = trace(4 * PATHS, 3, NULL);
    CHECK(g && a && b && c);
    if (g && a && b && c) {
        double noise = rmse(a, b) / sqrt(2.0); /* sigma / sqrt(N) of one image */
        double expected = noise * sqrt(1.0 + 1.0 / 64.0);
        double err_n = rmse(a, g), err_4n = rmse(c, g);
        double ratio = err_n / err_4n, ideal = sqrt((1.0 + 1.0 / 64.0) / (0.25 + 1.0 / 64.0));
        printf("noise %.5f: rmse %d paths %.5f (expected %.5f), %d paths %.5f, ratio %.3f "
               "(1/sqrt(N): %.3f)\n",
               noise, PATHS, err_n, expected, 4 * PATHS, err_4n, ratio, ideal);
        CHECK_MSG(err_n < 1.2 * expected, "rmse %.5f against the golden, noise allows %.5f", err_n,
                  1.2 * expected);
        double bias, bias_sd, pair, pair_sd;
        mean_difference(a, g, &bias, &bias_sd);
        mean_difference(a, b, &pair, &pair_sd);
        double standard_error = pair_sd / sqrt(2.0) * sqrt(1.0 + 1.0 / 64.0) / SIDE;
        printf("mean difference from the golden %+.5f, standard error %.5f\n", bias,
               standard_error);
        CHECK_MSG(fabs(bias) < 4.0 * standard_error, "mean %+.5f off the golden, 4 sigma %.5f",
                  bias, 4.0 * standard_error);
        CHECK_MSG(fabs(ratio / ideal - 1.0) < 0.15, "rmse ratio %.3f, 1/sqrt(N) gives %.3f", ratio,
                  ideal);
    }
    free(a);
    free(b);
    free(c);
    free(g);
    rd_image_free(&golden);
    return check_report("test_ref_cornell");
}
