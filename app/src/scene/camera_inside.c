/* A camera standing exactly on a wall, the floor or the ceiling looks along that surface: half
 * of what it sees lies outside the room (the rasteriser shows the clear colour there, the
 * tracer grazes the surface), and the near plane cuts away the surfaces it stands on. Standing
 * a few centimetres inside the room shows the same view without either. */
#include "scene_build_internal.h"

#include <math.h>

void app_camera_keep_inside(const app_project *p, double eye_mm[3])
{
    const app_room_plan *plan = &p->plan;
    /* Two passes: at a corner, moving off one wall must not leave the eye on the other. */
    for (int pass = 0; pass < 2; pass++)
        for (int i = 0; i < plan->corner_count; i++) {
            app_point2 a = plan->corners[i], b = plan->corners[(i + 1) % plan->corner_count];
            double dx = b.x - a.x, dy = b.y - a.y, len = hypot(dx, dy);
            if (!(len > 0.0))
                continue;
            double u = ((eye_mm[0] - a.x) * dx + (eye_mm[1] - a.y) * dy) / (len * len);
            if (u < 0.0 || u > 1.0)
                continue; /* beside the wall's line, not on the wall */
            /* Counter-clockwise corners: the room lies to the left of a -> b. */
            double nx = -dy / len, ny = dx / len;
            double inside = (eye_mm[0] - a.x) * nx + (eye_mm[1] - a.y) * ny;
            if (fabs(inside) < APP_CAMERA_WALL_CLEARANCE_MM) {
                eye_mm[0] += (APP_CAMERA_WALL_CLEARANCE_MM - inside) * nx;
                eye_mm[1] += (APP_CAMERA_WALL_CLEARANCE_MM - inside) * ny;
            }
        }
    double h = plan->height_mm;
    if (fabs(eye_mm[2]) < APP_CAMERA_WALL_CLEARANCE_MM)
        eye_mm[2] = APP_CAMERA_WALL_CLEARANCE_MM;
    else if (h > 2.0 * APP_CAMERA_WALL_CLEARANCE_MM &&
             fabs(eye_mm[2] - h) < APP_CAMERA_WALL_CLEARANCE_MM)
        eye_mm[2] = h - APP_CAMERA_WALL_CLEARANCE_MM;
}
