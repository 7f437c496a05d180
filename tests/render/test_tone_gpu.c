/* The GPU's tone map (shaders/tonemap.glsl) against its CPU twin for every curve, with and
 * without white balance, and the GPU's auto exposure against rd_auto_exposure_ev on an image
 * of known luminance: an emissive plane filling the view, one colour everywhere; a view drawn
 * in strips shares the whole view's exposure. The backend
 * comes from TESSERA_GL. */
#include "../common/check.h"
#include "render/primitives.h"
#include "render/render.h"
#include "render/shade_ref.h"

#include <math.h>
#include <stdlib.h>

enum { W = 16, H = 12 };

static rd_scene *plane_scene(rd_context *ctx, rd_mesh plane, const float emissive[3])
{
    rd_scene *s = rd_scene_create(ctx);
    rd_object_desc o = {.mesh = plane};
    for (int k = 0; k < 3; k++)
        o.material.emissive[k] = emissive[k];
    o.transform[0] = o.transform[5] = 100.0f;
    o.transform[10] = o.transform[15] = 1.0f;
    CHECK(rd_scene_add_object(s, &o) == RD_OK);
    return s;
}

static rd_view view_of_plane(void)
{
    return (rd_view){
        .eye = {0, -0.01f, 3}, .target = {0, 0, 0}, .fov_y_deg = 40, .width = W, .height = H};
}

/* The 8-bit value the CPU twin gives. */
static void expected_rgb8(const float radiance[3], float ev, const rd_view *v, int out[3])
{
    float wb[9], c[3], d[3];
    rd_white_balance_matrix(v->white_balance_k, wb);
    rd_ref_expose(radiance, ev, wb, c);
    rd_ref_tone_curve(c, v->tonemap, v->white, d);
    for (int k = 0; k < 3; k++)
        out[k] = (int)(rd_ref_srgb_encode(d[k]) * 255.0f + 0.5f);
}

static void test_curves(rd_context *ctx, rd_mesh plane)
{
    const float colours[][3] = {
        {0.3f, 0.05f, 2.0f}, {0.18f, 0.18f, 0.18f}, {5.0f, 4.0f, 3.0f}, {0.01f, 0.02f, 0.005f}};
    const rd_tonemap modes[] = {RD_TONEMAP_NEUTRAL, RD_TONEMAP_AGX, RD_TONEMAP_PHOTOGRAPHIC,
                                RD_TONEMAP_CLAMP};
    const float kelvins[] = {0.0f, 3000.0f};
    for (size_t c = 0; c < sizeof colours / sizeof colours[0]; c++) {
        rd_scene *s = plane_scene(ctx, plane, colours[c]);
        for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++)
            for (size_t kk = 0; kk < 2; kk++) {
                rd_view v = view_of_plane();
                v.tonemap = modes[m];
                v.white_balance_k = kelvins[kk];
                v.exposure_ev = 0.5f;
                CHECK(rd_render(ctx, s, &v) == RD_OK);
                unsigned char rgb[W * H * 4];
                CHECK(rd_read_rgba8(ctx, rgb, sizeof rgb) == RD_OK);
                int want[3], worst = 0;
                expected_rgb8(colours[c], v.exposure_ev, &v, want);
                for (int i = 0; i < W * H; i++)
                    for (int k = 0; k < 3; k++)
                        worst = abs(rgb[4 * i + k] - want[k]) > worst
                                    ? abs(rgb[4 * i + k] - want[k])
                                    : worst;
                CHECK_MSG(worst <= 1, "%s, %g K, colour %zu: 8-bit off by %d",
                          rd_tonemap_name(modes[m]), (double)kelvins[kk], c, worst);
            }
        rd_scene_destroy(s);
    }
}

/* A uniform image of luminance L: the measured EV brings L to the key (plus the compensation),
 * as rd_auto_exposure_ev computes it, and the image shows the key's display value. */
static void test_auto_exposure(rd_context *ctx, rd_mesh plane)
{
    const float colour[3] = {0.05f, 0.04f, 0.03f};
    rd_scene *s = plane_scene(ctx, plane, colour);
    for (int kk = 0; kk < 2; kk++) {
        rd_view v = view_of_plane();
        v.tonemap = RD_TONEMAP_NEUTRAL;
        v.auto_exposure = 1;
        v.exposure_ev = 0.25f; /* the compensation */
        v.white_balance_k = kk ? 4000.0f : 0.0f;
        CHECK(rd_render(ctx, s, &v) == RD_OK);
        float wb[9], c[3];
        rd_white_balance_matrix(v.white_balance_k, wb);
        rd_ref_expose(colour, 0.0f, wb, c);
        double y = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
        float want = rd_auto_exposure_ev(log(RD_EXPOSURE_DELTA + y), 1, 0.25f);
        float got = rd_last_frame_stats(ctx).exposure_ev;
        CHECK_MSG(fabsf(got - want) < 0.01f, "%g K: measured %g EV, expected %g",
                  (double)v.white_balance_k, (double)got, (double)want);
        /* The image is the twin's at that EV. */
        unsigned char rgb[W * H * 4];
        CHECK(rd_read_rgba8(ctx, rgb, sizeof rgb) == RD_OK);
        int expect[3];
        expected_rgb8(colour, want, &v, expect);
        for (int k = 0; k < 3; k++)
            CHECK_MSG(abs(rgb[4 * (W * H / 2) + k] - expect[k]) <= 1, "channel %d: %d, expected %d",
                      k, rgb[4 * (W * H / 2) + k], expect[k]);
        /* Tiled: several tiles take the one EV of the whole view. */
        unsigned char tiled[W * H * 4];
        CHECK(rd_render_tiled(ctx, s, &v, 8, tiled, NULL, NULL, NULL) == RD_OK);
        CHECK_MSG(fabsf(rd_last_frame_stats(ctx).exposure_ev - want) < 0.01f, "tiled: %g EV",
                  (double)rd_last_frame_stats(ctx).exposure_ev);
        int worst = 0;
        for (int i = 0; i < W * H * 4; i++)
            worst = abs(tiled[i] - rgb[i]) > worst ? abs(tiled[i] - rgb[i]) : worst;
        CHECK_MSG(worst <= 1, "tiled differs from one render by %d", worst);
    }
    /* Off: the fixed EV is used as it is. */
    rd_view v = view_of_plane();
    v.exposure_ev = -1.5f;
    CHECK(rd_render(ctx, s, &v) == RD_OK);
    CHECK(rd_last_frame_stats(ctx).exposure_ev == -1.5f);
    rd_scene_destroy(s);
}

/* A view drawn in strips (the planner's still view): each strip exposed with the EV measured
 * over the whole view shows exactly the rows of one whole render; a strip that metered only
 * itself would be exposed for its own rows (the bright top half here) and show a band. */
static void test_strips_share_exposure(rd_context *ctx, rd_mesh plane)
{
    rd_scene *s = rd_scene_create(ctx);
    const float bright = 2.0f, dim = 0.02f;
    for (int half = 0; half < 2; half++) {
        rd_object_desc o = {.mesh = plane};
        for (int k = 0; k < 3; k++)
            o.material.emissive[k] = half ? dim : bright;
        o.transform[0] = o.transform[5] = 100.0f;
        o.transform[10] = o.transform[15] = 1.0f;
        o.transform[13] = half ? -50.0f : 50.0f; /* bright above y = 0 (the image's top) */
        CHECK(rd_scene_add_object(s, &o) == RD_OK);
    }
    rd_view whole = view_of_plane();
    whole.tonemap = RD_TONEMAP_NEUTRAL;
    whole.auto_exposure = 1;
    whole.exposure_ev = 0.25f;
    CHECK(rd_render(ctx, s, &whole) == RD_OK);
    float whole_ev = rd_last_frame_stats(ctx).exposure_ev;
    unsigned char ref[W * H * 4];
    CHECK(rd_read_rgba8(ctx, ref, sizeof ref) == RD_OK);
    enum { STRIP = 3 };
    rd_view strip = whole;
    strip.height = STRIP;
    strip.full_width = W;
    strip.full_height = H;
    CHECK(rd_render(ctx, s, &strip) == RD_OK); /* the top strip metering itself */
    float own_ev = rd_last_frame_stats(ctx).exposure_ev;
    CHECK_MSG(fabsf(own_ev - whole_ev) > 1.0f, "the scene does not test strips: %g vs %g EV",
              (double)own_ev, (double)whole_ev);
    int worst = 0;
    for (int y0 = 0; y0 < H; y0 += STRIP) {
        strip.crop_y = y0;
        strip.auto_exposure = 1;
        float ev = 0.0f;
        CHECK(rd_measure_view_exposure(ctx, s, &strip, &ev) == RD_OK);
        CHECK_MSG(fabsf(ev - whole_ev) < 0.01f, "strip at row %d: %g EV, the whole view %g", y0,
                  (double)ev, (double)whole_ev);
        strip.auto_exposure = 0;
        strip.exposure_ev = ev;
        CHECK(rd_render(ctx, s, &strip) == RD_OK);
        unsigned char rows[W * STRIP * 4];
        CHECK(rd_read_rgba8(ctx, rows, sizeof rows) == RD_OK);
        for (int i = 0; i < W * STRIP * 4; i++) {
            int d = abs(rows[i] - ref[(size_t)y0 * W * 4 + (size_t)i]);
            worst = d > worst ? d : worst;
        }
        strip.exposure_ev = whole.exposure_ev;
    }
    CHECK_MSG(worst <= 1, "strips differ from the whole render by %d", worst);
    rd_scene_destroy(s);
}

int main(void)
{
    rd_context *ctx = NULL;
    if (rd_context_create(NULL, &ctx) != RD_OK) {
        fprintf(stderr, "no context: %s\n", rd_last_error());
        return 1;
    }
    rd_mesh_data d;
    rd_mesh_data_plane(&d);
    rd_mesh_desc desc = rd_mesh_data_desc(&d);
    rd_mesh plane = rd_mesh_create(ctx, &desc);
    rd_mesh_data_free(&d);
    test_curves(ctx, plane);
    test_auto_exposure(ctx, plane);
    test_strips_share_exposure(ctx, plane);
    rd_mesh_destroy(ctx, plane);
    rd_context_destroy(ctx);
    return check_report("tone_gpu");
}
