/* The planner's frame work on a real context:
 *  - probes refreshed on change within a face budget: an orbiting camera captures nothing, a
 *    moved object makes the probes re-capture at most the budget a frame until they are fresh,
 *    the reflection then shows the object where it now is, exactly as a scene built with it
 *    there, a changed screen size within the hysteresis band keeps the probe's size, and a
 *    live view's moving frame keeps it beyond the band;
 *  - the fast paths (depth prepass, the lean box-corrected variants, opaque and glass, a
 *    live frame's fixed-light programs) draw what the general path draws, to within one
 *    8-bit step on a few pixels, in a still frame and in a live frame.
 * The backend comes from TESSERA_GL; TESSERA_NO_FAST_PATHS=1 selects the general path. */
#include "../common/check.h"
#include "../common/gl_scene.h"
#include "render/primitives.h"
#include "render/render.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { W = 96, H = 72, BUDGET = 2 };

/* A room-like box seen from inside, a red block and a chrome sphere that reflects it. */
static rd_scene *make_scene(rd_context *ctx, rd_mesh box, rd_mesh sphere, float block_x,
                            rd_probe_update update, int resolution)
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
    test_place(block.transform, block_x, 0.8f, 0.0f, 0.4f);
    CHECK(rd_scene_add_object(s, &block) == RD_OK);
    rd_object_desc chrome = {.mesh = sphere,
                             .material = {.diffuse = {0.1f, 0.1f, 0.1f},
                                          .specular = {0.8f, 0.8f, 0.8f},
                                          .shininess = 80,
                                          .reflectivity = 0.9f,
                                          .glossiness = 0.95f}};
    test_place(chrome.transform, 0, 0, 0, 0.5f);
    CHECK(rd_scene_add_object(s, &chrome) == RD_OK);
    rd_light l = {.type = RD_LIGHT_POINT,
                  .position = {0.5f, -1.0f, 1.5f},
                  .diffuse = {1, 1, 1},
                  .specular = {1, 1, 1},
                  .attenuation = {1, 0, 0.1f}};
    CHECK(rd_scene_add_light(s, &l) == RD_OK);
    /* A spot light aimed into a corner of the room: its cone misses the block and the
     * sphere (culled for them, lights_reaching in draw.c) and lights the walls. */
    rd_light spot = {.type = RD_LIGHT_SPOT,
                     .position = {-1.5f, 1.2f, 1.5f},
                     .direction = {-0.47f, 0.75f, 0.47f},
                     .diffuse = {0.4f, 0.8f, 0.4f},
                     .specular = {1, 1, 1},
                     .attenuation = {1, 0, 0.1f},
                     .spot_inner_cos = 0.97f,
                     .spot_outer_cos = 0.9f};
    CHECK(rd_scene_add_light(s, &spot) == RD_OK);
    float ambient[3] = {0.2f, 0.2f, 0.2f};
    rd_scene_set_ambient(s, ambient);
    rd_reflection_defaults d = rd_scene_reflection_defaults(s);
    d.update = update;
    d.resolution = resolution;
    d.max_faces_per_frame = BUDGET;
    for (int k = 0; k < 3; k++) {
        d.proxy_min[k] = -2.0f;
        d.proxy_max[k] = 2.0f;
    }
    rd_scene_set_reflection_defaults(s, &d);
    return s;
}

static rd_view orbit_view(float angle_deg, float distance)
{
    float a = angle_deg * 3.14159265f / 180.0f;
    rd_view v = {.eye = {distance * sinf(a), -distance * cosf(a), 0.4f},
                 .target = {0, 0, 0},
                 .fov_y_deg = 50,
                 .width = W,
                 .height = H};
    return v;
}

static double max_diff(const uint8_t *a, const uint8_t *b, size_t n, size_t *differing)
{
    int worst = 0;
    *differing = 0;
    for (size_t i = 0; i < n; i++) {
        int d = abs((int)a[i] - (int)b[i]);
        if (d > 0)
            (*differing)++;
        if (d > worst)
            worst = d;
    }
    return worst;
}

static void test_on_change_probes(rd_context *ctx)
{
    rd_mesh box = test_upload_mesh(ctx, 0), sphere = test_upload_mesh(ctx, 1);
    rd_scene *s = make_scene(ctx, box, sphere, -0.9f, RD_PROBE_ON_CHANGE, 0);
    rd_view v = orbit_view(0, 1.6f);
    CHECK(rd_render(ctx, s, &v) == RD_OK);
    rd_frame_stats st = rd_last_frame_stats(ctx);
    CHECK_MSG(st.probes == 1 && st.faces_captured == 6, "first frame: %d probes, %d faces",
              st.probes, st.faces_captured);

    /* Orbiting (and zooming within the hysteresis band) changes nothing the probe saw. */
    for (int f = 1; f <= 8; f++) {
        rd_view o = orbit_view(8.0f * (float)f, 1.6f * (1.0f + 0.03f * (float)f));
        CHECK(rd_render(ctx, s, &o) == RD_OK);
        st = rd_last_frame_stats(ctx);
        CHECK_MSG(st.faces_captured == 0 && st.prefiltered == 0,
                  "orbit frame %d: %d faces, %d prefilter passes", f, st.faces_captured,
                  st.prefiltered);
    }
    /* Hysteresis: a big view where the probe's auto size is 256 texels (wanted about 160);
     * zoomed out to a wanted 116 it keeps its size (plain rounding would say 128 and capture
     * all six faces again), zoomed out to a wanted 73 it takes the smaller size. */
    rd_view big = orbit_view(64, 1.6f);
    big.width = 640;
    big.height = 480;
    rd_scene *h = make_scene(ctx, box, sphere, -0.9f, RD_PROBE_ON_CHANGE, 0);
    CHECK(rd_render(ctx, h, &big) == RD_OK);
    CHECK(rd_last_frame_stats(ctx).faces_captured == 6);
    big = orbit_view(64, 2.2f);
    big.width = 640;
    big.height = 480;
    CHECK(rd_render(ctx, h, &big) == RD_OK);
    CHECK_MSG(rd_last_frame_stats(ctx).faces_captured == 0,
              "zoomed out within the band: %d faces captured again",
              rd_last_frame_stats(ctx).faces_captured);
    big = orbit_view(64, 3.5f);
    big.width = 640;
    big.height = 480;
    CHECK(rd_render(ctx, h, &big) == RD_OK);
    CHECK_MSG(rd_last_frame_stats(ctx).faces_captured == 6,
              "zoomed out beyond the band: %d faces, expected a new capture",
              rd_last_frame_stats(ctx).faces_captured);
    /* Zoomed in beyond the band (a wanted 200 or more), a moving live frame keeps the size;
     * the still frame that follows takes the new one. */
    big = orbit_view(64, 1.2f);
    big.width = 640;
    big.height = 480;
    big.live = 1;
    CHECK(rd_render(ctx, h, &big) == RD_OK);
    CHECK_MSG(rd_last_frame_stats(ctx).faces_captured == 0,
              "live frame beyond the band: %d faces captured, expected the size kept",
              rd_last_frame_stats(ctx).faces_captured);
    big.live = 0;
    CHECK(rd_render(ctx, h, &big) == RD_OK);
    CHECK_MSG(rd_last_frame_stats(ctx).faces_captured == 6,
              "still frame after the live one: %d faces, expected a new capture",
              rd_last_frame_stats(ctx).faces_captured);
    rd_scene_destroy(h);

    /* The block moves to the other side: the probe re-captures, the budget a frame. */
    float before[6][4] = {{0}}, after[6][4];
    {
        float moved[16];
        test_place(moved, 0.9f, 0.8f, 0.0f, 0.4f);
        /* the mean of every face before the move */
        for (int face = 0; face < 6; face++) {
            static float px[512 * 512 * 4];
            int size = 0;
            CHECK(rd_scene_read_probe(s, 0, face, 0, px, sizeof px / sizeof px[0], &size) == RD_OK);
            for (int i = 0; i < size * size; i++)
                for (int c = 0; c < 4; c++)
                    before[face][c] += px[i * 4 + c] / (float)(size * size);
        }
        CHECK(rd_scene_set_transform(s, 1, moved) == RD_OK);
    }
    int total = 0, frames = 0;
    for (; frames < 20; frames++) {
        rd_view o = orbit_view(64, 1.6f);
        CHECK(rd_render(ctx, s, &o) == RD_OK);
        st = rd_last_frame_stats(ctx);
        CHECK_MSG(st.faces_captured <= BUDGET, "frame %d after the move: %d faces (budget %d)",
                  frames, st.faces_captured, BUDGET);
        if (st.faces_captured == 0)
            break;
        total += st.faces_captured;
    }
    CHECK_MSG(total == 6, "after the move %d faces were re-captured in %d frames, expected 6",
              total, frames);
    float change = 0.0f;
    for (int face = 0; face < 6; face++) {
        static float px[512 * 512 * 4];
        int size = 0;
        memset(after[face], 0, sizeof after[face]);
        CHECK(rd_scene_read_probe(s, 0, face, 0, px, sizeof px / sizeof px[0], &size) == RD_OK);
        for (int i = 0; i < size * size; i++)
            for (int c = 0; c < 4; c++)
                after[face][c] += px[i * 4 + c] / (float)(size * size);
        for (int c = 0; c < 3; c++)
            change += fabsf(after[face][c] - before[face][c]);
    }
    CHECK_MSG(change > 0.02f, "the reflection did not follow the block (change %g)",
              (double)change);

    /* Settled, the picture is the one of a scene built with the block in its new place. */
    static uint8_t live[W * H * 4], fresh[W * H * 4];
    rd_view o = orbit_view(64, 1.6f);
    CHECK(rd_render(ctx, s, &o) == RD_OK);
    CHECK_MSG(rd_last_frame_stats(ctx).faces_captured == 0, "still capturing when settled");
    CHECK(rd_read_rgba8(ctx, live, sizeof live) == RD_OK);
    rd_scene_destroy(s);
    s = make_scene(ctx, box, sphere, 0.9f, RD_PROBE_EVERY_FRAME, 0);
    /* the same probe size as the live scene reached: first frame from the same first view */
    rd_view first = orbit_view(0, 1.6f);
    CHECK(rd_render(ctx, s, &first) == RD_OK);
    CHECK(rd_render(ctx, s, &o) == RD_OK);
    CHECK(rd_read_rgba8(ctx, fresh, sizeof fresh) == RD_OK);
    size_t differing;
    double worst = max_diff(live, fresh, sizeof live, &differing);
    CHECK_MSG(worst <= 1.0, "settled live scene vs fresh scene: max diff %g (%zu values)", worst,
              differing);
    rd_scene_destroy(s);

    /* Without a budget, on change keeps its meaning: all six faces at once. */
    s = make_scene(ctx, box, sphere, -0.9f, RD_PROBE_ON_CHANGE, 32);
    rd_reflection_defaults d = rd_scene_reflection_defaults(s);
    d.max_faces_per_frame = 0;
    rd_scene_set_reflection_defaults(s, &d);
    CHECK(rd_render(ctx, s, &v) == RD_OK);
    CHECK(rd_render(ctx, s, &v) == RD_OK);
    CHECK(rd_last_frame_stats(ctx).faces_captured == 0);
    float moved[16];
    test_place(moved, 0.9f, 0.8f, 0.0f, 0.4f);
    CHECK(rd_scene_set_transform(s, 1, moved) == RD_OK);
    CHECK(rd_render(ctx, s, &v) == RD_OK);
    CHECK_MSG(rd_last_frame_stats(ctx).faces_captured == 6, "unbudgeted on change: %d faces",
              rd_last_frame_stats(ctx).faces_captured);
    rd_scene_destroy(s);
    rd_mesh_destroy(ctx, box);
    rd_mesh_destroy(ctx, sphere);
}

/* The fast paths against the general one, for a still frame and for a live view's moving
 * frame (rd_view.live: a rectangle light as a point, every light in the fixed-light programs'
 * unrolled loops, where the general path leaves out the spot light that misses an object). */
static void test_fast_paths_match(rd_context *ctx)
{
    rd_mesh box = test_upload_mesh(ctx, 0), sphere = test_upload_mesh(ctx, 1);
    static uint8_t img[2][W * H * 4];
    for (int live = 0; live < 2; live++) {
        for (int slow = 0; slow < 2; slow++) {
            setenv("TESSERA_NO_FAST_PATHS", slow ? "1" : "0", 1);
            rd_scene *s = make_scene(ctx, box, sphere, -0.3f, RD_PROBE_EVERY_FRAME, 32);
            /* a second reflective sphere partly behind the first: overdraw among fixtures */
            rd_object_desc second;
            CHECK(rd_scene_object_desc(s, 2, &second) == RD_OK);
            test_place(second.transform, 0.35f, 0.5f, 0.1f, 0.45f);
            second.material.glossiness = 1.0f;
            CHECK(rd_scene_add_object(s, &second) == RD_OK);
            /* a clear pane between the eye and the fixtures: glass through the box, whose lean
             * variant keeps the refraction */
            rd_object_desc pane = {.mesh = box,
                                   .double_sided = 1,
                                   .material = {.diffuse = {0.05f, 0.05f, 0.05f},
                                                .specular = {0.5f, 0.5f, 0.5f},
                                                .shininess = 100,
                                                .reflectivity = 0.1f,
                                                .glossiness = 1.0f,
                                                .transparency = 0.8f}};
            test_place(pane.transform, 0.1f, -0.8f, 0.2f, 1.0f);
            pane.transform[0] = 0.7f;
            pane.transform[5] = 0.02f;
            pane.transform[10] = 0.6f;
            CHECK(rd_scene_add_object(s, &pane) == RD_OK);
            /* a panel light over the block, facing down into the room */
            rd_light panel = {.type = RD_LIGHT_RECT,
                              .position = {-0.3f, 0.8f, 1.8f},
                              .direction = {0, 0, -1},
                              .diffuse = {0.6f, 0.5f, 0.4f},
                              .specular = {1, 1, 1},
                              .half_width = {0.3f, 0, 0},
                              .half_height = {0, 0.1f, 0}};
            CHECK(rd_scene_add_light(s, &panel) == RD_OK);
            rd_view v = orbit_view(20, 1.7f);
            v.live = live;
            CHECK(rd_render(ctx, s, &v) == RD_OK);
            CHECK(rd_render(ctx, s, &v) == RD_OK);
            CHECK(rd_read_rgba8(ctx, img[slow], sizeof img[slow]) == RD_OK);
            rd_scene_destroy(s);
        }
        unsetenv("TESSERA_NO_FAST_PATHS");
        size_t differing;
        double worst = max_diff(img[0], img[1], sizeof img[0], &differing);
        CHECK_MSG(worst <= 1.0 && differing <= W * H / 100,
                  "%s frame, fast paths vs general: max diff %g, %zu values differ",
                  live ? "live" : "still", worst, differing);
        /* the picture is not blank: the check above compares something */
        size_t lit = 0;
        for (size_t i = 0; i < sizeof img[0]; i += 4)
            lit += img[0][i] > 20;
        CHECK_MSG(lit > W * H / 2, "%s frame: only %zu lit pixels", live ? "live" : "still", lit);
    }
    rd_mesh_destroy(ctx, box);
    rd_mesh_destroy(ctx, sphere);
}

int main(void)
{
    rd_context *ctx = NULL;
    if (rd_context_create(NULL, &ctx) != RD_OK) {
        fprintf(stderr, "no context: %s\n", rd_last_error());
        return 1;
    }
    test_on_change_probes(ctx);
    test_fast_paths_match(ctx);
    rd_context_destroy(ctx);
    return check_report("frame work");
}
