/* Glazed tiles reflect the room (render/src/glaze.c, lit.frag's GLAZE): a dark room with a
 * glowing panel standing on a floor, seen low over the floor. A glazed floor (C_s 0.25, n 64)
 * with the glaze switch on shows the panel's reflection by Fresnel at grazing angles: the floor
 * just in front of the panel is brighter than the same floor matt (C_s 0.1, n 16) and than the
 * glazed floor with the switch off. Only what the scene needs: a matt floor makes no room probe,
 * nor a glazed tile out of view, and the glazed floor makes one. The backend comes from
 * TESSERA_GL. */
#include "../common/check.h"
#include "../common/gl_scene.h"
#include "render/primitives.h"
#include "render/render.h"

#include <string.h>

enum { W = 64, H = 48 };

typedef struct floor_result {
    int brightness; /* the floor in front of the panel: the sum of 16 pixels' R + G + B */
    rd_frame_stats stats;
} floor_result;

static floor_result render_floor(rd_context *ctx, rd_mesh box, rd_mesh plane, int glazed,
                                 rd_switch glaze, int tile_behind)
{
    floor_result out = {-1, {0}};
    rd_scene *s = rd_scene_create(ctx);
    rd_object_desc room = {
        .mesh = box,
        .double_sided = 1,
        .background = 1,
        .material = {.ambient = {0.1f, 0.1f, 0.1f}, .diffuse = {0.1f, 0.1f, 0.1f}}};
    test_place(room.transform, 0, 0, 1.0f, 4.0f);
    CHECK(rd_scene_add_object(s, &room) == RD_OK);
    rd_object_desc floor = {
        .mesh = plane,
        .background = 1,
        .material = {.ambient = {0.1f, 0.1f, 0.1f}, .diffuse = {0.1f, 0.1f, 0.1f}}};
    for (int k = 0; k < 3; k++)
        floor.material.specular[k] = glazed ? 0.25f : 0.1f;
    floor.material.shininess = glazed ? 64.0f : 16.0f;
    test_place(floor.transform, 0, 0, -0.99f, 3.9f);
    CHECK(rd_scene_add_object(s, &floor) == RD_OK);
    if (tile_behind) { /* a glazed tile out of view, behind the eye */
        rd_object_desc tile = floor;
        tile.material.specular[0] = tile.material.specular[1] = tile.material.specular[2] = 0.25f;
        tile.material.shininess = 64.0f;
        test_place(tile.transform, 0, -1.9f, -0.98f, 0.1f);
        CHECK(rd_scene_add_object(s, &tile) == RD_OK);
    }
    /* The glowing panel: a box standing on the floor at the back of the room. */
    rd_object_desc panel = {.mesh = box, .material = {.emissive = {4.0f, 4.0f, 4.0f}}};
    test_place(panel.transform, 0, 1.2f, -0.5f, 1.0f);
    CHECK(rd_scene_add_object(s, &panel) == RD_OK);
    float ambient[3] = {0.2f, 0.2f, 0.2f};
    rd_scene_set_ambient(s, ambient);
    rd_reflection_defaults d = rd_scene_reflection_defaults(s);
    d.update = RD_PROBE_EVERY_FRAME;
    d.resolution = 64;
    d.glaze = glaze;
    rd_scene_set_reflection_defaults(s, &d);
    /* The eye 14 cm over the floor looks level towards the panel: the floor between them is
     * seen at about 80 degrees from its normal, where Schlick's F is about 0.4. */
    rd_view v = {.eye = {0, -1.5f, -0.85f},
                 .target = {0, 0, -0.85f},
                 .fov_y_deg = 60,
                 .width = W,
                 .height = H};
    uint8_t px[W * H * 4];
    if (rd_render(ctx, s, &v) == RD_OK && rd_read_rgba8(ctx, px, sizeof px) == RD_OK) {
        out.stats = rd_last_frame_stats(ctx);
        /* Rows 6 to 10 below the horizon (top row first), about 0.7 m ahead: the floor where
         * it mirrors the panel (the panel's image spans about 3 to 21 rows below it). */
        out.brightness = 0;
        for (int y = H / 2 + 6; y < H / 2 + 10; y++)
            for (int x = W / 2 - 2; x < W / 2 + 2; x++) {
                const uint8_t *p = px + 4 * (y * W + x);
                out.brightness += p[0] + p[1] + p[2];
            }
    } else {
        CHECK_MSG(0, "render: %s", rd_last_error());
    }
    rd_scene_destroy(s);
    return out;
}

int main(void)
{
    rd_context *ctx = NULL;
    if (rd_context_create(&(rd_context_desc){.backend = RD_BACKEND_DEFAULT}, &ctx) != RD_OK) {
        fprintf(stderr, "no GL context: %s\n", rd_last_error());
        return 1;
    }
    rd_mesh box = test_upload_mesh(ctx, 0);
    rd_mesh_data d;
    rd_mesh_data_plane(&d);
    rd_mesh_desc pd = rd_mesh_data_desc(&d);
    rd_mesh plane = rd_mesh_create(ctx, &pd);
    rd_mesh_data_free(&d);

    floor_result glazed = render_floor(ctx, box, plane, 1, RD_SWITCH_ON, 0);
    floor_result matt = render_floor(ctx, box, plane, 0, RD_SWITCH_ON, 0);
    floor_result off = render_floor(ctx, box, plane, 1, RD_SWITCH_OFF, 0);
    floor_result away = render_floor(ctx, box, plane, 0, RD_SWITCH_ON, 1);
    printf("floor before the panel: glazed %d, matt %d, glaze off %d; room probes %d %d %d %d; "
           "glazes in view %d %d %d %d\n",
           glazed.brightness, matt.brightness, off.brightness, glazed.stats.room_probe,
           matt.stats.room_probe, off.stats.room_probe, away.stats.room_probe, glazed.stats.glazed,
           matt.stats.glazed, off.stats.glazed, away.stats.glazed);
    /* The panel's reflection at grazing angle: well above a matt floor's and the switch off. */
    CHECK_MSG(glazed.brightness > matt.brightness + 16 * 30, "glazed %d, matt %d",
              glazed.brightness, matt.brightness);
    CHECK_MSG(glazed.brightness > off.brightness + 16 * 30, "glazed %d, off %d", glazed.brightness,
              off.brightness);
    CHECK(glazed.stats.room_probe == 1 && glazed.stats.glazed == 1);
    CHECK(matt.stats.room_probe == 0 && matt.stats.glazed == 0);
    CHECK(off.stats.room_probe == 0);
    CHECK(away.stats.room_probe == 0 && away.stats.glazed == 0);
    rd_context_destroy(ctx);
    return check_report("test_glaze");
}
