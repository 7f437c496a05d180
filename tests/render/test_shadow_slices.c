/* Shadow maps made a few faces at a time (rd_scene_prepare_shadows, what the window's still
 * view does between frames) come out the same as made at once: a box on a floor under a point
 * light (a cube: six faces), a spot and a directional light (one face each), soft shadows.
 * Each call makes exactly the faces it is allowed while any are left; a change of settings in
 * the middle starts the remake again; the image rendered after the slices equals, byte for
 * byte, the image of a scene whose maps rd_render made in one go, also when rd_render finds the
 * remake half done. */
#include "../common/check.h"
#include "render/primitives.h"
#include "render/render.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 96
#define H 96
#define FACES 8 /* the point light's six, the spot's one, the directional light's one */

static rd_mesh_data plane, box;

static void scale_translate(float m[16], float s[3], float t[3])
{
    memset(m, 0, 16 * sizeof *m);
    m[0] = s[0];
    m[5] = s[1];
    m[10] = s[2];
    m[12] = t[0];
    m[13] = t[1];
    m[14] = t[2];
    m[15] = 1.0f;
}

static const rd_shadow_settings hard = {.mode = RD_SHADOWS_HARD, .map_size = 256};
static const rd_shadow_settings soft = {.mode = RD_SHADOWS_SOFT, .map_size = 512, .taps = 16};

static rd_scene *make_scene(rd_context *ctx)
{
    rd_material grey = {.ambient = {0.6f, 0.6f, 0.6f}, .diffuse = {0.6f, 0.6f, 0.6f}};
    rd_scene *s = rd_scene_create(ctx);
    rd_mesh_desc pd = rd_mesh_data_desc(&plane), bd = rd_mesh_data_desc(&box);
    rd_object_desc floor = {.mesh = rd_mesh_create(ctx, &pd), .material = grey, .background = 1};
    scale_translate(floor.transform, (float[3]){4, 4, 1}, (float[3]){0, 0, 0});
    rd_object_desc cube = {.mesh = rd_mesh_create(ctx, &bd), .material = grey};
    scale_translate(cube.transform, (float[3]){0.5f, 0.5f, 0.5f}, (float[3]){0, 0, 0.25f});
    CHECK(rd_scene_add_object(s, &floor) == RD_OK);
    CHECK(rd_scene_add_object(s, &cube) == RD_OK);
    const rd_light lights[3] = {
        {.type = RD_LIGHT_POINT,
         .position = {1.0f, 0.2f, 1.5f},
         .diffuse = {0.6f, 0.5f, 0.4f},
         .attenuation = {1.0f, 0.0f, 0.0f}},
        {.type = RD_LIGHT_SPOT,
         .position = {-1.0f, 0.8f, 1.6f},
         .direction = {1.0f, -0.8f, -1.5f},
         .diffuse = {0.3f, 0.4f, 0.6f},
         .attenuation = {1.0f, 0.0f, 0.0f},
         .spot_inner_cos = 0.766f,
         .spot_outer_cos = 0.707f},
        {.type = RD_LIGHT_DIRECTIONAL,
         .direction = {-0.4f, -1.0f, -1.5f},
         .diffuse = {0.3f, 0.3f, 0.3f}},
    };
    for (int i = 0; i < 3; i++)
        CHECK(rd_scene_add_light(s, &lights[i]) == RD_OK);
    rd_scene_set_ambient(s, (float[3]){0.1f, 0.1f, 0.1f});
    return s;
}

static unsigned char *render(rd_context *ctx, rd_scene *s)
{
    rd_view v = {.eye = {0.3f, -3.0f, 3.0f},
                 .target = {0, 0, 0},
                 .up = {0, 0, 1},
                 .fov_y_deg = 60.0f,
                 .width = W,
                 .height = H,
                 .supersample = 2,
                 .tonemap = RD_TONEMAP_CLAMP};
    unsigned char *img = calloc(W * H * 4, 1);
    CHECK_MSG(rd_render(ctx, s, &v) == RD_OK, "%s", rd_last_error());
    CHECK(rd_read_rgba8(ctx, img, W * H * 4) == RD_OK);
    return img;
}

static void check_same(const unsigned char *a, const unsigned char *b, const char *what)
{
    int differ = 0;
    for (size_t i = 0; i < (size_t)W * H * 4; i++)
        differ += a[i] != b[i];
    CHECK_MSG(differ == 0, "%s: %d bytes differ from the maps made at once", what, differ);
}

int main(void)
{
    CHECK(rd_mesh_data_plane(&plane) == RD_OK);
    CHECK(rd_mesh_data_box(&box) == RD_OK);
    rd_context *ctx = NULL;
    if (rd_context_create(&(rd_context_desc){0}, &ctx) != RD_OK) {
        fprintf(stderr, "no GL context: %s\n", rd_last_error());
        return 1;
    }
    /* The reference: rd_render makes the soft maps in one go. */
    rd_scene *once = make_scene(ctx);
    rd_scene_set_shadows(once, &hard);
    free(render(ctx, once));
    rd_scene_set_shadows(once, &soft);
    unsigned char *expected = render(ctx, once);

    /* The same switch from hard to soft, three faces a call. */
    rd_scene *sliced = make_scene(ctx);
    rd_scene_set_shadows(sliced, &hard);
    free(render(ctx, sliced));
    int left = -1;
    CHECK(rd_scene_prepare_shadows(ctx, sliced, 3, &left) == RD_OK);
    CHECK_MSG(left == 0, "the hard maps are made: %d faces left", left);
    rd_scene_set_shadows(sliced, &soft);
    CHECK(rd_scene_prepare_shadows(ctx, sliced, 3, &left) == RD_OK);
    CHECK_MSG(left == FACES - 3, "after one call of three: %d left, expected %d", left, FACES - 3);
    /* A change of settings halfway: the remake starts again. */
    rd_shadow_settings other = soft;
    other.map_size = 256;
    rd_scene_set_shadows(sliced, &other);
    CHECK(rd_scene_prepare_shadows(ctx, sliced, 2, &left) == RD_OK);
    CHECK_MSG(left == FACES - 2, "a new remake after a change: %d left, expected %d", left,
              FACES - 2);
    rd_scene_set_shadows(sliced, &soft);
    int calls = 0;
    for (int expect = FACES; expect > 0 && calls < 2 * FACES; calls++) {
        CHECK(rd_scene_prepare_shadows(ctx, sliced, 3, &left) == RD_OK);
        expect = expect > 3 ? expect - 3 : 0;
        CHECK_MSG(left == expect, "call %d: %d faces left, expected %d", calls + 1, left, expect);
    }
    CHECK_MSG(calls == 3, "eight faces three at a time take three calls, not %d", calls);
    CHECK(rd_scene_prepare_shadows(ctx, sliced, 3, &left) == RD_OK && left == 0);
    unsigned char *got = render(ctx, sliced);
    check_same(expected, got, "three faces a call");
    free(got);

    /* Half made, then rendered: rd_render finishes the remake. */
    rd_scene *half = make_scene(ctx);
    rd_scene_set_shadows(half, &hard);
    free(render(ctx, half));
    rd_scene_set_shadows(half, &soft);
    CHECK(rd_scene_prepare_shadows(ctx, half, 4, &left) == RD_OK && left == FACES - 4);
    got = render(ctx, half);
    check_same(expected, got, "four faces, then rd_render");
    CHECK(rd_scene_prepare_shadows(ctx, half, 1, &left) == RD_OK);
    CHECK_MSG(left == 0, "rd_render left %d faces to make", left);
    free(got);

    /* The test means something: the soft maps change the picture. */
    rd_scene_set_shadows(once, &hard);
    unsigned char *hard_img = render(ctx, once);
    int differ = 0;
    for (size_t i = 0; i < (size_t)W * H * 4; i++)
        differ += hard_img[i] != expected[i];
    CHECK_MSG(differ > 0, "hard and soft shadows render the same image");
    free(hard_img);
    free(expected);
    rd_scene_destroy(once);
    rd_scene_destroy(sliced);
    rd_scene_destroy(half);
    rd_mesh_data_free(&plane);
    rd_mesh_data_free(&box);
    rd_context_destroy(ctx);
    return check_report("test_shadow_slices");
}
