/* The selected fixture's move and rotate handles in the 3D view, as a planner shows them: two
 * double-headed arrows on the box's top, one along its wall (local x) and one out from it
 * (local y), and a ring about the vertical axis around its foot. Pure geometry here (where
 * they are, which one is under the pointer, the angle a ring drag turns by), tested without a
 * window (tests/ui/test_handle_geometry.c); drawn and dragged by handles_3d.c, over the pane like
 * the selection's outline and never in a render. Millimetres, z up, window y down. */
#ifndef UI_HANDLE_GEOMETRY_H
#define UI_HANDLE_GEOMETRY_H

#include "app/design/placement.h"

typedef enum ui_handle {
    UI_HANDLE_NONE = -1,
    UI_HANDLE_MOVE_X = 0, /* along the fixture's width: along its wall */
    UI_HANDLE_MOVE_Y,     /* along its depth: out from its wall */
    UI_HANDLE_ROTATE,     /* the ring: a turn about the vertical through its position */
} ui_handle;

#define UI_HANDLE_RING_SEGMENTS 48
/* A ring drag turns by whole steps of this many degrees. */
#define UI_HANDLE_ROTATE_STEP_DEG 15.0

typedef struct ui_handles {
    double centre[3];   /* the arrows' crossing: the top face's centre, mm */
    double axis[2][2];  /* the arrows' plan directions (local x, local y) */
    double reach_mm[2]; /* each arrow runs from centre - reach to centre + reach */
    double pivot[3];    /* the ring's centre: the object's position at the box's foot */
    double ring_mm;     /* the ring's radius */
} ui_handles;

/* The handles of fixture f whose object stands at position_mm (the pivot a rotate edit turns
 * about), moved by offset_mm in the plan (a live drag; NULL: none). */
void ui_handles_of(const app_fixture *f, const double position_mm[3], const double offset_mm[2],
                   ui_handles *out);

/* The ring's points, UI_HANDLE_RING_SEGMENTS of them, mm. */
void ui_handles_ring_point(const ui_handles *h, int k, double out[3]);

/* The handle whose drawn line passes within tolerance_px of window pixel (sx, sy) of a
 * width x height pane seen from eye towards target; arrows before the ring. */
ui_handle ui_handles_pick(const ui_handles *h, const double eye[3], const double target[3],
                          double fov_y_deg, int width, int height, double sx, double sy,
                          double tolerance_px);

/* The turn in degrees from plan point `from` to plan point `to` about the pivot,
 * counter-clockwise positive, in (-180, 180], rounded to whole steps of step_deg. */
double ui_handles_turn(const ui_handles *h, const double from[2], const double to[2],
                       double step_deg);

#endif
