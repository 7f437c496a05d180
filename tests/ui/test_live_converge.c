/* Temporal supersampling converges (ui/src/live_accum.h over rd_view.jitter): a scene of hard
 * edges rendered at 16 Halton offsets and averaged is much closer to the renderer's own 4 x 4
 * supersampled render than the first, unjittered frame is, and closer with 16 offsets than
 * with 4. Headless GL (the default backend). */
#include "check.h"
#include "live_accum.h"
#include "render/primitives.h"
#include "render/render.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { W = 96, H = 64 };

static double rmse(const unsigned char *a, const unsigned char *b)
{
    double s = 0;
    for (int i = 0; i < W * H; i++)
        for (int c = 0; c < 3; c++) {
            double d = (double)a[i * 4 + c] - (double)b[i * 4 + c];
            s += d * d;
        }
    return sqrt(s / (W * H * 3));
}

static void add_box(rd_scene *s, rd_mesh box, const float pos[3], const float size[3],
                    const float colour[3], float angle)
{
    rd_object_desc o = {.mesh = box, .shape = RD_SHAPE_BOX};
    memcpy(o.material.diffuse, colour, sizeof o.material.diffuse);
    memcpy(o.material.ambient, colour, sizeof o.material.ambient);
    float c = cosf(angle), sn = sinf(angle);
    float m[16] = {c * size[0], sn * size[0], 0, 0,      -sn * size[1], c * size[1], 0, 0, 0,
                   0,           size[2],      0, pos[0], pos[1],        pos[2],      1};
    memcpy(o.transform, m, sizeof m);
    CHECK(rd_scene_add_object(s, &o) == RD_OK);
}

int main(void)
{
    rd_context *ctx = NULL;
    if (rd_context_create(NULL, &ctx) != RD_OK) {
        fprintf(stderr, "SKIP: no headless OpenGL: %s\n", rd_last_error());
        return 77;
    }
    rd_mesh_data md;
    CHECK(rd_mesh_data_box(&md) == RD_OK);
    rd_mesh_desc desc = rd_mesh_data_desc(&md);
    rd_mesh box = rd_mesh_create(ctx, &desc);
    rd_mesh_data_free(&md);
    rd_scene *s = rd_scene_create(ctx);
    /* Thin bars at odd angles against a dark back: every edge is aliased at one sample. */
    for (int i = 0; i < 6; i++)
        add_box(s, box, (float[3]){-1.0f + 0.4f * (float)i, 0.0f, 0.0f},
                (float[3]){0.05f, 0.05f, 1.6f}, (float[3]){0.9f, 0.8f - 0.1f * (float)i, 0.6f},
                0.3f * (float)i);
    add_box(s, box, (float[3]){0, 0.6f, 0}, (float[3]){4, 0.1f, 4}, (float[3]){0.05f, 0.1f, 0.2f},
            0);
    rd_light light = {.type = RD_LIGHT_DIRECTIONAL,
                      .direction = {0.3f, 1.0f, -0.5f},
                      .diffuse = {1, 1, 1},
                      .specular = {0, 0, 0}};
    CHECK(rd_scene_add_light(s, &light) == RD_OK);
    rd_scene_set_ambient(s, (float[3]){0.3f, 0.3f, 0.3f});

    rd_view v = {.eye = {0.2f, -3.0f, 0.3f}, .target = {0, 0, 0}, .width = W, .height = H};
    size_t size = (size_t)W * H * 4;
    unsigned char *ref = malloc(size), *frame = malloc(size), *first = malloc(size);
    v.supersample = 4;
    CHECK(rd_render(ctx, s, &v) == RD_OK && rd_read_rgba8(ctx, ref, size) == RD_OK);
    v.supersample = 1;
    ui_accum a = {0};
    CHECK(ui_accum_resize(&a, W, H) == 0);
    double e4 = 0, e16 = 0;
    for (int pass = 0; pass < 16; pass++) {
        ui_jitter(pass, v.jitter);
        CHECK(rd_render(ctx, s, &v) == RD_OK && rd_read_rgba8(ctx, frame, size) == RD_OK);
        if (pass == 0)
            memcpy(first, frame, size);
        ui_accum_add(&a, 0, 0, W, H, frame);
        if (pass == 3)
            e4 = rmse(a.image, ref);
    }
    e16 = rmse(a.image, ref);
    double e1 = rmse(first, ref);
    printf("RMSE against 4x4 supersampling: 1 frame %.2f, 4 offsets %.2f, 16 offsets %.2f\n", e1,
           e4, e16);
    CHECK_MSG(e1 > 3.0, "the scene has edges to smooth (%.2f)", e1);
    CHECK_MSG(e16 < 0.5 * e1, "16 offsets %.2f against one frame %.2f", e16, e1);
    CHECK_MSG(e16 < e4, "16 offsets %.2f against 4 %.2f", e16, e4);
    /* A jitter of a pixel or more is refused. */
    v.jitter[0] = 1.0f;
    CHECK(rd_render(ctx, s, &v) == RD_ERR_INVALID_ARGUMENT);
    ui_accum_free(&a);
    free(ref);
    free(frame);
    free(first);
    rd_scene_destroy(s);
    rd_mesh_destroy(ctx, box);
    rd_context_destroy(ctx);
    return check_report("ui_live_converge");
}
