/* Polygon helpers of the tile layout: the shoelace area and a Sutherland-Hodgman clipper of a
 * convex polygon against a convex quadrilateral that keeps track of where each edge came from
 * (the tile's own edge, a cut along the region, a seam between pieces). */
#include "tile_layout_internal.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>

double app_polygon_signed_area(const app_point2 *points, int count)
{
    if (!points || count < 3)
        return 0.0;
    /* Shoelace about the first point, which keeps the products small for far-off polygons. */
    double a = 0.0, ox = points[0].x, oy = points[0].y;
    for (int i = 1; i + 1 < count; i++)
        a += (points[i].x - ox) * (points[i + 1].y - oy) -
             (points[i + 1].x - ox) * (points[i].y - oy);
    return 0.5 * a;
}

double tl_poly_area(const tl_poly *p)
{
    return app_polygon_signed_area(p->p, p->n);
}

/* Appends a point with the label of the edge that starts there; a point equal to the last one
 * replaces that one's label (the zero-length edge between them disappears). */
static void emit(tl_poly *o, app_point2 p, unsigned char lab)
{
    if (o->n > 0) {
        app_point2 q = o->p[o->n - 1];
        if (fabs(q.x - p.x) < 1e-9 && fabs(q.y - p.y) < 1e-9) {
            o->lab[o->n - 1] = lab;
            return;
        }
    }
    if (o->n < TL_MAX_POLY) {
        o->p[o->n] = p;
        o->lab[o->n] = lab;
        o->n++;
    }
}

static void close_poly(tl_poly *o)
{
    while (o->n > 1) {
        app_point2 a = o->p[o->n - 1], b = o->p[0];
        if (fabs(a.x - b.x) < 1e-9 && fabs(a.y - b.y) < 1e-9)
            o->n--; /* the edge from the previous point now closes the polygon */
        else
            break;
    }
    if (o->n < 3)
        o->n = 0;
}

/* Keeps the part of `in` left of the directed line a -> b. */
static void clip_half(const tl_poly *in, app_point2 a, app_point2 b, unsigned char label,
                      tl_poly *out)
{
    out->n = 0;
    double dx = b.x - a.x, dy = b.y - a.y;
    double len = sqrt(dx * dx + dy * dy);
    if (len <= 0.0 || in->n < 3) {
        *out = *in;
        return;
    }
    dx /= len;
    dy /= len;
    for (int i = 0; i < in->n; i++) {
        app_point2 p = in->p[i], q = in->p[(i + 1) % in->n];
        /* Signed distance left of the line; points within 1e-9 mm count as on it. */
        double fp = dx * (p.y - a.y) - dy * (p.x - a.x);
        double fq = dx * (q.y - a.y) - dy * (q.x - a.x);
        int pin = fp >= -1e-9, qin = fq >= -1e-9;
        if (pin)
            emit(out, p, in->lab[i]);
        if (pin != qin) {
            double t = fp / (fp - fq);
            app_point2 x = {p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)};
            emit(out, x, pin ? label : in->lab[i]);
        }
    }
    close_poly(out);
}

void tl_clip_convex(const tl_poly *in, const app_point2 q[4], unsigned char label, tl_poly *out)
{
    tl_poly a, b;
    /* Four half-planes: in -> a -> b -> a -> out (never clipping a buffer into itself). */
    clip_half(in, q[0], q[1], label, &a);
    if (a.n == 0) {
        out->n = 0;
        return;
    }
    clip_half(&a, q[1], q[2], label, &b);
    if (b.n == 0) {
        out->n = 0;
        return;
    }
    clip_half(&b, q[2], q[3], label, &a);
    if (a.n == 0) {
        out->n = 0;
        return;
    }
    clip_half(&a, q[3], q[0], label, out);
}

void tl_set_err(char *err, size_t err_size, const char *prefix, const char *fmt, ...)
{
    if (!err || err_size == 0)
        return;
    int n = snprintf(err, err_size, "%s: ", prefix);
    if (n < 0 || (size_t)n >= err_size)
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err + n, err_size - (size_t)n, fmt, ap);
    va_end(ap);
}
