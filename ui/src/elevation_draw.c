/* The elevation view (wall elevation for tiling): the tile panel's surface
 * unfolded and seen from the room, drawn with Dear ImGui's background list as plan_draw.c
 * draws the plan: the exact tile layout of app_room_tile_layouts (the one the print set's
 * elevations and the quantities count: print_elevation.c), whole tiles in the tile's colour,
 * cut tiles lighter with their cut edges in red, the joints in the grout's colour, openings,
 * covered parts, the fixtures standing in front as outlines, the start point of the tile grid,
 * and the surface's width and height. A click on the surface starts the tile grid there (one
 * edit line, one undo step). */
#include "tiles.h"

#include "elevation_header.h"
#include "gui.h"
#include "panel_layout.h"

#include <GLFW/glfw3.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define HEADER_LINE_PX 14.0f   /* the 13-pixel default font and a pixel of air */
#define FIXTURE_DEPTH_MM 450.0 /* fixtures this near the face are drawn (as the print set) */

static unsigned rgba(unsigned r, unsigned g, unsigned b, unsigned a)
{
    return (a << 24) | (b << 16) | (g << 8) | r;
}

static unsigned rgbf(const float c[3], float scale, float lift)
{
    unsigned v[3];
    for (int k = 0; k < 3; k++) {
        float x = lift + (1.0f - lift) * c[k] * scale;
        v[k] = (unsigned)lrintf(255.0f * (x < 0 ? 0 : x > 1 ? 1 : x));
    }
    return rgba(v[0], v[1], v[2], 255);
}

static void screen(const ui_tiles *t, app_point2 p, float *xy)
{
    ui_elev_to_screen(&t->view, p.x, p.y, &xy[0], &xy[1]);
}

/* A convex polygon filled as a fan of quads (the seam draws convex quads). */
static void fill_convex(const ui_tiles *t, const app_point2 *pts, int n, unsigned colour)
{
    int quads[64][4];
    int q = ui_elev_fan_quads(n, quads, 64);
    for (int k = 0; k < q; k++) {
        float xy[8];
        for (int j = 0; j < 4; j++)
            screen(t, pts[quads[k][j]], &xy[2 * j]);
        ui_gui_draw_quad_filled(xy, colour);
    }
}

static void polyline(const ui_tiles *t, const app_point2 *pts, int n, unsigned colour, float w)
{
    for (int k = 0; k < n; k++) {
        float a[2], b[2];
        screen(t, pts[k], a);
        screen(t, pts[(k + 1) % n], b);
        ui_gui_draw_line(a[0], a[1], b[0], b[1], colour, w);
    }
}

static void draw_layout(const ui_tiles *t, int li, const app_tiling *tiling, int *whole, int *cut)
{
    const app_tile_layout *l = &t->layouts[li];
    static const float grey[3] = {0.85f, 0.85f, 0.85f};
    float grout[3];
    for (int k = 0; k < 3; k++)
        grout[k] = powf(fminf(fmaxf(tiling->grout_color[k], 0.0f), 1.0f), 1.0f / 2.2f);
    /* A joint is drawn at least a pixel wide so the pattern shows at any zoom. */
    float joint = (float)(l->grout_mm * t->view.px_per_mm);
    joint = joint < 1.0f ? 1.0f : joint;
    for (int i = 0; i < l->tile_count; i++) {
        const app_placed_tile *pt = &l->tiles[i];
        int spec = pt->product >= 0 && pt->product < l->spec_count ? pt->product : 0;
        const float *c = t->colours ? t->colours[li][spec] : grey;
        /* Cut tiles lighter and reddish, so the tiler sees at once which to cut. */
        static const float cut_tint[3] = {1.0f, 0.86f, 0.82f};
        float cc[3] = {c[0], c[1], c[2]};
        if (!pt->whole)
            for (int k = 0; k < 3; k++)
                cc[k] = (0.45f + 0.55f * c[k]) * cut_tint[k];
        unsigned fill = rgbf(cc, 1.0f, 0.0f);
        for (int q = 0; q < pt->piece_count; q++) {
            const app_tile_piece *pc = &l->pieces[pt->first_piece + q];
            fill_convex(t, &l->points[pc->first], pc->count, fill);
        }
        *whole += pt->whole;
        *cut += !pt->whole;
        /* The tile's own edges in the grout's colour (darkened to show against light tiles),
         * cut edges in red; seams between convex pieces are not drawn. */
        for (int q = 0; q < pt->piece_count; q++) {
            const app_tile_piece *pc = &l->pieces[pt->first_piece + q];
            for (int k = 0; k < pc->count; k++) {
                unsigned char e = l->edges[pc->first + k];
                if (e == APP_EDGE_SEAM)
                    continue;
                float a[2], b[2];
                screen(t, l->points[pc->first + k], a);
                screen(t, l->points[pc->first + (k + 1) % pc->count], b);
                if (e == APP_EDGE_CUT)
                    ui_gui_draw_line(a[0], a[1], b[0], b[1], rgba(200, 30, 30, 255), 1.2f);
                else
                    ui_gui_draw_line(a[0], a[1], b[0], b[1], rgbf(grout, 0.7f, 0.0f), joint);
            }
        }
    }
    /* The start point: a grid point of the field lattice, as a cross in a circle. */
    float o[2];
    screen(t, l->origin, o);
    unsigned mark = rgba(230, 110, 0, 255);
    ui_gui_draw_circle(o[0], o[1], 7.0f, mark, 0);
    ui_gui_draw_line(o[0] - 11, o[1], o[0] + 11, o[1], mark, 2.0f);
    ui_gui_draw_line(o[0], o[1] - 11, o[0], o[1] + 11, mark, 2.0f);
}

static void draw_holes(const ui_tiles *t)
{
    for (int h = 0; h < t->region.hole_count; h++) {
        const app_region_hole *hole = &t->region.holes[h];
        const app_polygon *pg = &hole->polygon;
        app_point2 lo, hi;
        if (!ui_elev_bounds(pg->points, pg->count, &lo, &hi))
            continue;
        if (hole->kind == APP_HOLE_OPENING || hole->kind == APP_HOLE_NICHE) {
            fill_convex(t, pg->points, pg->count, rgba(255, 255, 255, 255));
            polyline(t, pg->points, pg->count, rgba(20, 20, 20, 255), 2.0f);
        } else {
            polyline(t, pg->points, pg->count, rgba(110, 110, 110, 255), 1.0f);
        }
        if (hole->name[0]) {
            float c[2];
            screen(t, (app_point2){(lo.x + hi.x) / 2, (lo.y + hi.y) / 2}, c);
            ui_gui_draw_text(c[0] - 3.5f * (float)strlen(hole->name), c[1] - 7,
                             rgba(40, 40, 40, 255), hole->name);
        }
    }
}

static void draw_fixtures(const planner *p, const ui_tiles *t, app_point2 lo, app_point2 hi)
{
    for (int i = 0; i < p->fixture_count; i++) {
        app_point2 sil[8], out[12], flo, fhi;
        double depth;
        int n = ui_elev_fixture_outline(&t->frame, &p->fixtures[i], FIXTURE_DEPTH_MM, sil, &depth);
        /* Only over the surface: a bath beside a pre-wall's side reaches far past it. */
        n = n >= 3 ? ui_elev_clip_box(sil, n, lo, hi, out) : 0;
        if (n < 3 || !ui_elev_bounds(out, n, &flo, &fhi))
            continue;
        polyline(t, out, n, rgba(30, 60, 140, 255), 1.8f);
        float c[2];
        screen(t, (app_point2){(flo.x + fhi.x) / 2, fhi.y}, c);
        ui_gui_draw_text(c[0] - 3.5f * (float)strlen(p->fixtures[i].name), c[1] - 16,
                         rgba(30, 60, 140, 255), p->fixtures[i].name);
    }
}

/* A dimension line with end ticks and its length in the middle. */
static void dimension(float x0, float y0, float x1, float y1, double mm, int vertical)
{
    unsigned ink = rgba(30, 60, 120, 255);
    ui_gui_draw_line(x0, y0, x1, y1, ink, 1.0f);
    float tx = vertical ? 5.0f : 0.0f, ty = vertical ? 0.0f : 5.0f;
    ui_gui_draw_line(x0 - tx, y0 - ty, x0 + tx, y0 + ty, ink, 1.0f);
    ui_gui_draw_line(x1 - tx, y1 - ty, x1 + tx, y1 + ty, ink, 1.0f);
    char label[32];
    snprintf(label, sizeof label, "%.0f", mm);
    float mx = (x0 + x1) / 2, my = (y0 + y1) / 2;
    if (vertical)
        ui_gui_draw_text(mx - 8.0f * (float)strlen(label) - 6.0f, my - 7, ink, label);
    else
        ui_gui_draw_text(mx - 3.5f * (float)strlen(label), my + 4, ink, label);
}

/* Level marks on the right of a wall tiling: its band's edges and its border rows. */
static void level_marks(const ui_tiles *t, const app_tiling *g, float x, double t_max)
{
    unsigned ink = rgba(120, 60, 20, 255);
    double marks[2 + APP_TILING_MAX_BORDERS];
    const char *what[2 + APP_TILING_MAX_BORDERS];
    int n = 0;
    if (g->from_mm > 0) {
        marks[n] = g->from_mm;
        what[n++] = "band from";
    }
    if (g->to_mm > 0 && g->to_mm < t_max) {
        marks[n] = g->to_mm;
        what[n++] = "band to";
    }
    for (int k = 0; k < g->border_count && k < APP_TILING_MAX_BORDERS; k++) {
        marks[n] = g->borders[k].bottom_mm;
        what[n++] = "border";
    }
    for (int k = 0; k < n; k++) {
        float sx, sy;
        ui_elev_to_screen(&t->view, 0, marks[k], &sx, &sy);
        ui_gui_draw_line(x, sy, x + 10, sy, ink, 1.5f);
        char label[64];
        snprintf(label, sizeof label, "+%.0f %s", marks[k], what[k]);
        ui_gui_draw_text(x + 13, sy - 7, ink, label);
    }
}

static void handle_input(planner *p, ui_tiles *t, app_point2 lo, app_point2 hi)
{
    double mx, my;
    ui_gui_pointer(&mx, &my);
    double s, tt;
    ui_elev_to_surface(&t->view, (float)mx, (float)my, &s, &tt);
    int free_pointer = !ui_gui_wants_mouse();
    t->hovering = free_pointer && s >= lo.x && s <= hi.x && tt >= lo.y && tt <= hi.y;
    t->hover[0] = s;
    t->hover[1] = tt;
    /* The right button pans: the surface point under the pointer stays under it. */
    int right = ui_gui_mouse_down(GLFW_MOUSE_BUTTON_RIGHT);
    if (right && (t->panning || free_pointer)) {
        if (t->panning) {
            double s0, t0;
            ui_elev_to_surface(&t->view, t->pan_x, t->pan_y, &s0, &t0);
            t->pan[0] += s0 - s;
            t->pan[1] += t0 - tt;
        }
        t->panning = 1;
        t->pan_x = (float)mx;
        t->pan_y = (float)my;
    } else {
        t->panning = 0;
    }
    int left = ui_gui_mouse_down(GLFW_MOUSE_BUTTON_LEFT);
    if (left && !t->pressed && t->hovering) {
        t->pressed = 1;
        t->press_x = (float)mx;
        t->press_y = (float)my;
    } else if (!left && t->pressed) {
        /* A click (not a drag) on the surface sets the start point. */
        t->pressed = 0;
        if (t->hovering && fabs(mx - t->press_x) < 4 && fabs(my - t->press_y) < 4)
            planner_elevation_click(p, s, tt);
    }
}

static void elevation_in_pane(planner *p, ui_rect r);

void planner_elevation_frame(planner *p, int width, int height)
{
    (void)width;
    (void)height;
    /* The elevation fills the 2D pane (panel_layout.h), clipped to it. */
    ui_rect r = p->layout.pane_2d;
    ui_gui_clip_push(r.x, r.y, r.x + r.w, r.y + r.h);
    elevation_in_pane(p, r);
    ui_gui_clip_pop();
}

static void elevation_in_pane(planner *p, ui_rect r)
{
    float bg[8] = {r.x, r.y, r.x + r.w, r.y, r.x + r.w, r.y + r.h, r.x, r.y + r.h};
    ui_gui_draw_quad_filled(bg, rgba(246, 244, 238, 255));
    ui_tiles *t = planner_tiles(p);
    if (!t)
        return;
    ui_tiles_refresh(p, t);
    unsigned ink = rgba(20, 20, 20, 255);
    if (!t->region_ok) {
        ui_gui_draw_text(r.x + 20, r.y + 60, rgba(180, 30, 30, 255), t->error);
        return;
    }
    app_point2 lo, hi;
    if (!ui_elev_bounds(t->region.outer.points, t->region.outer.count, &lo, &hi))
        return;
    float left = r.x, right_x = r.x + r.w, top = r.y;
    t->view = ui_elev_fit(lo.x, lo.y, hi.x, hi.y, ui_elev_mirrored(&t->frame), left, top + 40.0f,
                          right_x, r.y + r.h, 50.0f);
    t->view.px_per_mm *= t->zoom > 0 ? t->zoom : 1;
    /* Panned at most half the surface from its fit: some of the surface always stays at the
     * pane's centre, so no drag leaves an empty pane (Fit brings it back whole). */
    float half_w = (float)(hi.x - lo.x) * 0.5f, half_h = (float)(hi.y - lo.y) * 0.5f;
    t->pan[0] = t->pan[0] < -half_w ? -half_w : t->pan[0] > half_w ? half_w : t->pan[0];
    t->pan[1] = t->pan[1] < -half_h ? -half_h : t->pan[1] > half_h ? half_h : t->pan[1];
    t->view.centre[0] += t->pan[0];
    t->view.centre[1] += t->pan[1];
    if (p->view == UI_VIEW_ELEVATION && planner_input_live(p))
        handle_input(p, t, lo, hi);

    polyline(t, t->region.outer.points, t->region.outer.count, rgba(200, 200, 195, 255), 1.0f);
    int whole = 0, cut = 0, tilings = 0;
    for (int i = 0; i < t->layout_count && i < p->project.tiling_count; i++)
        if (!strcmp(p->project.tilings[i].surface, t->surface)) {
            draw_layout(t, i, &p->project.tilings[i], &whole, &cut);
            tilings++;
        }
    draw_holes(t);
    draw_fixtures(p, t, lo, hi);
    polyline(t, t->region.outer.points, t->region.outer.count, ink, 2.5f);

    /* Width below, height on the left (as seen: the mirrored s puts s0 on the right). */
    float a[2], b[2], c[2];
    ui_elev_to_screen(&t->view, lo.x, lo.y, &a[0], &a[1]);
    ui_elev_to_screen(&t->view, hi.x, lo.y, &b[0], &b[1]);
    ui_elev_to_screen(&t->view, lo.x, hi.y, &c[0], &c[1]);
    float xl = a[0] < b[0] ? a[0] : b[0], xr = a[0] < b[0] ? b[0] : a[0];
    int vertical = t->frame.kind == APP_SURFACE_WALL || t->frame.kind == APP_SURFACE_PREWALL_SIDE;
    for (int i = 0; vertical && i < p->project.tiling_count; i++)
        if (!strcmp(p->project.tilings[i].surface, t->surface))
            level_marks(t, &p->project.tilings[i], xr + 6, hi.y);
    dimension(a[0], a[1] + 22, b[0], b[1] + 22, hi.x - lo.x, 0);
    dimension(xl - 22, a[1], xl - 22, c[1], hi.y - lo.y, 1);

    char title[300];
    int wall = ui_elev_wall_index(t->surface);
    if (wall >= 0)
        snprintf(title, sizeof title, "Elevation of wall %d (%s), seen from the room", wall,
                 t->surface);
    else
        snprintf(title, sizeof title, "%s, seen from the room", t->surface);
    char line[1200];
    if (tilings)
        snprintf(line, sizeof line,
                 "%d whole, %d cut tiles (layouts: %.1f ms); a click starts "
                 "the grid",
                 whole, cut, t->refresh_ms);
    else
        snprintf(line, sizeof line, "not tiled%s%s", t->error[0] ? ": " : "", t->error);
    char at[64] = "";
    if (t->hovering)
        snprintf(at, sizeof at, "s %.0f  t %.0f mm", t->hover[0], t->hover[1]);
    /* One line each, elided to the pane's width, so the pointer's readout never covers the
     * title and no text runs past the pane's edge. */
    ui_elev_header header;
    ui_elev_header_layout(left, top, r.w, HEADER_LINE_PX, ui_gui_text_width, title, line, at,
                          &header);
    /* A band of the pane's paper behind the header keeps it readable over a zoomed surface. */
    float band[8] = {
        r.x, r.y, r.x + r.w, r.y, r.x + r.w, header.bottom + 2, r.x, header.bottom + 2};
    ui_gui_draw_quad_filled(band, rgba(246, 244, 238, 220));
    const unsigned colours[UI_ELEV_HEADER_LINES] = {ink, rgba(60, 60, 60, 255),
                                                    rgba(60, 60, 60, 255)};
    for (int i = 0; i < UI_ELEV_HEADER_LINES; i++)
        if (header.line[i].text[0])
            ui_gui_draw_text(header.line[i].x, header.line[i].y, colours[i], header.line[i].text);
}
