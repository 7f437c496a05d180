/* The plan view's geometry (ui/plan_view.h): the screen mapping round-trips, zoom keeps the
 * point under the pointer, hits find the right corner, wall and fixture, exact lengths, the
 * room's inside. */
#include "check.h"
#include "ui/plan_view.h"

#include <math.h>

int main(void)
{
    app_point2 ell[6] = {{0, 0}, {4000, 0}, {4000, 1500}, {1500, 1500}, {1500, 4000}, {0, 4000}};
    app_room_plan plan = {
        .corners = ell, .corner_count = 6, .height_mm = 2500, .wall_thickness_mm = 120};
    ui_plan_transform t = ui_plan_fit(&plan, 1000, 800, 40);
    /* The whole plan and its walls fit inside the margin. */
    for (int i = 0; i < 6; i++) {
        float sx, sy;
        ui_plan_to_screen(&t, ell[i].x, ell[i].y, &sx, &sy);
        CHECK(sx >= 40 - 1e-3 && sx <= 960 + 1e-3 && sy >= 40 - 1e-3 && sy <= 760 + 1e-3);
    }
    /* North is up: a larger plan y is higher on the screen. */
    float x0, y0, x1, y1;
    ui_plan_to_screen(&t, 0, 0, &x0, &y0);
    ui_plan_to_screen(&t, 0, 1000, &x1, &y1);
    CHECK(y1 < y0 && x1 == x0);
    double px, py;
    ui_plan_to_plan(&t, 123.5f, 456.25f, &px, &py);
    ui_plan_to_screen(&t, px, py, &x0, &y0);
    CHECK(fabsf(x0 - 123.5f) < 1e-3f && fabsf(y0 - 456.25f) < 1e-3f);

    /* Zooming at a point keeps that plan point under it. */
    double bx, by, ax, ay;
    ui_plan_to_plan(&t, 700, 200, &bx, &by);
    ui_plan_zoom_at(&t, 700, 200, 1.7);
    ui_plan_to_plan(&t, 700, 200, &ax, &ay);
    CHECK(fabs(ax - bx) < 1e-6 && fabs(ay - by) < 1e-6);
    ui_plan_zoom_at(&t, 700, 200, 1e9);
    CHECK(t.px_per_mm == 5);

    t = ui_plan_fit(&plan, 1000, 800, 40);
    float cx, cy;
    ui_plan_to_screen(&t, 1500, 1500, &cx, &cy);
    CHECK(ui_plan_hit_corner(&t, &plan, cx + 3, cy - 2, 8) == 3);
    CHECK(ui_plan_hit_corner(&t, &plan, cx + 30, cy - 20, 8) == -1);
    /* Halfway along wall 1 (x = 4000, y 0..1500). */
    ui_plan_to_screen(&t, 4000, 750, &cx, &cy);
    CHECK(ui_plan_hit_wall(&t, &plan, cx - 4, cy, 6) == 1);
    CHECK(ui_plan_hit_wall(&t, &plan, cx - 40, cy, 6) == -1);

    /* A mirror over a basin: the pointer on both picks the smaller (the mirror). */
    app_fixture fx[2] = {{.object = 0, .centre = {1000, 300}, .half = {300, 275}},
                         {.object = 1, .centre = {1000, 100}, .half = {250, 15}}};
    CHECK(ui_plan_hit_fixture(fx, 2, 1000, 100) == 1);
    CHECK(ui_plan_hit_fixture(fx, 2, 1000, 500) == 0);
    CHECK(ui_plan_hit_fixture(fx, 2, 2000, 500) == -1);
    /* A rotated footprint: 90 degrees swaps its extent. */
    app_fixture r = {.centre = {0, 0}, .half = {400, 100}, .angle_deg = 90};
    CHECK(ui_plan_hit_fixture(&r, 1, 0, 350) == 0 && ui_plan_hit_fixture(&r, 1, 350, 0) == -1);

    /* Typing an exact length moves the wall's end corner along the wall. */
    CHECK(fabs(ui_plan_wall_length(&plan, 0) - 4000) < 1e-9);
    app_point2 c = ui_plan_corner_for_length(&plan, 0, 3600);
    CHECK(fabs(c.x - 3600) < 1e-9 && fabs(c.y) < 1e-9);
    c = ui_plan_corner_for_length(&plan, 0, NAN);
    CHECK(c.x == 4000 && c.y == 0);
    CHECK(ui_plan_snap_grid(1234.4, 10) == 1230 && ui_plan_snap_grid(1236, 10) == 1240);

    /* Dragging a wall moves it along its outward normal only: wall 0 (y = 0, running +x) goes
     * to -y when dragged down, a drag along it moves nothing; the L's inner wall 3, (1500,1500)
     * -> (1500,4000), has the room on its left (-x), so outward is +x and a drag to -x moves it
     * into the room. */
    CHECK(fabs(ui_plan_wall_offset(&plan, 0, 500, -200) - 200) < 1e-9);
    CHECK(fabs(ui_plan_wall_offset(&plan, 0, 700, 0)) < 1e-9);
    app_point2 a, b;
    ui_plan_wall_moved(&plan, 0, 200, &a, &b);
    CHECK(a.x == 0 && fabs(a.y + 200) < 1e-9 && b.x == 4000 && fabs(b.y + 200) < 1e-9);
    CHECK(fabs(ui_plan_wall_offset(&plan, 3, -100, 50) + 100) < 1e-9);
    ui_plan_wall_moved(&plan, 3, -300, &a, &b);
    CHECK(fabs(a.x - 1200) < 1e-9 && a.y == 1500 && fabs(b.x - 1200) < 1e-9 && b.y == 4000);
    CHECK(ui_plan_wall_offset(&plan, 9, 100, 100) == 0); /* no such wall */

    /* Inside the L, not in its notch nor beyond its walls (drops and drags outside the room
     * are refused). */
    CHECK(ui_plan_contains(&plan, 500, 500));
    CHECK(ui_plan_contains(&plan, 3900, 1000));
    CHECK(ui_plan_contains(&plan, 1000, 3900));
    CHECK(!ui_plan_contains(&plan, 3000, 3000)); /* the notch */
    CHECK(!ui_plan_contains(&plan, 1979, -1180));
    CHECK(!ui_plan_contains(&plan, -10, 2000));
    CHECK(!ui_plan_contains(NULL, 500, 500));
    return check_report("ui_plan_view");
}
