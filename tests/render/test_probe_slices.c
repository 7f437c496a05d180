/* A probe's first capture split by faces (rd_reflection_defaults.split_captures = 2, what the
 * window's still view asks for): two chrome spheres in a room with a glazed red block (it
 * reads the room probe), probes captured on change. With a budget of four faces a frame (a blur
 * counting as two) no render captures more than four faces, the probes count as held until their
 * blur, and the image afterwards equals, byte for byte, the image of the same scene whose probes
 * were captured whole (six faces, one probe a frame). A new budget set with
 * rd_scene_set_capture_budget captures nothing again. Under a capture time too short for
 * anything but the first step (rd_scene_set_capture_time), each render captures one face or
 * makes one blur, and the image ends the same; a long one leaves the face budget in charge.
 * A strip that shows no sphere captures for the whole picture under split captures. The
 * backend comes from TESSERA_GL. */
#include "../common/check.h"
#include "../common/gl_scene.h"
#include "render/render.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { W = 96, H = 72 };

static rd_scene *make_scene(rd_context *ctx, rd_mesh box, rd_mesh sphere, int faces, int split)
{
    rd_scene *s = rd_scene_create(ctx);
    rd_object_desc room = {
        .mesh = box,
        .double_sided = 1,
        .background = 1,
        .material = {.ambient = {0.3f, 0.3f, 0.3f}, .diffuse = {0.6f, 0.65f, 0.7f}}};
    test_place(room.transform, 0, 0, 0, 4.0f);
    CHECK(rd_scene_add_object(s, &room) == RD_OK);
    /* Glazed (specular and shiny, no probe of its own): it reflects the room probe. */
    rd_object_desc block = {.mesh = box,
                            .material = {.ambient = {0.2f, 0.0f, 0.0f},
                                         .diffuse = {0.9f, 0.1f, 0.1f},
                                         .specular = {0.5f, 0.5f, 0.5f},
                                         .shininess = 64}};
    test_place(block.transform, -0.9f, 0.8f, 0.0f, 0.4f);
    CHECK(rd_scene_add_object(s, &block) == RD_OK);
    for (int i = 0; i < 2; i++) {
        rd_object_desc chrome = {
            .mesh = sphere,
            .material = {.diffuse = {0.1f, 0.1f, 0.1f}, .reflectivity = 0.9f, .glossiness = 0.95f}};
        test_place(chrome.transform, i ? 0.45f : -0.35f, 0.0f, 0.0f, 0.35f);
        CHECK(rd_scene_add_object(s, &chrome) == RD_OK);
    }
    rd_light l = {.type = RD_LIGHT_POINT,
                  .position = {0.5f, -1.0f, 1.5f},
                  .diffuse = {1, 1, 1},
                  .attenuation = {1, 0, 0.1f}};
    CHECK(rd_scene_add_light(s, &l) == RD_OK);
    rd_scene_set_ambient(s, (float[3]){0.2f, 0.2f, 0.2f});
    rd_reflection_defaults d = rd_scene_reflection_defaults(s);
    d.update = RD_PROBE_ON_CHANGE;
    d.resolution = 64;
    d.max_faces_per_frame = faces;
    d.split_captures = split;
    d.glaze = RD_SWITCH_ON;
    for (int k = 0; k < 3; k++) {
        d.proxy_min[k] = -2.0f;
        d.proxy_max[k] = 2.0f;
    }
    rd_scene_set_reflection_defaults(s, &d);
    return s;
}

static const rd_view view = {
    .eye = {0.2f, -1.8f, 0.4f}, .target = {0, 0, 0}, .fov_y_deg = 50, .width = W, .height = H};

/* Renders until no probe is held (at most `most` renders); returns the renders it took and
 * checks every render's faces against the budget. */
static int settle(rd_context *ctx, rd_scene *s, int budget, int most, int *total_faces)
{
    *total_faces = 0;
    for (int n = 1; n <= most; n++) {
        CHECK_MSG(rd_render(ctx, s, &view) == RD_OK, "%s", rd_last_error());
        rd_frame_stats st = rd_last_frame_stats(ctx);
        CHECK_MSG(st.faces_captured <= budget, "render %d captured %d faces, over the budget of %d",
                  n, st.faces_captured, budget);
        *total_faces += st.faces_captured;
        CHECK_MSG(st.glazed > 0, "render %d: the glazed block is out of view", n);
        if (!st.probes_held)
            return n;
    }
    return -1;
}

int main(void)
{
    rd_context *ctx = NULL;
    if (rd_context_create(&(rd_context_desc){0}, &ctx) != RD_OK) {
        fprintf(stderr, "no GL context: %s\n", rd_last_error());
        return 1;
    }
    rd_mesh box = test_upload_mesh(ctx, 0), sphere = test_upload_mesh(ctx, 1);
    uint8_t *whole = malloc(W * H * 4), *sliced = malloc(W * H * 4);

    /* Whole: a probe's six faces a frame, the room probe's six beside them. */
    rd_scene *a = make_scene(ctx, box, sphere, 6, 1);
    int faces = 0, renders = settle(ctx, a, 12, 12, &faces);
    CHECK_MSG(renders == 2 && faces == 18, "whole captures: %d renders, %d faces", renders, faces);
    CHECK(rd_render(ctx, a, &view) == RD_OK && rd_last_frame_stats(ctx).faces_captured == 0);
    CHECK(rd_read_rgba8(ctx, whole, W * H * 4) == RD_OK);

    rd_scene *b = make_scene(ctx, box, sphere, 4, 2);
    renders = settle(ctx, b, 4, 12, &faces);
    /* Eighteen faces (two spheres' and the room probe's) and three blurs (two faces' worth
     * each) in four-face frames: six renders at least; greedy packing wastes a few. */
    CHECK_MSG(renders >= 6 && renders <= 8 && faces == 18,
              "four faces a frame: %d renders, %d faces", renders, faces);
    rd_scene_set_capture_budget(b, 3, 2);
    CHECK(rd_render(ctx, b, &view) == RD_OK);
    CHECK_MSG(rd_last_frame_stats(ctx).faces_captured == 0, "a new budget captured %d faces again",
              rd_last_frame_stats(ctx).faces_captured);
    CHECK(rd_read_rgba8(ctx, sliced, W * H * 4) == RD_OK);
    int differ = 0;
    for (int i = 0; i < W * H * 4; i++)
        differ += whole[i] != sliced[i];
    CHECK_MSG(differ == 0, "%d bytes differ between whole and split captures", differ);

    /* A capture time of a microsecond: the first face or blur of each render goes, nothing
     * after it. Eighteen faces and three blurs: 21 renders, the same picture. An hour: the
     * budget of four faces decides, as above. */
    for (int hour = 0; hour < 2; hour++) {
        rd_scene *t = make_scene(ctx, box, sphere, 4, 2);
        rd_scene_set_capture_time(t, hour ? 3.6e6f : 1e-3f);
        renders = settle(ctx, t, hour ? 4 : 1, 30, &faces);
        if (hour)
            CHECK_MSG(renders >= 6 && renders <= 8 && faces == 18,
                      "an hour's capture time: %d renders, %d faces", renders, faces);
        else
            CHECK_MSG(renders == 21 && faces == 18,
                      "a microsecond's capture time: %d renders, %d faces", renders, faces);
        CHECK(rd_render(ctx, t, &view) == RD_OK && rd_last_frame_stats(ctx).faces_captured == 0);
        CHECK(rd_read_rgba8(ctx, sliced, W * H * 4) == RD_OK);
        differ = 0;
        for (int i = 0; i < W * H * 4; i++)
            differ += whole[i] != sliced[i];
        CHECK_MSG(differ == 0, "%d bytes differ between whole captures and a capture time's",
                  differ);
        rd_scene_destroy(t);
    }

    /* A strip of the picture's top rows shows no sphere, yet under split captures it captures
     * (and holds) the probes the whole picture needs; the whole-capture mode leaves them. */
    rd_view strip = view;
    strip.height = 6;
    strip.crop_y = 0;
    strip.full_width = W;
    strip.full_height = H;
    for (int split = 1; split <= 2; split++) {
        rd_scene *c = make_scene(ctx, box, sphere, 4, split);
        CHECK_MSG(rd_render(ctx, c, &strip) == RD_OK, "%s", rd_last_error());
        rd_frame_stats st = rd_last_frame_stats(ctx);
        int cubes = st.faces_captured - (st.room_probe ? 6 : 0);
        printf("top strip, split_captures %d: %d faces, %d held\n", split, st.faces_captured,
               st.probes_held);
        if (split == 2)
            CHECK_MSG(st.faces_captured == 4 && st.probes_held > 0,
                      "split: the strip captured %d faces, held %d probes", st.faces_captured,
                      st.probes_held);
        else
            CHECK_MSG(cubes <= 0 && st.probes_held == 0,
                      "whole: the strip captured %d cube faces, held %d probes", cubes,
                      st.probes_held);
        rd_scene_destroy(c);
    }

    free(whole);
    free(sliced);
    rd_scene_destroy(a);
    rd_scene_destroy(b);
    rd_context_destroy(ctx);
    return check_report("test_probe_slices");
}
