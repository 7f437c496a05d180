/* Adaptive supersampling (render/src/renderer_adaptive.c) on a real context: a room
 * with a block that casts a soft shadow and a chrome sphere that reflects them, rendered with
 * 2 x 2 samples everywhere and with the samples taken only where the once-per-pixel image
 * steps:
 *  - the adaptive image equals the full one within the golden tolerance (display and linear);
 *  - it refines some pixels and not most of them, and with no pixel refined (the largest
 *    threshold) it differs from the full render at the edges: the refinement is what makes
 *    the two agree;
 *  - a view of one smooth wall refines nothing;
 *  - tiled adaptive renders equal the untiled one; bad thresholds are refused.
 * The backend comes from TESSERA_GL. */
#include "../common/check.h"
#include "golden.h"
#include "../common/gl_scene.h"
#include "render/primitives.h"
#include "render/render.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { W = 192, H = 128 };

static rd_scene *make_scene(rd_context *ctx, rd_mesh box, rd_mesh sphere)
{
    rd_scene *s = rd_scene_create(ctx);
    rd_object_desc room = {
        .mesh = box,
        .double_sided = 1,
        .background = 1,
        .material = {.ambient = {0.3f, 0.3f, 0.3f}, .diffuse = {0.6f, 0.65f, 0.7f}}};
    test_place(room.transform, 0, 0, 0, 4.0f);
    CHECK(rd_scene_add_object(s, &room) == RD_OK);
    rd_object_desc block = {.mesh = box,
                            .material = {.ambient = {0.2f, 0.0f, 0.0f},
                                         .diffuse = {0.9f, 0.1f, 0.1f},
                                         .specular = {0.3f, 0.3f, 0.3f},
                                         .shininess = 20}};
    test_place(block.transform, -0.9f, 0.8f, -1.6f, 0.4f);
    CHECK(rd_scene_add_object(s, &block) == RD_OK);
    rd_object_desc chrome = {.mesh = sphere,
                             .material = {.diffuse = {0.1f, 0.1f, 0.1f},
                                          .specular = {0.8f, 0.8f, 0.8f},
                                          .shininess = 80,
                                          .reflectivity = 0.9f,
                                          .glossiness = 0.95f}};
    test_place(chrome.transform, 0.3f, 0, -1.5f, 0.5f);
    CHECK(rd_scene_add_object(s, &chrome) == RD_OK);
    rd_light l = {.type = RD_LIGHT_POINT,
                  .position = {0.5f, -0.5f, 1.2f},
                  .diffuse = {1, 1, 1},
                  .specular = {1, 1, 1},
                  .attenuation = {1, 0, 0.1f}};
    CHECK(rd_scene_add_light(s, &l) == RD_OK);
    float ambient[3] = {0.2f, 0.2f, 0.2f};
    rd_scene_set_ambient(s, ambient);
    rd_reflection_defaults d = rd_scene_reflection_defaults(s);
    d.resolution = 64;
    for (int k = 0; k < 3; k++) {
        d.proxy_min[k] = -2.0f;
        d.proxy_max[k] = 2.0f;
    }
    rd_scene_set_reflection_defaults(s, &d);
    rd_shadow_settings sh = rd_scene_shadows(s);
    sh.mode = RD_SHADOWS_SOFT;
    sh.map_size = 512;
    sh.taps = 8;
    sh.softness_m = 0.1f;
    rd_scene_set_shadows(s, &sh);
    return s;
}

static rd_view view_of(int adaptive, float threshold)
{
    rd_view v = {.eye = {0.2f, -1.8f, 0.6f},
                 .target = {0, 0.5f, -1.2f},
                 .fov_y_deg = 60,
                 .width = W,
                 .height = H,
                 .supersample = 2,
                 .adaptive = adaptive,
                 .adaptive_threshold = threshold};
    return v;
}

static uint8_t *render8(rd_context *ctx, rd_scene *s, const rd_view *v, long long *refined)
{
    uint8_t *px = malloc((size_t)W * H * 4);
    CHECK_MSG(rd_render(ctx, s, v) == RD_OK, "%s", rd_last_error());
    CHECK(rd_read_rgba8(ctx, px, (size_t)W * H * 4) == RD_OK);
    if (refined)
        *refined = rd_last_frame_stats(ctx).refined_pixels;
    return px;
}

static long failing_pixels(const uint8_t *a, const uint8_t *b, int *worst)
{
    long failing = 0;
    *worst = golden_compare_rgba8(a, b, W, H, GOLDEN_TOLERANCE, &failing, NULL, NULL);
    return failing;
}

static void test_adaptive_equals_full(rd_context *ctx, rd_scene *s)
{
    rd_view full = view_of(0, 0.0f), adaptive = view_of(1, 0.0f), none = view_of(1, 1.0f);
    long long refined = -1, refined_none = -1;
    uint8_t *a = render8(ctx, s, &full, NULL);
    uint8_t *b = render8(ctx, s, &adaptive, &refined);
    uint8_t *c = render8(ctx, s, &none, &refined_none);
    int worst_b, worst_c;
    long fail_b = failing_pixels(a, b, &worst_b), fail_c = failing_pixels(a, c, &worst_c);
    printf("adaptive: %lld of %d pixels refined; against the full 2 x 2 render %ld pixels over "
           "%d/255 (worst %d); with none refined %ld (worst %d)\n",
           refined, W * H, fail_b, GOLDEN_TOLERANCE, worst_b, fail_c, worst_c);
    CHECK_MSG(refined > W * H / 100 && refined < W * H / 2,
              "the edges and the penumbra are refined, the smooth walls not: %lld", refined);
    CHECK_MSG(golden_within_budget(fail_b, (long)W * H), "%ld pixels differ", fail_b);
    CHECK_MSG(refined_none == 0, "threshold 1 refines nothing: %lld", refined_none);
    CHECK_MSG(fail_c > fail_b && !golden_within_budget(fail_c, (long)W * H),
              "the centre samples alone miss the edges' coverage: %ld pixels", fail_c);
    free(a);
    free(b);
    free(c);
}

static void test_linear_readback(rd_context *ctx, rd_scene *s)
{
    size_t n = (size_t)W * H * 4;
    float *a = malloc(n * sizeof(float)), *b = malloc(n * sizeof(float));
    rd_view full = view_of(0, 0.0f), adaptive = view_of(1, 0.0f);
    CHECK(rd_render(ctx, s, &full) == RD_OK);
    CHECK(rd_read_linear(ctx, a, n) == RD_OK);
    CHECK(rd_render(ctx, s, &adaptive) == RD_OK);
    CHECK(rd_read_linear(ctx, b, n) == RD_OK);
    double se = 0.0;
    for (size_t i = 0; i < n; i++)
        if (i % 4 != 3)
            se += ((double)a[i] - b[i]) * ((double)a[i] - b[i]);
    double psnr = 10.0 * log10(1.0 / (se / ((double)W * H * 3)));
    printf("adaptive linear radiance against the full render: PSNR %.2f dB\n", psnr);
    CHECK_MSG(psnr > 40.0, "linear read-back of an adaptive render: %.2f dB", psnr);
    free(a);
    free(b);
}

static void test_smooth_wall(rd_context *ctx, rd_scene *s)
{
    /* Straight at the back wall's middle, no edge, shadow or highlight in view. */
    rd_view v = view_of(1, 0.0f);
    v.eye[0] = 0.0f;
    v.eye[1] = 0.0f;
    v.eye[2] = 0.5f;
    v.target[0] = 0.0f;
    v.target[1] = 2.0f;
    v.target[2] = 1.3f;
    v.fov_y_deg = 20;
    long long refined = -1;
    free(render8(ctx, s, &v, &refined));
    printf("smooth wall: %lld pixels refined\n", refined);
    CHECK_MSG(refined == 0, "a smooth wall refines nothing: %lld", refined);
}

static void test_tiled(rd_context *ctx, rd_scene *s)
{
    rd_view v = view_of(1, 0.0f);
    uint8_t *whole = render8(ctx, s, &v, NULL), *tiled = malloc((size_t)W * H * 4);
    CHECK_MSG(rd_render_tiled(ctx, s, &v, 48, tiled, NULL, NULL, NULL) == RD_OK, "%s",
              rd_last_error());
    int worst;
    long failing = failing_pixels(whole, tiled, &worst);
    printf("adaptive, tiles of 48 against untiled: %ld pixels over %d/255 (worst %d)\n", failing,
           GOLDEN_TOLERANCE, worst);
    CHECK_MSG(golden_within_budget(failing, (long)W * H), "%ld pixels differ", failing);
    free(whole);
    free(tiled);
}

static void test_bad_threshold(rd_context *ctx, rd_scene *s)
{
    float bad[] = {-0.1f, 1.5f, NAN};
    for (int k = 0; k < 3; k++) {
        rd_view v = view_of(1, bad[k]);
        CHECK_MSG(rd_render(ctx, s, &v) == RD_ERR_INVALID_ARGUMENT, "threshold %g accepted",
                  (double)bad[k]);
    }
}

int main(void)
{
    rd_context *ctx = NULL;
    if (rd_context_create(&(rd_context_desc){0}, &ctx) != RD_OK) {
        fprintf(stderr, "no GL context: %s\n", rd_last_error());
        return 1;
    }
    rd_mesh box = test_upload_mesh(ctx, 0), sphere = test_upload_mesh(ctx, 1);
    rd_scene *s = make_scene(ctx, box, sphere);
    test_adaptive_equals_full(ctx, s);
    test_linear_readback(ctx, s);
    test_smooth_wall(ctx, s);
    test_tiled(ctx, s);
    test_bad_threshold(ctx, s);
    rd_scene_destroy(s);
    rd_context_destroy(ctx);
    return check_report("test_adaptive_ss");
}
