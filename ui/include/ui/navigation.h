/* Moving the 3D view: orbit around a point, and walk through the room at eye height without
 * passing through walls. Pure math on app's room plan, no GL, no window:
 * tested in tests/ui. Millimetres, Z up, angles in degrees. */
#ifndef UI_NAVIGATION_H
#define UI_NAVIGATION_H

#include "app/design/room.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct ui_orbit {
    double target[3];   /* the point looked at */
    double distance_mm; /* from the target, clamped to [200, 50000] */
    double yaw_deg;     /* about +Z, 0 = looking along +Y */
    double pitch_deg;   /* above the horizon, clamped to [-85, 85] */
} ui_orbit;

typedef struct ui_walk {
    double eye[3];    /* eye height in eye[2] */
    double yaw_deg;   /* about +Z, 0 = looking along +Y */
    double pitch_deg; /* clamped to [-80, 80] */
} ui_walk;

/* Body radius of the walker: how close the eye may come to a wall. */
#define UI_WALK_RADIUS_MM 200.0

/* An orbit that frames the plan's bounding box from its south-west, from above. */
ui_orbit ui_orbit_framing(const app_room_plan *plan);
void ui_orbit_eye(const ui_orbit *o, double eye[3]);
/* Mouse drag in pixels: 0.3 degrees per pixel. */
void ui_orbit_drag(ui_orbit *o, double dx_px, double dy_px);
/* Wheel steps: each step 10 % closer (positive) or farther. */
void ui_orbit_zoom(ui_orbit *o, double steps);

/* The orbit that looks from eye at target (distance, yaw, pitch from the two points). */
ui_orbit ui_orbit_from_view(const double eye[3], const double target[3]);

/* Smooth camera flights (presentation mode): eye and target each move on a
 * straight line with smoothstep easing (zero speed at both ends); t in [0, 1]. */
double ui_ease(double t);
void ui_view_blend(const double eye0[3], const double target0[3], const double eye1[3],
                   const double target1[3], double t, double eye[3], double target[3]);

/* A walker standing at the plan's centre (or its first interior point found) at 1600 mm. */
ui_walk ui_walk_start(const app_room_plan *plan);
void ui_walk_target(const ui_walk *w, double target[3]);
void ui_walk_look(ui_walk *w, double dx_px, double dy_px);
/* Moves forward/right (mm) in the walker's heading; the move is cut short or slid along the
 * wall so the eye stays inside the plan polygon at least UI_WALK_RADIUS_MM from every wall.
 * Door openings let the walker pass only if the plan continues there, which a single room
 * does not: the room is closed. Returns 1 when the full move was made, 0 when blocked. */
int ui_walk_move(ui_walk *w, const app_room_plan *plan, double forward_mm, double right_mm);

/* 1 when (x, y) is inside the plan polygon and at least radius from each wall. */
int ui_plan_point_free(const app_room_plan *plan, double x, double y, double radius);

/* ---- cameras that stay in the room ---- */

/* How close the orbit's eye may come to a wall, the floor or the ceiling. */
#define UI_CAMERA_MARGIN_MM 150.0
/* The walker's eye height. */
#define UI_EYE_HEIGHT_MM 1600.0

/* A fixture's plan footprint: a rectangle of half sides half[] about centre, its local x axis
 * at angle_deg (app_fixture's). The walker keeps its radius from it. */
typedef struct ui_obstacle {
    double centre[2], half[2], angle_deg;
} ui_obstacle;

/* 1 when point p lies inside the room with the margin: in the plan polygon at least margin
 * from each wall, and between margin above the floor and margin under the ceiling. */
int ui_room_point_free(const app_room_plan *plan, const double p[3], double margin);
/* Moves p to the nearest point that is free with the margin (p unchanged when it is, or when
 * the room has no such point); returns 1 when it moved. */
int ui_room_clamp_point(const app_room_plan *plan, double p[3], double margin);
/* The orbit's eye kept inside the room: the target clamped in, then the eye on its ray from
 * the target no farther than the first wall, floor or ceiling (less the margin). The orbit's
 * own distance is what the user asked for; it comes back when the view turns away from the
 * wall. target gets the (clamped) point looked at, moved ahead along the view when the wall
 * leaves the arm shorter than 100 mm (eye and target never meet). */
void ui_orbit_eye_inside(const ui_orbit *o, const app_room_plan *plan, double eye[3],
                         double target[3]);

/* 1 when (x, y) is free for the walker: ui_plan_point_free and at least radius from every
 * obstacle's rectangle. */
int ui_walk_point_free(const app_room_plan *plan, const ui_obstacle *obstacles, int count, double x,
                       double y, double radius);
/* ui_walk_move that also keeps the walker radius away from the obstacles. */
int ui_walk_move_among(ui_walk *w, const app_room_plan *plan, const ui_obstacle *obstacles,
                       int count, double forward_mm, double right_mm);
/* A walker that starts from a view: standing under its eye (or at the nearest free point) at
 * UI_EYE_HEIGHT_MM, facing the view's heading, level. */
ui_walk ui_walk_from_view(const app_room_plan *plan, const ui_obstacle *obstacles, int count,
                          const double eye[3], const double target[3]);

#ifdef __cplusplus
}
#endif
#endif
