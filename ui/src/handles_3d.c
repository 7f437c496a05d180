/* The selected fixture's move and rotate handles over the 3D view (handle_geometry.h): drawn
 * on the background list over the pane, like the selection's outline, so no render written to
 * a file has them. An arrow dragged moves the fixture and its group along that axis live in
 * the renderer (fixture_drag.h) and commits one snapped move edit on release, as a drag in
 * the plan does; the ring dragged turns a ghost of the box by whole 15-degree steps about the
 * object's position and commits one `rotate` edit on release (the R key's and the menu's
 * 90-degree turn is the same edit). Each is one undo step and the checks run after it. */
#include "planner.h"

#include "gui.h"
#include "handle_geometry.h"
#include "box_outline.h"
#include "view_ray.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* Red and green for the arrows (a 3D tool's x and y), blue for the ring; the one under the
 * pointer or held in yellow; the turning ghost in the plan's guide colour. */
#define ARROW_X_COLOUR 0xff3c3cdcu
#define ARROW_Y_COLOUR 0xff3cb43cu
#define RING_COLOUR 0xffdc8c28u
#define HOT_COLOUR 0xff00d2ffu
#define HALO_COLOUR 0xa0000000u
#define HANDLE_PX 3.0f
#define PICK_PX 7.0

static const char *const handle_names[3] = {"move-x", "move-y", "rotate"};

static const app_fixture *fixture_of(const planner *p, int object)
{
    for (int i = 0; i < p->fixture_count; i++)
        if (p->fixtures[i].object == object)
            return &p->fixtures[i];
    return NULL;
}

/* The pane's camera, mm. */
typedef struct pane_view {
    ui_rect r;
    double eye[3], target[3], fov;
} pane_view;

static int pane_view_of(const planner *p, pane_view *v)
{
    v->r = planner_view_rect(p);
    if (v->r.w <= 0 || v->r.h <= 0)
        return 0;
    rd_view rv;
    planner_view(p, (int)v->r.w, (int)v->r.h, &rv);
    for (int k = 0; k < 3; k++) {
        v->eye[k] = rv.eye[k] * 1e3;
        v->target[k] = rv.target[k] * 1e3;
    }
    v->fov = rv.fov_y_deg;
    return 1;
}

static int project(const pane_view *v, const double pt[3], float *x, float *y)
{
    double sx, sy;
    if (!ui_view_project(v->eye, v->target, v->fov, (int)v->r.w, (int)v->r.h, pt, &sx, &sy))
        return 0;
    *x = v->r.x + (float)sx;
    *y = v->r.y + (float)sy;
    return 1;
}

/* Where the pointer's ray meets the plane z = height, plan mm. */
static int inside_pane(const pane_view *v, float x, float y)
{
    return x >= v->r.x && y >= v->r.y && x < v->r.x + v->r.w && y < v->r.y + v->r.h;
}

static int pointer_on_plane(const pane_view *v, double sx, double sy, double height, double q[2])
{
    double dir[3];
    return ui_view_ray(v->eye, v->target, v->fov, (int)v->r.w, (int)v->r.h, sx - v->r.x,
                       sy - v->r.y, dir) &&
           ui_ray_plane_z(v->eye, dir, height, q);
}

/* The selection's handles now, moved with a live arrow drag; 0 when none show. */
static int current_handles(const planner *p, ui_handles *h, const app_fixture **f_out)
{
    int sel = p->plan_o.selected_object;
    const app_fixture *f = sel >= 0 && sel < p->project.object_count ? fixture_of(p, sel) : NULL;
    if (!f || p->mode != UI_MODE_ORBIT || p->presenting || !p->scene_ready)
        return 0;
    const ui_fixture_drag *d = &p->fixture_drag;
    double off[2] = {0, 0};
    if (d->active && d->object == sel) {
        off[0] = d->centre[0] - d->start_centre[0];
        off[1] = d->centre[1] - d->start_centre[1];
    }
    /* The document position moves with a live drag; the handles' pivot is where it began. */
    double at[3];
    memcpy(at, p->project.objects[sel].position_mm, sizeof at);
    at[0] -= off[0];
    at[1] -= off[1];
    ui_handles_of(f, at, off, h);
    *f_out = f;
    return 1;
}

static void line3(const pane_view *v, const double a[3], const double b[3], unsigned colour,
                  float px)
{
    float x0, y0, x1, y1;
    if (!project(v, a, &x0, &y0) || !project(v, b, &x1, &y1))
        return;
    ui_gui_draw_line(x0, y0, x1, y1, HALO_COLOUR, px + 2);
    ui_gui_draw_line(x0, y0, x1, y1, colour, px);
}

static void draw_arrow(const pane_view *v, const ui_handles *h, int k, unsigned colour)
{
    double p[3], q[3];
    for (int j = 0; j < 2; j++) {
        p[j] = h->centre[j] - h->reach_mm[k] * h->axis[k][j];
        q[j] = h->centre[j] + h->reach_mm[k] * h->axis[k][j];
    }
    p[2] = q[2] = h->centre[2];
    line3(v, p, q, colour, HANDLE_PX);
    /* A head at each end: two barbs 80 mm back and 45 mm aside. */
    const double *ax = h->axis[k], *side = h->axis[1 - k];
    for (int end = -1; end <= 1; end += 2) {
        const double *tip = end > 0 ? q : p;
        for (int s = -1; s <= 1; s += 2) {
            double b[3] = {tip[0] - end * 80 * ax[0] + s * 45 * side[0],
                           tip[1] - end * 80 * ax[1] + s * 45 * side[1], tip[2]};
            line3(v, tip, b, colour, HANDLE_PX);
        }
    }
}

/* The ring drag's ghost: the box turned by the drag's angle about the pivot, and the angle
 * written beside the ring. */
static void draw_turn(const pane_view *v, const ui_handles *h, const app_fixture *f,
                      double turn_deg)
{
    app_fixture g = *f;
    double a = turn_deg * 3.14159265358979323846 / 180, c = cos(a), s = sin(a);
    double rx = f->centre[0] - h->pivot[0], ry = f->centre[1] - h->pivot[1];
    g.centre[0] = h->pivot[0] + rx * c - ry * s;
    g.centre[1] = h->pivot[1] + rx * s + ry * c;
    g.angle_deg = f->angle_deg + turn_deg;
    float seg[UI_BOX_EDGES][4];
    int n = ui_box_outline(v->eye, v->target, v->fov, (int)v->r.w, (int)v->r.h, &g, NULL, seg);
    for (int e = 0; e < n; e++)
        ui_gui_draw_line(v->r.x + seg[e][0], v->r.y + seg[e][1], v->r.x + seg[e][2],
                         v->r.y + seg[e][3], UI_PLAN_GUIDE_COLOUR, 2.0f);
    double at[3];
    ui_handles_ring_point(h, 0, at);
    float x, y;
    if (project(v, at, &x, &y)) {
        char label[32];
        snprintf(label, sizeof label, "%+.0f deg", turn_deg);
        float w = ui_gui_text_width(label);
        float bg[8] = {x + 3, y - 20, x + w + 9, y - 20, x + w + 9, y - 2, x + 3, y - 2};
        ui_gui_draw_quad_filled(bg, 0xebffffffu); /* white, as the plan's labels */
        ui_gui_draw_text(x + 6, y - 18, UI_PLAN_GUIDE_COLOUR, label);
    }
}

void planner_handles_3d(planner *p)
{
    ui_handles h;
    const app_fixture *f;
    pane_view v;
    if (!current_handles(p, &h, &f) || !pane_view_of(p, &v))
        return;
    int held = p->handle_drag.active ? p->handle_drag.kind : UI_HANDLE_NONE;
    int hot = held;
    if (hot == UI_HANDLE_NONE && !p->dragging && !ui_gui_wants_mouse()) {
        double mx, my;
        ui_gui_pointer(&mx, &my);
        hot = ui_handles_pick(&h, v.eye, v.target, v.fov, (int)v.r.w, (int)v.r.h, mx - v.r.x,
                              my - v.r.y, PICK_PX);
    }
    ui_gui_clip_push(v.r.x, v.r.y, v.r.x + v.r.w, v.r.y + v.r.h);
    for (int k = 0; k < UI_HANDLE_RING_SEGMENTS; k++) {
        double a[3], b[3];
        ui_handles_ring_point(&h, k, a);
        ui_handles_ring_point(&h, k + 1, b);
        line3(&v, a, b, hot == UI_HANDLE_ROTATE ? HOT_COLOUR : RING_COLOUR, HANDLE_PX);
    }
    draw_arrow(&v, &h, 0, hot == UI_HANDLE_MOVE_X ? HOT_COLOUR : ARROW_X_COLOUR);
    draw_arrow(&v, &h, 1, hot == UI_HANDLE_MOVE_Y ? HOT_COLOUR : ARROW_Y_COLOUR);
    if (held == UI_HANDLE_ROTATE)
        draw_turn(&v, &h, f, p->handle_drag.turn_deg);
    ui_gui_clip_pop();
}

int planner_handles_press(planner *p, double sx, double sy)
{
    ui_handles h;
    const app_fixture *f;
    pane_view v;
    if (!current_handles(p, &h, &f) || !pane_view_of(p, &v))
        return 0;
    int kind = ui_handles_pick(&h, v.eye, v.target, v.fov, (int)v.r.w, (int)v.r.h, sx - v.r.x,
                               sy - v.r.y, PICK_PX);
    if (kind == UI_HANDLE_NONE)
        return 0;
    double plane_z = kind == UI_HANDLE_ROTATE ? h.pivot[2] : h.centre[2], q[2];
    if (!pointer_on_plane(&v, sx, sy, plane_z, q))
        return 0; /* grabbed above the plane's horizon: nothing to follow */
    if (kind != UI_HANDLE_ROTATE) {
        double grab[3] = {q[0], q[1], plane_z};
        if (planner_fixture_drag_begin(p, f->object, grab) != 0)
            return 0;
    }
    p->handle_drag.active = 1;
    p->handle_drag.kind = kind;
    p->handle_drag.plane_z = plane_z;
    p->handle_drag.grab[0] = q[0];
    p->handle_drag.grab[1] = q[1];
    p->handle_drag.turn_deg = 0;
    return 1;
}

void planner_handles_pointer(planner *p, double sx, double sy)
{
    int kind = p->handle_drag.kind;
    ui_handles h;
    const app_fixture *f;
    pane_view v;
    double q[2];
    if (!p->handle_drag.active || !current_handles(p, &h, &f) || !pane_view_of(p, &v) ||
        !pointer_on_plane(&v, sx, sy, p->handle_drag.plane_z, q))
        return;
    if (kind == UI_HANDLE_ROTATE) {
        p->handle_drag.turn_deg =
            ui_handles_turn(&h, p->handle_drag.grab, q, UI_HANDLE_ROTATE_STEP_DEG);
        return;
    }
    /* Along the arrow only: the pointer's move projected on its axis. */
    const ui_fixture_drag *d = &p->fixture_drag;
    const double *ax = h.axis[kind == UI_HANDLE_MOVE_Y];
    double along =
        (q[0] - p->handle_drag.grab[0]) * ax[0] + (q[1] - p->handle_drag.grab[1]) * ax[1];
    planner_fixture_drag_to(p, d->start_centre[0] + along * ax[0],
                            d->start_centre[1] + along * ax[1]);
}

int planner_handles_dragging(const planner *p)
{
    return p->handle_drag.active;
}

void planner_handles_release(planner *p)
{
    int kind = p->handle_drag.kind;
    if (!p->handle_drag.active)
        return;
    p->handle_drag.active = 0;
    if (kind != UI_HANDLE_ROTATE) {
        planner_fixture_drag_end(p, 1);
        return;
    }
    int sel = p->plan_o.selected_object;
    double turn = p->handle_drag.turn_deg;
    if (turn == 0 || sel < 0 || sel >= p->project.object_count)
        return;
    const app_object *o = &p->project.objects[sel];
    double deg = fmod(o->rotation_deg[2] + turn, 360);
    char line[256];
    snprintf(line, sizeof line, "rotate \"%s\" %.0f", o->name, deg < 0 ? deg + 360 : deg);
    planner_edit(p, line);
}

int planner_handles_locate(planner *p, const char *name)
{
    int kind = 0;
    while (kind < 3 && strcmp(handle_names[kind], name))
        kind++;
    ui_handles h;
    const app_fixture *f;
    pane_view v;
    if (kind == 3) {
        snprintf(p->status, sizeof p->status, "locate handle move-x, move-y or rotate");
        return 1;
    }
    if (!current_handles(p, &h, &f) || !pane_view_of(p, &v)) {
        snprintf(p->status, sizeof p->status, "no handles show: pick a fixture in the 3D view");
        return 1;
    }
    /* A point to grab and where it goes: near an arrow's + head and 500 mm further along it;
     * on the ring in front of the fixture and 52 degrees round it (a 45-degree turn once
     * snapped to whole steps). */
    double from[3], to[3];
    float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    int shown = 0;
    if (kind == UI_HANDLE_ROTATE) {
        /* The front of the ring first; where that lies outside the pane (a fixture near the
         * camera), the first of its sides and back that does, both ends of the drag. */
        static const double starts_deg[] = {0, -90, 90, 180, -45, 45, -135, 135};
        const double deg = 3.14159265358979323846 / 180;
        for (size_t s = 0; s < sizeof starts_deg / sizeof starts_deg[0] && !shown; s++) {
            double a0 = atan2(h.axis[1][1], h.axis[1][0]) + starts_deg[s] * deg, a1 = a0 + 52 * deg;
            for (int k = 0; k < 2; k++) {
                from[k] = h.pivot[k] + h.ring_mm * (k ? sin(a0) : cos(a0));
                to[k] = h.pivot[k] + h.ring_mm * (k ? sin(a1) : cos(a1));
            }
            from[2] = to[2] = h.pivot[2];
            shown = project(&v, from, &x0, &y0) && project(&v, to, &x1, &y1) &&
                    inside_pane(&v, x0, y0) && inside_pane(&v, x1, y1);
        }
    } else {
        int k = kind == UI_HANDLE_MOVE_Y;
        for (int j = 0; j < 2; j++) {
            from[j] = h.centre[j] + 0.7 * h.reach_mm[k] * h.axis[k][j];
            to[j] = from[j] + 500 * h.axis[k][j];
        }
        from[2] = to[2] = h.centre[2];
        shown = project(&v, from, &x0, &y0) && project(&v, to, &x1, &y1);
    }
    if (!shown) {
        snprintf(p->status, sizeof p->status, "the %s handle is not in the view", name);
        return 1;
    }
    fprintf(stderr, "tessera: locate handle %s at %.0f %.0f to %.0f %.0f\n", name, x0, y0, x1, y1);
    return 0;
}
