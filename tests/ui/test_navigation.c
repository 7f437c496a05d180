/* Orbit and walk-through navigation (ui/navigation.h): the walker never leaves the room or
 * comes closer than its radius to a wall, also in an L-shaped room and at speed; the orbit
 * keeps its distance and clamps its pitch. */
#include "check.h"
#include "ui/navigation.h"

#include <math.h>

static double dist(const double a[3], const double b[3])
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

int main(void)
{
    app_point2 box[4] = {{0, 0}, {2400, 0}, {2400, 3000}, {0, 3000}};
    app_room_plan room = {.corners = box, .corner_count = 4, .height_mm = 2500};

    /* Orbit: the eye is distance_mm from the target whatever the angles. */
    ui_orbit o = ui_orbit_framing(&room);
    CHECK(fabs(o.target[0] - 1200) < 1e-9 && fabs(o.target[1] - 1500) < 1e-9);
    for (int i = 0; i < 50; i++) {
        ui_orbit_drag(&o, 37, -23);
        double eye[3];
        ui_orbit_eye(&o, eye);
        CHECK(fabs(dist(eye, o.target) - o.distance_mm) < 1e-6);
        CHECK(o.pitch_deg >= -85 && o.pitch_deg <= 85);
    }
    double d0 = o.distance_mm;
    ui_orbit_zoom(&o, 1);
    CHECK(fabs(o.distance_mm - d0 * 0.9) < 1e-6);
    ui_orbit_zoom(&o, -1000);
    CHECK(o.distance_mm == 50000);

    /* The walker starts inside, and walking 10 m into a wall stops at the radius. */
    ui_walk w = ui_walk_start(&room);
    CHECK(ui_plan_point_free(&room, w.eye[0], w.eye[1], UI_WALK_RADIUS_MM));
    CHECK(ui_walk_move(&w, &room, 500, 0) == 1);
    CHECK(ui_walk_move(&w, &room, 10000, 0) == 0);
    CHECK_MSG(fabs(w.eye[1] - (3000 - UI_WALK_RADIUS_MM)) < UI_WALK_RADIUS_MM * 0.5 + 1e-9,
              "stopped at y = %.1f", w.eye[1]);
    CHECK(w.eye[1] <= 3000 - UI_WALK_RADIUS_MM);

    /* Sliding: walking diagonally into the wall still moves along it. */
    double x0 = w.eye[0];
    w.yaw_deg = 45;
    ui_walk_move(&w, &room, 1000, 0);
    CHECK(w.eye[0] > x0 + 300);
    CHECK(ui_plan_point_free(&room, w.eye[0], w.eye[1], UI_WALK_RADIUS_MM));

    /* An L-shaped room: its bounding-box centre is outside; random walks stay inside. */
    app_point2 ell[6] = {{0, 0}, {4000, 0}, {4000, 1500}, {1500, 1500}, {1500, 4000}, {0, 4000}};
    app_room_plan l = {.corners = ell, .corner_count = 6, .height_mm = 2500};
    CHECK(!ui_plan_point_free(&l, 2000, 2000, 0));
    w = ui_walk_start(&l);
    CHECK(ui_plan_point_free(&l, w.eye[0], w.eye[1], UI_WALK_RADIUS_MM));
    unsigned seed = 12345;
    int inside = 1;
    for (int i = 0; i < 2000; i++) {
        seed = seed * 1103515245u + 12345u;
        w.yaw_deg = (seed >> 8) % 360;
        ui_walk_move(&w, &l, 50 + (seed >> 20) % 3000, 0);
        inside &= ui_plan_point_free(&l, w.eye[0], w.eye[1], UI_WALK_RADIUS_MM - 1e-6);
    }
    CHECK_MSG(inside, "the walker left the L-shaped room");

    /* An orbit made from a view reproduces that view's eye. */
    double eye0[3] = {300, 250, 1700}, tgt0[3] = {1200, 2900, 1000}, e[3], t[3];
    ui_orbit fv = ui_orbit_from_view(eye0, tgt0);
    ui_orbit_eye(&fv, e);
    CHECK_MSG(dist(e, eye0) < 1e-6, "eye off by %g mm", dist(e, eye0));
    /* Flights start and end exactly at their views, with zero speed at both ends. */
    double eye1[3] = {2000, 400, 1500}, tgt1[3] = {100, 2000, 900};
    ui_view_blend(eye0, tgt0, eye1, tgt1, 0, e, t);
    CHECK(dist(e, eye0) == 0 && dist(t, tgt0) == 0);
    ui_view_blend(eye0, tgt0, eye1, tgt1, 1, e, t);
    CHECK(dist(e, eye1) < 1e-9 && dist(t, tgt1) < 1e-9);
    CHECK(ui_ease(0.001) < 1e-5 && 1 - ui_ease(0.999) < 1e-5 && fabs(ui_ease(0.5) - 0.5) < 1e-12);
    CHECK(ui_ease(NAN) == 1 && ui_ease(-3) == 0 && ui_ease(7) == 1);

    /* Nonsense never passes. */
    CHECK(!ui_plan_point_free(&room, NAN, 10, 0));
    app_room_plan empty = {0};
    CHECK(!ui_plan_point_free(&empty, 1, 1, 0));
    return check_report("ui_navigation");
}
