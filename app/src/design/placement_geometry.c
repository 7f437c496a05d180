/* Plan geometry for the placement checks: oriented rectangles (separating axis test),
 * segment distances, point in polygon, walls and pre-walls of the plan (app/design/room.h). */
#include "placement_internal.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

pl_rect pl_rect_make(double cx, double cy, double angle_deg, double half_w, double half_d)
{
    double a = angle_deg * M_PI / 180.0;
    pl_rect r;
    r.c[0] = cx;
    r.c[1] = cy;
    r.ax[0] = cos(a);
    r.ax[1] = sin(a);
    r.ay[0] = -r.ax[1];
    r.ay[1] = r.ax[0];
    r.h[0] = half_w;
    r.h[1] = half_d;
    return r;
}

pl_rect pl_rect_of_fixture(const app_fixture *f)
{
    return pl_rect_make(f->centre[0], f->centre[1], f->angle_deg, f->half[0], f->half[1]);
}

pl_rect pl_rect_local(const app_fixture *f, double x0, double x1, double y0, double y1)
{
    pl_rect base = pl_rect_of_fixture(f);
    /* The fixture's back face is at local y = -half depth from its centre. */
    double mx = 0.5 * (x0 + x1), my = 0.5 * (y0 + y1) - f->half[1];
    pl_rect r = base;
    r.c[0] = base.c[0] + base.ax[0] * mx + base.ay[0] * my;
    r.c[1] = base.c[1] + base.ax[1] * mx + base.ay[1] * my;
    r.h[0] = 0.5 * fabs(x1 - x0);
    r.h[1] = 0.5 * fabs(y1 - y0);
    return r;
}

void pl_rect_corners(const pl_rect *r, double out[4][2])
{
    static const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
    for (int i = 0; i < 4; i++) {
        out[i][0] = r->c[0] + sx[i] * r->h[0] * r->ax[0] + sy[i] * r->h[1] * r->ay[0];
        out[i][1] = r->c[1] + sx[i] * r->h[0] * r->ax[1] + sy[i] * r->h[1] * r->ay[1];
    }
}

/* Half the extent of r projected on the unit axis u. */
static double radius_on(const pl_rect *r, const double u[2])
{
    return r->h[0] * fabs(r->ax[0] * u[0] + r->ax[1] * u[1]) +
           r->h[1] * fabs(r->ay[0] * u[0] + r->ay[1] * u[1]);
}

double pl_rect_penetration(const pl_rect *a, const pl_rect *b)
{
    const double *axes[4] = {a->ax, a->ay, b->ax, b->ay};
    double d[2] = {b->c[0] - a->c[0], b->c[1] - a->c[1]};
    double best = INFINITY;
    for (int i = 0; i < 4; i++) {
        double dist = fabs(d[0] * axes[i][0] + d[1] * axes[i][1]);
        double pen = radius_on(a, axes[i]) + radius_on(b, axes[i]) - dist;
        if (pen < best)
            best = pen;
    }
    return best;
}

static double clamp01(double t)
{
    return t < 0 ? 0 : t > 1 ? 1 : t;
}

/* Closest point on segment a0-a1 to p. */
static void closest_on_segment(const double a0[2], const double a1[2], const double p[2],
                               double out[2])
{
    double e[2] = {a1[0] - a0[0], a1[1] - a0[1]};
    double len2 = e[0] * e[0] + e[1] * e[1];
    double t = len2 > 0 ? clamp01(((p[0] - a0[0]) * e[0] + (p[1] - a0[1]) * e[1]) / len2) : 0;
    out[0] = a0[0] + t * e[0];
    out[1] = a0[1] + t * e[1];
}

static double cross3(const double o[2], const double a[2], const double b[2])
{
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

/* 1 when the segments cross properly (each one's ends strictly on both sides of the other). */
static int segments_cross(const double a0[2], const double a1[2], const double b0[2],
                          const double b1[2], double at[2])
{
    double d1 = cross3(b0, b1, a0), d2 = cross3(b0, b1, a1);
    double d3 = cross3(a0, a1, b0), d4 = cross3(a0, a1, b1);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) {
        double t = d1 / (d1 - d2);
        at[0] = a0[0] + t * (a1[0] - a0[0]);
        at[1] = a0[1] + t * (a1[1] - a0[1]);
        return 1;
    }
    return 0;
}

double pl_segment_distance(const double a0[2], const double a1[2], const double b0[2],
                           const double b1[2], double p[2])
{
    double at[2];
    if (segments_cross(a0, a1, b0, b1, at)) {
        p[0] = at[0];
        p[1] = at[1];
        return 0;
    }
    const double *ends[4] = {a0, a1, b0, b1};
    double best = INFINITY;
    for (int i = 0; i < 4; i++) {
        double q[2];
        if (i < 2)
            closest_on_segment(b0, b1, ends[i], q);
        else
            closest_on_segment(a0, a1, ends[i], q);
        double d = hypot(q[0] - ends[i][0], q[1] - ends[i][1]);
        if (d < best) {
            best = d;
            p[0] = 0.5 * (q[0] + ends[i][0]);
            p[1] = 0.5 * (q[1] + ends[i][1]);
        }
    }
    return best;
}

double pl_segment_rect_distance(const double s0[2], const double s1[2], const pl_rect *r,
                                double p[2])
{
    double c[4][2];
    pl_rect_corners(r, c);
    double best = INFINITY;
    for (int i = 0; i < 4; i++) {
        double q[2];
        double d = pl_segment_distance(s0, s1, c[i], c[(i + 1) % 4], q);
        if (d < best) {
            best = d;
            p[0] = q[0];
            p[1] = q[1];
        }
    }
    /* A segment wholly inside the rectangle touches no edge. */
    double m[2] = {s0[0] - r->c[0], s0[1] - r->c[1]};
    if (fabs(m[0] * r->ax[0] + m[1] * r->ax[1]) < r->h[0] &&
        fabs(m[0] * r->ay[0] + m[1] * r->ay[1]) < r->h[1]) {
        p[0] = s0[0];
        p[1] = s0[1];
        return 0;
    }
    return best;
}

double pl_rect_distance(const pl_rect *a, const pl_rect *b, double p[2])
{
    if (pl_rect_penetration(a, b) >= 0) {
        p[0] = 0.5 * (a->c[0] + b->c[0]);
        p[1] = 0.5 * (a->c[1] + b->c[1]);
        return 0;
    }
    double ca[4][2];
    pl_rect_corners(a, ca);
    double best = INFINITY;
    for (int i = 0; i < 4; i++) {
        double q[2];
        double d = pl_segment_rect_distance(ca[i], ca[(i + 1) % 4], b, q);
        if (d < best) {
            best = d;
            p[0] = q[0];
            p[1] = q[1];
        }
    }
    return best;
}

int pl_point_in_polygon(const app_point2 *poly, int n, double x, double y)
{
    int inside = 0;
    for (int i = 0, j = n - 1; i < n; j = i++) {
        if ((poly[i].y > y) != (poly[j].y > y)) {
            double xc =
                poly[j].x + (y - poly[j].y) * (poly[i].x - poly[j].x) / (poly[i].y - poly[j].y);
            if (x < xc)
                inside = !inside;
        }
    }
    return inside;
}

int pl_rect_outside_polygon(const pl_rect *r, const app_point2 *poly, int n, double where[2])
{
    if (n < 3)
        return 0;
    pl_rect s = *r;
    for (int k = 0; k < 2; k++)
        s.h[k] = s.h[k] > 2 * PL_TOLERANCE_MM ? s.h[k] - PL_TOLERANCE_MM : 0.5 * s.h[k];
    double c[4][2];
    pl_rect_corners(&s, c);
    for (int i = 0; i < 4; i++) {
        if (!pl_point_in_polygon(poly, n, c[i][0], c[i][1])) {
            where[0] = c[i][0];
            where[1] = c[i][1];
            return 1;
        }
    }
    for (int i = 0; i < n; i++) {
        double w0[2] = {poly[i].x, poly[i].y};
        double w1[2] = {poly[(i + 1) % n].x, poly[(i + 1) % n].y};
        for (int k = 0; k < 4; k++)
            if (segments_cross(w0, w1, c[k], c[(k + 1) % 4], where))
                return 1;
    }
    return 0;
}

void pl_wall_frame(const app_room_plan *plan, int wall, double origin[2], double dir[2],
                   double normal[2], double *length)
{
    int n = plan->corner_count;
    const app_point2 a = plan->corners[wall], b = plan->corners[(wall + 1) % n];
    double dx = b.x - a.x, dy = b.y - a.y;
    double len = hypot(dx, dy);
    origin[0] = a.x;
    origin[1] = a.y;
    dir[0] = len > 0 ? dx / len : 1;
    dir[1] = len > 0 ? dy / len : 0;
    /* Counter-clockwise polygon: the interior is on the left of each wall (app/design/room.h). */
    normal[0] = -dir[1];
    normal[1] = dir[0];
    *length = len;
}

pl_rect pl_prewall_rect(const app_room_plan *plan, int k)
{
    const app_prewall *pw = &plan->prewalls[k];
    double o[2], d[2], nrm[2], len;
    pl_wall_frame(plan, pw->wall, o, d, nrm, &len);
    double s = pw->offset_mm + 0.5 * pw->width_mm, t = 0.5 * pw->depth_mm;
    pl_rect r;
    r.c[0] = o[0] + d[0] * s + nrm[0] * t;
    r.c[1] = o[1] + d[1] * s + nrm[1] * t;
    r.ax[0] = d[0];
    r.ax[1] = d[1];
    r.ay[0] = nrm[0];
    r.ay[1] = nrm[1];
    r.h[0] = 0.5 * pw->width_mm;
    r.h[1] = 0.5 * pw->depth_mm;
    return r;
}

app_result pl_add_finding(app_findings *f, app_finding_kind kind, app_severity sev, int obj_a,
                          int obj_b, const double pos[2], const char *fmt, ...)
{
    if (f->count == f->capacity) {
        int cap = f->capacity ? 2 * f->capacity : 16;
        app_finding *items = realloc(f->items, (size_t)cap * sizeof *items);
        if (!items)
            return APP_ERR_OUT_OF_MEMORY;
        f->items = items;
        f->capacity = cap;
    }
    app_finding *x = &f->items[f->count++];
    memset(x, 0, sizeof *x);
    x->kind = kind;
    x->severity = sev;
    x->objects[0] = obj_a;
    x->objects[1] = obj_b;
    x->position_mm[0] = pos ? pos[0] : 0;
    x->position_mm[1] = pos ? pos[1] : 0;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(x->message, sizeof x->message, fmt, ap);
    va_end(ap);
    return APP_OK;
}

void app_findings_free(app_findings *f)
{
    if (!f)
        return;
    free(f->items);
    memset(f, 0, sizeof *f);
}

const char *app_finding_kind_name(app_finding_kind k)
{
    static const char *const names[] = {"collision", "outside-room", "prewall",      "opening",
                                        "free-area", "distance",     "barrier-free", "floating"};
    return (unsigned)k < sizeof names / sizeof names[0] ? names[k] : "unknown";
}

const char *app_severity_name(app_severity s)
{
    static const char *const names[] = {"info", "warning", "error"};
    return (unsigned)s < 3 ? names[s] : "unknown";
}

int app_findings_errors(const app_findings *f)
{
    int n = 0;
    for (int i = 0; f && i < f->count; i++)
        n += f->items[i].severity == APP_SEVERITY_ERROR;
    return n;
}
