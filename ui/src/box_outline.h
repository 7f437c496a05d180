/* The 12 edges of a fixture's box (its plan rectangle turned by angle_deg, from z0 to z1) as
 * the 3D view shows them: clipped against a plane just in front of the eye, then projected
 * with the view's camera (view_ray.h). Pure geometry, tested without a window
 * (tests/ui/test_box_outline.c); drawn by selection_3d.c. Millimetres, window y down. */
#ifndef UI_BOX_OUTLINE_H
#define UI_BOX_OUTLINE_H

#include "app/design/placement.h"

#define UI_BOX_EDGES 12

/* Writes the visible part of each edge as x0 y0 x1 y1 in pane pixels (the pane being width x
 * height) into segments, the box moved by offset_mm in the plan (a live drag; NULL: none);
 * returns how many (0-12). Edges wholly behind the eye are left out; the pane's clip
 * rectangle cuts the rest. */
int ui_box_outline(const double eye[3], const double target[3], double fov_y_deg, int width,
                   int height, const app_fixture *f, const double offset_mm[2],
                   float segments[UI_BOX_EDGES][4]);

#endif
