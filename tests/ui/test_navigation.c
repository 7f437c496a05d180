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

    /* The orbit's eye stays in the room: random orbits, far zooms and targets outside, in the
     * box and in the L-shaped room, never put it through a wall, the floor or the ceiling. */
    const app_room_plan *rooms[2] = {&room, &l};
    for (int r = 0; r < 2; r++) {
        ui_orbit orb = ui_orbit_framing(rooms[r]);
        int kept = 1, worst_r = 0;
        double eye[3], tgt[3];
        for (int i = 0; i < 3000; i++) {
            seed = seed * 1103515245u + 12345u;
            ui_orbit_drag(&orb, (double)((seed >> 8) % 200) - 100,
                          (double)((seed >> 16) % 200) - 100);
            if (i % 7 == 0)
                ui_orbit_zoom(&orb, (double)((seed >> 4) % 9) - 4);
            if (i % 50 == 0) /* a target anywhere, also outside or under the floor */
                for (int k = 0; k < 3; k++)
                    orb.target[k] = (double)((seed >> (k * 5)) % 9000) - 2500;
            ui_orbit_eye_inside(&orb, rooms[r], eye, tgt);
            if (!ui_room_point_free(rooms[r], eye, UI_CAMERA_MARGIN_MM - 1e-6) ||
                dist(eye, tgt) < 99) {
                if (kept)
                    fprintf(stderr,
                            "eye (%.1f %.1f %.1f) target (%.1f %.1f %.1f) from (%.1f %.1f %.1f) d "
                            "%.1f\n",
                            eye[0], eye[1], eye[2], tgt[0], tgt[1], tgt[2], orb.target[0],
                            orb.target[1], orb.target[2], orb.distance_mm);
                kept = 0;
                worst_r = r;
            }
        }
        CHECK_MSG(kept, "the orbit's eye left room %d", worst_r);
    }
    /* Against a wall the arm is cut there, not shortened elsewhere: looking at the room's
     * middle from 10 m away along +Y, the eye sits at the south wall's margin. */
    ui_orbit far = {{1200, 1500, 1200}, 10000, 0, 0};
    double fe[3], ft[3];
    ui_orbit_eye_inside(&far, &room, fe, ft);
    CHECK_MSG(fabs(fe[1] - UI_CAMERA_MARGIN_MM) < 2 && fabs(fe[0] - 1200) < 1e-6,
              "eye at (%.1f, %.1f)", fe[0], fe[1]);
    /* A target at the margin with the arm pointing through the wall: the eye stays inside,
     * the target moves ahead, the view direction is kept. */
    ui_orbit out_arm = {{2400 - UI_CAMERA_MARGIN_MM, 1500, 1200}, 2000, 270, 0};
    double oe[3], ot[3], want[3];
    ui_orbit_eye_inside(&out_arm, &room, oe, ot);
    ui_orbit_eye(&out_arm, want);
    CHECK(ui_room_point_free(&room, oe, UI_CAMERA_MARGIN_MM - 1e-6));
    CHECK_MSG(dist(oe, ot) > 99 && ot[0] < oe[0] && fabs(ot[1] - oe[1]) < 1e-6,
              "eye (%.1f %.1f) target (%.1f %.1f)", oe[0], oe[1], ot[0], ot[1]);
    /* In open space the orbit is untouched. */
    ui_orbit near = {{1200, 1500, 1200}, 500, 30, 10};
    double ne[3];
    ui_orbit_eye(&near, ne);
    ui_orbit_eye_inside(&near, &room, fe, ft);
    CHECK(dist(fe, ne) < 1e-9);
    /* A point clamped into the L's arm moves to the nearest interior point. */
    double out[3] = {3000, 3000, 5000};
    CHECK(ui_room_clamp_point(&l, out, UI_CAMERA_MARGIN_MM) == 1);
    CHECK(ui_room_point_free(&l, out, UI_CAMERA_MARGIN_MM - 1e-6));
    CHECK_MSG(out[2] == 2500 - UI_CAMERA_MARGIN_MM, "z %.1f", out[2]);

    /* Walking among fixtures: a 600 x 500 vanity across the path stops the walker its radius
     * short of the front, also when turned, and random walks never enter any footprint. */
    ui_obstacle vanity = {{1200, 2000}, {300, 250}, 0};
    ui_walk wk = {{1200, 600, UI_EYE_HEIGHT_MM}, 0, 0};
    CHECK(ui_walk_move_among(&wk, &room, &vanity, 1, 3000, 0) == 0);
    CHECK_MSG(fabs(wk.eye[1] - (2000 - 250 - UI_WALK_RADIUS_MM)) < UI_WALK_RADIUS_MM * 0.5 + 1e-6,
              "stopped at y = %.1f", wk.eye[1]);
    CHECK(wk.eye[1] <= 2000 - 250 - UI_WALK_RADIUS_MM + 1e-6);
    ui_obstacle turned = {{1200, 1500}, {400, 150}, 45};
    ui_obstacle both[2] = {vanity, turned};
    wk = (ui_walk){{300, 300, UI_EYE_HEIGHT_MM}, 0, 0};
    int clear = 1;
    for (int i = 0; i < 3000; i++) {
        seed = seed * 1103515245u + 12345u;
        wk.yaw_deg = (seed >> 8) % 360;
        ui_walk_move_among(&wk, &room, both, 2, 50 + (seed >> 20) % 2000, 0);
        clear &= ui_walk_point_free(&room, both, 2, wk.eye[0], wk.eye[1], UI_WALK_RADIUS_MM - 1e-6);
    }
    CHECK_MSG(clear, "the walker entered a fixture's footprint");
    CHECK(!ui_walk_point_free(&room, &turned, 1, 1200, 1500, 0));
    CHECK(!ui_walk_point_free(&room, &turned, 1, 1200 + 250, 1500 + 250, 10)); /* along its x */
    CHECK(ui_walk_point_free(&room, &turned, 1, 1200 + 300, 1500 - 300, 10));  /* beside it */

    /* Walk mode starts from the view: under the orbit's eye, at eye height, facing the same
     * way; an eye above a fixture steps off it to the nearest free point. */
    double veye[3] = {600, 700, 2300}, vtgt[3] = {1800, 1900, 500};
    ui_walk fw = ui_walk_from_view(&room, &vanity, 1, veye, vtgt);
    CHECK(fabs(fw.eye[0] - 600) < 1e-9 && fabs(fw.eye[1] - 700) < 1e-9);
    CHECK(fw.eye[2] == UI_EYE_HEIGHT_MM);
    CHECK_NEAR(fw.yaw_deg, 45, 1e-9);
    double over[3] = {1200, 2000, 2000};
    fw = ui_walk_from_view(&room, &vanity, 1, over, vtgt);
    CHECK(ui_walk_point_free(&room, &vanity, 1, fw.eye[0], fw.eye[1], UI_WALK_RADIUS_MM));
    CHECK_MSG(hypot(fw.eye[0] - 1200, fw.eye[1] - 2000) < 250 + UI_WALK_RADIUS_MM + 60,
              "stepped to (%.0f, %.0f)", fw.eye[0], fw.eye[1]);

    /* Nonsense never passes. */
    CHECK(!ui_plan_point_free(&room, NAN, 10, 0));
    app_room_plan empty = {0};
    CHECK(!ui_plan_point_free(&empty, 1, 1, 0));
    return check_report("ui_navigation");
}
