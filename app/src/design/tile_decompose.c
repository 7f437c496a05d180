/* The region of a surface (outline minus holes) cut into convex pieces: vertical slabs between
 * consecutive vertex (and crossing) abscissae, and in each slab the trapezoids between the edges
 * where the winding number is > 0 (outline +1, holes -1). Convex pieces make every tile's clip a
 * convex-convex Sutherland-Hodgman clip, which is robust where tile edges coincide with the
 * region's edges (the common case: a grid aligned to a window). docs/tiling.md. */
#include "tile_layout_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct tl_edge {
    double xl, yl, xr, yr; /* left and right end */
    int w;                 /* +1 / -1: the winding change crossing it upwards */
    int ring;
} tl_edge;

typedef struct tl_span {
    double yb0, yb1, yt0, yt1; /* bottom and top lines at the slab's left and right */
} tl_span;

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static double edge_y(const tl_edge *e, double x)
{
    return e->yl + (e->yr - e->yl) * (x - e->xl) / (e->xr - e->xl);
}

typedef struct active {
    double ym;
    int e;
} active;

static int cmp_active(const void *a, const void *b)
{
    double x = ((const active *)a)->ym, y = ((const active *)b)->ym;
    return x < y ? -1 : x > y;
}

/* Growable arrays. */
typedef struct growbuf {
    void *p;
    int n, cap;
    size_t elem;
} growbuf;

static void *grow(growbuf *g, int extra)
{
    if (g->n + extra > g->cap) {
        int cap = g->cap ? g->cap : 64;
        while (cap < g->n + extra)
            cap *= 2;
        void *p = realloc(g->p, (size_t)cap * g->elem);
        if (!p)
            return NULL;
        g->p = p;
        g->cap = cap;
    }
    return (char *)g->p + (size_t)g->n * g->elem;
}

/* x of the proper crossing of two edges, if any. */
static int crossing_x(const tl_edge *a, const tl_edge *b, double *x)
{
    double x0 = fmax(a->xl, b->xl), x1 = fmin(a->xr, b->xr);
    if (x1 - x0 <= 1e-9)
        return 0;
    double d0 = edge_y(a, x0) - edge_y(b, x0), d1 = edge_y(a, x1) - edge_y(b, x1);
    if ((d0 > 1e-9 && d1 < -1e-9) || (d0 < -1e-9 && d1 > 1e-9)) {
        *x = x0 + (x1 - x0) * d0 / (d0 - d1);
        return 1;
    }
    return 0;
}

/* Splits the vertical side x = const from ya to yb (ya < yb when going up, the reverse going
 * down) at the neighbour slab's span ends and appends the points with SEAM / CUT labels; the
 * last point (yb) is not appended. */
static int append_side(growbuf *pts, growbuf *labs, double x, double ya, double yb,
                       const tl_span *nb, int nb_count, int nb_left)
{
    double br[TL_MAX_SIDE_BREAKS + 2];
    int nbr = 0;
    double lo = fmin(ya, yb), hi = fmax(ya, yb);
    br[nbr++] = lo;
    for (int i = 0; i < nb_count && nbr < TL_MAX_SIDE_BREAKS; i++) {
        double e0 = nb_left ? nb[i].yb1 : nb[i].yb0, e1 = nb_left ? nb[i].yt1 : nb[i].yt0;
        if (e0 > lo + 1e-9 && e0 < hi - 1e-9)
            br[nbr++] = e0;
        if (e1 > lo + 1e-9 && e1 < hi - 1e-9)
            br[nbr++] = e1;
    }
    br[nbr++] = hi;
    qsort(br, (size_t)nbr, sizeof br[0], cmp_double);
    int up = yb >= ya;
    for (int k = 0; k + 1 < nbr; k++) {
        int idx = up ? k : nbr - 1 - k;
        double y0 = br[idx], y1 = up ? br[idx + 1] : br[idx - 1];
        if (fabs(y1 - y0) < 1e-12)
            continue;
        double ym = 0.5 * (y0 + y1);
        unsigned char lab = APP_EDGE_CUT;
        for (int i = 0; i < nb_count; i++) {
            double e0 = nb_left ? nb[i].yb1 : nb[i].yb0, e1 = nb_left ? nb[i].yt1 : nb[i].yt0;
            if (ym > e0 && ym < e1) {
                lab = APP_EDGE_SEAM;
                break;
            }
        }
        app_point2 *p = grow(pts, 1);
        unsigned char *l = grow(labs, 1);
        if (!p || !l)
            return -1;
        p->x = x;
        p->y = y0;
        *l = lab;
        pts->n++;
        labs->n++;
    }
    return 0;
}

/* Appends a point unless it equals the previous one (then the previous one takes the label). */
static int append_point(growbuf *pts, growbuf *labs, int first, double x, double y,
                        unsigned char lab)
{
    if (pts->n > first) {
        app_point2 *q = (app_point2 *)pts->p + pts->n - 1;
        if (fabs(q->x - x) < 1e-9 && fabs(q->y - y) < 1e-9) {
            ((unsigned char *)labs->p)[labs->n - 1] = lab;
            return 0;
        }
    }
    app_point2 *p = grow(pts, 1);
    unsigned char *l = grow(labs, 1);
    if (!p || !l)
        return -1;
    p->x = x;
    p->y = y;
    *l = lab;
    pts->n++;
    labs->n++;
    return 0;
}

int tl_decompose(const tl_ring *rings, int ring_count, tl_decomp *out)
{
    memset(out, 0, sizeof *out);
    int total = 0;
    for (int r = 0; r < ring_count; r++)
        total += rings[r].n > 0 ? rings[r].n : 0;
    if (total > 400000)
        return -2;
    tl_edge *edges = malloc(sizeof(tl_edge) * (size_t)(total + 1));
    double *xs = NULL;
    int ne = 0, nx = 0, xcap = 0, rc = -1;
    growbuf spans = {0, 0, 0, sizeof(tl_span)}, slab_of = {0, 0, 0, sizeof(int)};
    growbuf pts = {0, 0, 0, sizeof(app_point2)}, labs = {0, 0, 0, 1};
    growbuf traps = {0, 0, 0, sizeof(tl_trap)};
    active *act = NULL;
    if (!edges)
        goto done;
    xcap = total + 16;
    xs = malloc(sizeof(double) * (size_t)xcap);
    if (!xs)
        goto done;
    for (int r = 0; r < ring_count; r++) {
        const tl_ring *g = &rings[r];
        if (g->n < 3)
            continue;
        double a = app_polygon_signed_area(g->p, g->n);
        /* Walk so that outlines run counter-clockwise and holes clockwise. */
        int reverse = (g->sign > 0) ? (a < 0) : (a > 0);
        for (int i = 0; i < g->n; i++) {
            app_point2 p = g->p[reverse ? g->n - 1 - i : i];
            app_point2 q = g->p[reverse ? (2 * g->n - 2 - i) % g->n : (i + 1) % g->n];
            xs[nx++] = p.x;
            if (p.x == q.x)
                continue; /* vertical: no winding change across a slab */
            tl_edge *e = &edges[ne++];
            e->w = p.x < q.x ? 1 : -1;
            e->ring = r;
            if (p.x < q.x) {
                e->xl = p.x, e->yl = p.y, e->xr = q.x, e->yr = q.y;
            } else {
                e->xl = q.x, e->yl = q.y, e->xr = p.x, e->yr = p.y;
            }
        }
    }
    /* Crossings between edges of different rings become slab boundaries too. */
    for (int i = 0; i < ne; i++)
        for (int j = i + 1; j < ne; j++) {
            if (edges[i].ring == edges[j].ring)
                continue;
            double x;
            if (!crossing_x(&edges[i], &edges[j], &x))
                continue;
            if (nx == xcap) {
                xcap *= 2;
                double *nxs = realloc(xs, sizeof(double) * (size_t)xcap);
                if (!nxs)
                    goto done;
                xs = nxs;
            }
            xs[nx++] = x;
        }
    if (nx < 2) {
        rc = 0;
        goto done;
    }
    qsort(xs, (size_t)nx, sizeof xs[0], cmp_double);
    int u = 1;
    for (int i = 1; i < nx; i++)
        if (xs[i] - xs[u - 1] > 1e-9)
            xs[u++] = xs[i];
    nx = u;
    act = malloc(sizeof(active) * (size_t)(ne + 1));
    out->slab_count = nx - 1;
    out->slab_x = malloc(sizeof(double) * (size_t)nx);
    out->slab_first = malloc(sizeof(int) * (size_t)(nx + 1));
    if (!act || !out->slab_x || !out->slab_first)
        goto done;
    memcpy(out->slab_x, xs, sizeof(double) * (size_t)nx);

    /* Pass 1: the spans (bottom and top lines) of each slab, bottom to top. */
    for (int k = 0; k + 1 < nx; k++) {
        double xa = xs[k], xb = xs[k + 1], xm = 0.5 * (xa + xb);
        out->slab_first[k] = spans.n;
        int na = 0;
        for (int i = 0; i < ne; i++)
            if (edges[i].xl <= xa + 1e-9 && edges[i].xr >= xb - 1e-9) {
                act[na].e = i;
                act[na].ym = edge_y(&edges[i], xm);
                na++;
            }
        qsort(act, (size_t)na, sizeof act[0], cmp_active);
        int wind = 0, open = -1;
        for (int i = 0; i < na;) {
            int j = i, sum = 0;
            while (j < na && act[j].ym - act[i].ym < 1e-9)
                sum += edges[act[j++].e].w;
            int before = wind;
            wind += sum;
            if (before <= 0 && wind > 0)
                open = act[i].e;
            else if (before > 0 && wind <= 0 && open >= 0) {
                const tl_edge *b = &edges[open], *t = &edges[act[i].e];
                tl_span s = {edge_y(b, xa), edge_y(b, xb), edge_y(t, xa), edge_y(t, xb)};
                if ((s.yt0 - s.yb0) + (s.yt1 - s.yb1) > 1e-9) {
                    tl_span *d = grow(&spans, 1);
                    int *so = grow(&slab_of, 1);
                    if (!d || !so)
                        goto done;
                    *d = s;
                    *so = k;
                    spans.n++;
                    slab_of.n++;
                }
                open = -1;
            }
            i = j;
        }
    }
    out->slab_first[nx - 1] = spans.n;

    /* Pass 2: each span as a convex polygon, its vertical sides split at the neighbours. */
    const tl_span *sp = spans.p;
    const int *sk = slab_of.p;
    double area = 0.0;
    double bb[4] = {INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < spans.n; i++) {
        int k = sk[i];
        double xa = xs[k], xb = xs[k + 1];
        const tl_span *s = &sp[i];
        int first = pts.n;
        const tl_span *right = NULL, *left = NULL;
        int nr = 0, nl = 0;
        if (k + 1 < out->slab_count) {
            right = sp + out->slab_first[k + 1];
            nr = out->slab_first[k + 2] - out->slab_first[k + 1];
        }
        if (k > 0) {
            left = sp + out->slab_first[k - 1];
            nl = out->slab_first[k] - out->slab_first[k - 1];
        }
        if (append_point(&pts, &labs, first, xa, s->yb0, APP_EDGE_CUT) < 0)
            goto done;
        if (s->yt1 - s->yb1 > 1e-9) {
            if (append_point(&pts, &labs, first, xb, s->yb1, APP_EDGE_CUT) < 0)
                goto done;
            /* The point at yb1 was just added; the side adds from yb1 (replacing its label). */
            pts.n--;
            labs.n--;
            if (append_side(&pts, &labs, xb, s->yb1, s->yt1, right, nr, 0) < 0)
                goto done;
        } else if (append_point(&pts, &labs, first, xb, s->yb1, APP_EDGE_CUT) < 0)
            goto done;
        if (append_point(&pts, &labs, first, xb, s->yt1, APP_EDGE_CUT) < 0)
            goto done;
        if (s->yt0 - s->yb0 > 1e-9) {
            if (append_point(&pts, &labs, first, xa, s->yt0, APP_EDGE_CUT) < 0)
                goto done;
            pts.n--;
            labs.n--;
            if (append_side(&pts, &labs, xa, s->yt0, s->yb0, left, nl, 1) < 0)
                goto done;
        } else if (append_point(&pts, &labs, first, xa, s->yt0, APP_EDGE_CUT) < 0)
            goto done;
        /* Drop a closing duplicate. */
        app_point2 *P = pts.p;
        while (pts.n - first > 1 && fabs(P[pts.n - 1].x - P[first].x) < 1e-9 &&
               fabs(P[pts.n - 1].y - P[first].y) < 1e-9) {
            pts.n--;
            labs.n--;
        }
        int count = pts.n - first;
        if (count > TL_MAX_POLY - 8) {
            rc = -2;
            goto done;
        }
        tl_trap *t = grow(&traps, 1);
        if (!t)
            goto done;
        t->first = first;
        t->count = count;
        t->x0 = xa;
        t->x1 = xb;
        t->y0 = fmin(s->yb0, s->yb1);
        t->y1 = fmax(s->yt0, s->yt1);
        traps.n++;
        area += app_polygon_signed_area(P + first, count);
        bb[0] = fmin(bb[0], xa);
        bb[1] = fmin(bb[1], t->y0);
        bb[2] = fmax(bb[2], xb);
        bb[3] = fmax(bb[3], t->y1);
    }
    out->traps = traps.p;
    out->trap_count = traps.n;
    out->points = pts.p;
    out->labels = labs.p;
    out->point_count = pts.n;
    traps.p = pts.p = labs.p = NULL;
    out->area = area;
    if (out->trap_count > 0)
        memcpy(out->bbox, bb, sizeof bb);
    rc = 0;
done:
    free(edges);
    free(xs);
    free(act);
    free(spans.p);
    free(slab_of.p);
    free(traps.p);
    free(pts.p);
    free(labs.p);
    if (rc != 0)
        tl_decomp_free(out);
    return rc;
}

void tl_decomp_free(tl_decomp *d)
{
    if (!d)
        return;
    free(d->traps);
    free(d->points);
    free(d->labels);
    free(d->slab_x);
    free(d->slab_first);
    memset(d, 0, sizeof *d);
}

void tl_decomp_query(const tl_decomp *d, double s0, double t0, double s1, double t1,
                     void (*fn)(void *user, const tl_trap *t), void *user)
{
    if (d->slab_count <= 0 || s1 < d->slab_x[0] || s0 > d->slab_x[d->slab_count])
        return;
    /* First slab whose right end is beyond s0 (binary search). */
    int lo = 0, hi = d->slab_count - 1;
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (d->slab_x[mid + 1] < s0)
            lo = mid + 1;
        else
            hi = mid;
    }
    for (int k = lo; k < d->slab_count && d->slab_x[k] <= s1; k++)
        for (int i = d->slab_first[k]; i < d->slab_first[k + 1]; i++) {
            const tl_trap *t = &d->traps[i];
            if (t->y1 >= t0 && t->y0 <= t1)
                fn(user, t);
        }
}
