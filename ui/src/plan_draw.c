/* Drawing the plan view with Dear ImGui's background list (ui/src/plan_draw.h): a drawing a
 * tiler would recognise, north up, walls hatched dark, free areas dashed blue, findings red. */
#include "plan_draw.h"

#include "app/project/commands.h"
#include "gui.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define DEG (3.14159265358979323846 / 180.0)

static unsigned rgba(unsigned r, unsigned g, unsigned b, unsigned a)
{
    return (a << 24) | (b << 16) | (g << 8) | r;
}

static void to_screen(const ui_plan_transform *t, double x, double y, float *out)
{
    ui_plan_to_screen(t, x, y, &out[0], &out[1]);
}

/* The corners with the one being dragged moved. */
static app_point2 corner(const app_project *p, const ui_plan_overlay *o, int i)
{
    int n = p->plan.corner_count;
    i = ((i % n) + n) % n;
    if (i == o->drag_corner)
        return (app_point2){o->drag_mm[0], o->drag_mm[1]};
    if (o->wall_dragging && (i == o->drag_wall || i == (o->drag_wall + 1) % n)) {
        app_point2 a, b;
        ui_plan_wall_moved(&p->plan, o->drag_wall, o->drag_wall_mm, &a, &b);
        return i == o->drag_wall ? a : b;
    }
    return p->plan.corners[i];
}

/* A point at `along` mm along wall w and `out` mm outward (negative: into the room). */
static void wall_point(const app_project *p, const ui_plan_overlay *o, int w, double along,
                       double outward, double *x, double *y)
{
    app_point2 a = corner(p, o, w), b = corner(p, o, w + 1);
    double len = hypot(b.x - a.x, b.y - a.y);
    double ux = len > 0 ? (b.x - a.x) / len : 1, uy = len > 0 ? (b.y - a.y) / len : 0;
    /* Counter-clockwise plan: the room is on the left, outward is to the right (uy, -ux). */
    *x = a.x + ux * along + uy * outward;
    *y = a.y + uy * along - ux * outward;
}

static void draw_walls(const ui_plan_transform *t, const app_project *p, const ui_plan_overlay *o)
{
    int n = p->plan.corner_count;
    double th = p->plan.wall_thickness_mm > 0 ? p->plan.wall_thickness_mm : 120;
    for (int w = 0; w < n; w++) {
        app_point2 a = corner(p, o, w), b = corner(p, o, w + 1);
        double len = hypot(b.x - a.x, b.y - a.y);
        /* The wall's band, split around its openings. */
        double cuts[2 * 64 + 2];
        int c = 0;
        cuts[c++] = 0;
        for (int k = 0; k < p->plan.opening_count && c < 2 * 64; k++) {
            const app_opening *op = &p->plan.openings[k];
            if (op->wall != w)
                continue;
            cuts[c++] = op->offset_mm;
            cuts[c++] = op->offset_mm + op->width_mm;
        }
        cuts[c++] = len;
        for (int s = 0; s + 1 < c; s += 2) {
            double s0 = cuts[s], s1 = cuts[s + 1];
            if (s1 <= s0)
                continue;
            /* Extend the band's ends by the thickness at the wall's corners, so corners join. */
            double e0 = s == 0 ? -th : 0, e1 = s + 2 == c ? th : 0;
            double q[4][2];
            wall_point(p, o, w, s0, 0, &q[0][0], &q[0][1]);
            wall_point(p, o, w, s1, 0, &q[1][0], &q[1][1]);
            wall_point(p, o, w, s1 + e1, th, &q[2][0], &q[2][1]);
            wall_point(p, o, w, s0 + e0, th, &q[3][0], &q[3][1]);
            float xy[8];
            for (int k = 0; k < 4; k++)
                to_screen(t, q[k][0], q[k][1], &xy[2 * k]);
            ui_gui_draw_quad_filled(xy, o->selected_wall == w ? rgba(60, 110, 170, 255)
                                                              : rgba(70, 70, 72, 255));
        }
        /* Inside face line and the wall's length, written inside the room. */
        float pa[2], pb[2];
        to_screen(t, a.x, a.y, pa);
        to_screen(t, b.x, b.y, pb);
        ui_gui_draw_line(pa[0], pa[1], pb[0], pb[1], rgba(20, 20, 20, 255), 1.5f);
        double mx, my;
        wall_point(p, o, w, len / 2, th + 16 / t->px_per_mm, &mx, &my); /* outside the wall */
        float m[2];
        to_screen(t, mx, my, m);
        char label[32];
        snprintf(label, sizeof label, "%.0f", len);
        ui_gui_draw_text(m[0] - 14, m[1] - 7, rgba(30, 60, 120, 255), label);
    }
    for (int i = 0; i < n; i++) {
        app_point2 c = corner(p, o, i);
        float s[2];
        to_screen(t, c.x, c.y, s);
        int hot = i == o->hover_corner || i == o->drag_corner;
        ui_gui_draw_circle(s[0], s[1], hot ? 6.0f : 3.5f,
                           hot ? rgba(230, 120, 20, 255) : rgba(20, 20, 20, 255), 1);
    }
}

static void draw_openings(const ui_plan_transform *t, const app_project *p,
                          const ui_plan_overlay *o)
{
    double th = p->plan.wall_thickness_mm > 0 ? p->plan.wall_thickness_mm : 120;
    for (int k = 0; k < p->plan.opening_count; k++) {
        const app_opening *op = &p->plan.openings[k];
        if (op->wall < 0 || op->wall >= p->plan.corner_count)
            continue;
        double x[4], y[4];
        wall_point(p, o, op->wall, op->offset_mm, 0, &x[0], &y[0]);
        wall_point(p, o, op->wall, op->offset_mm + op->width_mm, 0, &x[1], &y[1]);
        wall_point(p, o, op->wall, op->offset_mm + op->width_mm, th, &x[2], &y[2]);
        wall_point(p, o, op->wall, op->offset_mm, th, &x[3], &y[3]);
        float s[4][2];
        for (int i = 0; i < 4; i++)
            to_screen(t, x[i], y[i], s[i]);
        unsigned ink = rgba(20, 20, 20, 255);
        if (op->type == APP_OPENING_WINDOW) {
            /* Two glass lines in the wall's middle third. */
            for (int g = 1; g <= 2; g++) {
                float a = g / 3.0f;
                ui_gui_draw_line(s[0][0] + a * (s[3][0] - s[0][0]),
                                 s[0][1] + a * (s[3][1] - s[0][1]),
                                 s[1][0] + a * (s[2][0] - s[1][0]),
                                 s[1][1] + a * (s[2][1] - s[1][1]), rgba(40, 110, 200, 255), 1.5f);
            }
            ui_gui_draw_line(s[0][0], s[0][1], s[3][0], s[3][1], ink, 1.0f);
            ui_gui_draw_line(s[1][0], s[1][1], s[2][0], s[2][1], ink, 1.0f);
            continue;
        }
        /* A door: the leaf drawn open at 90 degrees and its swing as a quarter circle. */
        int right = op->swing == APP_SWING_IN_RIGHT || op->swing == APP_SWING_OUT_RIGHT;
        int inward = op->swing == APP_SWING_IN_LEFT || op->swing == APP_SWING_IN_RIGHT;
        if (op->swing == APP_SWING_SLIDING) {
            ui_gui_draw_line(s[0][0], s[0][1], s[1][0], s[1][1], ink, 2.0f);
            continue;
        }
        double hinge = right ? op->offset_mm + op->width_mm : op->offset_mm;
        double hx, hy, lx, ly;
        wall_point(p, o, op->wall, hinge, inward ? 0 : th, &hx, &hy);
        wall_point(p, o, op->wall, hinge, inward ? -op->width_mm : th + op->width_mm, &lx, &ly);
        float hs[2], ls[2];
        to_screen(t, hx, hy, hs);
        to_screen(t, lx, ly, ls);
        ui_gui_draw_line(hs[0], hs[1], ls[0], ls[1], ink, 2.0f);
        double fx, fy;
        wall_point(p, o, op->wall, right ? op->offset_mm : op->offset_mm + op->width_mm,
                   inward ? 0 : th, &fx, &fy);
        float fs[2];
        to_screen(t, fx, fy, fs);
        float r = hypotf(ls[0] - hs[0], ls[1] - hs[1]);
        float a0 = atan2f(ls[1] - hs[1], ls[0] - hs[0]), a1 = atan2f(fs[1] - hs[1], fs[0] - hs[0]);
        if (a1 - a0 > 3.14159265f)
            a1 -= 6.28318531f;
        if (a0 - a1 > 3.14159265f)
            a1 += 6.28318531f;
        ui_gui_draw_arc(hs[0], hs[1], r, a0, a1, rgba(90, 90, 90, 255), 1.0f);
    }
}

static void draw_prewalls(const ui_plan_transform *t, const app_project *p,
                          const ui_plan_overlay *o)
{
    for (int k = 0; k < p->plan.prewall_count; k++) {
        const app_prewall *pw = &p->plan.prewalls[k];
        if (pw->wall < 0 || pw->wall >= p->plan.corner_count)
            continue;
        double q[4][2];
        wall_point(p, o, pw->wall, pw->offset_mm, 0, &q[0][0], &q[0][1]);
        wall_point(p, o, pw->wall, pw->offset_mm + pw->width_mm, 0, &q[1][0], &q[1][1]);
        wall_point(p, o, pw->wall, pw->offset_mm + pw->width_mm, -pw->depth_mm, &q[2][0], &q[2][1]);
        wall_point(p, o, pw->wall, pw->offset_mm, -pw->depth_mm, &q[3][0], &q[3][1]);
        float xy[8];
        for (int i = 0; i < 4; i++)
            to_screen(t, q[i][0], q[i][1], &xy[2 * i]);
        ui_gui_draw_quad_filled(xy, rgba(150, 150, 150, 255));
    }
}

static void rect_corners(double angle_deg, double cx, double cy, double hw, double hd, double off_y,
                         const ui_plan_transform *t, float xy[8])
{
    double c = cos(angle_deg * DEG), s = sin(angle_deg * DEG);
    static const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
    for (int k = 0; k < 4; k++) {
        double lx = sx[k] * hw, ly = sy[k] * hd + off_y;
        to_screen(t, cx + lx * c - ly * s, cy + lx * s + ly * c, &xy[2 * k]);
    }
}

static void outline(const float xy[8], unsigned colour, float thickness)
{
    for (int k = 0; k < 4; k++)
        ui_gui_draw_line(xy[2 * k], xy[2 * k + 1], xy[(2 * k + 2) % 8], xy[(2 * k + 3) % 8], colour,
                         thickness);
}

/* The dragged fixture's motion in the plan: its object's position goes from `from` to `to` and
 * it turns by `turn_deg` about it (the snap preview's pose, else the pointer's translation);
 * what is mounted on it moves along, as the release's move edit takes it along. */
typedef struct drag_motion {
    int active;
    double from[2], to[2], turn_deg;
    int *members; /* the dragged object and its group, by object index (1: moves) */
} drag_motion;

static drag_motion motion_of(const app_project *p, const app_fixture *fx, int n,
                             const ui_plan_overlay *o)
{
    drag_motion m = {0};
    const app_fixture *d = NULL;
    for (int i = 0; i < n && !d; i++)
        d = fx[i].object == o->drag_object ? &fx[i] : NULL;
    if (!d || o->drag_object >= p->object_count)
        return m;
    const double *at = p->objects[o->drag_object].position_mm;
    m.from[0] = at[0];
    m.from[1] = at[1];
    m.to[0] = at[0] + o->drag_mm[0] - d->centre[0];
    m.to[1] = at[1] + o->drag_mm[1] - d->centre[1];
    if (o->snap_shown) {
        m.to[0] = o->snap.pose.x;
        m.to[1] = o->snap.pose.y;
        m.turn_deg = o->snap.angle_deg - d->angle_deg;
    }
    m.members = calloc((size_t)p->object_count, sizeof *m.members);
    int *list = malloc((size_t)p->object_count * sizeof *list);
    if (m.members && list) {
        int k = app_group_members(p, o->drag_object, list);
        for (int j = 0; j < k; j++)
            m.members[list[j]] = 1;
    }
    free(list);
    if (m.members)
        m.members[o->drag_object] = 1;
    m.active = 1;
    return m;
}

static void draw_fixtures(const ui_plan_transform *t, const app_project *p, const app_fixture *fx,
                          const app_free_area *areas, int n, const ui_plan_overlay *o)
{
    drag_motion m = motion_of(p, fx, n, o);
    double c = cos(m.turn_deg * DEG), s = sin(m.turn_deg * DEG);
    for (int i = 0; i < n; i++) {
        const app_fixture *f = &fx[i];
        double cx = f->centre[0], cy = f->centre[1], angle = f->angle_deg;
        int moves =
            m.active &&
            (f->object == o->drag_object ||
             (m.members && f->object >= 0 && f->object < p->object_count && m.members[f->object]));
        if (moves) { /* where the release will put it */
            double rx = cx - m.from[0], ry = cy - m.from[1];
            cx = m.to[0] + rx * c - ry * s;
            cy = m.to[1] + rx * s + ry * c;
            angle += m.turn_deg;
        }
        float xy[8];
        if (areas && areas[i].has_area && fabs(angle - f->angle_deg) < 0.5) {
            /* Where the checks placed it (app_free_areas), so the drawing shows what was
             * checked; a fixture being dragged carries its area along until it is dropped and
             * checked again. */
            double dx = cx - f->centre[0], dy = cy - f->centre[1];
            for (int k = 0; k < 4; k++)
                to_screen(t, areas[i].corners[k][0] + dx, areas[i].corners[k][1] + dy, &xy[2 * k]);
            outline(xy, rgba(60, 120, 220, 160), 1.0f);
        }
        rect_corners(angle, cx, cy, f->half[0], f->half[1], 0, t, xy);
        int sel = f->object == o->selected_object;
        ui_gui_draw_quad_filled(xy, sel              ? rgba(250, 215, 150, 255)
                                    : f->has_product ? rgba(255, 255, 255, 255)
                                                     : rgba(225, 225, 220, 255));
        outline(xy, sel ? rgba(220, 110, 0, 255) : rgba(30, 30, 30, 255), sel ? 2.5f : 1.2f);
        float label[2];
        to_screen(t, cx, cy, label);
        if (t->px_per_mm * 2 * f->half[0] > 60)
            ui_gui_draw_text(label[0] - 3.5f * (float)strlen(f->name), label[1] - 7,
                             rgba(40, 40, 40, 255), f->name);
    }
    free(m.members);
}

static void draw_findings(const ui_plan_transform *t, const app_findings *f)
{
    for (int i = 0; f && i < f->count; i++) {
        const app_finding *g = &f->items[i];
        float s[2];
        to_screen(t, g->position_mm[0], g->position_mm[1], s);
        unsigned colour = g->severity == APP_SEVERITY_ERROR     ? rgba(215, 30, 30, 255)
                          : g->severity == APP_SEVERITY_WARNING ? rgba(235, 150, 0, 255)
                                                                : rgba(60, 120, 220, 255);
        ui_gui_draw_circle(s[0], s[1], 9.0f, colour, 0);
        ui_gui_draw_circle(s[0], s[1], 3.0f, colour, 1);
    }
}

/* A dashed line, DASH_PX on and GAP_PX off in window pixels whatever the zoom. */
static void dashed(const ui_plan_transform *t, const double a[2], const double b[2],
                   unsigned colour)
{
    enum { DASH_PX = 8, GAP_PX = 5 };
    float s0[2], s1[2];
    to_screen(t, a[0], a[1], s0);
    to_screen(t, b[0], b[1], s1);
    float len = hypotf(s1[0] - s0[0], s1[1] - s0[1]);
    for (float d = 0; d < len; d += DASH_PX + GAP_PX) {
        float e = fminf(d + DASH_PX, len), u0 = d / len, u1 = e / len;
        ui_gui_draw_line(s0[0] + u0 * (s1[0] - s0[0]), s0[1] + u0 * (s1[1] - s0[1]),
                         s0[0] + u1 * (s1[0] - s0[0]), s0[1] + u1 * (s1[1] - s0[1]), colour, 1.5f);
    }
}

/* A dimension line with end ticks and its length in mm written at its middle on a white
 * ground, as a drawing dimensions a clearance. */
static void dimension(const ui_plan_transform *t, const app_snap_dimension *d, unsigned colour)
{
    float a[2], b[2];
    to_screen(t, d->a[0], d->a[1], a);
    to_screen(t, d->b[0], d->b[1], b);
    float len = hypotf(b[0] - a[0], b[1] - a[1]);
    float nx = len > 0 ? -(b[1] - a[1]) / len * 5 : 0, ny = len > 0 ? (b[0] - a[0]) / len * 5 : 5;
    ui_gui_draw_line(a[0], a[1], b[0], b[1], colour, 1.5f);
    ui_gui_draw_line(a[0] - nx, a[1] - ny, a[0] + nx, a[1] + ny, colour, 1.5f);
    ui_gui_draw_line(b[0] - nx, b[1] - ny, b[0] + nx, b[1] + ny, colour, 1.5f);
    char label[32];
    snprintf(label, sizeof label, "%.0f", d->mm);
    float w = ui_gui_text_width(label), mx = 0.5f * (a[0] + b[0]), my = 0.5f * (a[1] + b[1]);
    float bg[8] = {mx - w / 2 - 3, my - 9, mx + w / 2 + 3, my - 9,
                   mx + w / 2 + 3, my + 9, mx - w / 2 - 3, my + 9};
    ui_gui_draw_quad_filled(bg, rgba(255, 255, 255, 235));
    ui_gui_draw_text(mx - w / 2, my - 7, colour, label);
}

/* The dragged fixture's snap: the wall face and the corner or neighbour it lines up with,
 * dashed, and its clear distances to the left, right and front. */
static void draw_snap(const ui_plan_transform *t, const ui_plan_overlay *o)
{
    if (!o->snap_shown)
        return;
    for (int g = 0; g < o->snap.guide_count; g++)
        dashed(t, o->snap.guides[g].a, o->snap.guides[g].b, UI_PLAN_GUIDE_COLOUR);
    for (int s = 0; s < APP_SNAP_SIDES; s++)
        if (o->snap.sides[s].found)
            dimension(t, &o->snap.sides[s], UI_PLAN_GUIDE_COLOUR);
}

void ui_plan_draw(const ui_plan_transform *t, const app_project *p, const app_fixture *fx,
                  const app_free_area *areas, int fixture_count, const app_findings *findings,
                  const ui_plan_overlay *o)
{
    float l = t->x0, r = t->x0 + t->width, top = t->y0, b = t->y0 + t->height;
    float bg[8] = {l, top, r, top, r, b, l, b};
    ui_gui_draw_quad_filled(bg, rgba(246, 244, 238, 255));
    if (p->plan.corner_count < 3)
        return;
    draw_prewalls(t, p, o);
    draw_fixtures(t, p, fx, areas, fixture_count, o);
    draw_walls(t, p, o);
    draw_openings(t, p, o);
    draw_findings(t, findings);
    draw_snap(t, o);
    /* A scale bar of one metre. */
    float x0 = t->x0 + 20, y0 = t->y0 + t->height - 20, len = (float)(1000 * t->px_per_mm);
    ui_gui_draw_line(x0, y0, x0 + len, y0, rgba(20, 20, 20, 255), 2.0f);
    ui_gui_draw_text(x0, y0 - 18, rgba(20, 20, 20, 255), "1 m");
}
