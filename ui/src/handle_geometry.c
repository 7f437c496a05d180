/* Where the 3D view's move and rotate handles are and which one the pointer is on
 * (handle_geometry.h). */
#include "handle_geometry.h"

#include "view_ray.h"

#include <math.h>

#define PI 3.14159265358979323846
/* The arrows reach this far beyond the box's sides and the ring this far beyond its farthest
 * corner, so both stay clear of the outline and can be grabbed on a small fixture. */
#define ARROW_BEYOND_MM 250.0
#define RING_BEYOND_MM 120.0

void ui_handles_of(const app_fixture *f, const double position_mm[3], const double offset_mm[2],
                   ui_handles *out)
{
    double off[2] = {offset_mm ? offset_mm[0] : 0, offset_mm ? offset_mm[1] : 0};
    double a = f->angle_deg * PI / 180;
    out->axis[0][0] = cos(a);
    out->axis[0][1] = sin(a);
    out->axis[1][0] = -sin(a);
    out->axis[1][1] = cos(a);
    out->centre[0] = f->centre[0] + off[0];
    out->centre[1] = f->centre[1] + off[1];
    out->centre[2] = f->z1;
    out->reach_mm[0] = f->half[0] + ARROW_BEYOND_MM;
    out->reach_mm[1] = f->half[1] + ARROW_BEYOND_MM;
    out->pivot[0] = position_mm[0] + off[0];
    out->pivot[1] = position_mm[1] + off[1];
    out->pivot[2] = f->z0;
    /* The farthest corner of the box from the pivot: the ring clears it at every turn. */
    double far = 0;
    for (int k = 0; k < 4; k++) {
        double lx = (k & 1 ? 1 : -1) * f->half[0], ly = (k & 2 ? 1 : -1) * f->half[1];
        double x = f->centre[0] + off[0] + lx * out->axis[0][0] + ly * out->axis[1][0];
        double y = f->centre[1] + off[1] + lx * out->axis[0][1] + ly * out->axis[1][1];
        far = fmax(far, hypot(x - out->pivot[0], y - out->pivot[1]));
    }
    out->ring_mm = far + RING_BEYOND_MM;
}

void ui_handles_ring_point(const ui_handles *h, int k, double out[3])
{
    double a = 2 * PI * k / UI_HANDLE_RING_SEGMENTS;
    out[0] = h->pivot[0] + h->ring_mm * cos(a);
    out[1] = h->pivot[1] + h->ring_mm * sin(a);
    out[2] = h->pivot[2];
}

/* The distance in pixels from (sx, sy) to the projected segment p-q; INFINITY when an end is
 * behind the eye. */
static double segment_px(const double eye[3], const double target[3], double fov, int w, int h,
                         const double p[3], const double q[3], double sx, double sy)
{
    double x0, y0, x1, y1;
    if (!ui_view_project(eye, target, fov, w, h, p, &x0, &y0) ||
        !ui_view_project(eye, target, fov, w, h, q, &x1, &y1))
        return INFINITY;
    double dx = x1 - x0, dy = y1 - y0, len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((sx - x0) * dx + (sy - y0) * dy) / len2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return hypot(sx - (x0 + t * dx), sy - (y0 + t * dy));
}

ui_handle ui_handles_pick(const ui_handles *h, const double eye[3], const double target[3],
                          double fov_y_deg, int width, int height, double sx, double sy,
                          double tolerance_px)
{
    ui_handle best = UI_HANDLE_NONE;
    double best_px = tolerance_px;
    for (int k = 0; k < 2; k++) {
        double p[3], q[3];
        for (int j = 0; j < 2; j++) {
            p[j] = h->centre[j] - h->reach_mm[k] * h->axis[k][j];
            q[j] = h->centre[j] + h->reach_mm[k] * h->axis[k][j];
        }
        p[2] = q[2] = h->centre[2];
        double d = segment_px(eye, target, fov_y_deg, width, height, p, q, sx, sy);
        if (d <= best_px) {
            best_px = d;
            best = k ? UI_HANDLE_MOVE_Y : UI_HANDLE_MOVE_X;
        }
    }
    if (best != UI_HANDLE_NONE)
        return best; /* an arrow over the ring where they cross */
    for (int k = 0; k < UI_HANDLE_RING_SEGMENTS; k++) {
        double p[3], q[3];
        ui_handles_ring_point(h, k, p);
        ui_handles_ring_point(h, k + 1, q);
        if (segment_px(eye, target, fov_y_deg, width, height, p, q, sx, sy) <= tolerance_px)
            return UI_HANDLE_ROTATE;
    }
    return UI_HANDLE_NONE;
}

double ui_handles_turn(const ui_handles *h, const double from[2], const double to[2],
                       double step_deg)
{
    double a0 = atan2(from[1] - h->pivot[1], from[0] - h->pivot[0]);
    double a1 = atan2(to[1] - h->pivot[1], to[0] - h->pivot[0]);
    double deg = (a1 - a0) * 180 / PI;
    while (deg > 180)
        deg -= 360;
    while (deg <= -180)
        deg += 360;
    if (step_deg > 0)
        deg = step_deg * floor(deg / step_deg + 0.5);
    return deg == 0 ? 0 : deg; /* no -0 */
}
