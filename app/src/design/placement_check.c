/* The placement checks: collisions between fixtures and with walls, pre-walls and openings;
 * free areas in front of fixtures and the 200 mm distances (DOMAIN.md "Clearances": VDI 6000
 * sheet 1, the withdrawn DIN 18022); barrier-free rules (DIN 18040-2) on request. The rules
 * and their numbers are listed in docs/editing.md. */
#include "placement_internal.h"

#include "catalog/catalog.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* DOMAIN.md "Clearances": at least 200 mm between objects and to side walls. It is a rule of
 * the trade, not advice: a shorter distance is an error like a blocked free area. */
#define SIDE_DISTANCE_MM PL_SIDE_DISTANCE_MM
/* Free areas are for standing and moving: anything reaching below this height blocks them. */
#define FREE_AREA_HEADROOM_MM 2000.0
/* Anything no higher than this is a floor covering (a mat, a rug): walked on, not around. */
#define FLOOR_COVERING_MM 20.0
/* DIN 18040-2: the wheelchair WC needs 900 mm clear on one side and 300 on the other, over
 * 700 mm of depth from the wall. */
#define WC_WIDE_SIDE_MM 900.0
#define WC_NARROW_SIDE_MM 300.0
#define WC_SIDE_DEPTH_MM 700.0

typedef struct check_ctx {
    const app_project *p;
    const app_fixture *fx;
    int count;
    app_barrier_free bf;
    app_point2 box[4]; /* the room box when the project has no plan */
    const app_point2 *poly;
    int poly_n;
    app_findings *out;
    pl_rect *rects;    /* each fixture's footprint, computed once */
    double (*aabb)[4]; /* and its axis-aligned bounds: x0, y0, x1, y1 */
} check_ctx;

static void bounds_of(const pl_rect *r, double box[4])
{
    double c[4][2];
    pl_rect_corners(r, c);
    box[0] = box[2] = c[0][0];
    box[1] = box[3] = c[0][1];
    for (int k = 1; k < 4; k++) {
        box[0] = fmin(box[0], c[k][0]);
        box[2] = fmax(box[2], c[k][0]);
        box[1] = fmin(box[1], c[k][1]);
        box[3] = fmax(box[3], c[k][1]);
    }
}

/* 1 when the bounds are more than margin apart: the rectangles cannot be that close (the
 * quick rejection that keeps the pair tests cheap for hundreds of fixtures). */
static int apart(const double a[4], const double b[4], double margin)
{
    return a[0] > b[2] + margin || b[0] > a[2] + margin || a[1] > b[3] + margin ||
           b[1] > a[3] + margin;
}

static int is_sanitary_category(int category)
{
    return category == CAT_CATEGORY_BASINS || category == CAT_CATEGORY_WCS_BIDETS ||
           category == CAT_CATEGORY_BATHS || category == CAT_CATEGORY_SHOWER_TRAYS ||
           category == CAT_CATEGORY_VANITY_UNITS;
}

/* Fixtures that need room beside them to be used (a basin, a WC); baths, trays and vanity
 * units are commonly fitted wall to wall. */
static int needs_side_room(int category)
{
    return category == CAT_CATEGORY_BASINS || category == CAT_CATEGORY_WCS_BIDETS;
}

int pl_side_distance_applies(int category_a, int category_b)
{
    return is_sanitary_category(category_a) && is_sanitary_category(category_b) &&
           (needs_side_room(category_a) || needs_side_room(category_b));
}

/* Whether a fixture takes room on the floor and in the air (not a mat, not an attachment). */
static int takes_room(const app_fixture *f)
{
    return f->role == APP_ROLE_FIXTURE && f->z1 > FLOOR_COVERING_MM;
}

/* A vanity unit carries its basin (the two may overlap and touch) only when it stands under
 * it: the basin's plan centre lies on the unit and the unit reaches no higher than the
 * basin's rim. Being a vanity unit is not enough: a tall cabinet of that product group
 * standing in front of a basin is furniture in its free area (DOMAIN.md "Clearances"). */
static int carries_basin(const app_fixture *unit, const pl_rect *unit_rect,
                         const app_fixture *basin)
{
    if (unit->category != CAT_CATEGORY_VANITY_UNITS || basin->category != CAT_CATEGORY_BASINS)
        return 0;
    double dx = basin->centre[0] - unit_rect->c[0], dy = basin->centre[1] - unit_rect->c[1];
    double u = dx * unit_rect->ax[0] + dy * unit_rect->ax[1];
    double v = dx * unit_rect->ay[0] + dy * unit_rect->ay[1];
    if (fabs(u) > unit_rect->h[0] + PL_TOLERANCE_MM || fabs(v) > unit_rect->h[1] + PL_TOLERANCE_MM)
        return 0;
    return unit->z1 <= basin->z1 + PL_TOLERANCE_MM;
}

/* Whether fixture i and fixture j are a basin and the vanity unit carrying it. */
static int carries(const check_ctx *c, int i, int j)
{
    return carries_basin(&c->fx[i], &c->rects[i], &c->fx[j]) ||
           carries_basin(&c->fx[j], &c->rects[j], &c->fx[i]);
}

static const char *category_label(int c)
{
    switch (c) {
    case CAT_CATEGORY_BASINS:
        return "basin";
    case CAT_CATEGORY_WCS_BIDETS:
        return "WC";
    case CAT_CATEGORY_BATHS:
        return "bath";
    case CAT_CATEGORY_SHOWER_TRAYS:
        return "shower";
    default:
        return "fixture";
    }
}

int app_free_area_size(const app_fixture *f, app_barrier_free bf, double *w, double *d)
{
    double width = f->width_mm;
    switch (f->category) {
    case CAT_CATEGORY_BASINS:
        /* DOMAIN.md: hand basin 450x350 -> 700x450; washbasin 600x550 -> 900x550; double
         * basin 1200x550 -> 1500x550. Between them by width: never narrower than the basin. */
        if (width < 500) {
            *w = 700;
            *d = 450;
        } else if (width >= 1100) {
            *w = fmax(1500, width + 300);
            *d = 550;
        } else {
            *w = fmax(900, width + 300);
            *d = 550;
        }
        break;
    case CAT_CATEGORY_WCS_BIDETS:
        *w = 800;
        *d = 550;
        break;
    case CAT_CATEGORY_SHOWER_TRAYS:
        *w = width;
        *d = 750;
        break;
    case CAT_CATEGORY_BATHS:
        *w = 900;
        *d = 750;
        break;
    default:
        return 0;
    }
    if (bf != APP_BARRIER_FREE_OFF) {
        double side = bf == APP_BARRIER_FREE_WHEELCHAIR ? 1500 : 1200;
        *w = fmax(*w, side);
        *d = fmax(*d, side);
    }
    return 1;
}

static double z_overlap(double a0, double a1, double b0, double b1)
{
    return fmin(a1, b1) - fmax(a0, b0);
}

/* Fixture-fixture collisions (3D: plan overlap and height overlap). */
static app_result check_collisions(check_ctx *c)
{
    for (int i = 0; i < c->count; i++) {
        const app_fixture *a = &c->fx[i];
        if (!takes_room(a))
            continue;
        const pl_rect ra = c->rects[i];
        for (int j = i + 1; j < c->count; j++) {
            const app_fixture *b = &c->fx[j];
            if (!takes_room(b) || carries(c, i, j) || (!a->has_product && !b->has_product) ||
                apart(c->aabb[i], c->aabb[j], SIDE_DISTANCE_MM))
                continue;
            const pl_rect rb = c->rects[j];
            double pen = pl_rect_penetration(&ra, &rb);
            double zo = z_overlap(a->z0, a->z1, b->z0, b->z1);
            double mid[2] = {0.5 * (a->centre[0] + b->centre[0]),
                             0.5 * (a->centre[1] + b->centre[1])};
            if (pen > PL_TOLERANCE_MM && zo > PL_TOLERANCE_MM) {
                app_result r = pl_add_finding(c->out, APP_FINDING_COLLISION, APP_SEVERITY_ERROR,
                                              a->object, b->object, mid,
                                              "\"%s\" and \"%s\" overlap (%.0f mm in plan, %.0f mm "
                                              "in height)",
                                              a->name, b->name, pen, zo);
                if (r != APP_OK)
                    return r;
                continue;
            }
            if (!pl_side_distance_applies(a->category, b->category))
                continue;
            double at[2];
            double dist = pl_rect_distance(&ra, &rb, at);
            if (dist < SIDE_DISTANCE_MM - PL_TOLERANCE_MM) {
                app_result r = pl_add_finding(
                    c->out, APP_FINDING_DISTANCE, APP_SEVERITY_ERROR, a->object, b->object, at,
                    "\"%s\" and \"%s\" are %.0f mm apart; at least %.0f mm between objects "
                    "(VDI 6000 sheet 1)",
                    a->name, b->name, dist, SIDE_DISTANCE_MM);
                if (r != APP_OK)
                    return r;
            }
        }
    }
    return APP_OK;
}

/* 1 when the plan rectangle (reaching from z0 to z1) hits a wall or a pre-wall; *what names
 * it, where a point. */
static int rect_blocked_by_room(const check_ctx *c, const pl_rect *r, double z0, double z1,
                                char *what, size_t what_size, double where[2])
{
    if (pl_rect_outside_polygon(r, c->poly, c->poly_n, where)) {
        snprintf(what, what_size, "a wall");
        return 1;
    }
    const app_room_plan *plan = &c->p->plan;
    for (int k = 0; k < plan->prewall_count && plan->corner_count >= 3; k++) {
        pl_rect pw = pl_prewall_rect(plan, k);
        if (pl_rect_penetration(r, &pw) > PL_TOLERANCE_MM &&
            z_overlap(z0, z1, 0, plan->prewalls[k].height_mm) > PL_TOLERANCE_MM) {
            snprintf(what, what_size, "the pre-wall \"%s\"", plan->prewalls[k].name);
            where[0] = pw.c[0];
            where[1] = pw.c[1];
            return 1;
        }
    }
    return 0;
}

static app_result check_room(check_ctx *c)
{
    const app_room_plan *plan = &c->p->plan;
    for (int i = 0; i < c->count; i++) {
        const app_fixture *f = &c->fx[i];
        pl_rect r = c->rects[i];
        double where[2];
        app_result res = APP_OK;
        if (pl_rect_outside_polygon(&r, c->poly, c->poly_n, where))
            res = pl_add_finding(c->out, APP_FINDING_OUTSIDE_ROOM, APP_SEVERITY_ERROR, f->object,
                                 -1, where, "\"%s\" reaches through a wall", f->name);
        if (res != APP_OK)
            return res;
        if (plan->corner_count < 3)
            continue;
        for (int k = 0; k < plan->prewall_count; k++) {
            pl_rect pw = pl_prewall_rect(plan, k);
            double pen = pl_rect_penetration(&r, &pw);
            if (pen > PL_TOLERANCE_MM &&
                z_overlap(f->z0, f->z1, 0, plan->prewalls[k].height_mm) > PL_TOLERANCE_MM) {
                res = pl_add_finding(c->out, APP_FINDING_PREWALL, APP_SEVERITY_ERROR, f->object, -1,
                                     pw.c, "\"%s\" overlaps the pre-wall \"%s\" by %.0f mm",
                                     f->name, plan->prewalls[k].name, pen);
                if (res != APP_OK)
                    return res;
            }
        }
        if (!takes_room(f))
            continue;
        for (int k = 0; k < plan->opening_count; k++) {
            const app_opening *op = &plan->openings[k];
            if (op->wall < 0 || op->wall >= plan->corner_count)
                continue;
            double o[2], d[2], nrm[2], len;
            pl_wall_frame(plan, op->wall, o, d, nrm, &len);
            /* The footprint in the wall's frame: along (s) and into the room (t). */
            double corners[4][2], s_lo = INFINITY, s_hi = -INFINITY, t_lo = INFINITY;
            pl_rect_corners(&r, corners);
            for (int q = 0; q < 4; q++) {
                double rx = corners[q][0] - o[0], ry = corners[q][1] - o[1];
                double sq = rx * d[0] + ry * d[1], tq = rx * nrm[0] + ry * nrm[1];
                s_lo = fmin(s_lo, sq);
                s_hi = fmax(s_hi, sq);
                t_lo = fmin(t_lo, tq);
            }
            double along = fmin(s_hi, op->offset_mm + op->width_mm) - fmax(s_lo, op->offset_mm);
            double zo = z_overlap(f->z0, f->z1, op->sill_mm, op->sill_mm + op->height_mm);
            if (along > PL_TOLERANCE_MM && t_lo < PL_OPENING_REACH_MM && zo > PL_TOLERANCE_MM) {
                double sm =
                    0.5 * (fmax(s_lo, op->offset_mm) + fmin(s_hi, op->offset_mm + op->width_mm));
                double at[2] = {o[0] + d[0] * sm, o[1] + d[1] * sm};
                int door = op->type == APP_OPENING_DOOR;
                res = pl_add_finding(c->out, APP_FINDING_OPENING,
                                     door ? APP_SEVERITY_ERROR : APP_SEVERITY_WARNING, f->object,
                                     -1, at, "\"%s\" stands in front of the %s \"%s\"", f->name,
                                     door ? "door" : "window", op->name);
                if (res != APP_OK)
                    return res;
                continue;
            }
            pl_rect sw;
            if (!pl_door_swing_rect(plan, k, &sw))
                continue;
            if (pl_rect_penetration(&r, &sw) > PL_TOLERANCE_MM && f->z0 < op->height_mm) {
                res = pl_add_finding(c->out, APP_FINDING_OPENING, APP_SEVERITY_ERROR, f->object, -1,
                                     sw.c, "\"%s\" is in the swing of the door \"%s\"", f->name,
                                     op->name);
                if (res != APP_OK)
                    return res;
            }
        }
    }
    return APP_OK;
}

/* The free area of fixture f shifted sideways by s along the fixture's width. */
static pl_rect free_area_at(const app_fixture *f, double s, double aw, double ad)
{
    double fd = 2 * f->half[1];
    return pl_rect_local(f, s - 0.5 * aw, s + 0.5 * aw, fd, fd + ad);
}

/* Whether no furniture other than fixture i (and the vanity unit carrying it) stands in the
 * area. */
static int area_clear_of_furniture(const check_ctx *c, int i, const pl_rect *area)
{
    double abox[4];
    bounds_of(area, abox);
    for (int j = 0; j < c->count; j++) {
        const app_fixture *b = &c->fx[j];
        if (j == i || !takes_room(b) || b->z0 >= FREE_AREA_HEADROOM_MM || carries(c, i, j) ||
            apart(abox, c->aabb[j], 0))
            continue;
        if (pl_rect_penetration(area, &c->rects[j]) > PL_TOLERANCE_MM)
            return 0;
    }
    return 1;
}

/* Adds the sideways offsets at which an edge of the area meets the point p (projected on the
 * fixture's width axis), within [-slide, slide]. */
static int add_edge_offsets(const pl_rect *fr, const double p[2], double aw, double slide,
                            double *s, int n)
{
    double x = (p[0] - fr->c[0]) * fr->ax[0] + (p[1] - fr->c[1]) * fr->ax[1];
    double cand[2] = {x + 0.5 * aw, x - 0.5 * aw};
    for (int k = 0; k < 2; k++)
        if (fabs(cand[k]) <= slide)
            s[n++] = cand[k];
    return n;
}

static int by_magnitude(const void *a, const void *b)
{
    double x = fabs(*(const double *)a), y = fabs(*(const double *)b);
    return (x > y) - (x < y);
}

/* DOMAIN.md "Clearances": a free area lies in front of its fixture and may slide sideways to
 * stay inside the room; it fits when some sideways position is clear of walls, pre-walls and
 * furniture (free areas may overlap each other, furniture may not stand in one). The area
 * keeps covering the fixture's front (or, narrower than the fixture, stays within it), so it
 * slides at most half the difference of the two widths. The positions tried are the centred
 * one, the two ends and those where an area edge meets a corner of a wall, pre-wall or
 * fixture nearby: where walls and fixtures stand square to the fixture (the common case) the
 * ends of every clear stretch are among them; past a slanted one a narrow fit may be missed
 * and reported as blocked, never the other way round. They are tried from the
 * least shift outwards; *s receives the first clear one, or, when none is, the least shifted
 * inside the room (*room_ok = 1) or the centred one (*room_ok = 0). Returns 1 when a clear
 * position exists, 0 when none does, -1 when out of memory. */
static int place_free_area(const check_ctx *c, int i, double aw, double ad, double *s, int *room_ok)
{
    const app_fixture *f = &c->fx[i];
    const pl_rect fr = c->rects[i];
    double slide = 0.5 * fabs(aw - 2 * f->half[0]);
    const app_room_plan *plan = &c->p->plan;
    int prewalls = plan->corner_count >= 3 ? plan->prewall_count : 0;
    size_t cap = 3 + 2 * (size_t)c->poly_n + 8 * (size_t)prewalls + 8 * (size_t)c->count;
    double *cand = malloc(cap * sizeof *cand);
    if (!cand)
        return -1;
    int n = 0;
    cand[n++] = 0;
    cand[n++] = -slide;
    cand[n++] = slide;
    if (slide > 0) {
        /* The sweep of every position: only what reaches into it can block one. */
        pl_rect sweep = free_area_at(f, 0, aw + 2 * slide, ad);
        double sbox[4];
        bounds_of(&sweep, sbox);
        for (int k = 0; k < c->poly_n; k++) {
            double p[2] = {c->poly[k].x, c->poly[k].y};
            n = add_edge_offsets(&fr, p, aw, slide, cand, n);
        }
        for (int k = 0; k < prewalls; k++) {
            pl_rect pw = pl_prewall_rect(plan, k);
            double pc[4][2];
            pl_rect_corners(&pw, pc);
            for (int q = 0; q < 4; q++)
                n = add_edge_offsets(&fr, pc[q], aw, slide, cand, n);
        }
        for (int j = 0; j < c->count; j++) {
            if (j == i || apart(sbox, c->aabb[j], 0))
                continue;
            double pc[4][2];
            pl_rect_corners(&c->rects[j], pc);
            for (int q = 0; q < 4; q++)
                n = add_edge_offsets(&fr, pc[q], aw, slide, cand, n);
        }
    }
    qsort(cand, (size_t)n, sizeof *cand, by_magnitude);
    int found = 0, have_room = 0;
    double room_s = 0;
    for (int k = 0; k < n && !found; k++) {
        pl_rect area = free_area_at(f, cand[k], aw, ad);
        char what[160];
        double where[2];
        if (rect_blocked_by_room(c, &area, 0, FREE_AREA_HEADROOM_MM, what, sizeof what, where))
            continue;
        if (!have_room) {
            have_room = 1;
            room_s = cand[k];
        }
        if (area_clear_of_furniture(c, i, &area)) {
            found = 1;
            room_s = cand[k];
        }
    }
    free(cand);
    *s = have_room ? room_s : 0;
    *room_ok = have_room;
    return found;
}

static app_result check_free_areas(check_ctx *c)
{
    for (int i = 0; i < c->count; i++) {
        const app_fixture *f = &c->fx[i];
        double aw, ad, s;
        int room_ok;
        if (f->role != APP_ROLE_FIXTURE || !app_free_area_size(f, c->bf, &aw, &ad))
            continue;
        int fits = place_free_area(c, i, aw, ad, &s, &room_ok);
        if (fits < 0)
            return APP_ERR_OUT_OF_MEMORY;
        if (fits)
            continue;
        pl_rect area = free_area_at(f, s, aw, ad);
        app_finding_kind kind =
            c->bf != APP_BARRIER_FREE_OFF ? APP_FINDING_BARRIER_FREE : APP_FINDING_FREE_AREA;
        const char *source = c->bf == APP_BARRIER_FREE_OFF ? "VDI 6000 sheet 1" : "DIN 18040-2";
        char what[160];
        double where[2];
        app_result r = APP_OK;
        if (!room_ok) {
            rect_blocked_by_room(c, &area, 0, FREE_AREA_HEADROOM_MM, what, sizeof what, where);
            r = pl_add_finding(c->out, kind, APP_SEVERITY_ERROR, f->object, -1, where,
                               "the %.0f x %.0f mm free area in front of %s \"%s\" is blocked by "
                               "%s at every sideways position (%s)",
                               aw, ad, category_label(f->category), f->name, what, source);
            if (r != APP_OK)
                return r;
            continue;
        }
        /* Inside the room but not clear: name the furniture in the least shifted position. */
        double abox[4];
        bounds_of(&area, abox);
        for (int j = 0; j < c->count; j++) {
            const app_fixture *b = &c->fx[j];
            if (j == i || !takes_room(b) || b->z0 >= FREE_AREA_HEADROOM_MM || carries(c, i, j) ||
                apart(abox, c->aabb[j], 0))
                continue;
            const pl_rect rb = c->rects[j];
            double pen = pl_rect_penetration(&area, &rb);
            if (pen <= PL_TOLERANCE_MM)
                continue;
            double mid[2] = {0.5 * (area.c[0] + rb.c[0]), 0.5 * (area.c[1] + rb.c[1])};
            r = pl_add_finding(c->out, kind, APP_SEVERITY_ERROR, f->object, b->object, mid,
                               "the %.0f x %.0f mm free area in front of %s \"%s\" is blocked by "
                               "\"%s\" (%.0f mm into it; %s)",
                               aw, ad, category_label(f->category), f->name, b->name, pen, source);
            if (r != APP_OK)
                return r;
        }
    }
    return APP_OK;
}

/* Whether the strip beside fixture f (local x from x0 to x1, y from the back to depth) is
 * clear of walls, pre-walls and other fixtures below the fixture's top. */
static int strip_clear(const check_ctx *c, const app_fixture *f, double x0, double x1, double depth,
                       char *what, size_t what_size, double where[2])
{
    pl_rect s = pl_rect_local(f, x0, x1, 2 * PL_TOLERANCE_MM, depth);
    if (rect_blocked_by_room(c, &s, f->z0, fmax(f->z1, f->z0 + 1), what, what_size, where))
        return 0;
    double sbox[4];
    bounds_of(&s, sbox);
    for (int j = 0; j < c->count; j++) {
        const app_fixture *b = &c->fx[j];
        if (b == f || !takes_room(b) || apart(sbox, c->aabb[j], 0))
            continue;
        const pl_rect rb = c->rects[j];
        if (pl_rect_penetration(&s, &rb) > PL_TOLERANCE_MM && b->z0 < FREE_AREA_HEADROOM_MM) {
            snprintf(what, what_size, "\"%s\"", b->name);
            where[0] = rb.c[0];
            where[1] = rb.c[1];
            return 0;
        }
    }
    return 1;
}

/* 200 mm from basins and WCs to the walls beside them (DOMAIN.md "Clearances"). */
static app_result check_side_walls(check_ctx *c)
{
    for (int i = 0; i < c->count; i++) {
        const app_fixture *f = &c->fx[i];
        if (f->role != APP_ROLE_FIXTURE || !needs_side_room(f->category))
            continue;
        double w = 2 * f->half[0], d = 2 * f->half[1];
        for (int side = -1; side <= 1; side += 2) {
            double x0 = side < 0 ? -0.5 * w - SIDE_DISTANCE_MM + PL_TOLERANCE_MM : 0.5 * w;
            double x1 = side < 0 ? -0.5 * w : 0.5 * w + SIDE_DISTANCE_MM - PL_TOLERANCE_MM;
            pl_rect s = pl_rect_local(f, x0, x1, 2 * PL_TOLERANCE_MM, d);
            char what[160];
            double where[2];
            if (!rect_blocked_by_room(c, &s, f->z0, f->z1, what, sizeof what, where))
                continue;
            app_result r = pl_add_finding(
                c->out, APP_FINDING_DISTANCE, APP_SEVERITY_ERROR, f->object, -1, where,
                "\"%s\" is less than %.0f mm from %s on its %s side "
                "(VDI 6000 sheet 1)",
                f->name, SIDE_DISTANCE_MM, what, side < 0 ? "left" : "right");
            if (r != APP_OK)
                return r;
        }
    }
    return APP_OK;
}

/* DIN 18040-2, wheelchair users: beside the WC 900 mm clear on one side, 300 on the other. */
static app_result check_wheelchair_wc(check_ctx *c)
{
    for (int i = 0; i < c->count; i++) {
        const app_fixture *f = &c->fx[i];
        if (f->role != APP_ROLE_FIXTURE || f->category != CAT_CATEGORY_WCS_BIDETS)
            continue;
        double hw = f->half[0], depth = fmax(2 * f->half[1], WC_SIDE_DEPTH_MM);
        char what[160];
        double where[2] = {f->centre[0], f->centre[1]};
        int left_wide =
            strip_clear(c, f, -hw - WC_WIDE_SIDE_MM, -hw, depth, what, sizeof what, where);
        int right_wide =
            strip_clear(c, f, hw, hw + WC_WIDE_SIDE_MM, depth, what, sizeof what, where);
        int left_narrow =
            strip_clear(c, f, -hw - WC_NARROW_SIDE_MM, -hw, depth, what, sizeof what, where);
        int right_narrow =
            strip_clear(c, f, hw, hw + WC_NARROW_SIDE_MM, depth, what, sizeof what, where);
        if ((left_wide && right_narrow) || (right_wide && left_narrow))
            continue;
        app_result r = pl_add_finding(
            c->out, APP_FINDING_BARRIER_FREE, APP_SEVERITY_ERROR, f->object, -1, f->centre,
            "WC \"%s\" needs %.0f mm clear on one side and %.0f mm on the other over %.0f mm "
            "depth (DIN 18040-2; left: %s, right: %s)",
            f->name, WC_WIDE_SIDE_MM, WC_NARROW_SIDE_MM, depth,
            left_wide     ? "900 clear"
            : left_narrow ? "300 clear"
                          : "under 300",
            right_wide     ? "900 clear"
            : right_narrow ? "300 clear"
                           : "under 300");
        if (r != APP_OK)
            return r;
    }
    return APP_OK;
}

/* DIN 18040-2: hinged doors must not open into a bathroom (someone fallen behind the door
 * would block it); outwards or sliding. */
static app_result check_barrier_free_doors(check_ctx *c)
{
    const app_room_plan *plan = &c->p->plan;
    for (int k = 0; k < plan->opening_count && plan->corner_count >= 3; k++) {
        const app_opening *op = &plan->openings[k];
        if (op->type != APP_OPENING_DOOR ||
            (op->swing != APP_SWING_IN_LEFT && op->swing != APP_SWING_IN_RIGHT) || op->wall < 0 ||
            op->wall >= plan->corner_count)
            continue;
        double o[2], d[2], n[2], len;
        pl_wall_frame(plan, op->wall, o, d, n, &len);
        double s = op->offset_mm + 0.5 * op->width_mm;
        double at[2] = {o[0] + d[0] * s, o[1] + d[1] * s};
        app_result r =
            pl_add_finding(c->out, APP_FINDING_BARRIER_FREE, APP_SEVERITY_ERROR, -1, -1, at,
                           "the door \"%s\" opens into the room; it should open "
                           "outwards or slide (DIN 18040-2)",
                           op->name);
        if (r != APP_OK)
            return r;
    }
    return APP_OK;
}

/* Sets up c for the fixtures of p: the room polygon and each fixture's footprint. */
static app_result ctx_init(check_ctx *c, const app_project *p, const app_fixture *fx, int count,
                           app_barrier_free bf, app_findings *out, char *err, size_t err_size)
{
    memset(c, 0, sizeof *c);
    c->p = p;
    c->fx = fx;
    c->count = count;
    c->bf = bf;
    c->out = out;
    if (p->plan.corner_count >= 3 && p->plan.corners) {
        c->poly = p->plan.corners;
        c->poly_n = p->plan.corner_count;
    } else {
        /* A version 1 project built in memory: its room box (project.h). */
        c->box[1].x = c->box[2].x = p->room.width_mm;
        c->box[2].y = c->box[3].y = p->room.depth_mm;
        c->poly = c->box;
        c->poly_n = 4;
    }
    c->rects = malloc((size_t)(count > 0 ? count : 1) * sizeof *c->rects);
    c->aabb = malloc((size_t)(count > 0 ? count : 1) * sizeof *c->aabb);
    if (!c->rects || !c->aabb) {
        free(c->rects);
        free(c->aabb);
        c->rects = NULL;
        c->aabb = NULL;
        if (err && err_size)
            snprintf(err, err_size, "out of memory for %d fixtures", count);
        return APP_ERR_OUT_OF_MEMORY;
    }
    for (int i = 0; i < count; i++) {
        c->rects[i] = pl_rect_of_fixture(&fx[i]);
        bounds_of(&c->rects[i], c->aabb[i]);
    }
    return APP_OK;
}

static void ctx_free(check_ctx *c)
{
    free(c->rects);
    free(c->aabb);
}

app_result app_placement_check(const app_project *p, const app_fixture *fx, int count,
                               const app_check_options *options, app_findings *out, char *err,
                               size_t err_size)
{
    check_ctx c;
    app_result r =
        ctx_init(&c, p, fx, count, options ? options->barrier_free : APP_BARRIER_FREE_OFF, out, err,
                 err_size);
    if (r != APP_OK)
        return r;
    r = check_room(&c);
    if (r == APP_OK)
        r = check_collisions(&c);
    if (r == APP_OK)
        r = check_free_areas(&c);
    if (r == APP_OK)
        r = check_side_walls(&c);
    if (r == APP_OK && c.bf == APP_BARRIER_FREE_WHEELCHAIR)
        r = check_wheelchair_wc(&c);
    if (r == APP_OK && c.bf != APP_BARRIER_FREE_OFF)
        r = check_barrier_free_doors(&c);
    if (r == APP_OK)
        r = pl_check_mounting(p, fx, count, out);
    ctx_free(&c);
    if (r != APP_OK && err && err_size)
        snprintf(err, err_size, "out of memory for the placement findings");
    return r;
}

app_result app_free_areas(const app_project *p, const app_fixture *fx, int count,
                          app_barrier_free bf, app_free_area *out, char *err, size_t err_size)
{
    check_ctx c;
    app_result r = ctx_init(&c, p, fx, count, bf, NULL, err, err_size);
    if (r != APP_OK)
        return r;
    for (int i = 0; i < count; i++) {
        const app_fixture *f = &fx[i];
        app_free_area *a = &out[i];
        memset(a, 0, sizeof *a);
        double aw, ad, s;
        int room_ok;
        if (f->role != APP_ROLE_FIXTURE || !app_free_area_size(f, bf, &aw, &ad))
            continue;
        /* The same placement the free-area check makes, so the drawing shows what it checked. */
        int fits = place_free_area(&c, i, aw, ad, &s, &room_ok);
        if (fits < 0) {
            r = APP_ERR_OUT_OF_MEMORY;
            if (err && err_size)
                snprintf(err, err_size, "out of memory placing the free areas");
            break;
        }
        pl_rect area = free_area_at(f, s, aw, ad);
        a->has_area = 1;
        a->clear = fits;
        a->width_mm = aw;
        a->depth_mm = ad;
        a->shift_mm = s;
        pl_rect_corners(&area, a->corners);
    }
    ctx_free(&c);
    return r;
}
