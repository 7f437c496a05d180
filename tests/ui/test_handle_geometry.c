/* The 3D view's handles (ui/src/handle_geometry.h): the arrows cross on the box's top along
 * its turned axes, the ring about the object's position clears every corner; a pixel on an
 * arrow picks it (an arrow before the ring where they cross), a pixel on the ring picks the
 * ring, a pixel away from both picks none; a turn is rounded to whole 15-degree steps,
 * counter-clockwise positive. */
#include "check.h"
#include "handle_geometry.h"
#include "view_ray.h"

#include <math.h>
#include <string.h>

#define PI 3.14159265358979323846

static const double eye[3] = {1000, -2000, 3000}, target[3] = {1000, 1000, 0};
static const int w = 960, h = 540;

static ui_handle pick_at(const ui_handles *hs, const double pt[3])
{
    double sx, sy;
    CHECK(ui_view_project(eye, target, 50, w, h, pt, &sx, &sy));
    return ui_handles_pick(hs, eye, target, 50, w, h, sx, sy, 7);
}

int main(void)
{
    /* A 600 x 500 box, 800 high, its back centre at (1000, 750) facing +y. */
    app_fixture f;
    memset(&f, 0, sizeof f);
    f.centre[0] = 1000;
    f.centre[1] = 1000;
    f.half[0] = 300;
    f.half[1] = 250;
    f.z1 = 800;
    const double at[3] = {1000, 750, 0};
    ui_handles hs;
    ui_handles_of(&f, at, NULL, &hs);
    CHECK_NEAR(hs.centre[2], 800, 1e-9);
    CHECK_NEAR(hs.axis[0][0], 1, 1e-12);
    CHECK_NEAR(hs.axis[1][1], 1, 1e-12);
    CHECK_NEAR(hs.pivot[1], 750, 1e-9);
    /* The farthest corners (+-300, 500) from the pivot, and 120 mm more. */
    CHECK_NEAR(hs.ring_mm, hypot(300, 500) + 120, 1e-9);

    /* Turned by 90 degrees and dragged by (100, -50): the axes turn, everything moves. */
    app_fixture g = f;
    g.angle_deg = 90;
    ui_handles hg;
    ui_handles_of(&g, at, (const double[2]){100, -50}, &hg);
    CHECK_NEAR(hg.axis[0][1], 1, 1e-12);
    CHECK_NEAR(hg.axis[1][0], -1, 1e-12);
    CHECK_NEAR(hg.centre[0], 1100, 1e-9);
    CHECK_NEAR(hg.pivot[1], 700, 1e-9);

    /* Picking: near each arrow's + head, on the ring beside the box, in empty floor. */
    double px[3] = {hs.centre[0] + 0.7 * hs.reach_mm[0], hs.centre[1], 800};
    double py[3] = {hs.centre[0], hs.centre[1] + 0.7 * hs.reach_mm[1], 800};
    double ring[3];
    ui_handles_ring_point(&hs, UI_HANDLE_RING_SEGMENTS / 2, ring); /* at -x, beside the box */
    double empty[3] = {hs.pivot[0] - 2 * hs.ring_mm, hs.pivot[1], 0};
    CHECK(pick_at(&hs, px) == UI_HANDLE_MOVE_X);
    CHECK(pick_at(&hs, py) == UI_HANDLE_MOVE_Y);
    CHECK(pick_at(&hs, ring) == UI_HANDLE_ROTATE);
    CHECK(pick_at(&hs, empty) == UI_HANDLE_NONE);
    /* The arrow wins where it passes over the ring. */
    double cross[3] = {hs.centre[0] + hs.reach_mm[0], hs.centre[1], 800};
    CHECK(pick_at(&hs, cross) == UI_HANDLE_MOVE_X);

    /* Turns about the pivot, rounded to 15 degrees; unrounded with step 0. */
    const double *c = hs.pivot;
    double from[2] = {c[0] + 500, c[1]};
    double to52[2] = {c[0] + 500 * cos(52 * PI / 180), c[1] + 500 * sin(52 * PI / 180)};
    double to_m8[2] = {c[0] + 500 * cos(-8 * PI / 180), c[1] + 500 * sin(-8 * PI / 180)};
    double to7[2] = {c[0] + 500 * cos(7 * PI / 180), c[1] + 500 * sin(7 * PI / 180)};
    double back[2] = {c[0] - 500, c[1] - 1};
    CHECK_NEAR(ui_handles_turn(&hs, from, to52, 15), 45, 1e-9);
    CHECK_NEAR(ui_handles_turn(&hs, from, to52, 0), 52, 1e-9);
    CHECK_NEAR(ui_handles_turn(&hs, from, to_m8, 15), -15, 1e-9);
    CHECK_NEAR(ui_handles_turn(&hs, from, to7, 15), 0, 1e-9);
    CHECK_NEAR(ui_handles_turn(&hs, from, back, 15), -180, 1e-9);
    return check_report("ui.handle_geometry");
}
