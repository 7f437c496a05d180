/* The tone curves, the auto exposure and the white balance on the CPU (render/src/tonemap_ref.c,
 * the twin of shaders/tonemap.glsl): finite display values in [0, 1] for any input, monotonic
 * in the exposure, each curve's defining points, the exposure of a known image, and a light of
 * the chosen colour temperature turned neutral. */
#include "../common/check.h"
#include "render/render.h"
#include "render/shade_ref.h"

#include <math.h>
#include <string.h>

static const rd_tonemap modes[] = {RD_TONEMAP_NEUTRAL, RD_TONEMAP_AGX, RD_TONEMAP_PHOTOGRAPHIC,
                                   RD_TONEMAP_CLAMP};

static void curve(rd_tonemap mode, float grey, float out[3])
{
    float c[3] = {grey, grey, grey};
    rd_ref_tonemap(c, 0.0f, mode, 4.0f, out);
}

static void test_range_and_extremes(void)
{
    const float inputs[] = {0.0f, 0.18f, 1.0f, 1e6f, 1e30f, INFINITY, -INFINITY, -1.0f, NAN};
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++)
        for (size_t i = 0; i < sizeof inputs / sizeof inputs[0]; i++) {
            float out[3];
            curve(modes[m], inputs[i], out);
            for (int k = 0; k < 3; k++)
                CHECK_MSG(isfinite(out[k]) && out[k] >= 0.0f && out[k] <= 1.0f, "%s(%g) = %g",
                          rd_tonemap_name(modes[m]), (double)inputs[i], (double)out[k]);
            /* coloured and mixed-extreme inputs too */
            float mixed[3] = {inputs[i], 0.5f, 1e6f};
            rd_ref_tonemap(mixed, 0.0f, modes[m], 4.0f, out);
            for (int k = 0; k < 3; k++)
                CHECK(isfinite(out[k]) && out[k] >= 0.0f && out[k] <= 1.0f);
        }
    /* Black stays black, huge goes to white (but for the clamp, which is white from 1). */
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
        float out[3];
        curve(modes[m], 0.0f, out);
        CHECK_MSG(out[0] < 1e-3f, "%s(0) = %g", rd_tonemap_name(modes[m]), (double)out[0]);
        curve(modes[m], 1e6f, out);
        if (modes[m] != RD_TONEMAP_PHOTOGRAPHIC) /* Reinhard's limit is L_white^2 / (1 + ...) */
            CHECK_MSG(out[0] > 0.97f, "%s(1e6) = %g", rd_tonemap_name(modes[m]), (double)out[0]);
    }
}

static void test_monotonic(void)
{
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
        float last = -1.0f;
        int ok = 1;
        for (int i = 0; i <= 4000; i++) {
            float x = 1e-6f * powf(10.0f, (float)i / 400.0f); /* 1e-6 .. 1e4 */
            float out[3];
            curve(modes[m], x, out);
            if (out[1] < last - 1e-6f) {
                ok = 0;
                fprintf(stderr, "%s falls at %g: %g after %g\n", rd_tonemap_name(modes[m]),
                        (double)x, (double)out[1], (double)last);
                break;
            }
            last = out[1];
        }
        CHECK_MSG(ok, "%s is not monotonic", rd_tonemap_name(modes[m]));
    }
}

/* Each curve's own shape at mid grey and at 1. */
static void test_defining_points(void)
{
    float out[3];
    /* PBR Neutral: below the shoulder a colour passes less the 0.04 black offset. */
    curve(RD_TONEMAP_NEUTRAL, 0.18f, out);
    CHECK_NEAR(out[0], 0.14f, 1e-5);
    float teal[3] = {0.1f, 0.4f, 0.45f};
    rd_ref_tonemap(teal, 0.0f, RD_TONEMAP_NEUTRAL, 0.0f, out);
    CHECK_NEAR(out[0], 0.06f, 1e-5);
    CHECK_NEAR(out[1], 0.36f, 1e-5);
    CHECK_NEAR(out[2], 0.41f, 1e-5);
    /* ... and 1 is compressed below 1 (the shoulder starts at 0.76). */
    curve(RD_TONEMAP_NEUTRAL, 1.0f, out);
    CHECK(out[0] > 0.8f && out[0] < 0.95f);
    /* AgX: mid grey lands near the middle of the display range; 1 well below white. */
    curve(RD_TONEMAP_AGX, 0.18f, out);
    CHECK_MSG(out[0] > 0.12f && out[0] < 0.3f, "agx(0.18) = %g", (double)out[0]);
    curve(RD_TONEMAP_AGX, 1.0f, out);
    CHECK_MSG(out[0] > 0.5f && out[0] < 0.9f, "agx(1) = %g", (double)out[0]);
    /* Reinhard eq. 4 with L_white 4: L = 1 gives (1 + 1/16) / 2. */
    curve(RD_TONEMAP_PHOTOGRAPHIC, 1.0f, out);
    CHECK_NEAR(out[0], (1.0 + 1.0 / 16.0) / 2.0, 1e-6);
    /* The names round-trip. */
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
        rd_tonemap back;
        CHECK(rd_tonemap_parse(rd_tonemap_name(modes[m]), &back) == RD_OK && back == modes[m]);
    }
    rd_tonemap t;
    CHECK(rd_tonemap_parse("filmic", &t) == RD_ERR_INVALID_ARGUMENT);
}

/* A known image: half its samples at L = 0.02, half at 0.5; log-average sqrt(0.02 x 0.5) = 0.1
 * (delta aside), so the EV brings 0.1 to the key. */
static void test_auto_exposure(void)
{
    double sum = 0.0;
    for (int i = 0; i < 1000; i++)
        sum += log(RD_EXPOSURE_DELTA + (i % 2 ? 0.02 : 0.5));
    float ev = rd_auto_exposure_ev(sum, 1000, 0.0f);
    double l_avg = exp(0.5 * (log(RD_EXPOSURE_DELTA + 0.02) + log(RD_EXPOSURE_DELTA + 0.5)));
    CHECK_NEAR(ev, log2(RD_EXPOSURE_KEY / l_avg), 1e-4);
    CHECK_NEAR(ev, log2(RD_EXPOSURE_KEY / 0.1), 0.01);
    CHECK_NEAR(rd_auto_exposure_ev(sum, 1000, 1.5f), ev + 1.5f, 1e-5);
    /* No samples or a non-finite sum: the compensation alone. */
    CHECK(rd_auto_exposure_ev(0.0, 0, 0.5f) == 0.5f);
    CHECK(rd_auto_exposure_ev(NAN, 10, 0.0f) == 0.0f);
    /* A black image stays within the view's range. */
    float black = rd_auto_exposure_ev(1000 * log(RD_EXPOSURE_DELTA), 1000, 0.0f);
    CHECK(black > -64.0f && black < 64.0f);
}

/* Planckian white of t kelvin in linear Rec. 709 RGB, from CIE 1931 XYZ (Y = 1). */
static void planck_rgb(double x, double y, float rgb[3])
{
    double X = x / y, Y = 1.0, Z = (1.0 - x - y) / y;
    rgb[0] = (float)(3.2404542 * X - 1.5371385 * Y - 0.4985314 * Z);
    rgb[1] = (float)(-0.9692660 * X + 1.8760108 * Y + 0.0415560 * Z);
    rgb[2] = (float)(0.0556434 * X - 0.2040259 * Y + 1.0572252 * Z);
}

static void test_white_balance(void)
{
    float m[9];
    rd_white_balance_matrix(0.0f, m);
    const float identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    CHECK(!memcmp(m, identity, sizeof m));
    /* A 2856 K lamp (CIE illuminant A: x 0.44757, y 0.40745) turns neutral at 2856 K. */
    float lamp[3], out[3];
    planck_rgb(0.44757, 0.40745, lamp);
    rd_white_balance_matrix(2856.0f, m);
    for (int i = 0; i < 3; i++)
        out[i] = m[3 * i] * lamp[0] + m[3 * i + 1] * lamp[1] + m[3 * i + 2] * lamp[2];
    CHECK_MSG(fabsf(out[0] - out[1]) < 0.01f * out[1] && fabsf(out[2] - out[1]) < 0.01f * out[1],
              "A lamp at 2856 K: %g %g %g", (double)out[0], (double)out[1], (double)out[2]);
    /* ... whose white it keeps in brightness (the Bradford transform keeps Y of the white). */
    CHECK_NEAR(0.2126f * out[0] + 0.7152f * out[1] + 0.0722f * out[2], 1.0, 0.02);
    /* The same lamp balanced for daylight stays warm: red above blue. */
    rd_white_balance_matrix(6500.0f, m);
    for (int i = 0; i < 3; i++)
        out[i] = m[3 * i] * lamp[0] + m[3 * i + 1] * lamp[1] + m[3 * i + 2] * lamp[2];
    CHECK(out[0] > 1.3f * out[2]);
    /* Out-of-range temperatures are clamped, never NaN. */
    const float ks[] = {1.0f, 1000.0f, 40000.0f, 1e9f};
    for (size_t i = 0; i < sizeof ks / sizeof ks[0]; i++) {
        rd_white_balance_matrix(ks[i], m);
        for (int k = 0; k < 9; k++)
            CHECK(isfinite(m[k]));
    }
}

int main(void)
{
    test_range_and_extremes();
    test_monotonic();
    test_defining_points();
    test_auto_exposure();
    test_white_balance();
    return check_report("tone_curves");
}
