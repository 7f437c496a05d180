/* Fixtures far outside the room's box: the renderer's depth range follows the room and drops
 * them, so `check` names them. */
#include "app/design/far_objects.h"
#include "app/project/project.h"
#include "placement_internal.h"

#include <math.h>
#include <stdio.h>

/* The fixture's axis-aligned box in plan: its rectangle turned by its angle. */
static void fixture_box(const app_fixture *f, double lo[3], double hi[3])
{
    double a = f->angle_deg * 3.14159265358979323846 / 180.0;
    double ex = fabs(cos(a)) * f->half[0] + fabs(sin(a)) * f->half[1];
    double ey = fabs(sin(a)) * f->half[0] + fabs(cos(a)) * f->half[1];
    lo[0] = f->centre[0] - ex;
    hi[0] = f->centre[0] + ex;
    lo[1] = f->centre[1] - ey;
    hi[1] = f->centre[1] + ey;
    lo[2] = f->z0;
    hi[2] = f->z1;
}

app_result app_far_objects_check(const app_project *p, const app_fixture *fx, int count,
                                 app_findings *out, char *err, size_t err_size)
{
    const app_room_plan *plan = &p->plan;
    double room_lo[3] = {INFINITY, INFINITY, 0.0}, room_hi[3] = {-INFINITY, -INFINITY, 0.0};
    for (int i = 0; i < plan->corner_count; i++) {
        room_lo[0] = fmin(room_lo[0], plan->corners[i].x);
        room_hi[0] = fmax(room_hi[0], plan->corners[i].x);
        room_lo[1] = fmin(room_lo[1], plan->corners[i].y);
        room_hi[1] = fmax(room_hi[1], plan->corners[i].y);
    }
    room_hi[2] = plan->height_mm;
    if (!(room_lo[0] <= room_hi[0]))
        return APP_OK; /* no plan: nothing to measure against */
    for (int i = 0; i < count; i++) {
        const app_fixture *f = &fx[i];
        double lo[3], hi[3], gap2 = 0.0;
        fixture_box(f, lo, hi);
        for (int k = 0; k < 3; k++) {
            double g = fmax(fmax(room_lo[k] - hi[k], lo[k] - room_hi[k]), 0.0);
            gap2 += g * g;
        }
        double gap = sqrt(gap2);
        if (!(gap > APP_FAR_OBJECT_LIMIT_MM))
            continue;
        const char *side = lo[2] > room_hi[2]   ? "above the ceiling"
                           : hi[2] < room_lo[2] ? "below the floor"
                                                : "beside the walls";
        app_result r = pl_add_finding(out, APP_FINDING_OUTSIDE_ROOM, APP_SEVERITY_ERROR, f->object,
                                      -1, f->centre,
                                      "%s is %.0f mm outside the room's box (%s; a unit slip?): "
                                      "renders may leave it out",
                                      f->name, gap, side);
        if (r != APP_OK) {
            snprintf(err, err_size, "out of memory for the placement findings");
            return r;
        }
    }
    return APP_OK;
}
