/* The tile layout of one tiling on one surface region (app/design/tile_layout.h, docs/tiling.md):
 * the pattern's lattice of cells laid from the alignment point, each cell clipped against the
 * convex pieces of the region (tile_decompose.c), whole and cut tiles told apart, border rows
 * laid as their own tiles in strips cut out of the field. */
#include "tile_layout_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define DEFAULT_MAX_TILES 2000000

typedef struct lay_ctx {
    app_tile_layout *out;
    const tl_decomp *field, *base;
    int caps[4]; /* tiles, pieces, points, edges */
    int *hits;   /* trapezoids met by the current cell */
    int hit_count, hit_cap;
    const tl_decomp *cur;
    int max_tiles;
    int failed; /* 1 out of memory, 2 too many tiles */
    double unassigned;
} lay_ctx;

static void collect(void *user, const tl_trap *t)
{
    lay_ctx *c = user;
    if (c->hit_count == c->hit_cap) {
        int cap = c->hit_cap ? 2 * c->hit_cap : 64;
        int *h = realloc(c->hits, sizeof *h * (size_t)cap);
        if (!h) {
            c->failed = 1;
            return;
        }
        c->hits = h;
        c->hit_cap = cap;
    }
    c->hits[c->hit_count++] = (int)(t - c->cur->traps);
}

static void trap_poly(const tl_decomp *d, int i, tl_poly *p)
{
    const tl_trap *t = &d->traps[i];
    p->n = t->count;
    memcpy(p->p, d->points + t->first, sizeof(app_point2) * (size_t)t->count);
    memcpy(p->lab, d->labels + t->first, (size_t)t->count);
}

/* The rectangle w x h about centre c with its width along angle phi, counter-clockwise, from
 * the tile's own (lower-left) corner. */
static void rect_at(app_point2 c, double phi, double w, double h, app_point2 q[4])
{
    double ux = cos(phi), uy = sin(phi), vx = -uy, vy = ux;
    double a = 0.5 * w, b = 0.5 * h;
    q[0] = (app_point2){c.x - a * ux - b * vx, c.y - a * uy - b * vy};
    q[1] = (app_point2){c.x + a * ux - b * vx, c.y + a * uy - b * vy};
    q[2] = (app_point2){c.x + a * ux + b * vx, c.y + a * uy + b * vy};
    q[3] = (app_point2){c.x - a * ux + b * vx, c.y - a * uy + b * vy};
}

static int reserve(void **p, int *cap, int need, size_t elem)
{
    if (need <= *cap)
        return 1;
    int c = *cap ? *cap : 256;
    while (c < need)
        c *= 2;
    void *n = realloc(*p, (size_t)c * elem);
    if (!n)
        return 0;
    *p = n;
    *cap = c;
    return 1;
}

static int add_piece(lay_ctx *c, const app_point2 *p, const unsigned char *lab, int n)
{
    app_tile_layout *L = c->out;
    if (!reserve((void **)&L->pieces, &c->caps[1], L->piece_count + 1, sizeof *L->pieces) ||
        !reserve((void **)&L->points, &c->caps[2], L->point_count + n, sizeof *L->points) ||
        !reserve((void **)&L->edges, &c->caps[3], L->point_count + n, 1)) {
        c->failed = 1;
        return 0;
    }
    L->pieces[L->piece_count].first = L->point_count;
    L->pieces[L->piece_count].count = n;
    memcpy(L->points + L->point_count, p, sizeof *p * (size_t)n);
    memcpy(L->edges + L->point_count, lab, (size_t)n);
    L->point_count += n;
    L->piece_count++;
    return 1;
}

/* Forgets the pieces from `first` on. */
static void drop_pieces(app_tile_layout *L, int first)
{
    if (L->piece_count > first) {
        L->point_count = L->pieces[first].first;
        L->piece_count = first;
    }
}

/* Clips one cell (work size w x h, nominal nw x nh, same centre) against decomposition d and
 * records the tile if anything of it is left. */
static void place_cell(lay_ctx *c, const tl_decomp *d, app_point2 centre, double phi, double w,
                       double h, double nw, double nh, int product, int row, int col, int herring)
{
    if (c->failed)
        return;
    app_point2 nq[4];
    rect_at(centre, phi, nw, nh, nq);
    double s0 = INFINITY, t0 = INFINITY, s1 = -INFINITY, t1 = -INFINITY;
    for (int k = 0; k < 4; k++) {
        s0 = fmin(s0, nq[k].x), s1 = fmax(s1, nq[k].x);
        t0 = fmin(t0, nq[k].y), t1 = fmax(t1, nq[k].y);
    }
    if (d->trap_count == 0 || s1 < d->bbox[0] || s0 > d->bbox[2] || t1 < d->bbox[1] ||
        t0 > d->bbox[3])
        return;
    c->hit_count = 0;
    c->cur = d;
    tl_decomp_query(d, s0, t0, s1, t1, collect, c);
    if (c->failed || c->hit_count == 0)
        return;
    tl_poly tp, clipped;
    double cell_area = 0.0;
    for (int i = 0; i < c->hit_count; i++) {
        trap_poly(d, c->hits[i], &tp);
        tl_clip_convex(&tp, nq, APP_EDGE_TILE, &clipped);
        cell_area += tl_poly_area(&clipped);
    }
    if (cell_area < 1e-9)
        return;
    app_tile_layout *L = c->out;
    app_point2 wq[4];
    rect_at(centre, phi, w, h, wq);
    int first_piece = L->piece_count;
    double area = 0.0;
    int whole = cell_area >= nw * nh * (1.0 - 1e-9);
    if (!whole) {
        for (int i = 0; i < c->hit_count; i++) {
            trap_poly(d, c->hits[i], &tp);
            tl_clip_convex(&tp, wq, APP_EDGE_TILE, &clipped);
            double a = tl_poly_area(&clipped);
            if (a < 1e-6)
                continue;
            if (!add_piece(c, clipped.p, clipped.lab, clipped.n))
                return;
            area += a;
        }
        if (area < 1.0) {
            /* Nothing worth a tile (under 1 mm2): the cell only lends its grout. */
            drop_pieces(L, first_piece);
            c->unassigned += cell_area;
            return;
        }
        whole = area >= w * h * (1.0 - 1e-6);
    }
    if (whole) {
        /* Drop the seam pieces: a whole tile is its cell. */
        drop_pieces(L, first_piece);
        unsigned char lab[4] = {APP_EDGE_TILE, APP_EDGE_TILE, APP_EDGE_TILE, APP_EDGE_TILE};
        if (!add_piece(c, wq, lab, 4))
            return;
        area = w * h;
    }
    if (L->tile_count >= c->max_tiles) {
        c->failed = 2;
        return;
    }
    if (!reserve((void **)&L->tiles, &c->caps[0], L->tile_count + 1, sizeof *L->tiles)) {
        c->failed = 1;
        return;
    }
    app_placed_tile *t = &L->tiles[L->tile_count++];
    memset(t, 0, sizeof *t);
    t->product = product;
    t->row = row;
    t->col = col;
    t->herring = herring;
    memcpy(t->cell, wq, sizeof wq);
    t->centre = centre;
    double deg = fmod(phi * 180.0 / PI, 360.0);
    t->rotation_deg = deg < 0 ? deg + 360.0 : deg;
    t->area_mm2 = area;
    t->cell_area_mm2 = cell_area;
    t->whole = whole;
    t->first_piece = first_piece;
    t->piece_count = L->piece_count - first_piece;
    /* The clipped shape's extent in the tile's own axes. */
    double ux = cos(phi), uy = sin(phi);
    double a0 = INFINITY, a1 = -INFINITY, b0 = INFINITY, b1 = -INFINITY;
    for (int p = first_piece; p < L->piece_count; p++)
        for (int k = 0; k < L->pieces[p].count; k++) {
            app_point2 q = L->points[L->pieces[p].first + k];
            double dx = q.x - wq[0].x, dy = q.y - wq[0].y;
            double a = dx * ux + dy * uy, b = -dx * uy + dy * ux;
            a0 = fmin(a0, a), a1 = fmax(a1, a), b0 = fmin(b0, b), b1 = fmax(b1, b);
        }
    t->cut_w_mm = whole ? w : fmin(w, a1 - a0);
    t->cut_h_mm = whole ? h : fmin(h, b1 - b0);
    t->cut_u0_mm = whole ? 0 : fmax(0.0, a0);
    t->cut_v0_mm = whole ? 0 : fmax(0.0, b0);
    if (whole)
        L->whole_count++;
    else
        L->cut_count++;
    L->tiled_area_mm2 += area;
}

static app_result check_spec(const app_tile_spec *s, const char *what, char *err, size_t err_size)
{
    if (!s || !(s->work_w_mm > 0.5) || !(s->work_h_mm > 0.5) || s->work_w_mm > 20000 ||
        s->work_h_mm > 20000) {
        tl_set_err(err, err_size, "tile_layout", "%s: work size must be 0.5..20000 mm", what);
        return APP_ERR_SCHEMA;
    }
    return APP_OK;
}

/* Lays the field lattice of the pattern over the local bounding box. */
static void lay_field(lay_ctx *c, const app_tile_spec *f, app_tile_pattern pat, double g,
                      app_point2 O, double theta, const double lb[4])
{
    double ux = cos(theta), uy = sin(theta);
    double w = f->work_w_mm, h = f->work_h_mm;
#define TO_SURFACE(u, v) ((app_point2){O.x + (u)*ux - (v)*uy, O.y + (u)*uy + (v)*ux})
    if (pat == APP_PATTERN_HERRINGBONE) {
        double Lg = fmax(w, h) + g, Sg = fmin(w, h) + g;
        double base = w >= h ? 0.0 : PI / 2;
        /* Lattice P = k (S, S) + m (L, -L): k = (u + v) / 2S, m = (u - v) / 2L. */
        double k0 = INFINITY, k1 = -INFINITY, m0 = INFINITY, m1 = -INFINITY;
        for (int i = 0; i < 4; i++) {
            double u = lb[(i & 1) ? 2 : 0], v = lb[(i & 2) ? 3 : 1];
            double k = (u + v) / (2 * Sg), m = (u - v) / (2 * Lg);
            k0 = fmin(k0, k), k1 = fmax(k1, k), m0 = fmin(m0, m), m1 = fmax(m1, m);
        }
        double reach = (Lg + Sg) / Sg;
        for (long m = (long)floor(m0) - 2; m <= (long)ceil(m1) + 2 && !c->failed; m++)
            for (long k = (long)floor(k0 - reach) - 1; k <= (long)ceil(k1 + reach) + 1; k++) {
                double pu = k * Sg + m * Lg, pv = k * Sg - m * Lg;
                place_cell(c, c->field, TO_SURFACE(pu + Lg / 2, pv + Sg / 2), theta + base, w, h,
                           w + g, h + g, 0, (int)m, (int)k, 0);
                place_cell(c, c->field, TO_SURFACE(pu + Sg / 2, pv + Sg + Lg / 2),
                           theta + base + PI / 2, w, h, w + g, h + g, 0, (int)m, (int)k, 1);
                if (c->failed)
                    return;
            }
        return;
    }
    /* Row patterns lay the long side along the rows; the vertical stack stands it up. The
     * tile's own axes stay the catalog's (w, h): its angle says where w points. */
    int stand = pat == APP_PATTERN_VERTICAL_STACK;
    double lng = fmax(w, h), sht = fmin(w, h);
    double W = (stand ? sht : lng) + g, H = (stand ? lng : sht) + g;
    double phi = theta + (((w >= h) != !stand) ? PI / 2 : 0.0);
    double frac = pat == APP_PATTERN_HALF_OFFSET    ? 0.5
                  : pat == APP_PATTERN_THIRD_OFFSET ? 1.0 / 3
                                                    : 0;
    int period = pat == APP_PATTERN_HALF_OFFSET ? 2 : pat == APP_PATTERN_THIRD_OFFSET ? 3 : 1;
    long j0 = (long)floor(lb[1] / H) - 1, j1 = (long)ceil(lb[3] / H) + 1;
    for (long j = j0; j <= j1 && !c->failed; j++) {
        long jm = ((j % period) + period) % period;
        double off = jm * frac * W;
        long i0 = (long)floor((lb[0] - off) / W) - 1, i1 = (long)ceil((lb[2] - off) / W) + 1;
        for (long i = i0; i <= i1; i++) {
            double u = i * W + off + W / 2, v = j * H + H / 2;
            place_cell(c, c->field, TO_SURFACE(u, v), phi, w, h, w + g, h + g, 0, (int)j, (int)i,
                       0);
            if (c->failed)
                return;
        }
    }
#undef TO_SURFACE
}

app_result tl_layout_region(const app_tile_layout_desc *desc, app_tile_layout *out, char *err,
                            size_t err_size)
{
    if (out)
        memset(out, 0, sizeof *out);
    if (!desc || !out || !desc->region || !desc->tiling || !desc->field) {
        tl_set_err(err, err_size, "tile_layout", "missing region, tiling or field tile");
        return APP_ERR_SCHEMA;
    }
    const app_surface_region *r = desc->region;
    const app_tiling *ti = desc->tiling;
    if (r->outer.count < 3) {
        tl_set_err(err, err_size, "tile_layout", "%s: the region has no outline", r->surface);
        return APP_ERR_SCHEMA;
    }
    app_result res = check_spec(desc->field, "field tile", err, err_size);
    if (res != APP_OK)
        return res;
    if (ti->border_count < 0 || ti->border_count > APP_TILING_MAX_BORDERS ||
        (ti->border_count > 0 && !desc->borders)) {
        tl_set_err(err, err_size, "tile_layout", "%s: border specs missing", ti->name);
        return APP_ERR_SCHEMA;
    }
    for (int b = 0; b < ti->border_count; b++)
        if ((res = check_spec(&desc->borders[b], "border tile", err, err_size)) != APP_OK)
            return res;
    double g = ti->grout_mm > 0 ? ti->grout_mm : desc->field->grout_mm;
    if (!isfinite(g) || g < 0 || g > 100 || !isfinite(ti->rotation_deg) || (int)ti->pattern < 0 ||
        ti->pattern > APP_PATTERN_HERRINGBONE) {
        tl_set_err(err, err_size, "tile_layout",
                   "%s: grout must be 0..100 mm, the rotation finite, the pattern known", ti->name);
        return APP_ERR_SCHEMA;
    }

    /* The outline's bounding box, cut to the band on walls. */
    double bb[4] = {INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < r->outer.count; i++) {
        bb[0] = fmin(bb[0], r->outer.points[i].x), bb[2] = fmax(bb[2], r->outer.points[i].x);
        bb[1] = fmin(bb[1], r->outer.points[i].y), bb[3] = fmax(bb[3], r->outer.points[i].y);
    }
    int banded = r->kind == APP_SURFACE_WALL || r->kind == APP_SURFACE_PREWALL_SIDE;
    double from = banded && ti->from_mm > bb[1] ? ti->from_mm : bb[1];
    double to = banded && ti->to_mm > 0 && ti->to_mm < bb[3] ? ti->to_mm : bb[3];
    if (!(to > from)) {
        tl_set_err(err, err_size, "tile_layout", "%s: the band %g..%g mm is empty", ti->name,
                   ti->from_mm, ti->to_mm);
        return APP_ERR_SCHEMA;
    }
    double margin = 10.0 + (bb[2] - bb[0]) + (bb[3] - bb[1]);
    int nrings = 1 + r->hole_count + 2 + ti->border_count;
    tl_ring *rings = calloc((size_t)nrings, sizeof *rings);
    app_point2 extra[2 + APP_TILING_MAX_BORDERS][4];
    lay_ctx c;
    memset(&c, 0, sizeof c);
    tl_decomp base, field;
    memset(&base, 0, sizeof base);
    memset(&field, 0, sizeof field);
    if (!rings) {
        tl_set_err(err, err_size, "tile_layout", "out of memory");
        return APP_ERR_OUT_OF_MEMORY;
    }
    int n = 0, ne = 0;
    rings[n++] = (tl_ring){r->outer.points, r->outer.count, 1};
    for (int i = 0; i < r->hole_count; i++)
        rings[n++] = (tl_ring){r->holes[i].polygon.points, r->holes[i].polygon.count, -1};
    double band[2][2] = {{bb[1] - margin, from}, {to, bb[3] + margin}};
    for (int k = 0; k < 2; k++) {
        if (band[k][1] - band[k][0] <= 0 || (k == 0 && from <= bb[1]) || (k == 1 && to >= bb[3]))
            continue;
        app_point2 *q = extra[ne++];
        q[0] = (app_point2){bb[0] - margin, band[k][0]};
        q[1] = (app_point2){bb[2] + margin, band[k][0]};
        q[2] = (app_point2){bb[2] + margin, band[k][1]};
        q[3] = (app_point2){bb[0] - margin, band[k][1]};
        rings[n++] = (tl_ring){q, 4, -1};
    }
    int base_rings = n;
    for (int b = 0; b < ti->border_count; b++) {
        double lo = ti->borders[b].bottom_mm - g;
        double hi = ti->borders[b].bottom_mm +
                    fmin(desc->borders[b].work_w_mm, desc->borders[b].work_h_mm) + g;
        app_point2 *q = extra[ne++];
        q[0] = (app_point2){bb[0] - margin, lo};
        q[1] = (app_point2){bb[2] + margin, lo};
        q[2] = (app_point2){bb[2] + margin, hi};
        q[3] = (app_point2){bb[0] - margin, hi};
        rings[n++] = (tl_ring){q, 4, -1};
    }
    int drc = tl_decompose(rings, base_rings, &base);
    if (drc == 0 && ti->border_count > 0)
        drc = tl_decompose(rings, n, &field);
    free(rings);
    if (drc != 0) {
        tl_set_err(err, err_size, "tile_layout", "%s: %s", r->surface,
                   drc == -1 ? "out of memory" : "the region is too complex");
        tl_decomp_free(&base);
        return drc == -1 ? APP_ERR_OUT_OF_MEMORY : APP_ERR_SCHEMA;
    }

    snprintf(out->surface, sizeof out->surface, "%s", r->surface);
    out->specs[0] = *desc->field;
    for (int b = 0; b < ti->border_count; b++)
        out->specs[1 + b] = desc->borders[b];
    out->spec_count = 1 + ti->border_count;
    out->grout_mm = g;
    out->region_area_mm2 = base.area;

    /* The lattice's angle and a grid point (docs/tiling.md "Alignment"). */
    double theta = ti->rotation_deg * PI / 180.0;
    if (ti->pattern == APP_PATTERN_DIAGONAL)
        theta += PI / 4;
    else if (ti->pattern == APP_PATTERN_HERRINGBONE)
        theta -= PI / 4; /* the zigzag rows run along s */
    double ux = cos(theta), uy = sin(theta);
    app_point2 O;
    if (ti->align == APP_ALIGN_LINE)
        O = (app_point2){ti->origin_mm[0], ti->origin_mm[1]};
    else if (ti->align == APP_ALIGN_CORNER)
        /* The grid point half a joint outside the corner: the first tile's edge is the corner. */
        O = (app_point2){bb[0] - 0.5 * g * (ux - uy), from - 0.5 * g * (uy + ux)};
    else
        O = (app_point2){0.5 * (bb[0] + bb[2]), 0.5 * (from + to)};
    if (!isfinite(O.x) || !isfinite(O.y)) {
        tl_set_err(err, err_size, "tile_layout", "%s: the origin is not finite", ti->name);
        tl_decomp_free(&base);
        tl_decomp_free(&field);
        return APP_ERR_SCHEMA;
    }
    out->origin = O;
    double deg = fmod(theta * 180.0 / PI, 360.0);
    out->angle_deg = deg < 0 ? deg + 360 : deg;

    /* The region's box in lattice coordinates (u along theta, v across). */
    double lb[4] = {INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < 4; i++) {
        double s = bb[(i & 1) ? 2 : 0] - O.x, t = ((i & 2) ? to : from) - O.y;
        double u = s * ux + t * uy, v = -s * uy + t * ux;
        lb[0] = fmin(lb[0], u), lb[2] = fmax(lb[2], u), lb[1] = fmin(lb[1], v),
        lb[3] = fmax(lb[3], v);
    }
    double fw = desc->field->work_w_mm + g, fh = desc->field->work_h_mm + g;
    double est = (lb[2] - lb[0] + 2 * fw) * (lb[3] - lb[1] + 2 * fh) / (fw * fh);
    c.out = out;
    c.base = &base;
    c.field = ti->border_count > 0 ? &field : &base;
    c.max_tiles = desc->max_tiles > 0 ? desc->max_tiles : DEFAULT_MAX_TILES;
    if (est > 4.0 * c.max_tiles + 1000) {
        tl_set_err(err, err_size, "tile_layout", "%s: about %.0f tiles, more than %d", r->surface,
                   est, c.max_tiles);
        tl_decomp_free(&base);
        tl_decomp_free(&field);
        return APP_ERR_SCHEMA;
    }
    lay_field(&c, desc->field, ti->pattern, g, O, theta, lb);

    /* Border rows: straight along s from the field's grid point, in their strips, the long
     * side along the row (a 47 x 297 border is laid 297 long, 47 high). */
    for (int b = 0; b < ti->border_count && !c.failed; b++) {
        const app_tile_spec *s = &desc->borders[b];
        int turn = s->work_w_mm < s->work_h_mm;
        double lng = fmax(s->work_w_mm, s->work_h_mm), sht = fmin(s->work_w_mm, s->work_h_mm);
        double W = lng + g, bottom = ti->borders[b].bottom_mm;
        double nw = turn ? s->work_w_mm + 2 * g : s->work_w_mm + g;
        double nh = turn ? s->work_h_mm + g : s->work_h_mm + 2 * g;
        long i0 = (long)floor((bb[0] - O.x) / W) - 1, i1 = (long)ceil((bb[2] - O.x) / W) + 1;
        for (long i = i0; i <= i1 && !c.failed; i++)
            place_cell(&c, &base, (app_point2){O.x + i * W + W / 2, bottom + sht / 2},
                       turn ? PI / 2 : 0.0, s->work_w_mm, s->work_h_mm, nw, nh, 1 + b, -1 - b,
                       (int)i, 0);
    }
    free(c.hits);
    tl_decomp_free(&base);
    tl_decomp_free(&field);
    if (c.failed) {
        if (c.failed == 2)
            tl_set_err(err, err_size, "tile_layout", "%s: more than %d tiles", r->surface,
                       c.max_tiles);
        else
            tl_set_err(err, err_size, "tile_layout", "%s: out of memory", r->surface);
        app_tile_layout_free(out);
        return c.failed == 2 ? APP_ERR_SCHEMA : APP_ERR_OUT_OF_MEMORY;
    }
    out->grout_area_mm2 = out->region_area_mm2 - out->tiled_area_mm2;
    out->unassigned_grout_mm2 = c.unassigned;
    return APP_OK;
}

double app_tile_edge_joint_mm(const app_tiling *tiling, double g)
{
    return tiling->edge_joint_mm < 0 ? g : tiling->edge_joint_mm;
}

app_result app_tile_layout_compute(const app_tile_layout_desc *desc, app_tile_layout *out,
                                   char *err, size_t err_size)
{
    if (out)
        memset(out, 0, sizeof *out);
    if (!desc || !out || !desc->region || !desc->tiling || !desc->field) {
        tl_set_err(err, err_size, "tile_layout", "missing region, tiling or field tile");
        return APP_ERR_SCHEMA;
    }
    const app_tiling *ti = desc->tiling;
    double g = ti->grout_mm > 0 ? ti->grout_mm : desc->field->grout_mm;
    double e = app_tile_edge_joint_mm(ti, g);
    if (!isfinite(e) || e > 100 || !isfinite(ti->min_cut_mm) || ti->min_cut_mm < 0) {
        tl_set_err(err, err_size, "tile_layout",
                   "%s: the edge joint must be 0..100 mm and the minimum cut >= 0", ti->name);
        return APP_ERR_SCHEMA;
    }
    app_tile_layout_desc d = *desc;
    app_surface_region shrunk;
    memset(&shrunk, 0, sizeof shrunk);
    app_result r = APP_OK;
    if (e > 0 && desc->region->outer.count >= 3) {
        if ((r = tl_region_shrink(desc->region, e, &shrunk, err, err_size)) != APP_OK)
            return r;
        d.region = &shrunk;
    }
    app_tiling fixed = *ti;
    if (ti->align == APP_ALIGN_AUTO) {
        app_point2 origin;
        r = tl_setout_solve(&d, &origin, err, err_size);
        fixed.align = APP_ALIGN_LINE;
        fixed.origin_mm[0] = origin.x;
        fixed.origin_mm[1] = origin.y;
        d.tiling = &fixed;
    }
    if (r == APP_OK)
        r = tl_layout_region(&d, out, err, err_size);
    app_surface_region_free(&shrunk);
    return r;
}

void app_tile_layout_free(app_tile_layout *l)
{
    if (!l)
        return;
    free(l->tiles);
    free(l->pieces);
    free(l->points);
    free(l->edges);
    memset(l, 0, sizeof *l);
}
