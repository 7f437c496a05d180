/* The error metrics of `tessera compare` (app/measure/image_compare.h): RMSE and PSNR against
 * values worked out by hand, masks, the sRGB curve, the heat-map ramp, and bad input. */
#include "../common/check.h"
#include "app/measure/image_compare.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define W 8
#define H 4

static void fill(float *img, float r, float g, float b)
{
    for (int i = 0; i < W * H; i++) {
        img[4 * i] = r;
        img[4 * i + 1] = g;
        img[4 * i + 2] = b;
        img[4 * i + 3] = 1.0f;
    }
}

static int near(double a, double b, double tol)
{
    return fabs(a - b) <= tol;
}

static float luminance(const unsigned char c[3])
{
    return 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2];
}

int main(void)
{
    static float a[W * H * 4], b[W * H * 4], mask[W * H];
    app_image_metrics m;

    /* Identical images: RMSE 0, PSNR +inf, max error 0. */
    fill(a, 0.2f, 0.5f, 0.9f);
    fill(b, 0.2f, 0.5f, 0.9f);
    CHECK(app_image_metrics_compute(a, b, W, H, NULL, &m) == 0);
    CHECK(m.pixels == W * H && m.mse == 0.0 && m.rmse == 0.0 && m.max_error == 0.0);
    CHECK(isinf(m.psnr) && m.psnr > 0.0);

    /* A constant offset of 0.1 on R, G and B: RMSE 0.1, PSNR 10 log10(1 / 0.01) = 20 dB. */
    fill(b, 0.3f, 0.6f, 1.0f);
    CHECK(app_image_metrics_compute(a, b, W, H, NULL, &m) == 0);
    CHECK_MSG(near(m.rmse, 0.1, 1e-6), "rmse %.9f", m.rmse);
    CHECK_MSG(near(m.psnr, 20.0, 1e-4), "psnr %.6f", m.psnr);
    CHECK(near(m.max_error, 0.1, 1e-6));
    /* Symmetric. */
    app_image_metrics m2;
    app_image_metrics_compute(b, a, W, H, NULL, &m2);
    CHECK(m2.mse == m.mse);

    /* The offset in one channel only: the mean runs over three channels, RMSE = 0.1 / sqrt 3. */
    fill(b, 0.2f, 0.5f, 1.0f);
    app_image_metrics_compute(a, b, W, H, NULL, &m);
    CHECK_MSG(near(m.rmse, 0.1 / sqrt(3.0), 1e-6), "rmse %.9f", m.rmse);
    /* Alpha is ignored. */
    fill(b, 0.2f, 0.5f, 0.9f);
    for (int i = 0; i < W * H; i++)
        b[4 * i + 3] = 0.0f;
    app_image_metrics_compute(a, b, W, H, NULL, &m);
    CHECK(m.mse == 0.0);

    /* Masks: the offset only in the left half, the mask selects the left half. All pixels:
     * MSE = 0.01 / 2; masked: 0.01. A mask value counts from 0.5 up. */
    fill(b, 0.2f, 0.5f, 0.9f);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            int i = y * W + x;
            if (x < W / 2)
                for (int k = 0; k < 3; k++)
                    b[4 * i + k] += 0.1f;
            mask[i] = x < W / 2 ? (y % 2 ? 1.0f : 0.5f) : 0.49f;
        }
    app_image_metrics_compute(a, b, W, H, NULL, &m);
    CHECK_MSG(near(m.rmse, sqrt(0.005), 1e-6), "rmse %.9f", m.rmse);
    CHECK(m.pixels == W * H);
    app_image_metrics_compute(a, b, W, H, mask, &m);
    CHECK(m.pixels == W * H / 2);
    CHECK_MSG(near(m.rmse, 0.1, 1e-6), "masked rmse %.9f", m.rmse);
    CHECK(near(m.psnr, 20.0, 1e-4));
    /* The other half: identical. */
    for (int i = 0; i < W * H; i++)
        mask[i] = mask[i] >= 0.5f ? 0.0f : 1.0f;
    app_image_metrics_compute(a, b, W, H, mask, &m);
    CHECK(m.pixels == W * H / 2 && m.mse == 0.0 && isinf(m.psnr));
    /* An empty mask: no pixels, NaN metrics. */
    memset(mask, 0, sizeof mask);
    CHECK(app_image_metrics_compute(a, b, W, H, mask, &m) == 0);
    CHECK(m.pixels == 0 && isnan(m.rmse) && isnan(m.psnr));

    /* Bad arguments. */
    CHECK(app_image_metrics_compute(NULL, b, W, H, NULL, &m) == -1);
    CHECK(m.pixels == 0 && isnan(m.psnr));
    CHECK(app_image_metrics_compute(a, b, 0, H, NULL, &m) == -1);

    /* Non-finite values count as 0: metrics stay finite. */
    fill(b, 0.2f, 0.5f, 0.9f);
    b[0] = NAN;
    b[5] = INFINITY;
    app_image_metrics_compute(a, b, W, H, NULL, &m);
    CHECK(isfinite(m.rmse) && isfinite(m.psnr) && isfinite(m.max_error));
    CHECK(isfinite(app_image_pixel_error(a, b)));

    /* Percentile: errors 0 (half the pixels) and 0.1 (the other half). */
    fill(b, 0.2f, 0.5f, 0.9f);
    for (int i = 0; i < W * H / 2; i++)
        for (int k = 0; k < 3; k++)
            b[4 * i + k] += 0.1f;
    CHECK(near(app_image_error_percentile(a, b, W, H, NULL, 0.25), 0.0, 1e-7));
    CHECK(near(app_image_error_percentile(a, b, W, H, NULL, 0.99), 0.1, 1e-6));
    CHECK(near(app_image_error_percentile(a, b, W, H, NULL, 1.0), 0.1, 1e-6));
    memset(mask, 0, sizeof mask);
    CHECK(app_image_error_percentile(a, b, W, H, mask, 0.5) == 0.0);

    /* The exact sRGB curve, both branches and the join. */
    CHECK(app_srgb_to_linear(0.0f) == 0.0f);
    CHECK(near(app_srgb_to_linear(1.0f), 1.0, 1e-6));
    CHECK(near(app_srgb_to_linear(0.5f), 0.21404114, 1e-6));
    CHECK(near(app_srgb_to_linear(0.04045f), 0.04045 / 12.92, 1e-9));
    CHECK(near(app_srgb_to_linear(0.04046f), 0.0031316, 1e-6));
    CHECK(near(app_srgb_to_linear(128.0f / 255.0f), 0.21586050, 1e-6));
    float prev = -1.0f;
    int monotonic = 1;
    for (int i = 0; i <= 255; i++) {
        float x = app_srgb_to_linear((float)i / 255.0f);
        monotonic &= x > prev;
        prev = x;
    }
    CHECK(monotonic);
    float px[8] = {0.5f, 1.0f, 0.0f, 0.25f, 0.5f, 0.5f, 0.5f, 0.5f};
    app_image_srgb_to_linear(px, 2);
    CHECK(near(px[0], 0.21404114, 1e-6) && px[1] == 1.0f && px[2] == 0.0f && px[3] == 0.25f);

    /* The ramp: black, blue, red, yellow, white at the stops; clamped; NaN black; luminance
     * rising all the way. */
    unsigned char c[3];
    app_heat_ramp(0.0f, c);
    CHECK(c[0] == 0 && c[1] == 0 && c[2] == 0);
    app_heat_ramp(0.25f, c);
    CHECK(c[0] == 0 && c[1] == 0 && c[2] == 255);
    app_heat_ramp(0.5f, c);
    CHECK(c[0] == 255 && c[1] == 0 && c[2] == 0);
    app_heat_ramp(0.75f, c);
    CHECK(c[0] == 255 && c[1] == 255 && c[2] == 0);
    app_heat_ramp(1.0f, c);
    CHECK(c[0] == 255 && c[1] == 255 && c[2] == 255);
    app_heat_ramp(7.0f, c);
    CHECK(c[0] == 255 && c[1] == 255 && c[2] == 255);
    app_heat_ramp(-1.0f, c);
    CHECK(c[0] == 0 && c[1] == 0 && c[2] == 0);
    app_heat_ramp(NAN, c);
    CHECK(c[0] == 0 && c[1] == 0 && c[2] == 0);
    float lum = -1.0f;
    int rising = 1;
    for (int i = 0; i <= 1000; i++) {
        app_heat_ramp((float)i / 1000.0f, c);
        rising &= luminance(c) >= lum;
        lum = luminance(c);
    }
    CHECK(rising);

    /* The heat map: the error at max_error is white, no error black, above max white. */
    fill(a, 0.5f, 0.5f, 0.5f);
    fill(b, 0.5f, 0.5f, 0.5f);
    for (int k = 0; k < 3; k++) {
        b[4 * 1 + k] = 0.6f;  /* error 0.1 */
        b[4 * 2 + k] = 0.55f; /* error 0.05: the ramp's middle, red */
        b[4 * 3 + k] = 1.5f;  /* far above */
    }
    static unsigned char heat[W * H * 4];
    app_image_heatmap(a, b, W, H, 0.1f, heat);
    CHECK(heat[0] == 0 && heat[1] == 0 && heat[2] == 0 && heat[3] == 255);
    CHECK(heat[4] == 255 && heat[5] == 255 && heat[6] == 255);
    CHECK_MSG(heat[8] == 255 && heat[9] == 0 && heat[10] < 3, "%d %d %d", heat[8], heat[9],
              heat[10]);
    CHECK(heat[12] == 255 && heat[13] == 255 && heat[14] == 255);
    /* No usable scale: anything that differs is white. */
    app_image_heatmap(a, b, W, H, 0.0f, heat);
    CHECK(heat[0] == 0 && heat[4] == 255 && heat[8] == 255 && heat[16] == 0);
    app_image_heatmap(a, b, W, H, NAN, heat);
    CHECK(heat[0] == 0 && heat[4] == 255);

    /* Where the error is: 3 x 3 blocks over 8 x 4 give 3 x 2 blocks, the last column 2 wide
     * and the last row 1 high. Pixel (7, 3) (the corner block) carries squared error 3 x 1.0,
     * pixel (4, 0) 3 x 0.25 and pixel (0, 0) 3 x 0.01: shares 1 / 1.26, 0.25 / 1.26, 0.01 / 1.26,
     * largest first; the blocks without error are left out. */
    fill(a, 0.5f, 0.5f, 0.5f);
    fill(b, 0.5f, 0.5f, 0.5f);
    for (int k = 0; k < 3; k++) {
        b[4 * (3 * W + 7) + k] = 1.5f;
        b[4 * 4 + k] = 1.0f;
        b[k] = 0.6f;
    }
    app_error_block blocks[8];
    int nb = app_image_worst_blocks(a, b, W, H, NULL, 3, blocks, 8);
    CHECK_MSG(nb == 3, "%d blocks", nb);
    CHECK(blocks[0].x == 6 && blocks[0].y == 3 && blocks[0].width == 2 && blocks[0].height == 1);
    CHECK(blocks[0].pixels == 2);
    CHECK_MSG(near(blocks[0].share, 1.0 / 1.26, 1e-6), "share %.9f", blocks[0].share);
    CHECK(blocks[1].x == 3 && blocks[1].y == 0 && blocks[1].width == 3 && blocks[1].height == 3);
    CHECK(near(blocks[1].share, 0.25 / 1.26, 1e-6));
    CHECK(blocks[2].x == 0 && blocks[2].y == 0 && near(blocks[2].share, 0.01 / 1.26, 1e-6));
    /* At most `count`. */
    CHECK(app_image_worst_blocks(a, b, W, H, NULL, 3, blocks, 1) == 1 && blocks[0].x == 6);
    /* A mask: the shares are of the masked error; the corner pixel left out. */
    for (int i = 0; i < W * H; i++)
        mask[i] = i == 3 * W + 7 ? 0.0f : 1.0f;
    nb = app_image_worst_blocks(a, b, W, H, mask, 3, blocks, 8);
    CHECK(nb == 2 && blocks[0].x == 3 && near(blocks[0].share, 0.25 / 0.26, 1e-6));
    CHECK(blocks[1].share < blocks[0].share);
    /* Identical images: no block. Bad arguments: -1. */
    CHECK(app_image_worst_blocks(a, a, W, H, NULL, 3, blocks, 8) == 0);
    CHECK(app_image_worst_blocks(a, b, W, H, NULL, 0, blocks, 8) == -1);
    CHECK(app_image_worst_blocks(a, b, W, H, NULL, 3, NULL, 8) == -1);
    CHECK(app_image_worst_blocks(NULL, b, W, H, NULL, 3, blocks, 8) == -1);
    return check_report("test_image_compare");
}
