/* The floor plan page: walls with their thickness, openings with door swings and windows,
 * pre-walls and niches, fixtures as top-down outlines labelled with article numbers, clearance
 * areas (DOMAIN.md "Clearances", VDI 6000 sheet 1), and dimension lines: each wall's inside
 * length with the openings on it, the room's overall inside size when it is not a rectangle,
 * and each fixture's distance to its nearest walls. Drawn at a true scale 1:N. */
#include "print_internal.h"

#include "app/design/placement.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct pr_view {
    double ox, oy; /* paper position of world (0, 0) */
    double n;      /* scale denominator */
    int turned;    /* 1: the plan is turned a quarter counter-clockwise to fit the sheet */
} pr_view;

/* World (x, y) to paper: plan y points up the page; a turned plan maps (x, y) to (-y, x) first,
 * a rotation (never a mirror), so the drawing stays the room seen from above. */
static double px(const pr_view *v, double x, double y)
{
    return v->ox + (v->turned ? -y : x) / v->n;
}
static double py(const pr_view *v, double x, double y)
{
    return v->oy - (v->turned ? x : y) / v->n;
}

void pr_offset_polygon(const app_point2 *c, int n, double distance, app_point2 *out)
{
    for (int i = 0; i < n; i++) {
        app_point2 a = c[(i + n - 1) % n], b = c[i], e = c[(i + 1) % n];
        double l1 = hypot(b.x - a.x, b.y - a.y), l2 = hypot(e.x - b.x, e.y - b.y);
        if (l1 < 1e-9 || l2 < 1e-9) {
            out[i] = b;
            continue;
        }
        /* Outward normals of a counter-clockwise polygon: the edge turned clockwise. */
        double n1x = (b.y - a.y) / l1, n1y = -(b.x - a.x) / l1;
        double n2x = (e.y - b.y) / l2, n2y = -(e.x - b.x) / l2;
        double bx = n1x + n2x, by = n1y + n2y, dot = 1.0 + n1x * n2x + n1y * n2y;
        if (dot < 0.2) /* a hairpin corner: a bevel rather than a miter far out */
            dot = 0.2;
        out[i].x = b.x + bx * distance / dot;
        out[i].y = b.y + by * distance / dot;
    }
}

/* Wall i's frame: start corner, unit along direction, inward normal, length. */
static void wall_frame(const app_room_plan *pl, int i, app_point2 *o, app_point2 *u,
                       app_point2 *nrm, double *len)
{
    app_point2 a = pl->corners[i], b = pl->corners[(i + 1) % pl->corner_count];
    double l = hypot(b.x - a.x, b.y - a.y);
    *o = a;
    *len = l;
    u->x = l > 0 ? (b.x - a.x) / l : 1;
    u->y = l > 0 ? (b.y - a.y) / l : 0;
    nrm->x = -u->y;
    nrm->y = u->x;
}

/* A quad in the wall's frame: along s0..s1, inward d0..d1 (negative = into the wall). */
static void wall_quad(cairo_t *cr, const pr_view *v, app_point2 o, app_point2 u, app_point2 n,
                      double s0, double s1, double d0, double d1)
{
    double ss[4] = {s0, s1, s1, s0}, dd[4] = {d0, d0, d1, d1};
    for (int k = 0; k < 4; k++) {
        double x = o.x + u.x * ss[k] + n.x * dd[k], y = o.y + u.y * ss[k] + n.y * dd[k];
        if (k == 0)
            cairo_move_to(cr, px(v, x, y), py(v, x, y));
        else
            cairo_line_to(cr, px(v, x, y), py(v, x, y));
    }
    cairo_close_path(cr);
}

static void wall_line(cairo_t *cr, const pr_view *v, app_point2 o, app_point2 u, app_point2 n,
                      double s0, double d0, double s1, double d1)
{
    cairo_move_to(cr, px(v, o.x + u.x * s0 + n.x * d0, o.y + u.y * s0 + n.y * d0),
                  py(v, o.x + u.x * s0 + n.x * d0, o.y + u.y * s0 + n.y * d0));
    cairo_line_to(cr, px(v, o.x + u.x * s1 + n.x * d1, o.y + u.y * s1 + n.y * d1),
                  py(v, o.x + u.x * s1 + n.x * d1, o.y + u.y * s1 + n.y * d1));
}

static void draw_openings(pr_doc *d, const pr_view *v)
{
    cairo_t *cr = d->cr;
    const app_room_plan *pl = &d->plan;
    double t = pl->wall_thickness_mm;
    for (int k = 0; k < pl->opening_count; k++) {
        const app_opening *op = &pl->openings[k];
        if (op->wall < 0 || op->wall >= pl->corner_count)
            continue;
        app_point2 o, u, n;
        double len;
        wall_frame(pl, op->wall, &o, &u, &n, &len);
        double s0 = op->offset_mm, s1 = op->offset_mm + op->width_mm;
        /* Cut the wall: white over the thickness, then the jambs. */
        cairo_set_source_rgb(cr, 1, 1, 1);
        wall_quad(cr, v, o, u, n, s0, s1, 0.5, -t - 0.5);
        cairo_fill(cr);
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_set_line_width(cr, PR_LINE_HEAVY);
        wall_line(cr, v, o, u, n, s0, 0, s0, -t);
        wall_line(cr, v, o, u, n, s1, 0, s1, -t);
        cairo_stroke(cr);
        if (op->type == APP_OPENING_WINDOW) {
            /* Sill lines on both faces, the frame as a double line in the middle. */
            cairo_set_line_width(cr, PR_LINE_FINE);
            wall_line(cr, v, o, u, n, s0, 0, s1, 0);
            wall_line(cr, v, o, u, n, s0, -t, s1, -t);
            cairo_stroke(cr);
            cairo_set_line_width(cr, PR_LINE_MEDIUM);
            wall_line(cr, v, o, u, n, s0, -t * 0.42, s1, -t * 0.42);
            wall_line(cr, v, o, u, n, s0, -t * 0.58, s1, -t * 0.58);
            cairo_stroke(cr);
            continue;
        }
        /* Doors. The hinge side is named as seen from inside the room facing the wall, where
         * s grows to the viewer's left: hinge left = the s1 end. */
        cairo_set_line_width(cr, PR_LINE_MEDIUM);
        if (op->swing == APP_SWING_SLIDING) {
            wall_quad(cr, v, o, u, n, s0, s1, 20, 60);
            cairo_stroke(cr);
            continue;
        }
        int left = op->swing == APP_SWING_IN_LEFT || op->swing == APP_SWING_OUT_LEFT;
        int in = op->swing == APP_SWING_IN_LEFT || op->swing == APP_SWING_IN_RIGHT;
        double hinge = left ? s1 : s0, free_end = left ? s0 : s1;
        double face = in ? 0.0 : -t, dir = in ? 1.0 : -1.0, w = op->width_mm;
        /* The leaf, open at 90 degrees. */
        cairo_set_line_width(cr, PR_LINE_WIDE);
        wall_line(cr, v, o, u, n, hinge, face, hinge, face + dir * w);
        cairo_stroke(cr);
        /* The swing: a quarter circle from the leaf's end to the free jamb. */
        cairo_set_line_width(cr, PR_LINE_THIN);
        const int segs = 24;
        for (int i = 0; i <= segs; i++) {
            double a = (PR_PI / 2) * i / segs;
            double s = hinge + (free_end - hinge) * sin(a);
            double dd = face + dir * w * cos(a);
            double x = o.x + u.x * s + n.x * dd, y = o.y + u.y * s + n.y * dd;
            if (i == 0)
                cairo_move_to(cr, px(v, x, y), py(v, x, y));
            else
                cairo_line_to(cr, px(v, x, y), py(v, x, y));
        }
        cairo_stroke(cr);
    }
}

/* Niches: cut into the wall's section from its inside face, dashed (above the plan's cut). */
static void draw_niches(pr_doc *d, const pr_view *v)
{
    cairo_t *cr = d->cr;
    const app_room_plan *pl = &d->plan;
    for (int k = 0; k < pl->niche_count; k++) {
        const app_niche *ni = &pl->niches[k];
        if (ni->wall < 0 || ni->wall >= pl->corner_count)
            continue;
        app_point2 o, u, n;
        double len;
        wall_frame(pl, ni->wall, &o, &u, &n, &len);
        wall_quad(cr, v, o, u, n, ni->offset_mm, ni->offset_mm + ni->width_mm, 0.3, -ni->depth_mm);
        cairo_set_source_rgb(cr, 1, 1, 1);
        cairo_fill_preserve(cr);
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_set_line_width(cr, PR_LINE_FINE);
        const double dash[2] = {1.5, 0.8};
        cairo_set_dash(cr, dash, 2, 0);
        cairo_stroke(cr);
        cairo_set_dash(cr, NULL, 0, 0);
    }
}

static void draw_prewalls(pr_doc *d, const pr_view *v)
{
    cairo_t *cr = d->cr;
    const app_room_plan *pl = &d->plan;
    for (int k = 0; k < pl->prewall_count; k++) {
        const app_prewall *pw = &pl->prewalls[k];
        if (pw->wall < 0 || pw->wall >= pl->corner_count)
            continue;
        app_point2 o, u, n;
        double len;
        wall_frame(pl, pw->wall, &o, &u, &n, &len);
        wall_quad(cr, v, o, u, n, pw->offset_mm, pw->offset_mm + pw->width_mm, 0, pw->depth_mm);
        cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
        cairo_fill_preserve(cr);
        cairo_set_source_rgb(cr, 0.45, 0.45, 0.45);
        cairo_set_line_width(cr, PR_LINE_THIN);
        pr_hatch_path(cr, 1.2, 45);
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_set_line_width(cr, PR_LINE_WIDE);
        cairo_stroke(cr);
    }
}

static void draw_walls(pr_doc *d, const pr_view *v, const app_point2 *outer)
{
    cairo_t *cr = d->cr;
    const app_room_plan *pl = &d->plan;
    int n = pl->corner_count;
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
    for (int i = 0; i < n; i++)
        (i ? cairo_line_to : cairo_move_to)(cr, px(v, outer[i].x, outer[i].y),
                                            py(v, outer[i].x, outer[i].y));
    cairo_close_path(cr);
    for (int i = 0; i < n; i++)
        (i ? cairo_line_to : cairo_move_to)(cr, px(v, pl->corners[i].x, pl->corners[i].y),
                                            py(v, pl->corners[i].x, pl->corners[i].y));
    cairo_close_path(cr);
    /* Cut walls: a mid grey with a light hatch, heavy outlines (ISO 128-50 for sections). */
    cairo_set_source_rgb(cr, 0.62, 0.62, 0.62);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
    cairo_set_line_width(cr, PR_LINE_THIN);
    pr_hatch_path(cr, 1.0, 45);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, PR_LINE_HEAVY);
    cairo_stroke(cr);
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
}

/* Hull of a fixture's footprint (all parts below 1800 mm, else all). */
static int fixture_hull(const pr_fixture *f, app_point2 **out)
{
    int total = 0;
    for (int q = 0; q < f->part_count; q++)
        total += f->parts[q].count;
    app_point2 *pts = malloc((size_t)(total + 1) * sizeof *pts);
    app_point2 *hull = malloc((size_t)(total + 2) * sizeof *hull);
    if (!pts || !hull) {
        free(pts);
        free(hull);
        return 0;
    }
    int n = 0;
    for (int q = 0; q < f->part_count; q++)
        for (int i = 0; i < f->parts[q].count; i++)
            pts[n++] = (app_point2){f->parts[q].pts[i][0], f->parts[q].pts[i][1]};
    int h = pr_convex_hull(pts, n, hull);
    free(pts);
    *out = hull;
    return h;
}

/* The wall a fixture stands against: the one whose inside face is nearest to its footprint
 * (among walls the footprint overlaps along their length). Returns -1 if none. */
static int nearest_wall(const app_room_plan *pl, const app_point2 *hull, int h, int skip_dir_of,
                        double *dist_out, double *s_lo, double *s_hi)
{
    int best = -1;
    double best_d = 1e300;
    for (int i = 0; i < pl->corner_count; i++) {
        app_point2 o, u, n;
        double len;
        wall_frame(pl, i, &o, &u, &n, &len);
        if (skip_dir_of >= 0) {
            app_point2 o2, u2, n2;
            double l2;
            wall_frame(pl, skip_dir_of, &o2, &u2, &n2, &l2);
            if (fabs(u.x * u2.x + u.y * u2.y) > 0.5)
                continue;
        }
        double dmin = 1e300, lo = 1e300, hi = -1e300;
        for (int k = 0; k < h; k++) {
            double rx = hull[k].x - o.x, ry = hull[k].y - o.y;
            double s = rx * u.x + ry * u.y, dd = rx * n.x + ry * n.y;
            dmin = dd < dmin ? dd : dmin;
            lo = s < lo ? s : lo;
            hi = s > hi ? s : hi;
        }
        if (hi < 0 || lo > len || dmin < -1.0)
            continue;
        /* Nearest wins; near-ties (a fixture in a corner touches two walls) go to the wall
         * the fixture runs along the most, the one it stands against (a bath's long side). */
        double overlap = fmin(hi, len) - fmax(lo, 0.0);
        if (best < 0 || dmin < best_d - 10.0 ||
            (dmin < best_d + 10.0 && overlap > *s_hi - *s_lo + 1e-9)) {
            best_d = dmin;
            best = i;
            *s_lo = fmax(lo, 0.0);
            *s_hi = fmin(hi, len);
        }
    }
    *dist_out = best_d;
    return best;
}

/* The free area in front of each fixture (DOMAIN.md "Clearances") where `tessera check`
 * places it (app_free_areas): the checks' sizes, slid sideways to stay inside the room and
 * clear of furniture, so the drawing shows what the check accepted. Without the catalog's
 * product sizes the fixtures cannot be built and no area is drawn (nor could it be checked). */
static void draw_clearances(pr_doc *d, const pr_view *v, int labels)
{
    cairo_t *cr = d->cr;
    app_fixture *fx = NULL;
    app_free_area *areas = NULL;
    int n = 0;
    char err[1024];
    app_result r = app_placement_fixtures(d->p, d->db ? app_placement_catalog_lookup : NULL, d->db,
                                          &fx, &n, err, sizeof err);
    if (r == APP_OK) {
        areas = malloc((size_t)(n > 0 ? n : 1) * sizeof *areas);
        if (!areas) {
            r = APP_ERR_OUT_OF_MEMORY;
            snprintf(err, sizeof err, "out of memory");
        }
    }
    if (r == APP_OK)
        r = app_free_areas(d->p, fx, n, APP_BARRIER_FREE_OFF, areas, err, sizeof err);
    if (r != APP_OK) {
        if (d->o->verbose)
            fprintf(stderr, "tessera print: no clearance areas: %s\n", err);
        free(areas);
        free(fx);
        return;
    }
    for (int i = 0; i < n; i++) {
        const app_free_area *a = &areas[i];
        if (!a->has_area)
            continue;
        double cx = 0, cy = 0;
        for (int k = 0; k < 4; k++) {
            cx += a->corners[k][0] / 4;
            cy += a->corners[k][1] / 4;
        }
        if (labels) {
            /* Its size inside it, moved across the area when texts are in the way, left out
             * (the hatch stays, the legend explains it) when the area has no free spot. */
            char text[64];
            snprintf(text, sizeof text, "free %.0f x %.0f", a->width_mm, a->depth_mm);
            pr_set_font(cr, 1.8, 0);
            cairo_set_source_rgb(cr, 0.2, 0.4, 0.6);
            double x = px(v, cx, cy), y = py(v, cx, cy);
            double hw = fabs(px(v, a->corners[0][0], a->corners[0][1]) - x);
            double hh = fabs(py(v, a->corners[0][0], a->corners[0][1]) - y);
            static const double moves[][2] = {{0, 0},  {0, -1}, {0, 1},   {-1, 0},  {1, 0},
                                              {0, -2}, {0, 2},  {-1, -1}, {1, 1},   {-1, 1},
                                              {1, -1}, {0, -3}, {0, 3},   {-2, -2}, {2, 2}};
            for (size_t m = 0; m < sizeof moves / sizeof moves[0]; m++) {
                double tx = x + moves[m][0] * 3.0, ty = y + moves[m][1] * 2.5;
                if (fabs(tx - x) > hw || fabs(ty - y) > hh)
                    continue;
                if (pr_box_is_free(cr, pr_text_measure(cr, tx, ty, 0, 0.5, 0.5, text), 0.4)) {
                    pr_text(cr, tx, ty, 0.5, 0.5, text);
                    break;
                }
            }
            continue;
        }
        d->clearances_drawn++;
        cairo_new_path(cr);
        for (int k = 0; k < 4; k++)
            cairo_line_to(cr, px(v, a->corners[k][0], a->corners[k][1]),
                          py(v, a->corners[k][0], a->corners[k][1]));
        cairo_close_path(cr);
        cairo_set_source_rgb(cr, 0.55, 0.7, 0.85);
        cairo_set_line_width(cr, PR_LINE_THIN);
        pr_hatch_path(cr, 2.0, 135);
        const double dash[2] = {2.0, 1.0};
        cairo_set_dash(cr, dash, 2, 0);
        cairo_stroke(cr);
        cairo_set_dash(cr, NULL, 0, 0);
    }
    cairo_set_source_rgb(cr, 0, 0, 0);
    free(areas);
    free(fx);
}

/* The floor's tile layout as light joints under everything else (s, t = plan x, y). */
static void draw_floor_tiles(pr_doc *d, const pr_view *v)
{
    cairo_t *cr = d->cr;
    for (int li = 0; li < d->layout_count; li++) {
        const app_tile_layout *l = &d->layouts[li];
        if (strcmp(l->surface, "floor") != 0)
            continue;
        for (int i = 0; i < l->tile_count; i++) {
            const app_placed_tile *pt = &l->tiles[i];
            for (int q = 0; q < pt->piece_count; q++) {
                const app_tile_piece *pc = &l->pieces[pt->first_piece + q];
                for (int k = 0; k < pc->count; k++) {
                    if (l->edges[pc->first + k] == APP_EDGE_SEAM)
                        continue;
                    app_point2 a = l->points[pc->first + k];
                    app_point2 b = l->points[pc->first + (k + 1) % pc->count];
                    cairo_move_to(cr, px(v, a.x, a.y), py(v, a.x, a.y));
                    cairo_line_to(cr, px(v, b.x, b.y), py(v, b.x, b.y));
                }
            }
        }
        cairo_set_source_rgb(cr, 0.72, 0.72, 0.72);
        cairo_set_line_width(cr, 0.1);
        cairo_stroke(cr);
    }
    cairo_set_source_rgb(cr, 0, 0, 0);
}

typedef struct part_ref {
    int fixture, part;
    double top, bottom;
} part_ref;

static int cmp_top(const void *a, const void *b)
{
    const part_ref *p = a, *q = b;
    return p->top < q->top ? -1 : p->top > q->top;
}

/* Parts in order of their top, lowest first, so what is higher covers what is under it, as
 * seen from above. Overhead parts (bottom above 1800 mm: lamps, shower heads) are dashed. */
static int draw_fixtures(pr_doc *d, const pr_view *v)
{
    cairo_t *cr = d->cr;
    int total = 0, drawn = 0;
    for (int i = 0; i < d->fixture_count; i++)
        total += d->fixtures[i].part_count;
    part_ref *refs = malloc((size_t)(total + 1) * sizeof *refs);
    if (!refs)
        return 0;
    int n = 0;
    for (int i = 0; i < d->fixture_count; i++)
        for (int q = 0; q < d->fixtures[i].part_count; q++) {
            const pr_part *pp = &d->fixtures[i].parts[q];
            double top = -1e300, bottom = 1e300;
            for (int k = 0; k < pp->count; k++) {
                top = pp->pts[k][2] > top ? pp->pts[k][2] : top;
                bottom = pp->pts[k][2] < bottom ? pp->pts[k][2] : bottom;
            }
            refs[n++] = (part_ref){i, q, top, bottom};
        }
    qsort(refs, (size_t)n, sizeof *refs, cmp_top);
    for (int r = 0; r < n; r++) {
        const pr_part *pp = &d->fixtures[refs[r].fixture].parts[refs[r].part];
        app_point2 *pts = malloc((size_t)(pp->count + 1) * sizeof *pts);
        app_point2 *hull = malloc((size_t)(pp->count + 2) * sizeof *hull);
        if (pts && hull && pp->count > 0) {
            for (int k = 0; k < pp->count; k++)
                pts[k] = (app_point2){pp->pts[k][0], pp->pts[k][1]};
            int h = pr_convex_hull(pts, pp->count, hull);
            for (int k = 0; k < h; k++)
                (k ? cairo_line_to : cairo_move_to)(cr, px(v, hull[k].x, hull[k].y),
                                                    py(v, hull[k].x, hull[k].y));
            cairo_close_path(cr);
            int overhead = refs[r].bottom > 1800.0;
            if (!overhead) {
                cairo_set_source_rgb(cr, 1, 1, 1);
                cairo_fill_preserve(cr);
            }
            cairo_set_source_rgb(cr, 0, 0, 0);
            cairo_set_line_width(cr, overhead ? PR_LINE_THIN : PR_LINE_MEDIUM);
            const double dash[2] = {1.2, 0.8};
            if (overhead)
                cairo_set_dash(cr, dash, 2, 0);
            cairo_stroke(cr);
            cairo_set_dash(cr, NULL, 0, 0);
        }
        free(pts);
        free(hull);
    }
    free(refs);
    for (int i = 0; i < d->fixture_count; i++)
        drawn += d->fixtures[i].part_count > 0;
    return drawn;
}

/* The fixtures' numbers (the legend names them), drawn after the walls and dimensions. */
static void draw_fixture_labels(pr_doc *d, const pr_view *v)
{
    cairo_t *cr = d->cr;
    /* Numbers last, in white circles, so no outline crosses them. Larger fixtures first, at
     * their middle; a number whose place is taken moves out on a leader, and one that finds
     * no free place is only in the legend. */
    int *order = malloc((size_t)(d->fixture_count + 1) * sizeof *order);
    if (!order)
        return;
    int nl = 0;
    for (int i = 0; i < d->fixture_count; i++)
        if (d->fixtures[i].part_count > 0)
            order[nl++] = i;
    for (int a = 1; a < nl; a++) /* insertion sort by footprint, largest first */
        for (int b = a; b > 0; b--) {
            const pr_fixture *p0 = &d->fixtures[order[b - 1]], *p1 = &d->fixtures[order[b]];
            double a0 = (p0->max[0] - p0->min[0]) * (p0->max[1] - p0->min[1]);
            double a1 = (p1->max[0] - p1->min[0]) * (p1->max[1] - p1->min[1]);
            if (a1 <= a0)
                break;
            int t = order[b];
            order[b] = order[b - 1];
            order[b - 1] = t;
        }
    pr_box within = {d->area_x, d->area_y, d->area_x + d->area_w, d->area_y + d->area_h};
    for (int r = 0; r < nl; r++) {
        pr_fixture *f = &d->fixtures[order[r]];
        if (!f->number)
            continue;
        double fx = (f->min[0] + f->max[0]) / 2, fy = (f->min[1] + f->max[1]) / 2;
        f->number_placed = pr_place_balloon(cr, px(v, fx, fy), py(v, fx, fy), f->number, within);
    }
    free(order);
}

/* Distances from each floor fixture to its nearest wall and to the nearest wall across. */
static void draw_fixture_distances(pr_doc *d, const pr_view *v)
{
    for (int i = 0; i < d->fixture_count; i++) {
        const pr_fixture *f = &d->fixtures[i];
        double area = (f->max[0] - f->min[0]) * (f->max[1] - f->min[1]);
        /* Floor fixtures only: not what hangs above 1200 mm, not flat things (a mat). */
        if (f->part_count == 0 || f->min[2] > 1200.0 || f->max[2] - f->min[2] < 100.0 ||
            (area < 90000.0 && !f->has_product))
            continue;
        /* A fixture standing on another (a mixer on its basin) is placed by that one. */
        int on_other = 0;
        for (int j = 0; j < d->fixture_count && !on_other; j++) {
            const pr_fixture *g = &d->fixtures[j];
            on_other = j != i && g->part_count > 0 && g->min[0] <= f->min[0] &&
                       g->max[0] >= f->max[0] && g->min[1] <= f->min[1] && g->max[1] >= f->max[1] &&
                       g->max[2] <= f->min[2] + 50.0 &&
                       (g->max[0] - g->min[0]) * (g->max[1] - g->min[1]) > area;
        }
        if (on_other)
            continue;
        app_point2 *hull = NULL;
        int h = fixture_hull(f, &hull);
        if (h < 3) {
            free(hull);
            continue;
        }
        double dist, lo, hi;
        int w1 = nearest_wall(&d->plan, hull, h, -1, &dist, &lo, &hi);
        int w2 = w1 >= 0 ? nearest_wall(&d->plan, hull, h, w1, &dist, &lo, &hi) : -1;
        int walls[2] = {w1, w2};
        for (int k = 0; k < 2; k++) {
            if (walls[k] < 0)
                continue;
            app_point2 o, u, n;
            double len;
            wall_frame(&d->plan, walls[k], &o, &u, &n, &len);
            /* The hull point nearest the wall; the dimension runs square to the wall. */
            int best = 0;
            double bd = 1e300;
            for (int j = 0; j < h; j++) {
                double dd = (hull[j].x - o.x) * n.x + (hull[j].y - o.y) * n.y;
                if (dd < bd) {
                    bd = dd;
                    best = j;
                }
            }
            double s = (hull[best].x - o.x) * u.x + (hull[best].y - o.y) * u.y;
            /* In front of a pre-wall the distance that matters is to its face. */
            double face = 0.0;
            for (int q = 0; q < d->plan.prewall_count; q++) {
                const app_prewall *pw = &d->plan.prewalls[q];
                if (pw->wall == walls[k] && s >= pw->offset_mm - 1e-6 &&
                    s <= pw->offset_mm + pw->width_mm + 1e-6 && pw->depth_mm <= bd + 1.0)
                    face = pw->depth_mm > face ? pw->depth_mm : face;
            }
            bd -= face;
            if (bd < 5.0)
                continue; /* standing against the wall */
            double fx = o.x + u.x * s + n.x * face, fy = o.y + u.y * s + n.y * face;
            /* A value landing on another text moves the dimension sideways, with extension
             * lines from the fixture and the wall. */
            double ax = px(v, fx, fy), ay = py(v, fx, fy);
            double bx = px(v, fx + n.x * bd, fy + n.y * bd),
                   by = py(v, fx + n.x * bd, fy + n.y * bd);
            static const double shifts[] = {0, 3, -3, 6, -6, 9, -9, 12, -12};
            double shift = 0;
            for (size_t q = 0; q < sizeof shifts / sizeof shifts[0]; q++) {
                int mark = pr_text_boxes_mark(d->cr);
                int ok = pr_dimension_placed(d->cr, ax, ay, bx, by, shifts[q], bd, 0);
                pr_text_boxes_rollback(d->cr, mark);
                if (ok) {
                    shift = shifts[q];
                    break;
                }
            }
            pr_dimension(d->cr, ax, ay, bx, by, shift, bd);
        }
        free(hull);
    }
}

/* One wall's chains at `step` mm further out than their places: the openings' and pre-walls'
 * stops inside, the wall's length outside. Returns 1 when every value found a free place. */
static int chain_pass(pr_doc *d, const pr_view *v, app_point2 o, app_point2 u, const double *stops,
                      int ns, double len, double t, double step, int draw)
{
    int ok = 1;
    if (ns > 2)
        for (int k = 0; k + 1 < ns; k++) {
            double s0 = stops[k], s1 = stops[k + 1];
            if (s1 - s0 < 1.0)
                continue;
            double x0 = o.x + u.x * s0, y0 = o.y + u.y * s0, x1 = o.x + u.x * s1,
                   y1 = o.y + u.y * s1;
            ok &= pr_dimension_placed(d->cr, px(v, x0, y0), py(v, x0, y0), px(v, x1, y1),
                                      py(v, x1, y1), -(t + 5.0 + step), s1 - s0, draw);
        }
    double x1 = o.x + u.x * len, y1 = o.y + u.y * len;
    ok &= pr_dimension_placed(d->cr, px(v, o.x, o.y), py(v, o.x, o.y), px(v, x1, y1), py(v, x1, y1),
                              -(t + (ns > 2 ? 10.5 : 5.0) + step), len, draw);
    return ok;
}

/* Wall lengths outside the walls, with the openings and pre-walls as an inner chain. */
static void draw_wall_dimensions(pr_doc *d, const pr_view *v)
{
    const app_room_plan *pl = &d->plan;
    double t = pl->wall_thickness_mm / v->n;
    for (int i = 0; i < pl->corner_count; i++) {
        app_point2 o, u, n;
        double len;
        wall_frame(pl, i, &o, &u, &n, &len);
        double stops[2 + 4 * 64];
        int ns = 0;
        stops[ns++] = 0;
        for (int k = 0; k < pl->opening_count && ns < 2 + 4 * 64 - 2; k++)
            if (pl->openings[k].wall == i) {
                stops[ns++] = pl->openings[k].offset_mm;
                stops[ns++] = pl->openings[k].offset_mm + pl->openings[k].width_mm;
            }
        for (int k = 0; k < pl->prewall_count && ns < 2 + 4 * 64 - 2; k++)
            if (pl->prewalls[k].wall == i) {
                stops[ns++] = pl->prewalls[k].offset_mm;
                stops[ns++] = pl->prewalls[k].offset_mm + pl->prewalls[k].width_mm;
            }
        stops[ns++] = len;
        /* Sort (insertion; a handful of stops). */
        for (int a = 1; a < ns; a++)
            for (int b = a; b > 0 && stops[b] < stops[b - 1]; b--) {
                double tmp = stops[b];
                stops[b] = stops[b - 1];
                stops[b - 1] = tmp;
            }
        /* The interior lies to the left of a->b on paper as in the world (the page is not
         * mirrored), so outward is a negative offset. A chain whose values would land on texts
         * already drawn moves outwards, a step at a time, the overall length with it. */
        int attempt;
        for (attempt = 0; attempt < 4; attempt++) {
            int mark = pr_text_boxes_mark(d->cr);
            int ok = chain_pass(d, v, o, u, stops, ns, len, t, 4.0 * attempt, 0);
            pr_text_boxes_rollback(d->cr, mark);
            if (ok)
                break;
        }
        chain_pass(d, v, o, u, stops, ns, len, t, attempt < 4 ? 4.0 * attempt : 0.0, 1);
    }
}

/* "corner N" beyond each outer corner, on the corner's outward diagonal, so the plan reads
 * against the elevations (which name the corners at each face's ends) and the legend's start. */
static void draw_corner_names(pr_doc *d, const pr_view *v, const app_point2 *outer)
{
    cairo_t *cr = d->cr;
    const app_room_plan *pl = &d->plan;
    pr_set_font(cr, PR_TEXT_SMALL, 1);
    cairo_set_source_rgb(cr, 0, 0, 0);
    for (int i = 0; i < pl->corner_count; i++) {
        double ix = px(v, pl->corners[i].x, pl->corners[i].y),
               iy = py(v, pl->corners[i].x, pl->corners[i].y);
        double ox = px(v, outer[i].x, outer[i].y), oy = py(v, outer[i].x, outer[i].y);
        double dx = ox - ix, dy = oy - iy, l = hypot(dx, dy);
        if (l < 1e-9)
            continue;
        dx /= l;
        dy /= l;
        char text[32];
        snprintf(text, sizeof text, "corner %d", i + 1);
        /* The text grows away from the drawing: anchored at its end nearest the corner. */
        double ax = dx >= 0 ? 0.0 : 1.0, ay = dy >= 0 ? 0.0 : 1.0;
        static const double dists[] = {1.5, 3.5, 6.0, 9.0, 12.0};
        for (size_t k = 0; k < sizeof dists / sizeof dists[0]; k++) {
            double tx = ox + dx * dists[k], ty = oy + dy * dists[k];
            if (pr_box_is_free(cr, pr_text_measure(cr, tx, ty, 0, ax, ay, text), 0.4)) {
                pr_text(cr, tx, ty, ax, ay, text);
                break;
            }
        }
    }
}

static int is_axis_rectangle(const app_room_plan *pl)
{
    if (pl->corner_count != 4)
        return 0;
    for (int i = 0; i < 4; i++) {
        app_point2 a = pl->corners[i], b = pl->corners[(i + 1) % 4];
        if (fabs(a.x - b.x) > 1e-6 && fabs(a.y - b.y) > 1e-6)
            return 0;
    }
    return 1;
}

/* Room for the dimension chains outside each wall, in paper mm (the value's text included):
 * one chain (wall lengths) ~8 mm, a second (openings, pre-walls) ~14 mm; a room that is not an
 * axis-aligned rectangle also has its overall size at ~17 mm on every side. Sides are the world's
 * bottom, right, top and left. */
static void side_borders(const app_room_plan *pl, double border[4])
{
    if (!is_axis_rectangle(pl)) {
        for (int k = 0; k < 4; k++)
            border[k] = 17.0;
        return;
    }
    for (int k = 0; k < 4; k++)
        border[k] = 8.0;
    for (int i = 0; i < 4; i++) {
        app_point2 o, u, n;
        double len;
        wall_frame(pl, i, &o, &u, &n, &len);
        int busy = 0;
        for (int k = 0; k < pl->opening_count; k++)
            busy |= pl->openings[k].wall == i;
        for (int k = 0; k < pl->prewall_count; k++)
            busy |= pl->prewalls[k].wall == i;
        /* The outward normal -n names the side. */
        int side = -n.y < -0.5 ? 0 : (-n.x > 0.5 ? 1 : (-n.y > 0.5 ? 2 : 3));
        if (busy)
            border[side] = 14.0;
    }
}

typedef struct plan_layout {
    int scale, turned;
    int legend_below; /* 0: the legend stands right of the drawing */
    double w, h;      /* the drawing with its chains, paper mm */
    double left, top; /* the chains' room on the paper's left and top */
} plan_layout;

/* The drawing's paper size at 1:n, turned or not; returns 1 when it fits beside (or under) the
 * legend in the drawing area. */
static int layout_fits(const pr_doc *d, const double ext[4], const double border[4], int n,
                       int turned, double lw, double lh, plan_layout *out)
{
    double ww = (ext[2] - ext[0]) / n, wh = (ext[3] - ext[1]) / n;
    plan_layout l = {.scale = n, .turned = turned};
    if (!turned) { /* paper left/right/top/bottom = world left/right/top/bottom */
        l.w = ww + border[3] + border[1];
        l.h = wh + border[2] + border[0];
        l.left = border[3];
        l.top = border[2];
    } else { /* turned a quarter counter-clockwise: world top to the left, right to the top */
        l.w = wh + border[2] + border[0];
        l.h = ww + border[3] + border[1];
        l.left = border[2];
        l.top = border[1];
    }
    const double gap = 5.0;
    if (l.w + gap + lw <= d->area_w && l.h <= d->area_h && lh <= d->area_h) {
        *out = l;
        return 1;
    }
    if (l.h + gap + lh <= d->area_h && l.w <= d->area_w && lw <= d->area_w) {
        l.legend_below = 1;
        *out = l;
        return 1;
    }
    *out = l;
    return 0;
}

/* The largest standard scale at which the plan and its legend fit the sheet, the plan turned a
 * quarter when that gives a larger scale (a long room on a landscape sheet); the forced scale
 * when --scale gives one. */
static plan_layout choose_layout(pr_doc *d, const double ext[4], double lw, double lh, int *fits)
{
    double border[4];
    side_borders(&d->plan, border);
    plan_layout l;
    if (d->o->scale > 0) {
        *fits = layout_fits(d, ext, border, d->o->scale, 0, lw, lh, &l) ||
                layout_fits(d, ext, border, d->o->scale, 1, lw, lh, &l);
        if (!*fits)
            layout_fits(d, ext, border, d->o->scale, 0, lw, lh, &l);
        return l;
    }
    for (int i = 0; i < APP_PRINT_SCALE_COUNT; i++)
        for (int turned = 0; turned < 2; turned++)
            if (layout_fits(d, ext, border, app_print_scales[i], turned, lw, lh, &l)) {
                *fits = 1;
                return l;
            }
    *fits = 0;
    layout_fits(d, ext, border, app_print_scales[APP_PRINT_SCALE_COUNT - 1], 0, lw, lh, &l);
    return l;
}

app_result pr_draw_plan(pr_doc *d)
{
    const app_room_plan *pl = &d->plan;
    int n = pl->corner_count;
    app_point2 *outer = malloc((size_t)n * sizeof *outer);
    if (!outer) {
        snprintf(d->err, d->err_size, "print: out of memory");
        return APP_ERR_OUT_OF_MEMORY;
    }
    pr_offset_polygon(pl->corners, n, pl->wall_thickness_mm, outer);
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (int i = 0; i < n; i++) {
        x0 = outer[i].x < x0 ? outer[i].x : x0;
        x1 = outer[i].x > x1 ? outer[i].x : x1;
        y0 = outer[i].y < y0 ? outer[i].y : y0;
        y1 = outer[i].y > y1 ? outer[i].y : y1;
    }
    /* The legend's size, measured on a scratch context (an SVG page's context is made by
     * pr_page_begin, after the scale is known). */
    double lw = 0, lh = 0;
    cairo_surface_t *scratch = cairo_recording_surface_create(CAIRO_CONTENT_COLOR_ALPHA, NULL);
    cairo_t *mcr = cairo_create(scratch);
    pr_legend_size(d, mcr, &lw, &lh);
    cairo_destroy(mcr);
    cairo_surface_destroy(scratch);
    const double ext[4] = {x0, y0, x1, y1};
    int fits = 0;
    plan_layout lay = choose_layout(d, ext, lw, lh, &fits);
    int scale = lay.scale;
    if (d->o->verbose && !fits)
        fprintf(stderr, "tessera print: the plan does not fit the paper at 1:%d\n", scale);
    if (d->report)
        d->report->plan_scale = scale;
    app_result r = pr_page_begin(d, "Floor plan", scale);
    if (r != APP_OK) {
        free(outer);
        return r;
    }
    /* The drawing centred in what the legend leaves; the legend at the top right, or under it. */
    double region_w = lay.legend_below ? d->area_w : d->area_w - lw - 5.0;
    double region_h = lay.legend_below ? d->area_h - lh - 5.0 : d->area_h;
    double dl = d->area_x + (region_w - lay.w) / 2 + lay.left;
    double dt = d->area_y + (region_h - lay.h) / 2 + lay.top;
    pr_view v = {.n = scale, .turned = lay.turned};
    if (!lay.turned) {
        v.ox = dl - x0 / scale;
        v.oy = dt + y1 / scale;
    } else {
        v.ox = dl + y1 / scale;
        v.oy = dt + x1 / scale;
    }
    double legend_x =
        lay.legend_below ? d->area_x + (d->area_w - lw) / 2 : d->area_x + d->area_w - lw;
    double legend_y = lay.legend_below ? d->area_y + d->area_h - lh : d->area_y;
    cairo_t *cr = d->cr;
    cairo_save(cr);
    cairo_rectangle(cr, d->area_x - 4, d->area_y - 4, d->area_w + 8, d->area_h + 8);
    cairo_clip(cr);
    /* The legend's block is kept clear of the plan's labels. */
    pr_box_reserve(cr, pr_box_to_paper(cr, legend_x - 1.0, legend_y - 1.0, legend_x + lw + 1.0,
                                       legend_y + lh + 1.0));
    draw_floor_tiles(d, &v);
    if (!d->o->no_clearances)
        draw_clearances(d, &v, 0);
    int drawn = draw_fixtures(d, &v);
    if (d->report)
        d->report->fixtures = drawn;
    draw_prewalls(d, &v);
    draw_walls(d, &v, outer);
    draw_niches(d, &v);
    draw_openings(d, &v);
    draw_wall_dimensions(d, &v);
    if (!is_axis_rectangle(pl)) {
        double ix0 = 1e300, iy0 = 1e300, ix1 = -1e300, iy1 = -1e300;
        for (int i = 0; i < n; i++) {
            ix0 = pl->corners[i].x < ix0 ? pl->corners[i].x : ix0;
            ix1 = pl->corners[i].x > ix1 ? pl->corners[i].x : ix1;
            iy0 = pl->corners[i].y < iy0 ? pl->corners[i].y : iy0;
            iy1 = pl->corners[i].y > iy1 ? pl->corners[i].y : iy1;
        }
        /* Overall inside size below and left of everything else. */
        pr_dimension(cr, px(&v, ix0, y0), py(&v, ix0, y0), px(&v, ix1, y0), py(&v, ix1, y0), -16.0,
                     ix1 - ix0);
        pr_dimension(cr, px(&v, x0, iy0), py(&v, x0, iy0), px(&v, x0, iy1), py(&v, x0, iy1), 16.0,
                     iy1 - iy0);
    }
    draw_corner_names(d, &v, outer);
    draw_fixture_distances(d, &v);
    draw_fixture_labels(d, &v);
    if (!d->o->no_clearances)
        draw_clearances(d, &v, 1);
    pr_legend_draw(d, legend_x, legend_y, scale);
    cairo_restore(cr);
    free(outer);
    return pr_page_end(d);
}
