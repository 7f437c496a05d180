/* The elevation view's geometry (wall elevation for tiling): a room surface
 * unfolded flat and seen from the room, as the print set's elevations show it
 * (app/src/output/print_elevation.c): a wall seen from inside has its s coordinate growing to the
 * left. Pure math over app's surface frames, layouts and fixtures, tested without a window
 * (tests/ui/test_elevation_view.c); drawing is in elevation_draw.c. Screen y grows downwards,
 * the surface's t (height on a wall) upwards. */
#ifndef UI_ELEVATION_VIEW_H
#define UI_ELEVATION_VIEW_H

#include "app/design/placement.h"
#include "app/design/room_surfaces.h"
#include "app/design/tile_layout.h"

typedef struct ui_elev_transform {
    double centre[2]; /* the surface point (s, t) at the drawing area's centre */
    double px_per_mm;
    int mirror;           /* 1: s grows to the left on the screen */
    float x0, y0, x1, y1; /* the drawing area, window pixels */
} ui_elev_transform;

/* 1 when the surface, seen from the room (looking along -normal with t up), shows its s axis
 * growing to the left: walls and pre-wall fronts (s runs along the wall from its start corner,
 * which is on the viewer's right), the ceiling seen from below. 0 for the floor seen from
 * above (plan x to the right). */
int ui_elev_mirrored(const app_surface_frame *f);

/* The box s0..s1 x t0..t1 (any order) centred in the area with margin_px around it, the same
 * scale on both axes. A degenerate box or area gives a 0.1 px/mm transform. */
ui_elev_transform ui_elev_fit(double s0, double t0, double s1, double t1, int mirror, float x0,
                              float y0, float x1, float y1, float margin_px);
void ui_elev_to_screen(const ui_elev_transform *v, double s, double t, float *sx, float *sy);
void ui_elev_to_surface(const ui_elev_transform *v, float sx, float sy, double *s, double *t);

/* The bounding box of a polygon: lo = (min s, min t), hi = (max s, max t); 0 when empty. */
int ui_elev_bounds(const app_point2 *pts, int count, app_point2 *lo, app_point2 *hi);

/* A fixture's silhouette on the surface: its box (plan footprint x z0..z1) projected onto the
 * surface's (s, t) plane, as a convex polygon (<= 8 points, counter-clockwise in (s, t)).
 * Returns the point count, 0 when the fixture does not stand at the surface: its nearest
 * point must be between -50 and max_depth_mm in front of it (on a floor: its bottom at most
 * that high, so a ceiling lamp or a wall-hung mirror is not drawn on the floor). *depth gets
 * that nearest distance. */
int ui_elev_fixture_outline(const app_surface_frame *f, const app_fixture *fx, double max_depth_mm,
                            app_point2 out[8], double *depth);

/* A convex polygon (n <= 8 points) clipped to the box lo..hi (Sutherland-Hodgman), so a
 * silhouette reaching past the surface is drawn only over it. Returns the point count of out
 * (<= n + 4; 0 when nothing is left). */
int ui_elev_clip_box(const app_point2 *in, int n, app_point2 lo, app_point2 hi, app_point2 out[12]);

/* A convex polygon of n points split into a fan of quads for a quad-filling drawer: quad k
 * is points (0, 2k + 1, 2k + 2, 2k + 3) with the last index clamped to n - 1 (a triangle
 * repeats its last point). Returns the number of quads (0 when n < 3), at most cap. */
int ui_elev_fan_quads(int n, int quads[][4], int cap);

/* Whole and cut tiles of a layout. */
void ui_elev_count_tiles(const app_tile_layout *l, int *whole, int *cut);

/* The wall number of "wall:I", else -1. */
int ui_elev_wall_index(const char *surface);

/* A clicked surface point made into a tiling start point: rounded to grid_mm (0 = as is). */
void ui_elev_snap_point(double s, double t, double grid_mm, double *out_s, double *out_t);

#endif
