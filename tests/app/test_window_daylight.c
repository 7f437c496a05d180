/* A window's daylight rendered (docs/rendering.md, "Daylight"): a room lit only by a window,
 * seen from inside. With daylight the floor and walls near the window are brighter than with
 * the window closed to it (`light` 0); the exterior seen through the opening is not a grey
 * panel (a sky gradient over green ground); and a clear noon sun through a south window puts
 * a sunlit patch on the floor that the overcast sky does not. */
#include "../common/check.h"
#include "app/project/project.h"
#include "app/scene/scene_build.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { W = 160, H = 120 };

static const char *ROOM =
    "{\"version\": 2, \"room\": {}, \"plan\": {\"corners\": [[0, 0], [3000, 0], [3000, 2400], "
    "[0, 2400]], \"height\": 2500, \"wall_thickness\": 150, \"openings\": [{\"type\": "
    "\"window\", \"wall\": 0, \"offset\": 1100, \"width\": 800, \"sill\": 900, \"height\": "
    "1200, \"light\": [%s]}]},"
    "\"render\": {\"ambient\": [0.02, 0.02, 0.02]},"
    "\"daylight\": {\"sky\": \"%s\", \"date\": \"2026-06-21\", \"time\": \"12:00\", \"site\": "
    "\"greenwich\"},"
    "\"cameras\": [{\"position\": [1500, 2300, 1500], \"target\": [1500, 0, 1100], \"fov\": 70}]}";

/* Renders the room; img gets W x H rgba8. */
static int render(rd_context *ctx, const char *light, const char *sky, uint8_t *img)
{
    char text[2048], err[2048];
    snprintf(text, sizeof text, ROOM, light, sky);
    app_project p;
    app_result r = app_project_parse(text, strlen(text), "window.json", &p, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    if (r != APP_OK)
        return 0;
    app_scene s;
    r = app_scene_build(ctx, &p, &s, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    int ok = 0;
    if (r == APP_OK) {
        const app_camera *cam = &p.cameras[0];
        rd_view v = {.fov_y_deg = (float)cam->fov_deg, .width = W, .height = H};
        for (int k = 0; k < 3; k++) {
            v.eye[k] = (float)(cam->position_mm[k] * 1e-3);
            v.target[k] = (float)(cam->target_mm[k] * 1e-3);
        }
        rd_scene_set_shadows(s.scene, &(rd_shadow_settings){.mode = RD_SHADOWS_HARD});
        ok = rd_render(ctx, s.scene, &v) == RD_OK && rd_read_rgba8(ctx, img, W * H * 4) == RD_OK;
        CHECK_MSG(ok, "%s", rd_last_error());
        app_scene_release(ctx, &s);
    }
    app_project_free(&p);
    return ok;
}

static double luma(const uint8_t *px)
{
    return 0.2126 * px[0] + 0.7152 * px[1] + 0.0722 * px[2];
}

/* Mean luma of the rows [y0, y1) and columns [x0, x1). */
static double region(const uint8_t *img, int x0, int x1, int y0, int y1)
{
    double sum = 0;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++)
            sum += luma(&img[(y * W + x) * 4]);
    return sum / ((x1 - x0) * (y1 - y0));
}

int main(void)
{
    rd_context *ctx = NULL;
    if (rd_context_create(NULL, &ctx) != RD_OK) {
        fprintf(stderr, "no context: %s\n", rd_last_error());
        return 1;
    }
    static uint8_t day[W * H * 4], closed[W * H * 4], sunny[W * H * 4];
    if (render(ctx, "1, 1, 1", "overcast", day) && render(ctx, "0, 0, 0", "overcast", closed) &&
        render(ctx, "1, 1, 1", "clear", sunny)) {
        /* the floor in front of the window (the bottom rows) and the side walls near it */
        double floor_day = region(day, 40, 120, 100, 120),
               floor_closed = region(closed, 40, 120, 100, 120);
        double side_day = region(day, 0, 20, 30, 90), side_closed = region(closed, 0, 20, 30, 90);
        printf("floor near the window: luma %.1f with daylight, %.1f without\n", floor_day,
               floor_closed);
        printf("side wall near the window: luma %.1f with daylight, %.1f without\n", side_day,
               side_closed);
        CHECK(floor_day > floor_closed + 20.0);
        CHECK(side_day > side_closed + 10.0);
        /* the exterior: a column down the middle of the opening */
        int cx = W / 2, top = -1, bottom = -1;
        for (int y = 0; y < H; y++) {
            const uint8_t *px = &day[(y * W + cx) * 4];
            if (luma(px) > 100 && top < 0)
                top = y;
        }
        int green = 0, sky = 0, grey = 0;
        for (int y = 0; y < H; y++) {
            const uint8_t *px = &day[(y * W + cx) * 4];
            const uint8_t *shut = &closed[(y * W + cx) * 4];
            int is_pane = abs((int)luma(px) - (int)luma(shut)) > 20 && y < 90;
            if (!is_pane)
                continue;
            bottom = y;
            green += px[1] > px[0] + 8 && px[1] > px[2] + 8;
            sky += px[2] >= px[0] && luma(px) > 150;
            grey += abs(px[0] - 64) < 6 && abs(px[1] - 64) < 6 && abs(px[2] - 64) < 6;
        }
        printf("pane column: rows %d..%d, %d green (ground), %d sky, %d grey\n", top, bottom, green,
               sky, grey);
        CHECK(green >= 3);
        CHECK(sky >= 3);
        CHECK(grey == 0);
        /* the sun: a patch on the floor far brighter than anything the overcast sky gives */
        int patch = 0;
        for (int y = 60; y < H; y++)
            for (int x = 0; x < W; x++)
                patch += luma(&sunny[(y * W + x) * 4]) > region(day, 40, 120, 100, 120) + 60;
        printf("sunlit pixels: %d\n", patch);
        CHECK(patch > 100);
        FILE *f = fopen("window_daylight.ppm", "wb");
        if (f) {
            fprintf(f, "P6 %d %d 255\n", W, 3 * H);
            const uint8_t *imgs[3] = {day, closed, sunny};
            for (int i = 0; i < 3; i++)
                for (int k = 0; k < W * H; k++)
                    fwrite(&imgs[i][k * 4], 1, 3, f);
            fclose(f);
        }
    }
    rd_context_destroy(ctx);
    return check_report("window_daylight");
}
