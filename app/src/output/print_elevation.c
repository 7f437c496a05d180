/* Wall elevations: each wall (and each pre-wall's front) seen from inside the room, unfolded,
 * with its exact tile layout (tile_layout.h: whole tiles in the tile's colour, cut tiles
 * hatched with their cut edges drawn heavier, the grout between them), the openings, the
 * fixtures near the wall as side silhouettes, and height dimensions: the tile rows, the room
 * height, level marks at the top of each fixture (basin rim, WC, shower head) and at the
 * openings' sill and head. Seen from inside, a wall's s coordinate grows to the left. */
#include "print_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* What elevation `index` shows: wall i < corner_count, then pre-wall fronts. */
typedef struct elev {
    char surface[96];
    char title[128];
    app_point2 o, u, n;        /* plan frame of the face: s = 0, along, inward normal */
    double s0, length, height; /* the face spans s0 .. s0 + length (room_surfaces.h frames) */
    double depth;              /* pre-walls: the face stands this far in front of the wall */
} elev;

int pr_elevation_count(const pr_doc *d)
{
    return d->plan.corner_count + d->plan.prewall_count;
}

static void elev_of(const pr_doc *d, int index, elev *e)
{
    const app_room_plan *pl = &d->plan;
    memset(e, 0, sizeof *e);
    int wall = index < pl->corner_count ? index : pl->prewalls[index - pl->corner_count].wall;
    app_point2 a = pl->corners[wall], b = pl->corners[(wall + 1) % pl->corner_count];
    double l = hypot(b.x - a.x, b.y - a.y);
    e->u = (app_point2){l > 0 ? (b.x - a.x) / l : 1, l > 0 ? (b.y - a.y) / l : 0};
    e->n = (app_point2){-e->u.y, e->u.x};
    e->o = a;
    e->height = pl->height_mm;
    e->length = l;
    if (index < pl->corner_count) {
        snprintf(e->surface, sizeof e->surface, "wall:%d", index);
        snprintf(e->title, sizeof e->title, "Elevation wall %d", index + 1);
        return;
    }
    /* A pre-wall's front keeps its wall's s (app/design/room_surfaces.h), in a plane depth_mm in
     * front of the wall. */
    const app_prewall *pw = &pl->prewalls[index - pl->corner_count];
    snprintf(e->surface, sizeof e->surface, "prewall:%s:front", pw->name);
    snprintf(e->title, sizeof e->title, "Elevation pre-wall %.60s (wall %d)", pw->name, wall + 1);
    e->o.x = a.x + e->n.x * pw->depth_mm;
    e->o.y = a.y + e->n.y * pw->depth_mm;
    e->s0 = pw->offset_mm;
    e->length = pw->width_mm;
    e->height = pw->height_mm;
    e->depth = pw->depth_mm;
}

/* Paper room around an elevation's face: the rows' chain left and the height right (16 mm
 * each), the length, the corner names and the counts below (20 mm), its caption above (6 mm). */
#define EL_SIDE 16.0
#define EL_BELOW 20.0
#define EL_ABOVE 6.0
#define EL_LEGEND 8.0 /* the page's bottom line: whole / cut legend and the scale bar */

/* The face's extent in model mm, pre-walls unfolded (sides beside it, top above). */
static void elev_extent(const pr_doc *d, int index, double *w, double *h)
{
    elev e;
    elev_of(d, index, &e);
    *w = e.length + 2 * e.depth;
    *h = e.height + e.depth;
}

static int elev_fits(const pr_doc *d, int index, int n, double rw, double rh)
{
    double w, h;
    elev_extent(d, index, &w, &h);
    return w / n + 2 * EL_SIDE <= rw && h / n + EL_BELOW + EL_ABOVE <= rh;
}

int pr_elevation_scale(pr_doc *d, int index)
{
    if (d->o->scale > 0)
        return d->o->scale;
    double aw = d->page_w - 28.0, ah = d->page_h - 44.0 - EL_LEGEND;
    for (int i = 0; i < APP_PRINT_SCALE_COUNT; i++)
        if (elev_fits(d, index, app_print_scales[i], aw, ah))
            return app_print_scales[i];
    return app_print_scales[APP_PRINT_SCALE_COUNT - 1];
}

/* Two elevations side by side (1) or one above the other (2) at scale n, or 0. */
static int pair_arrangement(const pr_doc *d, int a, int b, int n)
{
    double aw = d->page_w - 28.0, ah = d->page_h - 44.0 - EL_LEGEND;
    if (elev_fits(d, a, n, aw / 2, ah) && elev_fits(d, b, n, aw / 2, ah))
        return 1;
    if (elev_fits(d, a, n, aw, ah / 2) && elev_fits(d, b, n, aw, ah / 2))
        return 2;
    return 0;
}

int pr_elevation_pages(pr_doc *d, pr_page *pages)
{
    int count = pr_elevation_count(d), n = 0;
    for (int i = 0; i < count; i++) {
        int si = pr_elevation_scale(d, i);
        if (i + 1 < count && pr_elevation_scale(d, i + 1) == si &&
            pair_arrangement(d, i, i + 1, si)) {
            pages[n++] = (pr_page){PR_PAGE_ELEVATION, i, i + 1};
            i++;
        } else {
            pages[n++] = (pr_page){PR_PAGE_ELEVATION, i, -1};
        }
    }
    return n;
}

/* Surface coordinates (s, t) to paper: x = ax + bx s, y = ay + by t. A wall seen from inside
 * has bx = -1/n (s grows to the left) and by = -1/n (up the page); the unfolded side and top
 * faces of a pre-wall turn the other way on one axis. */
typedef struct ev {
    double ax, bx, ay, by;
    double n; /* the scale's denominator */
} ev;

static double ex(const ev *v, double s)
{
    return v->ax + v->bx * s;
}
static double ey(const ev *v, double t)
{
    return v->ay + v->by * t;
}

static void rect_st(cairo_t *cr, const ev *v, double s0, double t0, double s1, double t1)
{
    cairo_move_to(cr, ex(v, s0), ey(v, t0));
    cairo_line_to(cr, ex(v, s1), ey(v, t0));
    cairo_line_to(cr, ex(v, s1), ey(v, t1));
    cairo_line_to(cr, ex(v, s0), ey(v, t1));
    cairo_close_path(cr);
}

/* The colour of a tile product from the catalog (its variant's diffuse), linear -> sRGB-ish. */
static void tile_colour(pr_doc *d, const app_product_ref *ref, double rgb[3])
{
    rgb[0] = rgb[1] = rgb[2] = 0.85;
    if (!d->db)
        return;
    cat_product prod;
    char err[256];
    if (cat_product_find(d->db, ref->manufacturer, ref->article, &prod, err, sizeof err) !=
        CAT_DB_OK)
        return;
    const cat_variant *var = prod.variant_count ? &prod.variants[0] : NULL;
    for (int i = 0; i < prod.variant_count; i++)
        if (ref->variant[0] && !strcmp(prod.variants[i].code, ref->variant))
            var = &prod.variants[i];
    if (var)
        for (int k = 0; k < 3; k++)
            rgb[k] = pow(fmin(fmax(var->material.diffuse[k], 0.0), 1.0), 1.0 / 2.2);
    cat_product_free(&prod);
}

static void draw_layout(pr_doc *d, const ev *v, const app_tile_layout *l, const app_tiling *t,
                        int *whole, int *cut)
{
    cairo_t *cr = d->cr;
    double colours[1 + APP_TILING_MAX_BORDERS][3];
    for (int k = 0; k < l->spec_count; k++)
        tile_colour(d, &l->specs[k].product, colours[k]);
    /* Grout: the tiled band, in the grout colour; the tiles cover all but the joints. */
    double gr = pow(fmin(fmax(t->grout_color[0], 0), 1), 1 / 2.2);
    double gg = pow(fmin(fmax(t->grout_color[1], 0), 1), 1 / 2.2);
    double gb = pow(fmin(fmax(t->grout_color[2], 0), 1), 1 / 2.2);
    for (int i = 0; i < l->tile_count; i++) {
        const app_placed_tile *pt = &l->tiles[i];
        const double *c =
            colours[pt->product >= 0 && pt->product < l->spec_count ? pt->product : 0];
        /* The whole tile's clipped shape: its convex pieces. */
        for (int q = 0; q < pt->piece_count; q++) {
            const app_tile_piece *pc = &l->pieces[pt->first_piece + q];
            for (int k = 0; k < pc->count; k++) {
                app_point2 p = l->points[pc->first + k];
                (k ? cairo_line_to : cairo_move_to)(cr, ex(v, p.x), ey(v, p.y));
            }
            cairo_close_path(cr);
        }
        cairo_set_source_rgb(cr, c[0], c[1], c[2]);
        if (pt->whole) {
            cairo_fill(cr);
            (*whole)++;
        } else {
            /* Cut tiles: lighter, hatched, so the tiler sees at once which to cut. */
            cairo_set_source_rgb(cr, 0.55 + 0.45 * c[0], 0.55 + 0.45 * c[1], 0.55 + 0.45 * c[2]);
            cairo_fill_preserve(cr);
            cairo_set_source_rgb(cr, 0.78 * c[0], 0.5 * c[1], 0.45 * c[2]);
            cairo_set_line_width(cr, 0.08);
            pr_hatch_path(cr, 0.9, 45);
            cairo_new_path(cr);
            (*cut)++;
        }
        /* Cut tiles carry their number (as in the cut plan), at the clipped shape's centre,
         * drawn last where no other text is. */
        if (!pt->whole && pt->piece_count > 0) {
            double cx = 0, cy = 0;
            int np = 0;
            for (int q = 0; q < pt->piece_count; q++) {
                const app_tile_piece *pc = &l->pieces[pt->first_piece + q];
                for (int k = 0; k < pc->count; k++, np++) {
                    cx += l->points[pc->first + k].x;
                    cy += l->points[pc->first + k].y;
                }
            }
            if (d->cut_label_count == d->cut_label_cap) {
                int cap = d->cut_label_cap ? d->cut_label_cap * 2 : 256;
                pr_cut_label *c = realloc(d->cut_labels, (size_t)cap * sizeof *c);
                if (!c)
                    continue; /* only this number is left out */
                d->cut_labels = c;
                d->cut_label_cap = cap;
            }
            d->cut_labels[d->cut_label_count++] =
                (pr_cut_label){ex(v, cx / np), ey(v, cy / np), i + 1};
        }
        /* Edges: the tile's own edges thin (the grout line), cut edges heavier in red; one
         * path per kind and tile, so a mosaic wall stays a few strokes per tile. */
        for (int kind = APP_EDGE_TILE; kind <= APP_EDGE_CUT; kind++) {
            int any = 0;
            for (int q = 0; q < pt->piece_count; q++) {
                const app_tile_piece *pc = &l->pieces[pt->first_piece + q];
                for (int k = 0; k < pc->count; k++) {
                    if (l->edges[pc->first + k] != kind)
                        continue;
                    app_point2 a = l->points[pc->first + k];
                    app_point2 b = l->points[pc->first + (k + 1) % pc->count];
                    cairo_move_to(cr, ex(v, a.x), ey(v, a.y));
                    cairo_line_to(cr, ex(v, b.x), ey(v, b.y));
                    any = 1;
                }
            }
            if (!any)
                continue;
            if (kind == APP_EDGE_CUT) {
                cairo_set_source_rgb(cr, 0.75, 0.1, 0.1);
                cairo_set_line_width(cr, PR_LINE_FINE);
            } else {
                cairo_set_source_rgb(cr, gr * 0.55, gg * 0.55, gb * 0.55);
                cairo_set_line_width(cr, l->grout_mm / v->n > 0.1 ? l->grout_mm / v->n : 0.1);
            }
            cairo_stroke(cr);
        }
    }
}

typedef struct sil {
    int fixture, part;
    double depth; /* distance from the face into the room, mean */
} sil;

static int cmp_depth(const void *a, const void *b)
{
    const sil *p = a, *q = b;
    return p->depth > q->depth ? -1 : p->depth < q->depth;
}

/* Fixtures within 450 mm of the face: side silhouettes (convex hull per part in the face's
 * (s, z) plane), nearer parts over farther ones; a level mark at each fixture's top. */
static void draw_fixtures(pr_doc *d, const ev *v, const elev *e, double *marks, int *mark_count)
{
    cairo_t *cr = d->cr;
    int total = 0;
    for (int i = 0; i < d->fixture_count; i++)
        total += d->fixtures[i].part_count;
    sil *list = malloc((size_t)(total + 1) * sizeof *list);
    if (!list)
        return;
    int n = 0;
    for (int i = 0; i < d->fixture_count; i++) {
        for (int q = 0; q < d->fixtures[i].part_count; q++) {
            const pr_part *pp = &d->fixtures[i].parts[q];
            double dmin = 1e300, dsum = 0, smin = 1e300, smax = -1e300;
            for (int k = 0; k < pp->count; k++) {
                double rx = pp->pts[k][0] - e->o.x, ry = pp->pts[k][1] - e->o.y;
                double s = rx * e->u.x + ry * e->u.y, dd = rx * e->n.x + ry * e->n.y;
                dmin = dd < dmin ? dd : dmin;
                dsum += dd;
                smin = s < smin ? s : smin;
                smax = s > smax ? s : smax;
            }
            if (pp->count == 0 || dmin > 450.0 || dmin < -50.0 || smax < e->s0 ||
                smin > e->s0 + e->length)
                continue;
            list[n++] = (sil){i, q, dsum / pp->count};
        }
    }
    qsort(list, (size_t)n, sizeof *list, cmp_depth);
    for (int r = 0; r < n; r++) {
        const pr_part *pp = &d->fixtures[list[r].fixture].parts[list[r].part];
        app_point2 *pts = malloc((size_t)(pp->count + 1) * sizeof *pts);
        app_point2 *hull = malloc((size_t)(pp->count + 2) * sizeof *hull);
        if (pts && hull) {
            for (int k = 0; k < pp->count; k++) {
                double rx = pp->pts[k][0] - e->o.x, ry = pp->pts[k][1] - e->o.y;
                pts[k] = (app_point2){rx * e->u.x + ry * e->u.y, pp->pts[k][2]};
            }
            int h = pr_convex_hull(pts, pp->count, hull);
            for (int k = 0; k < h; k++)
                (k ? cairo_line_to : cairo_move_to)(cr, ex(v, hull[k].x), ey(v, hull[k].y));
            cairo_close_path(cr);
            cairo_set_source_rgb(cr, 1, 1, 1);
            cairo_fill_preserve(cr);
            cairo_set_source_rgb(cr, 0, 0, 0);
            cairo_set_line_width(cr, PR_LINE_WIDE);
            cairo_stroke(cr);
        }
        free(pts);
        free(hull);
    }
    /* One level mark per fixture shown, at its top, at the fixture's right end as drawn (text
     * to the right) or, if that runs past the face or onto a text already there, at its left
     * end (text to the left); a third collision drops the mark. Catalog products first
     * (pass 0), so a crowded wall keeps the marks that matter to the installer. Then each
     * fixture's number (as on the plan) at the middle of its silhouette, or on a leader. */
    const double face_l = ex(v, e->s0 + e->length), face_r = ex(v, e->s0);
    double mid_s[256], mid_t[256];
    int shown_list[256], nshown = 0;
    for (int pass = 0; pass < 2; pass++)
        for (int i = 0; i < d->fixture_count; i++) {
            int shown = 0;
            for (int r = 0; r < n && !shown; r++)
                shown = list[r].fixture == i;
            if (!shown || d->fixtures[i].has_product != (pass == 0))
                continue;
            const pr_fixture *f = &d->fixtures[i];
            double smin = 1e300, smax = -1e300;
            for (int q = 0; q < f->part_count; q++)
                for (int k = 0; k < f->parts[q].count; k++) {
                    double rx = f->parts[q].pts[k][0] - e->o.x, ry = f->parts[q].pts[k][1] - e->o.y;
                    double s = rx * e->u.x + ry * e->u.y;
                    smin = s < smin ? s : smin;
                    smax = s > smax ? s : smax;
                }
            smin = smin < e->s0 ? e->s0 : smin;
            smax = smax > e->s0 + e->length ? e->s0 + e->length : smax;
            double top = f->max[2];
            if (nshown < 256) {
                shown_list[nshown] = i;
                mid_s[nshown] = (smin + smax) / 2;
                mid_t[nshown++] = (f->min[2] + f->max[2]) / 2;
            }
            char text[64];
            snprintf(text, sizeof text, "+%.0f", top);
            pr_set_font(cr, PR_TEXT_SMALL, 0);
            double w = pr_text_width(cr, text) + 4.0, y = ey(v, top);
            for (int attempt = 0; attempt < 2; attempt++) {
                int left = attempt == 1;
                double x = left ? ex(v, smax) + 1.0 : ex(v, smin) - 1.0;
                double bx0 = left ? x - w : x - 1.5, bx1 = left ? x + 1.5 : x + w;
                if ((!left && bx1 > face_r + 2.0) || (left && bx0 < face_l - 2.0))
                    continue;
                pr_box tb = pr_text_measure(cr, left ? x - 2.0 : x + 2.0, y - 0.7, 0,
                                            left ? 1.0 : 0.0, 1.0, text);
                if (!pr_box_is_free(cr, tb, 0.3))
                    continue;
                pr_level_mark(cr, x, y, text, left);
                if (*mark_count < 64)
                    marks[(*mark_count)++] = top;
                break;
            }
        }
    pr_box within = {d->area_x, d->area_y, d->area_x + d->area_w, d->area_y + d->area_h - 8.0};
    for (int k = 0; k < nshown; k++) {
        const pr_fixture *f = &d->fixtures[shown_list[k]];
        if (f->number)
            pr_place_balloon(cr, ex(v, mid_s[k]), ey(v, mid_t[k]), f->number, within);
    }
    free(list);
}

static void draw_openings(pr_doc *d, const ev *v, int wall)
{
    cairo_t *cr = d->cr;
    const app_room_plan *pl = &d->plan;
    for (int k = 0; k < pl->opening_count; k++) {
        const app_opening *op = &pl->openings[k];
        if (op->wall != wall)
            continue;
        double s0 = op->offset_mm, s1 = op->offset_mm + op->width_mm;
        double t0 = op->type == APP_OPENING_WINDOW ? op->sill_mm : 0, t1 = t0 + op->height_mm;
        rect_st(cr, v, s0, t0, s1, t1);
        cairo_set_source_rgb(cr, 1, 1, 1);
        cairo_fill_preserve(cr);
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_set_line_width(cr, PR_LINE_HEAVY);
        cairo_stroke(cr);
        cairo_set_line_width(cr, PR_LINE_THIN);
        if (op->type == APP_OPENING_WINDOW) {
            double inset = 50.0;
            rect_st(cr, v, s0 + inset, t0 + inset, s1 - inset, t1 - inset);
            cairo_stroke(cr);
        } else if (op->swing != APP_SWING_SLIDING) {
            /* The opening symbol: lines from the free side's corners to the hinge side's
             * middle (hinge left as seen from inside = the s1 end). */
            int left = op->swing == APP_SWING_IN_LEFT || op->swing == APP_SWING_OUT_LEFT;
            double hs = left ? s1 : s0, fs = left ? s0 : s1;
            const double dash[2] = {2.0, 1.0};
            cairo_set_dash(cr, dash, 2, 0);
            cairo_move_to(cr, ex(v, fs), ey(v, t0));
            cairo_line_to(cr, ex(v, hs), ey(v, (t0 + t1) / 2));
            cairo_line_to(cr, ex(v, fs), ey(v, t1));
            cairo_stroke(cr);
            cairo_set_dash(cr, NULL, 0, 0);
        }
        pr_set_font(cr, PR_TEXT_SMALL, 0);
        char text[96];
        snprintf(text, sizeof text, "%s %.0f x %.0f", op->name[0] ? op->name : "opening",
                 op->width_mm, op->height_mm);
        pr_text(cr, ex(v, (s0 + s1) / 2), ey(v, (t0 + t1) / 2), 0.5, 0.5, text);
    }
}

/* The tile rows' joints (distinct bottom and top edges of the cells) as a dimension chain. */
static int row_stops(const app_tile_layout *l, double t0, double t1, double *stops, int cap)
{
    int n = 0;
    if (fabs(fmod(l->angle_deg, 90.0)) > 1e-6)
        return 0; /* diagonal and turned layouts have no rows to dimension */
    for (int i = 0; i < l->tile_count && n < cap - 2; i++) {
        double lo = 1e300, hi = -1e300;
        for (int k = 0; k < 4; k++) {
            lo = l->tiles[i].cell[k].y < lo ? l->tiles[i].cell[k].y : lo;
            hi = l->tiles[i].cell[k].y > hi ? l->tiles[i].cell[k].y : hi;
        }
        double vals[2] = {lo, hi};
        for (int j = 0; j < 2; j++) {
            double t = vals[j] < t0 ? t0 : (vals[j] > t1 ? t1 : vals[j]);
            int dup = 0;
            for (int m = 0; m < n && !dup; m++)
                dup = fabs(stops[m] - t) < 4.0; /* a joint is one stop, not two */
            if (!dup)
                stops[n++] = t;
        }
    }
    for (int a = 1; a < n; a++)
        for (int b = a; b > 0 && stops[b] < stops[b - 1]; b--) {
            double tmp = stops[b];
            stops[b] = stops[b - 1];
            stops[b - 1] = tmp;
        }
    return n;
}

static const app_tile_layout *layout_for(const pr_doc *d, const char *surface, int from, int *index)
{
    for (int i = from; i < d->layout_count; i++)
        if (!strcmp(d->layouts[i].surface, surface)) {
            *index = i;
            return &d->layouts[i];
        }
    return NULL;
}

/* One unfolded face of a pre-wall: its outline (s0..s1 x t0..t1 in its own frame) filled,
 * its tiles, its outline heavy, its name. */
static void draw_face(pr_doc *d, const ev *v, const char *surface, double s0, double t0, double s1,
                      double t1, int *whole, int *cut)
{
    cairo_t *cr = d->cr;
    rect_st(cr, v, s0, t0, s1, t1);
    cairo_set_source_rgb(cr, 0.97, 0.97, 0.96);
    cairo_fill(cr);
    const app_tile_layout *l;
    int li = -1;
    for (int from = 0; (l = layout_for(d, surface, from, &li)) != NULL; from = li + 1) {
        cairo_save(cr);
        rect_st(cr, v, s0, t0, s1, t1);
        cairo_clip(cr);
        draw_layout(d, v, l, &d->p->tilings[li], whole, cut);
        cairo_restore(cr);
    }
    rect_st(cr, v, s0, t0, s1, t1);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, PR_LINE_WIDE);
    cairo_stroke(cr);
    pr_set_font(cr, 1.6, 0);
    const char *face = strrchr(surface, ':');
    pr_text(cr, (ex(v, s0) + ex(v, s1)) / 2, fmin(ey(v, t0), ey(v, t1)) - 1.5, 0.5, 1.0,
            face ? face + 1 : surface);
}

/* The sides and the top of pre-wall k unfolded around its front (app/design/room_surfaces.h frames:
 * left/right s from the wall into the room, t up, left at the larger s of the wall; top s
 * along the wall, t from the wall into the room). */
static void draw_unfolded_faces(pr_doc *d, const ev *front, const elev *e, int k, int *whole,
                                int *cut)
{
    const app_prewall *pw = &d->plan.prewalls[k];
    const double n = front->n, depth = pw->depth_mm;
    const double xl = ex(front, e->s0 + e->length), xr = ex(front, e->s0);
    char surface[128];
    /* Left face: attached at the front's left edge, its s = depth there, s = 0 farthest. */
    ev lv = {.ax = xl - depth / n, .bx = 1.0 / n, .ay = front->ay, .by = front->by, .n = n};
    snprintf(surface, sizeof surface, "prewall:%s:left", pw->name);
    draw_face(d, &lv, surface, 0, 0, depth, pw->height_mm, whole, cut);
    ev rv = {.ax = xr + depth / n, .bx = -1.0 / n, .ay = front->ay, .by = front->by, .n = n};
    snprintf(surface, sizeof surface, "prewall:%s:right", pw->name);
    draw_face(d, &rv, surface, 0, 0, depth, pw->height_mm, whole, cut);
    /* Top: above the front, its t = depth at the front's top edge. */
    double ytop = ey(front, pw->height_mm);
    ev tv = {.ax = front->ax, .bx = front->bx, .ay = ytop - depth / n, .by = 1.0 / n, .n = n};
    snprintf(surface, sizeof surface, "prewall:%s:top", pw->name);
    draw_face(d, &tv, surface, e->s0, 0, e->s0 + e->length, depth, whole, cut);
}

/* Elevation `index` at 1:scale, centred in the region (paper mm). */
static void draw_one(pr_doc *d, int index, int scale, double rx, double ry, double rw, double rh)
{
    elev e;
    elev_of(d, index, &e);
    cairo_t *cr = d->cr;
    const double s0 = e.s0, s1 = e.s0 + e.length;
    /* A pre-wall's sheet is unfolded: its sides left and right of the front, its top above. */
    const double side = index < d->plan.corner_count ? 0.0 : e.depth;
    double left_edge = rx + rw / 2 - e.length / 2 / scale;
    double tall = (e.height + side) / scale;
    double floor_y = ry + (rh - tall - EL_BELOW - EL_ABOVE) / 2 + EL_ABOVE + tall;
    ev v = {.ax = left_edge + s1 / scale,
            .bx = -1.0 / scale,
            .ay = floor_y,
            .by = -1.0 / scale,
            .n = scale};
    cairo_save(cr);

    /* The wall face. */
    rect_st(cr, &v, s0, 0, s1, e.height);
    cairo_set_source_rgb(cr, 0.97, 0.97, 0.96);
    cairo_fill(cr);
    int whole = 0, cut = 0, li = -1;
    double rows[512];
    int nrows = 0;
    const app_tile_layout *l;
    const char *articles = "";
    char tiles_text[256] = "";
    for (int from = 0; (l = layout_for(d, e.surface, from, &li)) != NULL; from = li + 1) {
        cairo_save(cr);
        rect_st(cr, &v, s0, 0, s1, e.height);
        cairo_clip(cr);
        int w0 = whole, c0 = cut;
        draw_layout(d, &v, l, &d->p->tilings[li], &whole, &cut);
        cairo_restore(cr);
        const app_tiling *t = &d->p->tilings[li];
        double t0 = t->from_mm, t1 = t->to_mm > 0 ? t->to_mm : e.height;
        if (nrows == 0)
            nrows = row_stops(l, t0 > 0 ? t0 : 0, t1 < e.height ? t1 : e.height, rows, 512);
        size_t used = strlen(tiles_text);
        snprintf(tiles_text + used, sizeof tiles_text - used, "%s%s: %d whole, %d cut",
                 used ? "; " : "", t->product.article, whole - w0, cut - c0);
        articles = t->product.article;
    }
    (void)articles;
    if (d->report) {
        d->report->tiles_whole += whole;
        d->report->tiles_cut += cut;
        if (index < APP_PRINT_REPORT_MAX_ELEVATIONS) {
            d->report->elevation_whole[index] = whole;
            d->report->elevation_cut[index] = cut;
        }
    }
    /* Pre-walls standing against this wall, seen from the front. */
    if (index < d->plan.corner_count)
        for (int k = 0; k < d->plan.prewall_count; k++) {
            const app_prewall *pw = &d->plan.prewalls[k];
            if (pw->wall != index)
                continue;
            int pi = -1;
            char surface[128];
            snprintf(surface, sizeof surface, "prewall:%s:front", pw->name);
            rect_st(cr, &v, pw->offset_mm, 0, pw->offset_mm + pw->width_mm, pw->height_mm);
            cairo_set_source_rgb(cr, 0.93, 0.93, 0.93);
            cairo_fill(cr);
            const app_tile_layout *pl = layout_for(d, surface, 0, &pi);
            if (pl) {
                /* The front face keeps the wall's s: drawn in the wall's own frame. */
                int w2 = 0, c2 = 0;
                cairo_save(cr);
                rect_st(cr, &v, pw->offset_mm, 0, pw->offset_mm + pw->width_mm, pw->height_mm);
                cairo_clip(cr);
                draw_layout(d, &v, pl, &d->p->tilings[pi], &w2, &c2);
                cairo_restore(cr);
            }
            rect_st(cr, &v, pw->offset_mm, 0, pw->offset_mm + pw->width_mm, pw->height_mm);
            cairo_set_source_rgb(cr, 0, 0, 0);
            cairo_set_line_width(cr, PR_LINE_WIDE);
            cairo_stroke(cr);
        }
    if (index < d->plan.corner_count)
        draw_openings(d, &v, index);
    double marks[64];
    int nmarks = 0;
    draw_fixtures(d, &v, &e, marks, &nmarks);
    /* The face's outline: floor and ceiling lines heavy, corners medium. */
    rect_st(cr, &v, s0, 0, s1, e.height);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, PR_LINE_HEAVY);
    cairo_stroke(cr);

    if (side > 0) {
        int w3 = 0, c3 = 0;
        draw_unfolded_faces(d, &v, &e, index - d->plan.corner_count, &w3, &c3);
        whole += w3;
        cut += c3;
        if (d->report) {
            d->report->tiles_whole += w3;
            d->report->tiles_cut += c3;
            if (index < APP_PRINT_REPORT_MAX_ELEVATIONS) {
                d->report->elevation_whole[index] = whole;
                d->report->elevation_cut[index] = cut;
            }
        }
        if (w3 + c3 > 0) {
            size_t used = strlen(tiles_text);
            snprintf(tiles_text + used, sizeof tiles_text - used,
                     "%ssides and top: %d whole, %d cut", used ? "; " : "", w3, c3);
        }
    }

    /* Dimensions: the length below, the tile rows on the left, the height on the right (as
     * drawn: s = length is at the left), outside the unfolded sides of a pre-wall. */
    double left = ex(&v, s1), right = ex(&v, s0), bottom = ey(&v, 0), top = ey(&v, e.height);
    double sw = side / scale;
    pr_dimension(cr, left, bottom, right, bottom, -8.0, e.length);
    if (side > 0) {
        pr_dimension(cr, left - sw, bottom, left, bottom, -8.0, side);
        pr_dimension(cr, right, bottom, right + sw, bottom, -8.0, side);
    }
    /* The rows' chain, unless its values would overlap (small tiles): then the typical row
     * height goes into the summary instead. */
    double typical = 0;
    int small = 0;
    for (int k = 0; k + 1 < nrows; k++) {
        double h = rows[k + 1] - rows[k];
        typical = h > typical ? h : typical;
        small += h / scale < 8.0; /* a value needs ~6 mm of line */
    }
    int crowded = nrows > 1 && small * 2 > nrows - 1;
    for (int k = 0; !crowded && k + 1 < nrows; k++)
        if (rows[k + 1] - rows[k] > 1.0)
            pr_dimension(cr, left - sw, ey(&v, rows[k]), left - sw, ey(&v, rows[k + 1]), 8.0,
                         rows[k + 1] - rows[k]);
    if (crowded) {
        size_t used = strlen(tiles_text);
        snprintf(tiles_text + used, sizeof tiles_text - used, "; rows every %.0f mm", typical);
    }
    pr_dimension(cr, right + sw, bottom, right + sw, top, -8.0, e.height);
    /* Corner names under the face, so the sheet reads against the plan. */
    pr_set_font(cr, PR_TEXT_SMALL, 0);
    cairo_set_source_rgb(cr, 0, 0, 0);
    if (index < d->plan.corner_count) {
        char a[32], b[32];
        snprintf(a, sizeof a, "corner %d", index + 1);
        snprintf(b, sizeof b, "corner %d", (index + 1) % d->plan.corner_count + 1);
        pr_text(cr, right, bottom + 13.0, 1.0, 1.0, a);
        pr_text(cr, left, bottom + 13.0, 0.0, 1.0, b);
    }
    /* The caption above, the counts of this face under the corner names. */
    pr_set_font(cr, PR_TEXT_LARGE, 1);
    pr_text(cr, (left + right) / 2, top - sw - (side > 0 ? 5.5 : 2.5), 0.5, 1.0, e.title);
    char summary[400];
    snprintf(summary, sizeof summary, "%s   %s", e.surface,
             tiles_text[0] ? tiles_text : "not tiled");
    pr_set_font(cr, PR_TEXT_SMALL, 0);
    pr_text(cr, (left + right) / 2, bottom + 17.5, 0.5, 1.0, summary);
    cairo_restore(cr);
}

/* The page's bottom line: the whole / cut legend and the graphic scale. */
static void draw_legend_row(pr_doc *d, int scale)
{
    cairo_t *cr = d->cr;
    pr_set_font(cr, PR_TEXT_SMALL, 0);
    double lx = d->area_x, ly = d->area_y + d->area_h - 1.0;
    cairo_rectangle(cr, lx, ly - 3.0, 5.0, 3.0);
    cairo_set_source_rgb(cr, 0.8, 0.8, 0.8);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, PR_LINE_THIN);
    cairo_stroke(cr);
    pr_text(cr, lx + 6.5, ly, 0.0, 1.0, "whole tile");
    cairo_rectangle(cr, lx + 26.0, ly - 3.0, 5.0, 3.0);
    cairo_set_source_rgb(cr, 0.91, 0.91, 0.91);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0.6, 0.4, 0.35);
    cairo_set_line_width(cr, 0.08);
    pr_hatch_path(cr, 0.9, 45);
    cairo_set_source_rgb(cr, 0.75, 0.1, 0.1);
    cairo_set_line_width(cr, PR_LINE_FINE);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    pr_text(cr, lx + 32.5, ly, 0.0, 1.0, "cut tile (cut edges red, numbers as in the cut plan)");
    pr_scale_bar(cr, d->area_x + d->area_w - 2.0, ly, scale);
}

/* The cut tiles' numbers last, each where no other text is (over a silhouette or a label it is
 * left out: the cut plan still lists it). */
static void draw_cut_labels(pr_doc *d)
{
    cairo_t *cr = d->cr;
    pr_set_font(cr, 1.3, 0);
    cairo_set_source_rgb(cr, 0.55, 0.1, 0.1);
    for (int i = 0; i < d->cut_label_count; i++) {
        const pr_cut_label *c = &d->cut_labels[i];
        char num[16];
        snprintf(num, sizeof num, "%d", c->number);
        if (pr_box_is_free(cr, pr_text_measure(cr, c->x, c->y, 0, 0.5, 0.5, num), 0.15))
            pr_text(cr, c->x, c->y, 0.5, 0.5, num);
    }
    cairo_set_source_rgb(cr, 0, 0, 0);
    d->cut_label_count = 0;
}

app_result pr_draw_elevation(pr_doc *d, int index, int second)
{
    int scale = pr_elevation_scale(d, index);
    if (d->report && (d->report->elevation_scale == 0 || scale > d->report->elevation_scale))
        d->report->elevation_scale = scale;
    elev a, b;
    elev_of(d, index, &a);
    char title[300];
    if (second >= 0) {
        elev_of(d, second, &b);
        snprintf(title, sizeof title, "Elevations: %.120s; %.120s", a.title + strlen("Elevation "),
                 b.title + strlen("Elevation "));
    } else {
        snprintf(title, sizeof title, "%s", a.title);
    }
    app_result r = pr_page_begin(d, title, scale);
    if (r != APP_OK)
        return r;
    cairo_t *cr = d->cr;
    cairo_save(cr);
    cairo_rectangle(cr, d->area_x - 4, d->area_y - 4, d->area_w + 8, d->area_h + 8);
    cairo_clip(cr);
    d->cut_label_count = 0;
    draw_legend_row(d, scale);
    double rx = d->area_x, ry = d->area_y, rw = d->area_w, rh = d->area_h - EL_LEGEND;
    if (second < 0) {
        draw_one(d, index, scale, rx, ry, rw, rh);
    } else if (pair_arrangement(d, index, second, scale) == 1) {
        draw_one(d, index, scale, rx, ry, rw / 2, rh);
        draw_one(d, second, scale, rx + rw / 2, ry, rw / 2, rh);
    } else {
        draw_one(d, index, scale, rx, ry, rw, rh / 2);
        draw_one(d, second, scale, rx, ry + rh / 2, rw, rh / 2);
    }
    draw_cut_labels(d);
    cairo_restore(cr);
    return pr_page_end(d);
}
