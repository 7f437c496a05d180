/* The white furnace (docs/reference.md, "Indirect light"): inside a closed box whose every wall
 * has diffuse albedo a and emits E, the radiance is the same everywhere and in every direction,
 * L = E + a L, so L = E / (1 - a) exactly (the Neumann series of the rendering equation). The
 * path tracer, with next-event estimation of the emitting walls, MIS and Russian roulette, must
 * reach it within 1 % for a = 0.5 and 0.8, from the image mean and from every pixel within its
 * noise. A tracer that drops a bounce, counts the walls' light twice or biases the roulette
 * misses it by far more (one bounce too few at a = 0.8 is 20 %). */
#include "../common/check.h"
#include "ref_test_scenes.h"

#include <math.h>
#include <stdio.h>

#define SIDE 8

/* The box [0, 2]^3 of six inward-facing walls of albedo a emitting e, seen from its centre. */
static void furnace(float a, float e, int bounces, int paths, double *mean, double *worst,
                    int clamp_half)
{
    ref_scene *s = ref_scene_create();
    CHECK(s != NULL);
    rd_material m = {.diffuse = {a, a, a}, .emissive = {e, e, e}};
    const float x = 2.0f;
    const float o[6][3] = {{0, 0, 0}, {x, 0, 0}, {0, 0, 0}, {0, x, 0}, {0, 0, 0}, {0, 0, x}};
    const float u[6][3] = {{0, x, 0}, {0, 0, x}, {0, 0, x}, {x, 0, 0}, {x, 0, 0}, {0, x, 0}};
    const float v[6][3] = {{0, 0, x}, {0, x, 0}, {x, 0, 0}, {0, 0, x}, {0, x, 0}, {x, 0, 0}};
    for (int i = 0; i < 6; i++)
        CHECK(add_rect(s, o[i], u[i], v[i], &m, 0) == REF_OK);
    ref_render_desc d = {.view = {.eye = {1.0f, 1.0f, 1.0f},
                                  .target = {2.0f, 1.3f, 0.8f},
                                  .fov_y_deg = 100.0f,
                                  .width = SIDE,
                                  .height = SIDE,
                                  .tonemap = RD_TONEMAP_CLAMP},
                         .samples = paths,
                         .bounces = bounces,
                         .seed = 7,
                         .threads = 2};
    ref_image img;
    CHECK(ref_render(s, &d, &img) == REF_OK);
    if (clamp_half)
        ref_image_clamp_half(&img);
    double sum = 0.0, far = 0.0, expected = e / (1.0 - a);
    for (int i = 0; i < SIDE * SIDE; i++)
        for (int k = 0; k < 3; k++) {
            double l = img.linear[4 * i + k];
            sum += l;
            far = fmax(far, fabs(l / expected - 1.0));
        }
    *mean = sum / (3.0 * SIDE * SIDE) / expected - 1.0;
    *worst = far;
    ref_image_free(&img);
    ref_scene_destroy(s);
}

int main(void)
{
    const float albedo[2] = {0.5f, 0.8f};
    for (int i = 0; i < 2; i++) {
        double mean, worst;
        furnace(albedo[i], 0.25f, 256, 2048, &mean, &worst, 0);
        printf("furnace a = %.1f: mean %+.3f %%, worst pixel %.2f %%\n", (double)albedo[i],
               100.0 * mean, 100.0 * worst);
        CHECK(fabs(mean) < 0.01);
        /* Each pixel averages 2048 paths (sigma about 2 % at a = 0.8, measured): all 64 stay
         * within 4 sigma. */
        CHECK(worst < 0.08);
    }
    /* Two bounces after the direct light cut the series after a^3: E (1 + a + a^2 + a^3) =
     * E (1 - a^4) / (1 - a) (the furnace's own check that --bounces counts bounces). */
    double mean, worst;
    furnace(0.8f, 0.25f, 2, 512, &mean, &worst, 0);
    double cut = -0.8 * 0.8 * 0.8 * 0.8;
    printf("furnace a = 0.8, 2 bounces: mean %+.3f %% (expected %+.3f %%)\n", 100.0 * mean,
           100.0 * cut);
    CHECK(fabs(mean - cut) < 0.01);
    /* RENDERING.md section 11's HDR extreme: walls emitting 1e6 give a finite 2e6, which an
     * .exr's half floats cannot hold; ref_image_clamp_half keeps it at the largest half. */
    furnace(0.5f, 1e6f, 256, 16, &mean, &worst, 1);
    double clamped = (1.0 + mean) * 1e6 / (1.0 - 0.5);
    printf("furnace of 1e6: %.1f after the clamp\n", clamped);
    CHECK_NEAR(clamped, (double)REF_HALF_MAX, 1.0);
    return check_report("test_ref_furnace");
}
