/* The placement findings shown live in the 3D view as well as on the plan:
 * each finding's plan point, at the height of the fixture it is about (else 1 m), projected
 * with the view's camera and marked with a ring and its kind in the plan's colours (red for
 * an error, orange for a warning); the full message is in the Edit panel's list. */
#include "planner.h"

#include "gui.h"
#include "view_ray.h"

#include <stdio.h>

static double finding_height(const planner *p, const app_finding *f)
{
    for (int i = 0; i < p->fixture_count; i++)
        if (f->objects[0] >= 0 && p->fixtures[i].object == f->objects[0])
            return 0.5 * (p->fixtures[i].z0 + p->fixtures[i].z1);
    return 1000.0;
}

void planner_findings_3d(planner *p, int window_width, int window_height)
{
    (void)window_width;
    (void)window_height;
    /* Projected into the 3D view's pane, drawn there only. */
    ui_rect r = planner_view_rect(p);
    int width = (int)r.w, height = (int)r.h;
    if (!p->findings.count || width <= 0 || height <= 0)
        return;
    rd_view v;
    planner_view(p, width, height, &v);
    double eye[3], target[3];
    for (int k = 0; k < 3; k++) {
        eye[k] = v.eye[k] * 1e3;
        target[k] = v.target[k] * 1e3;
    }
    ui_gui_clip_push(r.x, r.y, r.x + r.w, r.y + r.h);
    for (int i = 0; i < p->findings.count; i++) {
        const app_finding *f = &p->findings.items[i];
        double pt[3] = {f->position_mm[0], f->position_mm[1], finding_height(p, f)}, sx, sy;
        if (!ui_view_project(eye, target, v.fov_y_deg, width, height, pt, &sx, &sy) || sx < 0 ||
            sy < 0 || sx > width || sy > height)
            continue;
        sx += r.x;
        sy += r.y;
        /* The plan's colours (plan_draw.c), as ImGui's ABGR. */
        unsigned colour = f->severity == APP_SEVERITY_ERROR     ? 0xff1e1ed7u
                          : f->severity == APP_SEVERITY_WARNING ? 0xff0096ebu
                                                                : 0xffdc783cu;
        ui_gui_draw_circle((float)sx, (float)sy, 9.0f, colour, 0);
        ui_gui_draw_circle((float)sx, (float)sy, 3.0f, colour, 1);
        ui_gui_draw_text((float)sx + 12.0f, (float)sy - 7.0f, colour,
                         app_finding_kind_name(f->kind));
    }
    ui_gui_clip_pop();
}
