/* The room's tileable surfaces (app/design/room_surfaces.h) on the L-shaped test room
 * (tests/data/projects/v2_l_room.json): the list and frames, and each region's area against a
 * hand computation: the sloped ceiling line, a window, a niche, a pre-wall's footprint on its
 * wall and on the floor, a bath covering the wall below its rim and the floor under it. */
#include "app/project/project.h"
#include "app/design/room_surfaces.h"
#include "test_util.h"

#include <math.h>

#define DATA TESSERA_PROJECT_TEST_DATA

static double region_area(const app_project *p, const char *surface, const app_fixture_box *fx,
                          int nfx, app_surface_frame *frame)
{
    app_surface_region r;
    char err[512];
    app_result res = app_room_surface_region(p, surface, fx, nfx, &r, frame, err, sizeof err);
    CHECK_MSG(res == APP_OK, "%s", err);
    if (res != APP_OK)
        return -1;
    double a = app_surface_region_area(&r);
    app_surface_region_free(&r);
    return a;
}

#define AREA_IS(p, name, fx, nfx, want)                                                            \
    do {                                                                                           \
        double got_ = region_area(p, name, fx, nfx, NULL);                                         \
        char msg_[160];                                                                            \
        snprintf(msg_, sizeof msg_, "%s: %.1f mm2, want %.1f", name, got_, (double)(want));        \
        CHECK_MSG(fabs(got_ - (want)) < 1.0, "%s", msg_);                                          \
    } while (0)

int main(void)
{
    app_project p;
    char err[1024];
    if (app_project_read(DATA "/v2_l_room.json", &p, err, sizeof err) != APP_OK) {
        CHECK_MSG(0, "%s", err);
        return check_report("room_surfaces");
    }
    app_surface_frame *frames = NULL;
    int count = 0;
    CHECK(app_room_surface_list(&p, &frames, &count, err, sizeof err) == APP_OK);
    CHECK(count == 2 + 6 + 4);
    if (count == 12) {
        CHECK(!strcmp(frames[0].surface, "floor") && !strcmp(frames[1].surface, "ceiling"));
        CHECK(!strcmp(frames[3].surface, "wall:1"));
        CHECK(frames[3].origin_mm[0] == 3000 && frames[3].s_axis[1] == 1 &&
              frames[3].normal[0] == -1);
        CHECK(!strcmp(frames[8].surface, "prewall:wc-box:front"));
        CHECK(!strcmp(frames[11].surface, "prewall:wc-box:right"));
        CHECK(frames[9].kind == APP_SURFACE_PREWALL_TOP && frames[9].origin_mm[2] == 1200);
        double pt[3];
        /* wall 5 runs from (0, 3000) to (0, 0): s = 1000 on the pre-wall's front */
        app_surface_frame_point(&frames[8], 1000, 300, pt);
        CHECK(fabs(pt[0] - 200) < 1e-9 && fabs(pt[1] - 2000) < 1e-9 && pt[2] == 300);
        CHECK(frames[10].normal[1] == -1); /* left: at the larger s, facing along the wall */
    }
    free(frames);

    /* The bath of the fixture as a box: x 1700..3000, y 50..750, z 0..560 (50 mm off wall 0). */
    app_fixture_box bath = {"bath", {1700, 50, 0}, {3000, 750, 560}};
    /* wall 0 is the slope's wall (1600 mm high), minus the niche and the bath */
    AREA_IS(&p, "wall:0", &bath, 1, 3000.0 * 1600 - 600 * 400 - 1300 * 560);
    AREA_IS(&p, "wall:0", NULL, 0, 3000.0 * 1600 - 600 * 400);
    /* wall 1: the slope's triangle (700 x 1000 / 2), the window; the bath stands against it */
    AREA_IS(&p, "wall:1", NULL, 0, 1800.0 * 2600 - 350000 - 800 * 1200);
    AREA_IS(&p, "wall:1", &bath, 1, 1800.0 * 2600 - 350000 - 800 * 1200 - 700 * 560);
    /* wall 4 with the door (800 x 2000) */
    AREA_IS(&p, "wall:4", &bath, 1, 1800.0 * 2600 - 800 * 2000);
    /* wall 5: the slope's triangle and the pre-wall's footprint */
    AREA_IS(&p, "wall:5", &bath, 1, 3000.0 * 2600 - 350000 - 1200 * 1200);
    /* floor: the L minus the pre-wall's footprint and the bath */
    AREA_IS(&p, "floor", &bath, 1, 7.56e6 - 1200 * 200 - 1300 * 700);
    AREA_IS(&p, "ceiling", &bath, 1, 7.56e6);
    AREA_IS(&p, "prewall:wc-box:front", &bath, 1, 1200.0 * 1200);
    AREA_IS(&p, "prewall:wc-box:top", NULL, 0, 1200.0 * 200);
    AREA_IS(&p, "prewall:wc-box:left", NULL, 0, 200.0 * 1200);
    /* a wall-hung box 300 mm off the floor does not cover the floor */
    app_fixture_box hung = {"basin", {1000, 0, 300}, {1600, 500, 850}};
    AREA_IS(&p, "floor", &hung, 1, 7.56e6 - 1200 * 200);
    AREA_IS(&p, "wall:0", &hung, 1, 3000.0 * 1600 - 600 * 400 - 600 * 550);

    app_surface_region r;
    CHECK(app_room_surface_region(&p, "wall:6", NULL, 0, &r, NULL, err, sizeof err) ==
          APP_ERR_NOT_FOUND);
    CHECK(tu_contains(err, "no surface \"wall:6\""));
    CHECK(app_room_surface_region(&p, "prewall:wc-box:back", NULL, 0, &r, NULL, err, sizeof err) ==
          APP_ERR_NOT_FOUND);
    app_project_free(&p);
    return check_report("room_surfaces");
}
