/* Objects sharing one probe with different glossiness (a product's parts: a glass screen, g =
 * 1, and its chrome rail, g = 0.9): the probe's blur must cover every one of them. It was made
 * for the group's first object only, so a mirror-first group left the rail's blurred levels
 * unmade and the rail read black (the designed demo's shower screen at print quality). Here a
 * mirror sphere and a glossy sphere share a group in a lit room, with prefiltered and with
 * box-mip blur and a fixed 512-texel probe: the glossy sphere shows the room (its centre pixel
 * is at least half as bright as the same sphere alone in its own group) in both orders of the
 * group. The backend comes from TESSERA_GL. */
#include "../common/check.h"
#include "../common/gl_scene.h"
#include "render/primitives.h"
#include "render/render.h"

#include <string.h>

enum { W = 64, H = 48 };

/* The centre pixel's brightness of the glossy sphere (at x = 0.6), 0..765. */
static int glossy_brightness(rd_context *ctx, rd_mesh box, rd_mesh sphere, int mirror_first,
                             int shared, rd_blur_method blur)
{
    rd_scene *s = rd_scene_create(ctx);
    rd_object_desc room = {
        .mesh = box,
        .double_sided = 1,
        .background = 1,
        .material = {.ambient = {0.5f, 0.5f, 0.5f}, .diffuse = {0.7f, 0.7f, 0.7f}}};
    test_place(room.transform, 0, 0, 0, 4.0f);
    CHECK(rd_scene_add_object(s, &room) == RD_OK);
    rd_object_desc mirror = {.mesh = sphere,
                             .group = 7,
                             .material = {.diffuse = {0.02f, 0.02f, 0.02f},
                                          .specular = {0.9f, 0.9f, 0.9f},
                                          .shininess = 500,
                                          .reflectivity = 0.9f,
                                          .glossiness = 1.0f}};
    test_place(mirror.transform, -0.6f, 0, 0, 0.25f);
    rd_object_desc glossy = mirror;
    glossy.group = shared ? 7 : 8;
    glossy.material.glossiness = 0.9f;
    test_place(glossy.transform, 0.6f, 0, 0, 0.25f);
    CHECK(rd_scene_add_object(s, mirror_first ? &mirror : &glossy) == RD_OK);
    CHECK(rd_scene_add_object(s, mirror_first ? &glossy : &mirror) == RD_OK);
    rd_light l = {.type = RD_LIGHT_POINT,
                  .position = {0, -1.0f, 1.5f},
                  .diffuse = {1, 1, 1},
                  .specular = {1, 1, 1},
                  .attenuation = {1, 0, 0}};
    CHECK(rd_scene_add_light(s, &l) == RD_OK);
    float ambient[3] = {0.4f, 0.4f, 0.4f};
    rd_scene_set_ambient(s, ambient);
    rd_reflection_defaults d = rd_scene_reflection_defaults(s);
    d.update = RD_PROBE_EVERY_FRAME;
    d.resolution = 512;
    d.blur = blur;
    rd_scene_set_reflection_defaults(s, &d);
    rd_view v = {
        .eye = {0, -1.8f, 0}, .target = {0, 0, 0}, .fov_y_deg = 50, .width = W, .height = H};
    uint8_t px[W * H * 4];
    int b = -1;
    if (rd_render(ctx, s, &v) == RD_OK && rd_read_rgba8(ctx, px, sizeof px) == RD_OK) {
        /* The glossy sphere's centre: x = 0.6 at distance 1.8 and 50 degrees of view. */
        int x = W / 2 + (int)(0.6f / (1.8f * 0.4663f) * (H / 2.0f) + 0.5f), y = H / 2;
        const uint8_t *p = px + 4 * (y * W + x);
        b = p[0] + p[1] + p[2];
    } else {
        CHECK_MSG(0, "render: %s", rd_last_error());
    }
    rd_scene_destroy(s);
    return b;
}

int main(void)
{
    rd_context *ctx = NULL;
    if (rd_context_create(&(rd_context_desc){.backend = RD_BACKEND_DEFAULT}, &ctx) != RD_OK) {
        fprintf(stderr, "no GL context: %s\n", rd_last_error());
        return 1;
    }
    rd_mesh_data d;
    rd_mesh_data_box(&d);
    rd_mesh_desc bd = rd_mesh_data_desc(&d);
    rd_mesh box = rd_mesh_create(ctx, &bd);
    rd_mesh_data_free(&d);
    rd_mesh_data_sphere(32, 16, &d);
    rd_mesh_desc sd = rd_mesh_data_desc(&d);
    rd_mesh sphere = rd_mesh_create(ctx, &sd);
    rd_mesh_data_free(&d);
    const rd_blur_method blurs[2] = {RD_BLUR_PREFILTERED, RD_BLUR_BOX_MIPS};
    for (int k = 0; k < 2; k++) {
        int alone = glossy_brightness(ctx, box, sphere, 1, 0, blurs[k]);
        int mirror_first = glossy_brightness(ctx, box, sphere, 1, 1, blurs[k]);
        int glossy_first = glossy_brightness(ctx, box, sphere, 0, 1, blurs[k]);
        printf("blur %d: glossy sphere alone %d, sharing after a mirror %d, before it %d\n", k,
               alone, mirror_first, glossy_first);
        CHECK(alone > 150); /* the lit room is what it shows */
        CHECK_MSG(2 * mirror_first >= alone, "blur %d: %d against %d alone", k, mirror_first,
                  alone);
        CHECK_MSG(2 * glossy_first >= alone, "blur %d: %d against %d alone", k, glossy_first,
                  alone);
    }
    rd_context_destroy(ctx);
    return check_report("test_probe_group_gloss");
}
