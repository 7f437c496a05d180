/* The generator's primitives: lofts of rounded rectangles (a lathe when each ring is a circle),
 * profiles swept along paths, and boxes. A loft is built as a polygon mesh first so that it can
 * be smoothed by Catmull-Clark subdivision (mesh_subdivide.cpp) before it is triangulated. */
#include "gen_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct poly {
    double *pos;
    int nv, capv;
    int *fidx;
    int nfi, capfi;
    int *fstart; /* nf + 1 entries once finished */
    int nf, capf;
    int fail;
} poly;

static int grow(void **p, int *cap, int need, size_t elem)
{
    if (need <= *cap)
        return 1;
    int n = *cap ? *cap : 64;
    while (n < need)
        n *= 2;
    void *q = realloc(*p, (size_t)n * elem);
    if (!q)
        return 0;
    *p = q;
    *cap = n;
    return 1;
}

static int poly_vertex(poly *p, const gen_frame *f, double x, double y, double z)
{
    if (p->fail || !grow((void **)&p->pos, &p->capv, 3 * (p->nv + 1), sizeof(double))) {
        p->fail = 1;
        return 0;
    }
    for (int k = 0; k < 3; k++)
        p->pos[3 * p->nv + k] = f->o[k] + x * f->u[k] + y * f->v[k] + z * f->w[k];
    return p->nv++;
}

static void poly_face(poly *p, const int *v, int n)
{
    if (p->fail || !grow((void **)&p->fidx, &p->capfi, p->nfi + n, sizeof(int)) ||
        !grow((void **)&p->fstart, &p->capf, p->nf + 2, sizeof(int))) {
        p->fail = 1;
        return;
    }
    p->fstart[p->nf++] = p->nfi;
    for (int i = 0; i < n; i++)
        p->fidx[p->nfi++] = v[i];
    p->fstart[p->nf] = p->nfi;
}

static void poly_free(poly *p)
{
    free(p->pos);
    free(p->fidx);
    free(p->fstart);
}

/* Adds the polygon mesh to the part: subdivided and triangulated by OpenMesh, or fanned. */
static void poly_emit(gen_ctx *c, int part, poly *p, int subdivide)
{
    gen_builder *b = c->b;
    if (p->fail) {
        b->failed = 1;
        return;
    }
    if (b->failed || part < 0 || p->nf == 0)
        return;
    if (subdivide > 0) {
        double *pos = NULL;
        int *tri = NULL, nv = 0, nt = 0;
        char err[256];
        if (cat_mesh_subdivide(p->pos, p->nv, p->fstart, p->fidx, p->nf, subdivide, &pos, &nv, &tri,
                               &nt, err, sizeof err)) {
            unsigned base = (unsigned)b->gm->model.meshes[part].vertex_count;
            for (int v = 0; v < nv; v++)
                gen_vertex(b, part, pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]);
            for (int t = 0; t < nt; t++)
                gen_triangle(b, part, base + (unsigned)tri[3 * t], base + (unsigned)tri[3 * t + 1],
                             base + (unsigned)tri[3 * t + 2]);
            free(pos);
            free(tri);
            return;
        }
        free(pos);
        free(tri);
        /* OpenMesh refused the cage: a bug in a generator, reported rather than hidden. */
        if (!b->error[0])
            snprintf(b->error, sizeof b->error, "%s", err);
        b->failed = 1;
        return;
    }
    unsigned base = (unsigned)b->gm->model.meshes[part].vertex_count;
    for (int v = 0; v < p->nv; v++)
        gen_vertex(b, part, p->pos[3 * v], p->pos[3 * v + 1], p->pos[3 * v + 2]);
    for (int f = 0; f < p->nf; f++) {
        const int *v = p->fidx + p->fstart[f];
        int n = p->fstart[f + 1] - p->fstart[f];
        for (int k = 1; k + 1 < n; k++)
            gen_triangle(b, part, base + (unsigned)v[0], base + (unsigned)v[k],
                         base + (unsigned)v[k + 1]);
    }
}

gen_frame gen_frame_at(double x, double y, double z)
{
    gen_frame f = {{x, y, z}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    return f;
}

static void cross(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

static double normalize(double v[3])
{
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (l > 0)
        for (int k = 0; k < 3; k++)
            v[k] /= l;
    return l;
}

gen_frame gen_frame_axis(double x, double y, double z, const double dir[3])
{
    gen_frame f = gen_frame_at(x, y, z);
    double w[3] = {dir[0], dir[1], dir[2]};
    if (normalize(w) == 0)
        return f;
    double a[3] = {0, 0, 1};
    if (fabs(w[2]) >= 0.9) {
        a[0] = 1;
        a[2] = 0;
    }
    cross(a, w, f.u);
    normalize(f.u);
    cross(w, f.u, f.v);
    memcpy(f.w, w, sizeof w);
    return f;
}

gen_ring gen_ring_round(double hx, double hy, double z, double r)
{
    gen_ring g = {hx, hy, z, {r, r, r, r}, 0, 0};
    return g;
}

void gen_loft(gen_ctx *c, int part, const gen_frame *f, const gen_ring *rings, int n,
              int corner_segs, int subdivide)
{
    if (corner_segs < 1)
        corner_segs = 1;
    /* Unsmoothed lofts sample each corner arc at both ends (flat sides stay exact); cages for
     * subdivision sample it at the middles of its steps, so that no two points of a ring
     * coincide when a side has zero length (a circle), which subdivision would crease. */
    int mid = subdivide > 0, pts = mid ? corner_segs : corner_segs + 1;
    int per = 4 * pts;
    poly p = {0};
    int *first = calloc((size_t)n + 1, sizeof *first);
    if (!first) {
        c->b->failed = 1;
        return;
    }
    static const double sx[4] = {1, -1, -1, 1}, sy[4] = {1, 1, -1, -1};
    for (int i = 0; i < n; i++) {
        const gen_ring *g = &rings[i];
        if (g->hx <= 0 && g->hy <= 0) {
            first[i] = -1 - poly_vertex(&p, f, g->cx, g->cy, g->z); /* a pole */
            continue;
        }
        first[i] = p.nv;
        double m = g->hx < g->hy ? g->hx : g->hy;
        for (int k = 0; k < 4; k++) {
            double r = g->r[k] < m ? g->r[k] : m;
            r = r > 0 ? r : 0;
            double ccx = g->cx + sx[k] * (g->hx - r), ccy = g->cy + sy[k] * (g->hy - r);
            for (int t = 0; t < pts; t++) {
                double a = (k + (t + 0.5 * mid) / corner_segs) * GEN_PI / 2;
                poly_vertex(&p, f, ccx + r * cos(a), ccy + r * sin(a), g->z);
            }
        }
    }
    for (int i = 0; i + 1 < n; i++) {
        int a = first[i], b = first[i + 1];
        for (int j = 0; j < per; j++) {
            int j1 = (j + 1) % per;
            if (a < 0 && b < 0)
                continue;
            if (a < 0) {
                int v[3] = {-1 - a, b + j1, b + j};
                poly_face(&p, v, 3);
            } else if (b < 0) {
                int v[3] = {a + j, a + j1, -1 - b};
                poly_face(&p, v, 3);
            } else {
                int v[4] = {a + j, a + j1, b + j1, b + j};
                poly_face(&p, v, 4);
            }
        }
    }
    free(first);
    poly_emit(c, part, &p, subdivide);
    poly_free(&p);
}

void gen_sweep(gen_ctx *c, int part, const double *path, int n, const double *profile, int np,
               const double side_in[3], int cap)
{
    if (n < 2 || np < 3)
        return;
    int closed = cap == 2;
    poly p = {0};
    gen_frame id = gen_frame_at(0, 0, 0);
    double side[3] = {side_in[0], side_in[1], side_in[2]};
    for (int i = 0; i < n; i++) {
        int i0 = i > 0 ? i - 1 : closed ? n - 1 : 0, i1 = i + 1 < n ? i + 1 : closed ? 0 : i;
        double t[3];
        for (int k = 0; k < 3; k++)
            t[k] = path[3 * i1 + k] - path[3 * i0 + k];
        normalize(t);
        double d = side[0] * t[0] + side[1] * t[1] + side[2] * t[2];
        for (int k = 0; k < 3; k++)
            side[k] -= d * t[k];
        if (normalize(side) < 1e-9) { /* side along the tangent: take any perpendicular */
            gen_frame f = gen_frame_axis(0, 0, 0, t);
            memcpy(side, f.u, sizeof side);
        }
        double up[3];
        cross(t, side, up);
        for (int j = 0; j < np; j++) {
            double x = profile[2 * j], y = profile[2 * j + 1];
            poly_vertex(&p, &id, path[3 * i] + x * side[0] + y * up[0],
                        path[3 * i + 1] + x * side[1] + y * up[1],
                        path[3 * i + 2] + x * side[2] + y * up[2]);
        }
    }
    int rings = closed ? n : n - 1;
    for (int i = 0; i < rings; i++) {
        int a = i * np, b = ((i + 1) % n) * np;
        for (int j = 0; j < np; j++) {
            int j1 = (j + 1) % np;
            int v[4] = {a + j, a + j1, b + j1, b + j};
            poly_face(&p, v, 4);
        }
    }
    if (cap == 1) {
        for (int e = 0; e < 2; e++) {
            int at = e ? n - 1 : 0, ring = at * np;
            double ctr[3] = {0, 0, 0};
            for (int j = 0; j < np; j++)
                for (int k = 0; k < 3; k++)
                    ctr[k] += p.pos[3 * (ring + j) + k] / np;
            int cv = poly_vertex(&p, &id, ctr[0], ctr[1], ctr[2]);
            for (int j = 0; j < np; j++) {
                int j1 = (j + 1) % np;
                int v[3] = {cv, ring + j1, ring + j};
                if (e) {
                    v[0] = ring + j;
                    v[1] = ring + j1;
                    v[2] = cv;
                }
                poly_face(&p, v, 3);
            }
        }
    }
    poly_emit(c, part, &p, 0);
    poly_free(&p);
}

void gen_tube(gen_ctx *c, int part, const double *path, int n, double r, int segs, int closed)
{
    double prof[2 * 32];
    segs = segs < 3 ? 3 : segs > 32 ? 32 : segs;
    for (int j = 0; j < segs; j++) {
        prof[2 * j] = r * cos(2 * GEN_PI * j / segs);
        prof[2 * j + 1] = r * sin(2 * GEN_PI * j / segs);
    }
    /* A side direction not along the path's first segment. */
    double t[3] = {path[3] - path[0], path[4] - path[1], path[5] - path[2]};
    double side[3] = {0, 0, 1};
    if (fabs(t[2]) > 0.9 * sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2])) {
        side[0] = 1;
        side[2] = 0;
    }
    gen_sweep(c, part, path, n, prof, segs, side, closed ? 2 : 1);
}

void gen_box(gen_ctx *c, int part, double x0, double y0, double z0, double x1, double y1, double z1)
{
    gen_builder *b = c->b;
    /* Each face: 4 corners counter-clockwise seen from outside. */
    const double q[6][4][3] = {
        {{x0, y0, z0}, {x0, y1, z0}, {x1, y1, z0}, {x1, y0, z0}}, /* -z */
        {{x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}}, /* +z */
        {{x0, y0, z0}, {x1, y0, z0}, {x1, y0, z1}, {x0, y0, z1}}, /* -y */
        {{x0, y1, z0}, {x0, y1, z1}, {x1, y1, z1}, {x1, y1, z0}}, /* +y */
        {{x0, y0, z0}, {x0, y0, z1}, {x0, y1, z1}, {x0, y1, z0}}, /* -x */
        {{x1, y0, z0}, {x1, y1, z0}, {x1, y1, z1}, {x1, y0, z1}}, /* +x */
    };
    for (int f = 0; f < 6; f++) {
        unsigned v[4];
        for (int k = 0; k < 4; k++)
            v[k] = gen_vertex(b, part, q[f][k][0], q[f][k][1], q[f][k][2]);
        gen_triangle(b, part, v[0], v[1], v[2]);
        gen_triangle(b, part, v[0], v[2], v[3]);
    }
}

void gen_rbox(gen_ctx *c, int part, double x0, double y0, double z0, double x1, double y1,
              double z1, double e)
{
    double hx = (x1 - x0) / 2, hy = (y1 - y0) / 2, hz = (z1 - z0) / 2;
    double m = hx < hy ? hx : hy;
    m = m < hz ? m : hz;
    e = e < m * 0.9 ? e : m * 0.9;
    gen_frame f = gen_frame_at((x0 + x1) / 2, (y0 + y1) / 2, z0);
    gen_ring r[6] = {
        gen_ring_round(0, 0, 0, 0),
        gen_ring_round(hx - e * 0.3, hy - e * 0.3, 0, e * 0.7),
        gen_ring_round(hx, hy, e, e),
        gen_ring_round(hx, hy, 2 * hz - e, e),
        gen_ring_round(hx - e * 0.3, hy - e * 0.3, 2 * hz, e * 0.7),
        gen_ring_round(0, 0, 2 * hz, 0),
    };
    gen_loft(c, part, &f, r, 6, 2, 0);
}

void gen_cylinder(gen_ctx *c, int part, double x, double y, double z, const double w[3], double r,
                  double len, int segs)
{
    gen_frame f = gen_frame_axis(x, y, z, w);
    gen_ring g[6] = {gen_ring_round(0, 0, 0, 0),   gen_ring_round(r, r, 0, r),
                     gen_ring_round(r, r, 0, r),   gen_ring_round(r, r, len, r),
                     gen_ring_round(r, r, len, r), gen_ring_round(0, 0, len, 0)};
    gen_loft(c, part, &f, g, 6, segs / 4 > 1 ? segs / 4 : 1, 0);
}

void gen_ellipsoid(gen_ctx *c, int part, double x, double y, double z, double rx, double ry,
                   double rz)
{
    gen_frame f = gen_frame_at(x, y, z);
    enum { N = 9 };
    gen_ring g[N];
    for (int i = 0; i < N; i++) {
        double a = -GEN_PI / 2 + GEN_PI * i / (N - 1);
        double cr = cos(a);
        if (i == 0 || i == N - 1)
            cr = 0;
        g[i] = gen_ring_round(rx * cr, ry * cr, rz * sin(a), (rx < ry ? rx : ry) * cr);
    }
    gen_loft(c, part, &f, g, N, 3, 0);
}
