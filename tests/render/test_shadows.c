/* Shadows (docs/rendering.md "Shadows"): a 0.5 m box on a floor under a point light at
 * (1, 0, 1.5) casts its shadow where the geometry says -- the ray from the light over the box's
 * far top edge (-0.25, 0, 0.5) meets the floor at x = -0.875, so the floor at (-0.55, 0) is in
 * shadow and (-0.55, 0.8) and (0.6, 0) are not; shadows change nothing outside it; the
 * reference tracer's shadow rays agree with the shadow maps (PSNR over the whole image, linear
 * RGB, peak 1, as `tessera compare`); a tiled render equals the untiled one within the golden
 * tolerance. Seen from straight above, 128 x 128 pixels, 60 degrees. */
#include "../common/check.h"
#include "../common/golden.h"
#include "ref/ref.h"
#include "render/image_io.h"
#include "render/primitives.h"
#include "render/render.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 128
#define H 128

typedef struct part {
    rd_mesh_data data;
    float transform[16];
    int background;
} part;

static part parts[2];

static void scale_translate(float m[16], float sx, float sy, float sz, float tx, float ty, float tz)
{
    memset(m, 0, 16 * sizeof *m);
    m[0] = sx;
    m[5] = sy;
    m[10] = sz;
    m[12] = tx;
    m[13] = ty;
    m[14] = tz;
    m[15] = 1.0f;
}

static const rd_material grey = {.ambient = {0.7f, 0.7f, 0.7f},
                                 .diffuse = {0.7f, 0.7f, 0.7f},
                                 .specular = {0.0f, 0.0f, 0.0f},
                                 .shininess = 1.0f};
/* Three lights, one at a time, each with a floor point in the box's shadow and two outside:
 * a point light (a cube map), a 45-degree spot aimed past the box (one perspective map), a
 * directional light (one orthographic map; its shadow ends at x = -0.25 - 0.5 / 1.5). */
typedef struct scenario {
    const char *name;
    rd_light light;
    float shadow[2], beside[2], lit[2];
} scenario;

static const scenario scenarios[3] = {
    {"point",
     {.type = RD_LIGHT_POINT,
      .position = {1.0f, 0.0f, 1.5f},
      .diffuse = {1.0f, 1.0f, 1.0f},
      .attenuation = {1.0f, 0.0f, 0.0f}},
     {-0.55f, 0.0f},
     {-0.55f, 0.8f},
     {0.6f, 0.0f}},
    {"spot",
     {.type = RD_LIGHT_SPOT,
      .position = {1.0f, 0.0f, 1.5f},
      .direction = {-1.55f, 0.0f, -1.5f},
      .diffuse = {1.0f, 1.0f, 1.0f},
      .attenuation = {1.0f, 0.0f, 0.0f},
      .spot_inner_cos = 0.766f,  /* 40 degrees */
      .spot_outer_cos = 0.707f}, /* 45 degrees */
     {-0.55f, 0.0f},
     {-0.55f, 0.8f},
     {0.6f, 0.0f}},
    {"directional",
     {.type = RD_LIGHT_DIRECTIONAL,
      .direction = {-1.0f, 0.0f, -1.5f},
      .diffuse = {1.0f, 1.0f, 1.0f}},
     {-0.42f, 0.0f},
     {-0.42f, 0.8f},
     {0.6f, 0.0f}},
};
static rd_light lamp;
static float softness_m; /* 0: the default disk */
static const float ambient[3] = {0.1f, 0.1f, 0.1f};

static rd_view top_view(int w, int h)
{
    return (rd_view){.eye = {0, 0, 5},
                     .target = {0, 0, 0},
                     .up = {0, 1, 0},
                     .fov_y_deg = 60.0f,
                     .width = w,
                     .height = h,
                     .supersample = 2,
                     .tonemap = RD_TONEMAP_CLAMP};
}

/* The pixel over floor point (x, y) in the top view (+X right, +Y up). */
static size_t pixel_of(float x, float y)
{
    float half = 5.0f * tanf(30.0f * 3.14159265f / 180.0f);
    int col = (int)((x / half + 1.0f) * 0.5f * W), row = (int)((1.0f - y / half) * 0.5f * H);
    return (size_t)row * W + (size_t)col;
}

static float luminance(const float *linear, size_t pixel)
{
    const float *p = linear + 4 * pixel;
    return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
}

static rd_scene *gpu_scene(rd_context *ctx, rd_shadow_mode mode)
{
    rd_scene *s = rd_scene_create(ctx);
    for (int i = 0; i < 2; i++) {
        rd_mesh_desc md = rd_mesh_data_desc(&parts[i].data);
        rd_object_desc o = {
            .mesh = rd_mesh_create(ctx, &md), .material = grey, .background = parts[i].background};
        memcpy(o.transform, parts[i].transform, sizeof o.transform);
        CHECK(rd_scene_add_object(s, &o) == RD_OK);
    }
    CHECK(rd_scene_add_light(s, &lamp) == RD_OK);
    rd_scene_set_ambient(s, ambient);
    rd_scene_set_shadows(s, &(rd_shadow_settings){.mode = mode, .softness_m = softness_m});
    return s;
}

static float *gpu_render(rd_context *ctx, rd_shadow_mode mode)
{
    rd_scene *s = gpu_scene(ctx, mode);
    float *img = malloc(W * H * 4 * sizeof *img);
    rd_view v = top_view(W, H);
    CHECK_MSG(rd_render(ctx, s, &v) == RD_OK, "%s", rd_last_error());
    CHECK(rd_read_linear(ctx, img, W * H * 4) == RD_OK);
    rd_scene_destroy(s);
    return img;
}

static float *ref_render_linear(rd_shadow_mode mode)
{
    ref_scene *s = ref_scene_create();
    for (int i = 0; i < 2; i++) {
        ref_mesh_desc d = {.positions = parts[i].data.positions,
                           .normals = parts[i].data.normals,
                           .uvs = parts[i].data.uvs,
                           .indices = parts[i].data.indices,
                           .vertex_count = parts[i].data.vertex_count,
                           .index_count = parts[i].data.index_count,
                           .material = grey,
                           .background = parts[i].background};
        memcpy(d.transform, parts[i].transform, sizeof d.transform);
        CHECK(ref_scene_add_mesh(s, &d) == REF_OK);
    }
    CHECK(ref_scene_add_light(s, &lamp) == REF_OK);
    ref_scene_set_ambient(s, ambient);
    ref_scene_set_shadows(s, &(rd_shadow_settings){.mode = mode, .softness_m = softness_m});
    ref_image img = {0};
    CHECK_MSG(ref_render(s, &(ref_render_desc){.view = top_view(W, H)}, &img) == REF_OK, "%s",
              ref_last_error());
    float *out = malloc(W * H * 4 * sizeof *out);
    if (img.linear)
        memcpy(out, img.linear, W * H * 4 * sizeof *out);
    ref_image_free(&img);
    ref_scene_destroy(s);
    return out;
}

static double psnr(const float *a, const float *b)
{
    double sum = 0.0;
    for (size_t i = 0; i < (size_t)W * H; i++)
        for (int c = 0; c < 3; c++) {
            double d = (double)a[4 * i + c] - (double)b[4 * i + c];
            sum += d * d;
        }
    double mse = sum / (3.0 * W * H);
    return mse > 0.0 ? -10.0 * log10(mse) : INFINITY;
}

static void check_geometry(const float *off, const float *on, const char *what, const scenario *sc)
{
    size_t shadow = pixel_of(sc->shadow[0], sc->shadow[1]),
           beside = pixel_of(sc->beside[0], sc->beside[1]), lit = pixel_of(sc->lit[0], sc->lit[1]);
    float ls = luminance(on, shadow), ls_off = luminance(off, shadow);
    printf("%s %s: shadow %.4f (unshadowed %.4f), beside %.4f/%.4f, lit side %.4f/%.4f\n", what,
           sc->name, ls, ls_off, luminance(on, beside), luminance(off, beside), luminance(on, lit),
           luminance(off, lit));
    /* In the umbra only the ambient term is left: 0.1 x 0.7 = 0.07. */
    CHECK_MSG(fabsf(ls - 0.07f) < 0.01f, "%s: umbra %.4f, expected the ambient 0.07", what, ls);
    CHECK_MSG(ls_off > 0.2f, "%s: without shadows the floor there is lit (%.4f)", what, ls_off);
    CHECK_MSG(fabsf(luminance(on, beside) - luminance(off, beside)) < 0.005f,
              "%s: beside the shadow nothing changes", what);
    CHECK_MSG(fabsf(luminance(on, lit) - luminance(off, lit)) < 0.005f,
              "%s: on the light's side nothing changes", what);
}

/* The soft shadow's penumbra survives the adaptive taps (shadow.glsl: two outer taps first,
 * the rest only where they disagree): along the floor row through the umbra, the
 * GPU's soft render has about as many part-lit pixels as the reference's, where every sample
 * takes all its taps. */
static int penumbra_pixels(const float *off, const float *on, const scenario *sc)
{
    int count = 0;
    int row = (int)(pixel_of(0.0f, sc->shadow[1]) / W);
    for (int x = 0; x < W; x++) {
        size_t i = (size_t)row * W + (size_t)x;
        float l = luminance(on, i), l_off = luminance(off, i);
        if (l_off > 0.2f && l > 0.07f + 0.02f && l < l_off - 0.02f)
            count++;
    }
    return count;
}

static void check_penumbra(rd_context *ctx, const scenario *sc)
{
    /* A disk of 25 cm: a penumbra some ten pixels wide at 128 x 128. */
    lamp = sc->light;
    softness_m = 0.25f;
    float *off = gpu_render(ctx, RD_SHADOWS_OFF), *soft = gpu_render(ctx, RD_SHADOWS_SOFT);
    float *ref_off = ref_render_linear(RD_SHADOWS_OFF),
          *ref_soft = ref_render_linear(RD_SHADOWS_SOFT);
    softness_m = 0.0f;
    int gpu = penumbra_pixels(off, soft, sc), ref = penumbra_pixels(ref_off, ref_soft, sc);
    printf("%s: penumbra pixels on the umbra's row: GPU soft %d, reference soft %d\n", sc->name,
           gpu, ref);
    CHECK_MSG(ref > 0, "%s: the reference's soft shadow has a penumbra", sc->name);
    CHECK_MSG(gpu * 3 >= ref * 2 && gpu <= ref * 3 / 2 + 2,
              "%s: GPU penumbra %d pixels against the reference's %d", sc->name, gpu, ref);
    free(off);
    free(soft);
    free(ref_off);
    free(ref_soft);
}

static void write_png(const char *name, const float *linear)
{
    /* For a look at the test scene: tone map clamp + sRGB, what rd_read_rgba8 gives. */
    unsigned char *px = malloc(W * H * 4);
    for (size_t i = 0; i < (size_t)W * H * 4; i++) {
        float x = fminf(fmaxf(linear[i], 0.0f), 1.0f);
        x = x <= 0.0031308f ? 12.92f * x : 1.055f * powf(x, 1.0f / 2.4f) - 0.055f;
        px[i] = (unsigned char)(x * 255.0f + 0.5f);
    }
    rd_image_write_rgba8(name, W, H, px, NULL, 0);
    free(px);
}

static void check_tiled_equals_untiled(rd_context *ctx)
{
    /* Odd sizes, a forced 48-pixel tile: 5 x 3 tiles with ragged edges, soft shadows. */
    const int w = 203, h = 131;
    rd_scene *s = gpu_scene(ctx, RD_SHADOWS_SOFT);
    rd_view v = top_view(w, h);
    v.eye[0] = 2.0f; /* an oblique view: perspective across tile edges */
    v.eye[1] = -3.0f;
    v.eye[2] = 3.0f;
    v.up[0] = v.up[1] = 0.0f;
    v.up[2] = 1.0f;
    unsigned char *whole = malloc((size_t)w * h * 4), *tiled = malloc((size_t)w * h * 4);
    CHECK(rd_render(ctx, s, &v) == RD_OK);
    CHECK(rd_read_rgba8(ctx, whole, (size_t)w * h * 4) == RD_OK);
    CHECK_MSG(rd_render_tiled(ctx, s, &v, 48, tiled, NULL, NULL, NULL) == RD_OK, "%s",
              rd_last_error());
    long failing = 0;
    int wx = -1, wy = -1;
    int worst = golden_compare_rgba8(whole, tiled, w, h, GOLDEN_TOLERANCE, &failing, &wx, &wy);
    printf("tiled vs untiled (%dx%d, tiles of 48): worst %d/255 at (%d, %d), %ld pixels over "
           "%d/255\n",
           w, h, worst, wx, wy, failing, GOLDEN_TOLERANCE);
    CHECK_MSG(golden_within_budget(failing, (long)w * h), "%ld pixels differ", failing);
    /* A window outside the image is refused. */
    rd_view bad = v;
    bad.full_width = w;
    bad.full_height = h;
    bad.crop_x = w - 10;
    CHECK(rd_render(ctx, s, &bad) == RD_ERR_INVALID_ARGUMENT);
    free(whole);
    free(tiled);
    rd_scene_destroy(s);
}

int main(void)
{
    CHECK(rd_mesh_data_plane(&parts[0].data) == RD_OK);
    scale_translate(parts[0].transform, 4, 4, 1, 0, 0, 0);
    parts[0].background = 1; /* a room's floor: receives, casts nothing */
    CHECK(rd_mesh_data_box(&parts[1].data) == RD_OK);
    scale_translate(parts[1].transform, 0.5f, 0.5f, 0.5f, 0, 0, 0.25f);
    rd_context *ctx = NULL;
    if (rd_context_create(&(rd_context_desc){0}, &ctx) != RD_OK) {
        fprintf(stderr, "no GL context: %s\n", rd_last_error());
        return 1;
    }
    for (int k = 0; k < 3; k++) {
        const scenario *sc = &scenarios[k];
        lamp = sc->light;
        float *off = gpu_render(ctx, RD_SHADOWS_OFF), *hard = gpu_render(ctx, RD_SHADOWS_HARD),
              *soft = gpu_render(ctx, RD_SHADOWS_SOFT);
        check_geometry(off, hard, "GPU hard", sc);
        check_geometry(off, soft, "GPU soft", sc);
        float *ref_off = ref_render_linear(RD_SHADOWS_OFF),
              *ref_hard = ref_render_linear(RD_SHADOWS_HARD),
              *ref_soft = ref_render_linear(RD_SHADOWS_SOFT);
        check_geometry(ref_off, ref_hard, "reference hard", sc);
        check_geometry(ref_off, ref_soft, "reference soft", sc);
        double p_off = psnr(off, ref_off), p_hard = psnr(hard, ref_hard),
               p_soft = psnr(soft, ref_soft);
        printf("%s: PSNR GPU vs reference: off %.1f dB, hard %.1f dB, soft %.1f dB; GPU soft vs "
               "reference off %.1f dB\n",
               sc->name, p_off, p_hard, p_soft, psnr(soft, ref_off));
        CHECK_MSG(p_hard >= 35.0, "%s, hard shadows: PSNR %.1f dB < 35", sc->name, p_hard);
        CHECK_MSG(p_soft >= 35.0, "%s, soft shadows: PSNR %.1f dB < 35", sc->name, p_soft);
        if (getenv("TESSERA_TEST_IMAGES")) {
            char name[64];
            snprintf(name, sizeof name, "shadows_%s_gpu_soft.png", sc->name);
            write_png(name, soft);
            snprintf(name, sizeof name, "shadows_%s_ref_soft.png", sc->name);
            write_png(name, ref_soft);
        }
        free(off);
        free(hard);
        free(soft);
        free(ref_off);
        free(ref_hard);
        free(ref_soft);
    }
    for (int k = 0; k < 3; k++)
        check_penumbra(ctx, &scenarios[k]);
    lamp = scenarios[0].light;
    check_tiled_equals_untiled(ctx);
    rd_context_destroy(ctx);
    rd_mesh_data_free(&parts[0].data);
    rd_mesh_data_free(&parts[1].data);
    return check_report("test_shadows");
}
