/* Tile joints drawn from the layout (shaders/grout.glsl): a floor of 600 mm tiles with 3 mm
 * joints, its texture the tile with a light grout border (the catalog's images are drawn so),
 * the grout dark. Seen from across a room, where a joint is a fraction of a pixel, no pixel on
 * the floor may be lighter than the tile or the grout (the border texels must not show as a
 * light line), and the joints must still darken the floor a little; seen close, a joint's
 * centre is the grout's colour. The backend comes from TESSERA_GL. */
#include "../common/check.h"
#include "render/primitives.h"
#include "render/render.h"
#include "render/shade_ref.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { TEX = 256, TILES = 12 };

#define GROUT 0.05f /* dark grout (linear) */
#define TILE 0.3f   /* mid-grey tile (linear) */

static rd_texture tile_texture(rd_context *ctx)
{
    /* The tile's nominal cell: the tile (0.5) with half a 3 mm joint of light grout (1.0, twice
     * the tile) on every side. */
    float *rgba = malloc((size_t)TEX * TEX * 4 * sizeof *rgba);
    for (int y = 0; y < TEX; y++)
        for (int x = 0; x < TEX; x++) {
            float mx = ((float)x + 0.5f) * 603.0f / TEX, my = ((float)y + 0.5f) * 603.0f / TEX;
            float edge = fminf(fminf(mx, 603.0f - mx), fminf(my, 603.0f - my));
            float v = edge < 1.5f ? 1.0f : 0.5f;
            for (int k = 0; k < 3; k++)
                rgba[4 * (y * TEX + x) + k] = v;
            rgba[4 * (y * TEX + x) + 3] = 1.0f;
        }
    rd_texture t =
        rd_texture_create(ctx, &(rd_texture_desc){.width = TEX, .height = TEX, .rgba = rgba});
    free(rgba);
    return t;
}

/* A floor of TILES x TILES tiles at z = 0 (the plane primitive is 1 x 1 m, UVs 0..1). */
static rd_scene *floor_scene(rd_context *ctx, rd_mesh plane, rd_texture tex, int joints)
{
    rd_scene *s = rd_scene_create(ctx);
    rd_object_desc o = {.mesh = plane};
    float side = 0.603f * TILES;
    o.transform[0] = o.transform[5] = side;
    o.transform[10] = o.transform[15] = 1.0f;
    o.material.ambient[0] = o.material.ambient[1] = o.material.ambient[2] = TILE;
    o.material.diffuse[0] = o.material.diffuse[1] = o.material.diffuse[2] = TILE;
    o.material.diffuse_texture = tex;
    o.material.uv_scale[0] = o.material.uv_scale[1] = (float)TILES;
    if (joints) {
        o.material.joint_width[0] = o.material.joint_width[1] = 3.0f / 603.0f;
        o.material.joint_color[0] = o.material.joint_color[1] = o.material.joint_color[2] = GROUT;
    }
    CHECK(rd_scene_add_object(s, &o) == RD_OK);
    rd_scene_set_ambient(s, (const float[3]){1, 1, 1});
    return s;
}

static int luma(const unsigned char *p)
{
    return (int)lround(0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]);
}

/* The display value of an albedo lit by the unit ambient alone, as the renderer resolves it. */
static int display_of(float albedo)
{
    unsigned char out[3];
    float c[3] = {albedo, albedo, albedo};
    rd_ref_display_rgb8(c, 0.0f, RD_TONEMAP_CLAMP, 0.0f, out);
    return out[1];
}

enum { W = 320, H = 180 };

static void far_view(rd_context *ctx, rd_scene *s, unsigned char *rgb)
{
    /* From 1.6 m up, looking 4 m across the floor: joints of 3 mm are under a pixel. */
    rd_view v = {.eye = {0.3f, -3.0f, 1.6f},
                 .target = {0.3f, 2.0f, 0.0f},
                 .fov_y_deg = 50,
                 .width = W,
                 .height = H,
                 .tonemap = RD_TONEMAP_CLAMP};
    CHECK(rd_render(ctx, s, &v) == RD_OK);
    CHECK(rd_read_rgba8(ctx, rgb, (size_t)W * H * 4) == RD_OK);
}

static void test_far(rd_context *ctx, rd_mesh plane, rd_texture tex)
{
    int tile = display_of(TILE * 0.5f), grout = display_of(GROUT);
    unsigned char *with = malloc((size_t)W * H * 4), *without = malloc((size_t)W * H * 4);
    rd_scene *s = floor_scene(ctx, plane, tex, 1);
    far_view(ctx, s, with);
    rd_scene_destroy(s);
    s = floor_scene(ctx, plane, tex, 0);
    far_view(ctx, s, without);
    rd_scene_destroy(s);
    /* Lighter than the tile by more than LIGHTER display levels: the mip levels that span whole
     * tiles average the image's border in (here 2 % of its area at twice the tile's value:
     * up to 3 levels); a border texel shown as a line is 12 and more. */
    enum { LIGHTER = 3 };
    int lighter = 0, darkened = 0, floor_px = 0, light_without = 0;
    for (int i = 0; i < W * H; i++) {
        if (with[4 * i] == 0 && with[4 * i + 1] == 0) /* background */
            continue;
        floor_px++;
        int y = luma(with + 4 * i);
        lighter += y > tile + LIGHTER;
        darkened += y < tile - 1;
        light_without += luma(without + 4 * i) > tile + LIGHTER;
    }
    /* Without joints drawn, the texture's light border shows (the test sees the defect). */
    CHECK_MSG(light_without > 0, "the plain texture shows no light border pixels");
    CHECK_MSG(floor_px > W * H / 4, "the floor covers %d pixels", floor_px);
    CHECK_MSG(lighter == 0, "%d floor pixels lighter than the tile (%d) and the grout (%d)",
              lighter, tile, grout);
    CHECK_MSG(darkened > floor_px / 50, "joints darken only %d of %d pixels", darkened, floor_px);
    free(with);
    free(without);
}

/* Close: looking straight down on a joint 10 cm away; the joint spans pixels, its centre
 * column is the grout. */
static void test_near(rd_context *ctx, rd_mesh plane, rd_texture tex)
{
    rd_scene *s = floor_scene(ctx, plane, tex, 1);
    /* The plane is centred on the origin; tile edges at multiples of 0.603 m from its corner
     * at -side/2, so x = -side/2 + 6 * 0.603 = 0 is a joint (TILES is even). */
    rd_view v = {.eye = {0.0f, 0.0001f, 0.1f},
                 .target = {0.0f, 0.0f, 0.0f},
                 .fov_y_deg = 20,
                 .width = 64,
                 .height = 64,
                 .tonemap = RD_TONEMAP_CLAMP};
    CHECK(rd_render(ctx, s, &v) == RD_OK);
    unsigned char rgb[64 * 64 * 4];
    CHECK(rd_read_rgba8(ctx, rgb, sizeof rgb) == RD_OK);
    int grout = display_of(GROUT), darkest = 255;
    for (int x = 0; x < 64; x++) {
        int y = luma(rgb + 4 * (32 * 64 + x));
        darkest = y < darkest ? y : darkest;
    }
    CHECK_MSG(abs(darkest - grout) <= 2, "the joint's centre is %d, the grout %d", darkest, grout);
    rd_scene_destroy(s);
}

/* The CPU twin (grout_ref.c), which the reference tracer draws joints with. */
static void test_twin(void)
{
    const float w[2] = {0.01f, 0.02f}, point[2] = {0, 0};
    CHECK(rd_ref_joint_coverage((const float[2]){0.004f, 0.5f}, w, point) == 1.0f);
    CHECK(rd_ref_joint_coverage((const float[2]){-0.004f, 0.5f}, w, point) == 1.0f);
    CHECK(rd_ref_joint_coverage((const float[2]){0.006f, 0.5f}, w, point) == 0.0f);
    CHECK(rd_ref_joint_coverage((const float[2]){0.5f, 2.995f}, w, point) == 1.0f);
    /* A footprint of a whole cell or more: the band's share of it. */
    float cov = rd_ref_joint_coverage((const float[2]){0.3f, 0.3f}, w, (const float[2]){1, 1});
    CHECK_NEAR(cov, 0.01 + 0.02 - 0.01 * 0.02, 1e-6);
    /* A footprint of 4 joints' width centred on the edge: a quarter of it (per axis). */
    cov = rd_ref_joint_coverage((const float[2]){1.0f, 0.5f}, w, (const float[2]){0.04f, 0.0f});
    CHECK_NEAR(cov, 0.25, 1e-5);
    /* The texture is read clear of the band: never nearer the edge than half the joint plus
     * four footprints. */
    float st[2];
    rd_ref_joint_texcoord((const float[2]){2.001f, -0.999f}, w, 256, 256, 1.0f, st);
    CHECK(st[0] >= 2.0f + 0.005f + 4.0f / 256.0f - 1e-6f);
    CHECK(st[1] >= -1.0f + 0.01f + 4.0f / 256.0f - 1e-6f);
}

int main(void)
{
    test_twin();
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
    rd_texture tex = tile_texture(ctx);
    test_far(ctx, plane, tex);
    test_near(ctx, plane, tex);
    rd_texture_destroy(ctx, tex);
    rd_mesh_destroy(ctx, plane);
    rd_context_destroy(ctx);
    return check_report("grout");
}
