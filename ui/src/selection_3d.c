/* The selection outlined in the 3D view, as the plan outlines it (plan_draw.c): the selected
 * fixture's box and the boxes of the fixtures mounted on it (its group, app_group_members)
 * projected with the view's camera and drawn as lines in the plan's selection colour on the
 * background list over the 3D pane. It is drawn over whatever the pane shows (a moving frame,
 * the accumulating or refined still) and never enters a render: renders written to files
 * (render-image, print-pdf) come from the scene alone. */
#include "planner.h"

#include "app/project/commands.h"
#include "box_outline.h"
#include "gui.h"

#include <stdlib.h>

/* The plan's selection outline (plan_draw.c: 220, 110, 0) as Dear ImGui's 0xAABBGGRR, over a
 * dark halo so it shows on white sanitaryware and on dark tiles alike. */
#define SELECTION_COLOUR 0xff006edcu
#define HALO_COLOUR 0xa0000000u
#define SELECTED_PX 2.5f
#define MEMBER_PX 1.5f
#define HALO_PX 2.0f

static const app_fixture *fixture_of(const planner *p, int object)
{
    for (int i = 0; i < p->fixture_count; i++)
        if (p->fixtures[i].object == object)
            return &p->fixtures[i];
    return NULL;
}

/* Where a fixture's box shows now: a 3D drag moves its group's objects in the scene live
 * (fixture_drag.h) while the footprints stay where the drag began. */
static void drag_offset(const planner *p, int object, double offset[2])
{
    offset[0] = offset[1] = 0;
    const ui_fixture_drag *d = &p->fixture_drag;
    if (!d->active)
        return;
    for (int k = 0; k < d->object_count; k++)
        if (d->objects[k] == object) {
            offset[0] = d->centre[0] - d->start_centre[0];
            offset[1] = d->centre[1] - d->start_centre[1];
            return;
        }
}

/* Draws (draw = 1) or measures one fixture's outline; grows bounds (window pixels x0 y0 x1
 * y1) by its segments. Returns how many segments it has. */
static int outline_fixture(const planner *p, const rd_view *v, ui_rect r, int object,
                           float thickness, int draw, float bounds[4])
{
    const app_fixture *f = fixture_of(p, object);
    if (!f)
        return 0;
    double eye[3], target[3], offset[2];
    for (int k = 0; k < 3; k++) {
        eye[k] = v->eye[k] * 1e3;
        target[k] = v->target[k] * 1e3;
    }
    drag_offset(p, object, offset);
    float s[UI_BOX_EDGES][4];
    int n = ui_box_outline(eye, target, v->fov_y_deg, (int)r.w, (int)r.h, f, offset, s);
    for (int pass = 0; draw && pass < 2; pass++)
        for (int e = 0; e < n; e++)
            ui_gui_draw_line(r.x + s[e][0], r.y + s[e][1], r.x + s[e][2], r.y + s[e][3],
                             pass ? SELECTION_COLOUR : HALO_COLOUR,
                             pass ? thickness : thickness + HALO_PX);
    for (int e = 0; e < n; e++)
        for (int c = 0; c < 2; c++) {
            float x = r.x + s[e][2 * c], y = r.y + s[e][2 * c + 1];
            bounds[0] = x < bounds[0] ? x : bounds[0];
            bounds[1] = y < bounds[1] ? y : bounds[1];
            bounds[2] = x > bounds[2] ? x : bounds[2];
            bounds[3] = y > bounds[3] ? y : bounds[3];
        }
    return n;
}

/* The selection's outline, drawn or measured; 0 when nothing of it shows in the pane. */
static int selection_outline(const planner *p, int draw, float bounds[4])
{
    ui_rect r = planner_view_rect(p);
    int sel = p->plan_o.selected_object;
    bounds[0] = bounds[1] = 1e9f;
    bounds[2] = bounds[3] = -1e9f;
    if (sel < 0 || sel >= p->project.object_count || r.w <= 0 || r.h <= 0 || !p->fixtures)
        return 0;
    rd_view v;
    planner_view(p, (int)r.w, (int)r.h, &v);
    if (draw)
        ui_gui_clip_push(r.x, r.y, r.x + r.w, r.y + r.h);
    int n = outline_fixture(p, &v, r, sel, SELECTED_PX, draw, bounds);
    int *members = malloc(sizeof *members * (size_t)p->project.object_count);
    int count = members ? app_group_members(&p->project, sel, members) : 0;
    for (int k = 0; k < count; k++)
        if (members[k] != sel)
            n += outline_fixture(p, &v, r, members[k], MEMBER_PX, draw, bounds);
    free(members);
    if (draw)
        ui_gui_clip_pop();
    /* Only the part inside the pane counts. */
    bounds[0] = bounds[0] < r.x ? r.x : bounds[0];
    bounds[1] = bounds[1] < r.y ? r.y : bounds[1];
    bounds[2] = bounds[2] > r.x + r.w ? r.x + r.w : bounds[2];
    bounds[3] = bounds[3] > r.y + r.h ? r.y + r.h : bounds[3];
    return n > 0 && bounds[0] < bounds[2] && bounds[1] < bounds[3];
}

void planner_selection_3d(planner *p)
{
    float bounds[4];
    selection_outline(p, 1, bounds);
}

int planner_selection_3d_bounds(const planner *p, float bounds[4])
{
    return selection_outline(p, 0, bounds);
}
