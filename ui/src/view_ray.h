/* Rays through the 3D view's pixels and what they hit: the floor, a horizontal plane, a
 * fixture's box. Pure geometry (no window), shared by the catalog's drop (drag_drop.c) and the
 * 3D fixture drag (fixture_drag.c), and tested without a window (tests/ui/test_fixture_drag.c).
 * Millimetres, z up, window y down. */
#ifndef UI_VIEW_RAY_H
#define UI_VIEW_RAY_H

#include "app/design/placement.h"

/* The direction (not unit) of the ray from eye through window pixel (sx, sy) for a perspective
 * camera looking at target with a vertical field of view fov_y_deg over width x height, the
 * renderer's projection (RENDERING.md section 2). Returns 0 for degenerate input. */
int ui_view_ray(const double eye[3], const double target[3], double fov_y_deg, int width,
                int height, double sx, double sy, double dir[3]);

/* The window pixel (sx, sy) where world point pt (mm) shows, the inverse of ui_view_ray:
 * 0 when it lies behind the eye. */
int ui_view_project(const double eye[3], const double target[3], double fov_y_deg, int width,
                    int height, const double pt[3], double *sx, double *sy);

/* Where the ray o + t d (t > 0) meets the plane z = height: 1 and out[2], or 0. */
int ui_ray_plane_z(const double o[3], const double d[3], double height, double out[2]);

/* The ray parameter t > 0 where o + t d enters fixture f's box (its plan rectangle turned by
 * angle_deg about its centre, from z0 to z1), or -1 when it misses. */
double ui_ray_fixture(const double o[3], const double d[3], const app_fixture *f);

/* The fixture nearest along the ray, or -1. */
int ui_pick_fixture(const double o[3], const double d[3], const app_fixture *fixtures, int count);

#endif
