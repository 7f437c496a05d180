/* The snap guides and distance labels of a fixture dragged in the 3D view (by the fixture
 * itself or by a move arrow): the same preview as the plan's drag (app/design/snap_guides.h)
 * for where the release's move edit will put it, drawn at the fixture's foot over the pane
 * (never in a render): the wall face and the corner or neighbour line dashed, the left, right
 * and front clear distances as lines with their length in mm. */
#include "planner.h"

#include "gui.h"
#include "view_ray.h"

#include <math.h>
#include <stdio.h>

#define GRID_MM 10.0 /* the plan drag's grid (planner_plan.c) */

typedef struct pane_view {
    ui_rect r;
    double eye[3], target[3], fov;
} pane_view;

static int project(const pane_view *v, double x, double y, double z, float out[2])
{
    double pt[3] = {x, y, z}, sx, sy;
    if (!ui_view_project(v->eye, v->target, v->fov, (int)v->r.w, (int)v->r.h, pt, &sx, &sy))
        return 0;
    out[0] = v->r.x + (float)sx;
    out[1] = v->r.y + (float)sy;
    return 1;
}

static void line(const pane_view *v, const double a[2], const double b[2], double z, int dash)
{
    float s0[2], s1[2];
    if (!project(v, a[0], a[1], z, s0) || !project(v, b[0], b[1], z, s1))
        return;
    float len = hypotf(s1[0] - s0[0], s1[1] - s0[1]), step = dash ? 13.0f : len;
    for (float d = 0; d < len; d += step) {
        float e = dash ? fminf(d + 8, len) : len, u0 = d / len, u1 = e / len;
        ui_gui_draw_line(s0[0] + u0 * (s1[0] - s0[0]), s0[1] + u0 * (s1[1] - s0[1]),
                         s0[0] + u1 * (s1[0] - s0[0]), s0[1] + u1 * (s1[1] - s0[1]),
                         UI_PLAN_GUIDE_COLOUR, 2.0f);
    }
}

void planner_snap_guides_3d(planner *p)
{
    const ui_fixture_drag *d = &p->fixture_drag;
    if (!d->active || p->presenting)
        return;
    int k = 0;
    while (k < p->fixture_count && p->fixtures[k].object != d->object)
        k++;
    pane_view v;
    v.r = planner_view_rect(p);
    if (k == p->fixture_count || v.r.w <= 0 || v.r.h <= 0)
        return;
    rd_view rv;
    planner_view(p, (int)v.r.w, (int)v.r.h, &rv);
    for (int j = 0; j < 3; j++) {
        v.eye[j] = rv.eye[j] * 1e3;
        v.target[j] = rv.target[j] * 1e3;
    }
    v.fov = rv.fov_y_deg;
    int own = 0; /* the dragged object among those the drag moves */
    while (own < d->object_count && d->objects[own] != d->object)
        own++;
    if (own == d->object_count)
        return;
    const double *start = d->start[own];
    /* The pose the release asks for (planner_drag_object): where the drag began, moved. */
    const app_fixture *f = &p->fixtures[k];
    double dx = d->centre[0] - d->start_centre[0], dy = d->centre[1] - d->start_centre[1];
    app_pose in = {ui_plan_snap_grid(start[0] + dx, GRID_MM),
                   ui_plan_snap_grid(start[1] + dy, GRID_MM), start[2],
                   p->project.objects[d->object].rotation_deg[2]};
    /* The document holds the live position: the preview measures from where it began. */
    app_project *pr = &p->project;
    double live[3];
    for (int j = 0; j < 3; j++) {
        live[j] = pr->objects[d->object].position_mm[j];
        pr->objects[d->object].position_mm[j] = start[j];
    }
    app_snap_preview s;
    app_snap_preview_of(pr, p->fixtures, p->fixture_count, k, in, &s);
    for (int j = 0; j < 3; j++)
        pr->objects[d->object].position_mm[j] = live[j];

    double z = f->z0;
    ui_gui_clip_push(v.r.x, v.r.y, v.r.x + v.r.w, v.r.y + v.r.h);
    for (int g = 0; g < s.guide_count; g++)
        line(&v, s.guides[g].a, s.guides[g].b, z, 1);
    for (int i = 0; i < APP_SNAP_SIDES; i++) {
        const app_snap_dimension *m = &s.sides[i];
        float mid[2];
        if (!m->found)
            continue;
        line(&v, m->a, m->b, z, 0);
        if (!project(&v, 0.5 * (m->a[0] + m->b[0]), 0.5 * (m->a[1] + m->b[1]), z, mid))
            continue;
        char label[32];
        snprintf(label, sizeof label, "%.0f", m->mm);
        float w = ui_gui_text_width(label);
        float bg[8] = {mid[0] - w / 2 - 3, mid[1] - 9, mid[0] + w / 2 + 3, mid[1] - 9,
                       mid[0] + w / 2 + 3, mid[1] + 9, mid[0] - w / 2 - 3, mid[1] + 9};
        ui_gui_draw_quad_filled(bg, 0xebffffffu);
        ui_gui_draw_text(mid[0] - w / 2, mid[1] - 7, UI_PLAN_GUIDE_COLOUR, label);
    }
    ui_gui_clip_pop();
}
