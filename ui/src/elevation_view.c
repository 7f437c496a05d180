/* The elevation view's geometry (elevation_view.h). */
#include "elevation_view.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define DEG (3.14159265358979323846 / 180.0)

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

int ui_elev_mirrored(const app_surface_frame *f)
{
    /* The viewer looks along -normal with t up; their right hand points along
     * (-normal) x t. */
    const double *n = f->normal, *t = f->t_axis;
    double right[3] = {-(n[1] * t[2] - n[2] * t[1]), -(n[2] * t[0] - n[0] * t[2]),
                       -(n[0] * t[1] - n[1] * t[0])};
    return dot3(f->s_axis, right) < 0;
}

ui_elev_transform ui_elev_fit(double s0, double t0, double s1, double t1, int mirror, float x0,
                              float y0, float x1, float y1, float margin_px)
{
    ui_elev_transform v = {{(s0 + s1) / 2, (t0 + t1) / 2}, 0.1, mirror, x0, y0, x1, y1};
    double w = fabs(s1 - s0), h = fabs(t1 - t0);
    double aw = (double)(x1 - x0) - 2.0 * margin_px, ah = (double)(y1 - y0) - 2.0 * margin_px;
    if (!(w > 0) || !(h > 0) || !(aw > 0) || !(ah > 0) || !isfinite(w) || !isfinite(h))
        return v;
    v.px_per_mm = fmin(aw / w, ah / h);
    return v;
}

void ui_elev_to_screen(const ui_elev_transform *v, double s, double t, float *sx, float *sy)
{
    double cx = (v->x0 + v->x1) / 2.0, cy = (v->y0 + v->y1) / 2.0;
    double ds = (s - v->centre[0]) * v->px_per_mm;
    *sx = (float)(v->mirror ? cx - ds : cx + ds);
    *sy = (float)(cy - (t - v->centre[1]) * v->px_per_mm);
}

void ui_elev_to_surface(const ui_elev_transform *v, float sx, float sy, double *s, double *t)
{
    double cx = (v->x0 + v->x1) / 2.0, cy = (v->y0 + v->y1) / 2.0;
    double ds = (sx - cx) / v->px_per_mm;
    *s = v->centre[0] + (v->mirror ? -ds : ds);
    *t = v->centre[1] - (sy - cy) / v->px_per_mm;
}

int ui_elev_bounds(const app_point2 *pts, int count, app_point2 *lo, app_point2 *hi)
{
    if (!pts || count < 1)
        return 0;
    *lo = *hi = pts[0];
    for (int i = 1; i < count; i++) {
        lo->x = fmin(lo->x, pts[i].x);
        lo->y = fmin(lo->y, pts[i].y);
        hi->x = fmax(hi->x, pts[i].x);
        hi->y = fmax(hi->y, pts[i].y);
    }
    return 1;
}

static int cmp_point(const void *a, const void *b)
{
    const app_point2 *p = a, *q = b;
    if (p->x != q->x)
        return p->x < q->x ? -1 : 1;
    return p->y < q->y ? -1 : p->y > q->y;
}

static double cross(app_point2 o, app_point2 a, app_point2 b)
{
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

/* Andrew's monotone chain: the hull of n <= 8 points, counter-clockwise, into out. */
static int hull(app_point2 *pts, int n, app_point2 out[8])
{
    qsort(pts, (size_t)n, sizeof *pts, cmp_point);
    app_point2 h[17];
    int k = 0;
    for (int i = 0; i < n; i++) {
        while (k >= 2 && cross(h[k - 2], h[k - 1], pts[i]) <= 1e-9)
            k--;
        h[k++] = pts[i];
    }
    for (int i = n - 2, lower = k + 1; i >= 0; i--) {
        while (k >= lower && cross(h[k - 2], h[k - 1], pts[i]) <= 1e-9)
            k--;
        h[k++] = pts[i];
    }
    k = k > 1 ? k - 1 : k; /* the last point repeats the first */
    if (k > 8)
        k = 8;
    memcpy(out, h, (size_t)k * sizeof *out);
    return k;
}

int ui_elev_fixture_outline(const app_surface_frame *f, const app_fixture *fx, double max_depth_mm,
                            app_point2 out[8], double *depth)
{
    double c = cos(fx->angle_deg * DEG), s = sin(fx->angle_deg * DEG);
    static const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
    app_point2 pts[8];
    double dmin = INFINITY;
    for (int k = 0; k < 8; k++) {
        double lx = sx[k % 4] * fx->half[0], ly = sy[k % 4] * fx->half[1];
        double p[3] = {fx->centre[0] + lx * c - ly * s - f->origin_mm[0],
                       fx->centre[1] + lx * s + ly * c - f->origin_mm[1],
                       (k < 4 ? fx->z0 : fx->z1) - f->origin_mm[2]};
        pts[k] = (app_point2){dot3(p, f->s_axis), dot3(p, f->t_axis)};
        dmin = fmin(dmin, dot3(p, f->normal));
    }
    if (depth)
        *depth = dmin;
    if (dmin < -50.0 || dmin > max_depth_mm)
        return 0;
    return hull(pts, 8, out);
}

/* Keeps the part of poly on the inner side of one box edge: axis 0 (s) or 1 (t), the side
 * v >= limit (keep_above) or v <= limit. */
static int clip_edge(const app_point2 *in, int n, int axis, double limit, int keep_above,
                     app_point2 *out)
{
    int m = 0;
    for (int i = 0; i < n; i++) {
        app_point2 a = in[i], b = in[(i + 1) % n];
        double va = axis ? a.y : a.x, vb = axis ? b.y : b.x;
        int ina = keep_above ? va >= limit : va <= limit;
        int inb = keep_above ? vb >= limit : vb <= limit;
        if (ina)
            out[m++] = a;
        if (ina != inb) {
            double f = (limit - va) / (vb - va);
            out[m++] = (app_point2){a.x + f * (b.x - a.x), a.y + f * (b.y - a.y)};
        }
    }
    return m;
}

int ui_elev_clip_box(const app_point2 *in, int n, app_point2 lo, app_point2 hi, app_point2 out[12])
{
    /* Each edge adds at most one point to a convex polygon: 8 + 4. */
    app_point2 a[12], b[12];
    if (n < 3 || n > 8)
        return 0;
    memcpy(a, in, (size_t)n * sizeof *a);
    n = clip_edge(a, n, 0, lo.x, 1, b);
    n = clip_edge(b, n, 0, hi.x, 0, a);
    n = clip_edge(a, n, 1, lo.y, 1, b);
    n = clip_edge(b, n, 1, hi.y, 0, a);
    if (n < 3)
        return 0;
    memcpy(out, a, (size_t)n * sizeof *out);
    return n;
}

int ui_elev_fan_quads(int n, int quads[][4], int cap)
{
    int q = 0;
    for (int i = 1; i + 1 < n && q < cap; i += 2, q++) {
        quads[q][0] = 0;
        quads[q][1] = i;
        quads[q][2] = i + 1;
        quads[q][3] = i + 2 < n ? i + 2 : n - 1;
    }
    return q;
}

void ui_elev_count_tiles(const app_tile_layout *l, int *whole, int *cut)
{
    *whole = *cut = 0;
    for (int i = 0; l && i < l->tile_count; i++) {
        if (l->tiles[i].whole)
            (*whole)++;
        else
            (*cut)++;
    }
}

int ui_elev_wall_index(const char *surface)
{
    if (!surface || strncmp(surface, "wall:", 5))
        return -1;
    char *end;
    long i = strtol(surface + 5, &end, 10);
    return end != surface + 5 && !*end && i >= 0 && i < 1000000 ? (int)i : -1;
}

void ui_elev_snap_point(double s, double t, double grid_mm, double *out_s, double *out_t)
{
    *out_s = grid_mm > 0 ? round(s / grid_mm) * grid_mm : s;
    *out_t = grid_mm > 0 ? round(t / grid_mm) * grid_mm : t;
}
