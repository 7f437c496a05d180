/* The 2D plan view's geometry: the mapping between plan millimetres and
 * window pixels, and what is under the pointer (a corner, a wall, a fixture). Pure math over
 * app's plan and fixtures, tested without a window; drawing is in ui/src/plan_draw.c. Screen
 * y grows downwards, plan y upwards (north up). */
#ifndef UI_PLAN_VIEW_H
#define UI_PLAN_VIEW_H

#include "app/design/placement.h"
#include "app/design/room.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct ui_plan_transform {
    double centre_mm[2]; /* the plan point at the view's centre */
    double px_per_mm;    /* zoom, clamped to [0.005, 5] */
    float width, height; /* the view's size, window pixels */
    float x0, y0;        /* the view's top-left corner in the window (its pane), pixels */
} ui_plan_transform;

/* The whole plan centred with margin_px around it. */
ui_plan_transform ui_plan_fit(const app_room_plan *plan, float width, float height,
                              float margin_px);
void ui_plan_to_screen(const ui_plan_transform *t, double x_mm, double y_mm, float *sx, float *sy);
void ui_plan_to_plan(const ui_plan_transform *t, float sx, float sy, double *x_mm, double *y_mm);
/* Zooms by factor keeping the plan point under (sx, sy) where it is. */
void ui_plan_zoom_at(ui_plan_transform *t, float sx, float sy, double factor);

/* The corner within radius_px of (sx, sy), nearest first; -1 if none. */
int ui_plan_hit_corner(const ui_plan_transform *t, const app_room_plan *plan, float sx, float sy,
                       float radius_px);
/* The wall within radius_px, nearest first; -1 if none. */
int ui_plan_hit_wall(const ui_plan_transform *t, const app_room_plan *plan, float sx, float sy,
                     float radius_px);
/* The fixture whose footprint holds the plan point, the smallest first (a mirror over a basin
 * before the basin's vanity); -1 if none. */
int ui_plan_hit_fixture(const app_fixture *fx, int count, double x_mm, double y_mm);

double ui_plan_wall_length(const app_room_plan *plan, int wall);
/* The new position of the wall's end corner that gives it length_mm, keeping its direction
 * (typing an exact length). */
app_point2 ui_plan_corner_for_length(const app_room_plan *plan, int wall, double length_mm);
/* Dragging a whole wall: how far (mm) a drag by (dx, dy) moves wall `wall` along its outward
 * normal (the plan is counter-clockwise: outward is to the right of start -> end), and where
 * its two corners go when moved by offset_mm that way. */
double ui_plan_wall_offset(const app_room_plan *plan, int wall, double dx, double dy);
void ui_plan_wall_moved(const app_room_plan *plan, int wall, double offset_mm, app_point2 *start,
                        app_point2 *end);
/* 1 when the plan point lies inside the room's walls (even-odd rule over the corners): a
 * product dropped or a fixture dragged outside, beyond the walls' snapping distance, is
 * refused rather than left outside the room. */
int ui_plan_contains(const app_room_plan *plan, double x_mm, double y_mm);
/* Rounds to a grid (mm), for dragged corners and fixtures. */
double ui_plan_snap_grid(double v_mm, double grid_mm);

#ifdef __cplusplus
}
#endif
#endif
