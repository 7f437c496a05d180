/* Drag and drop from the catalog browser into a view (ui/src/drag_drop.h). A drop places the
 * browser's selected product through planner_place_selected, so it snaps to the nearest wall
 * exactly as the Place button and the plan's own placing do, as one undo step. Scripts drop
 * through planner_drop_selected too (drop-selected VIEW SX SY). */
#include "drag_drop.h"

#include "gui.h"
#include "planner.h"
#include "thumbnails.h"
#include "view_ray.h"

#include <GLFW/glfw3.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

int ui_floor_point(const double eye[3], const double target[3], double fov_y_deg, int width,
                   int height, double sx, double sy, double out_mm[2])
{
    double d[3];
    if (!ui_view_ray(eye, target, fov_y_deg, width, height, sx, sy, d) || !(d[2] < -1e-9) ||
        !(eye[2] > 0))
        return 0;
    return ui_ray_plane_z(eye, d, 0.0, out_mm);
}

int planner_drop_selected(planner *p, int view, double sx, double sy)
{
    double x, y;
    if (view == UI_VIEW_PLAN) {
        if (!p->plan_fitted) {
            planner_status(p, "drop: the plan view has not been shown yet");
            return 1;
        }
        ui_plan_to_plan(&p->plan_t, (float)sx, (float)sy, &x, &y);
    } else {
        /* Window pixels to the 3D view's pane. */
        ui_rect r = planner_view_rect(p);
        int w = (int)r.w, h = (int)r.h;
        sx -= r.x;
        sy -= r.y;
        rd_view v;
        planner_view(p, w, h, &v);
        double eye[3], target[3], pt[2];
        for (int k = 0; k < 3; k++) {
            eye[k] = v.eye[k] * 1e3;
            target[k] = v.target[k] * 1e3;
        }
        if (!ui_floor_point(eye, target, v.fov_y_deg, w, h, sx, sy, pt)) {
            planner_status(p, "drop: no floor under the pointer at %.0f, %.0f", sx, sy);
            return 1;
        }
        x = pt[0];
        y = pt[1];
    }
    return planner_place_selected(p, x, y);
}

void planner_drag_ghost(planner *p, int hit, double x, double y)
{
    ui_drag_drop *d = &p->drop;
    d->active = 1;
    d->hit = hit;
    d->x = x;
    d->y = y;
    const char *name = p->browser.selected >= 0 ? p->browser.product.name : "";
    snprintf(d->label, sizeof d->label, "%s\nrelease over the %s to place", name,
             p->view == UI_VIEW_PLAN ? "plan" : "3D view");
}

void planner_drag_drop_frame(planner *p)
{
    ui_drag_drop *d = &p->drop;
    if (planner_input_live(p)) {
        double mx, my;
        ui_gui_pointer(&mx, &my);
        int down = ui_gui_mouse_down(GLFW_MOUSE_BUTTON_LEFT);
        if (!d->active && p->browser.drag_hit >= 0 && down) {
            if (p->browser.drag_hit != p->browser.selected)
                ui_catalog_browser_select(&p->browser, p->browser.drag_hit);
            if (p->browser.selected >= 0)
                planner_drag_ghost(p, p->browser.selected, mx, my);
        } else if (d->active && down) {
            d->x = mx;
            d->y = my;
        } else if (d->active) {
            /* Released: over a panel nothing happens, over a view the product is placed. */
            d->active = 0;
            if (ui_gui_pointer_over_panel())
                planner_status(p, "dropped on a panel: nothing placed");
            else if (ui_rect_contains(p->layout.pane_2d, mx, my) && p->view_2d == UI_VIEW_PLAN)
                planner_drop_selected(p, UI_VIEW_PLAN, mx, my);
            else if (ui_rect_contains(p->layout.pane_3d, mx, my))
                planner_drop_selected(p, UI_VIEW_3D, mx, my);
            else
                planner_status(p, "dropped outside the plan and the 3D view: nothing placed");
        }
    }
    if (d->active) {
        unsigned tex = 0;
        if (d->hit >= 0 && d->hit < p->browser.hit_count)
            tex = ui_thumbnails_get(p->browser.thumbs, p->browser.hits[d->hit].product_id, 0);
        ui_gui_draw_ghost((float)d->x, (float)d->y, tex, 48.0f, d->label);
    }
}
