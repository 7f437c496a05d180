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
    /* floor, ceiling, 6 walls, 4 pre-wall faces, then the window's 4 reveals, the door's 3 (no
     * bottom: the floor runs through) and the niche's 5 faces */
    CHECK(count == 2 + 6 + 4 + 4 + 3 + 5);
    if (count == 24) {
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
        CHECK(!strcmp(frames[12].surface, "reveal:window:left"));
        CHECK(!strcmp(frames[18].surface, "reveal:door:top"));
        CHECK(!strcmp(frames[19].surface, "niche:shower-niche:left"));
        CHECK(!strcmp(frames[23].surface, "niche:shower-niche:back"));
        /* wall 0 runs from (0, 0) along +x, its inward normal +y; the niche (s 2000..2600,
         * t 1000..1400) is 80 deep, so its back lies at y = -80 */
        app_surface_frame_point(&frames[23], 2000, 1000, pt);
        CHECK(pt[0] == 2000 && pt[1] == -80 && pt[2] == 1000 && frames[23].normal[1] == 1);
        /* its left face at x = 2600 faces -x into the niche; s runs from the wall's face in */
        app_surface_frame_point(&frames[19], 80, 1400, pt);
        CHECK(pt[0] == 2600 && pt[1] == -80 && pt[2] == 1400 && frames[19].normal[0] == -1);
        /* the top (soffit) at 1400 faces down, the bottom (sill) at 1000 up */
        CHECK(frames[21].normal[2] == -1 && frames[21].origin_mm[2] == 1400);
        CHECK(frames[22].normal[2] == 1 && frames[22].origin_mm[2] == 1000);
        /* the window on wall 1 (x = 3000, running +y, normal -x) goes through the 150 mm wall:
         * its right reveal at y = 500 runs from x = 3150 (the back) to 3000 (the face) */
        app_surface_frame_point(&frames[13], 0, 900, pt);
        CHECK(fabs(pt[0] - 3150) < 1e-9 && fabs(pt[1] - 500) < 1e-9 && pt[2] == 900);
        app_surface_frame_point(&frames[13], 150, 900, pt);
        CHECK(fabs(pt[0] - 3000) < 1e-9 && frames[13].normal[1] == 1);
        for (int k = 12; k < 24; k++) {
            /* right-handed (s x t = normal) except the back, which keeps the wall's axes */
            const double *a = frames[k].s_axis, *b = frames[k].t_axis, *n = frames[k].normal;
            double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                           a[0] * b[1] - a[1] * b[0]};
            double sign = k == 23 ? -1 : 1;
            CHECK_MSG(fabs(c[0] - sign * n[0]) + fabs(c[1] - sign * n[1]) +
                              fabs(c[2] - sign * n[2]) <
                          1e-9,
                      "%s", frames[k].surface);
        }
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

    /* Reveals and the niche (areas by hand): the window 800 x 1200 through the 150 mm wall, the
     * door 800 x 2000 to its leaf at half the wall (75 mm), the niche 600 x 400, 80 deep. */
    AREA_IS(&p, "reveal:window:left", NULL, 0, 150.0 * 1200);
    AREA_IS(&p, "reveal:window:right", NULL, 0, 150.0 * 1200);
    AREA_IS(&p, "reveal:window:top", NULL, 0, 800.0 * 150);
    AREA_IS(&p, "reveal:window:bottom", NULL, 0, 800.0 * 150);
    AREA_IS(&p, "reveal:door:left", NULL, 0, 75.0 * 2000);
    AREA_IS(&p, "reveal:door:top", NULL, 0, 800.0 * 75);
    AREA_IS(&p, "niche:shower-niche:back", NULL, 0, 600.0 * 400);
    AREA_IS(&p, "niche:shower-niche:left", NULL, 0, 80.0 * 400);
    AREA_IS(&p, "niche:shower-niche:bottom", NULL, 0, 600.0 * 80);
    /* the niche's five faces: 0.24 + 2 x 0.032 + 2 x 0.048 = 0.40 m2 */
    double niche = 0;
    const char *faces[5] = {"left", "right", "top", "bottom", "back"};
    for (int k = 0; k < 5; k++) {
        char name[64];
        snprintf(name, sizeof name, "niche:shower-niche:%s", faces[k]);
        niche += region_area(&p, name, NULL, 0, NULL);
    }
    CHECK_NEAR(niche, 400000.0, 1e-6);

    app_surface_region r;
    CHECK(app_room_surface_region(&p, "reveal:door:bottom", NULL, 0, &r, NULL, err, sizeof err) ==
          APP_ERR_NOT_FOUND);
    CHECK(app_room_surface_region(&p, "niche:window:back", NULL, 0, &r, NULL, err, sizeof err) ==
          APP_ERR_NOT_FOUND);
    CHECK(app_room_surface_region(&p, "wall:6", NULL, 0, &r, NULL, err, sizeof err) ==
          APP_ERR_NOT_FOUND);
    CHECK(tu_contains(err, "no surface \"wall:6\""));
    CHECK(app_room_surface_region(&p, "prewall:wc-box:back", NULL, 0, &r, NULL, err, sizeof err) ==
          APP_ERR_NOT_FOUND);
    app_project_free(&p);
    return check_report("room_surfaces");
}
