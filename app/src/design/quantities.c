/* Tile quantities (app/design/quantities.h, docs/tiling.md "Quantities"): per tile product the
 * placed whole and cut tiles, the cuts served by another cut's remainder (offcut reuse: best fit,
 * largest cut first; decor never; others may be turned), and the amount to order with the
 * surplus, rounded up to whole boxes. */
#include "app/design/quantities.h"
#include "tile_layout_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

app_quantity_options app_quantity_options_default(void)
{
    app_quantity_options o = {10.0, 3.0, 50.0, 1};
    return o;
}

int app_product_ref_equal(const app_product_ref *a, const app_product_ref *b)
{
    return !strcasecmp(a->manufacturer, b->manufacturer) && !strcasecmp(a->article, b->article) &&
           !strcmp(a->variant, b->variant);
}

/* A cut piece, and what is left of its tile. A piece that is a right triangle in a corner of
 * the tile (the edge pieces of diagonal layouts) leaves the opposite half of the tile, a right
 * triangle, besides the strips beside its bounding extent. Triangles are described by their
 * legs in counter-clockwise order from the right angle, so that fitting one into another is a
 * rotation, never a mirror (a tile has a face). */
typedef struct cut_item {
    int layout, tile;
    double w, h;   /* the piece's extent, tile axes */
    double rw, rh; /* the usable rectangular remainder (0 x 0 = none) */
    int tri;       /* the piece is a corner triangle with legs t1, t2 */
    double t1, t2;
    int rtri; /* the remainder holds the opposite half triangle, legs r1, r2 (less the kerf) */
    double r1, r2;
    int served; /* its piece comes from another tile's remainder */
    int source; /* its remainder serves another cut */
} cut_item;

static double demand_area(const cut_item *c)
{
    return c->tri ? 0.5 * c->t1 * c->t2 : c->w * c->h;
}

static double supply_area(const cut_item *c)
{
    return fmax(c->rw * c->rh, c->rtri ? 0.5 * c->r1 * c->r2 : 0.0);
}

static int cmp_demand(const void *a, const void *b)
{
    const cut_item *x = *(cut_item *const *)a, *y = *(cut_item *const *)b;
    double ax = demand_area(x), ay = demand_area(y);
    if (ax != ay)
        return ax > ay ? -1 : 1;
    return x->layout != y->layout ? x->layout - y->layout : x->tile - y->tile;
}

static int cmp_supply(const void *a, const void *b)
{
    const cut_item *x = *(cut_item *const *)a, *y = *(cut_item *const *)b;
    double ax = supply_area(x), ay = supply_area(y);
    if (ax != ay)
        return ax < ay ? -1 : 1;
    return x->layout != y->layout ? x->layout - y->layout : x->tile - y->tile;
}

/* Whether tile t's clipped shape is one right triangle with its right angle in a corner of the
 * tile and its legs along the tile's edges; then its legs (counter-clockwise) and the legs of
 * the opposite half of the tile, shrunk by the kerf along the cut. */
static int corner_triangle(const app_tile_layout *L, const app_placed_tile *t, double W, double H,
                           double kerf, double *l1, double *l2, double *r1, double *r2)
{
    if (t->piece_count != 1)
        return 0;
    const app_tile_piece *pc = &L->pieces[t->first_piece];
    double ux = t->cell[1].x - t->cell[0].x, uy = t->cell[1].y - t->cell[0].y;
    double vx = t->cell[3].x - t->cell[0].x, vy = t->cell[3].y - t->cell[0].y;
    double lu = hypot(ux, uy), lv = hypot(vx, vy);
    if (!(lu > 0) || !(lv > 0))
        return 0;
    /* The piece in tile axes, without collinear points. */
    double u[8], v[8];
    int n = 0;
    for (int i = 0; i < pc->count; i++) {
        app_point2 a = L->points[pc->first + (i + pc->count - 1) % pc->count];
        app_point2 b = L->points[pc->first + i];
        app_point2 c = L->points[pc->first + (i + 1) % pc->count];
        double cr = (b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x);
        if (fabs(cr) < 1e-6 * (hypot(b.x - a.x, b.y - a.y) * hypot(c.x - b.x, c.y - b.y) + 1e-12))
            continue;
        if (n == 8)
            return 0;
        double dx = b.x - t->cell[0].x, dy = b.y - t->cell[0].y;
        u[n] = (dx * ux + dy * uy) / lu;
        v[n] = (dx * vx + dy * vy) / lv;
        n++;
    }
    if (n != 3)
        return 0;
    const double eps = 0.01; /* mm */
    for (int i = 0; i < 3; i++) {
        int cu = fabs(u[i]) < eps ? 0 : fabs(u[i] - W) < eps ? 1 : -1;
        int cv = fabs(v[i]) < eps ? 0 : fabs(v[i] - H) < eps ? 1 : -1;
        if (cu < 0 || cv < 0)
            continue;
        int j = (i + 1) % 3, k = (i + 2) % 3; /* counter-clockwise after i */
        /* Both others on the edges through this corner, one on each. */
        int j_on_u = fabs(v[j] - v[i]) < eps, k_on_u = fabs(v[k] - v[i]) < eps;
        int j_on_v = fabs(u[j] - u[i]) < eps, k_on_v = fabs(u[k] - u[i]) < eps;
        if (!((j_on_u && k_on_v) || (j_on_v && k_on_u)))
            continue;
        *l1 = hypot(u[j] - u[i], v[j] - v[i]);
        *l2 = hypot(u[k] - u[i], v[k] - v[i]);
        /* The opposite half: right angle at the opposite corner; counter-clockwise its first
         * leg runs along the axis the piece's first leg does not. Shifting the hypotenuse by
         * the kerf scales the legs by 1 - kerf / (distance from the right angle to it). */
        double d = W * H / hypot(W, H), f = d > kerf ? 1.0 - kerf / d : 0.0;
        int first_along_u = j_on_u;
        *r1 = (first_along_u ? W : H) * f;
        *r2 = (first_along_u ? H : W) * f;
        return 1;
    }
    return 0;
}

/* The remainder of a tile w x h from which the piece [u0, u0 + pw] x [v0, v0 + ph] (tile axes)
 * was cut: the largest strip beside the piece (before or after it along w, full height) or
 * above or below it (full width), less the kerf; none when narrower than the minimum. */
static void offcut_rest(double w, double h, double u0, double v0, double pw, double ph,
                        const app_quantity_options *o, double *rw, double *rh)
{
    double a_w = fmax(u0, w - u0 - pw) - o->kerf_mm, a_h = h;
    double b_w = w, b_h = fmax(v0, h - v0 - ph) - o->kerf_mm;
    int a_ok = a_w >= o->min_offcut_mm && a_h >= o->min_offcut_mm;
    int b_ok = b_w >= o->min_offcut_mm && b_h >= o->min_offcut_mm;
    *rw = *rh = 0;
    if (a_ok && (!b_ok || a_w * a_h >= b_w * b_h))
        *rw = a_w, *rh = a_h;
    else if (b_ok)
        *rw = b_w, *rh = b_h;
}

static int fits(const cut_item *d, const cut_item *s, int rotatable, int *rotated)
{
    const double eps = 1e-6;
    /* The piece's extent into the rectangular rest (triangles too: by their extent). */
    if (d->w <= s->rw + eps && d->h <= s->rh + eps) {
        *rotated = 0;
        return 1;
    }
    if (rotatable && d->w <= s->rh + eps && d->h <= s->rw + eps) {
        *rotated = 1;
        return 1;
    }
    /* The triangular rest lies at the opposite corner: using it turns the piece. */
    if (!rotatable || !s->rtri)
        return 0;
    *rotated = 1;
    if (d->tri)
        return d->t1 <= s->r1 + eps && d->t2 <= s->r2 + eps;
    /* A rectangle in the right angle of the rest, either way round. */
    return d->w / s->r1 + d->h / s->r2 <= 1 + eps || d->h / s->r1 + d->w / s->r2 <= 1 + eps;
}

/* Matches the cuts of one product; appends the uses to q. */
static app_result match_offcuts(cut_item *items, int n, int line, const app_tile_spec *spec,
                                app_quantities *q, int *cap, char *err, size_t err_size)
{
    cut_item **dem = malloc(sizeof *dem * (size_t)(n + 1));
    cut_item **sup = malloc(sizeof *sup * (size_t)(n + 1));
    if (!dem || !sup) {
        free(dem);
        free(sup);
        tl_set_err(err, err_size, "quantities", "out of memory");
        return APP_ERR_OUT_OF_MEMORY;
    }
    int ns = 0;
    for (int i = 0; i < n; i++) {
        dem[i] = &items[i];
        if (items[i].rw > 0 || items[i].rtri)
            sup[ns++] = &items[i];
    }
    qsort(dem, (size_t)n, sizeof *dem, cmp_demand);
    qsort(sup, (size_t)ns, sizeof *sup, cmp_supply);
    for (int i = 0; i < n; i++) {
        cut_item *d = dem[i];
        if (d->source)
            continue; /* its tile is bought whole: its remainder already serves a cut */
        /* Best fit: the smallest remainder that takes the piece (at most 4096 looked at). */
        int lo = 0, hi = ns;
        while (lo < hi) {
            int mid = (lo + hi) / 2;
            if (supply_area(sup[mid]) < demand_area(d) - 1e-6)
                lo = mid + 1;
            else
                hi = mid;
        }
        for (int k = lo, looked = 0; k < ns && looked < 4096; k++, looked++) {
            cut_item *s = sup[k];
            int rotated;
            if (s == d || s->served || s->source || !fits(d, s, spec->rotatable, &rotated))
                continue;
            if (q->offcut_count == *cap) {
                int nc = *cap ? 2 * *cap : 64;
                app_offcut_use *u = realloc(q->offcuts, sizeof *u * (size_t)nc);
                if (!u) {
                    free(dem);
                    free(sup);
                    tl_set_err(err, err_size, "quantities", "out of memory");
                    return APP_ERR_OUT_OF_MEMORY;
                }
                q->offcuts = u;
                *cap = nc;
            }
            app_offcut_use *u = &q->offcuts[q->offcut_count++];
            u->product = line;
            u->source_layout = s->layout;
            u->source_tile = s->tile;
            u->target_layout = d->layout;
            u->target_tile = d->tile;
            u->piece_w_mm = d->w;
            u->piece_h_mm = d->h;
            /* Which rest and piece shape served (a triangle rest only when the rectangle
             * could not). */
            int rect_rest = d->w <= s->rw + 1e-6 && d->h <= s->rh + 1e-6;
            if (!rect_rest && spec->rotatable)
                rect_rest = d->w <= s->rh + 1e-6 && d->h <= s->rw + 1e-6;
            u->rest_triangle = !rect_rest;
            u->rest_w_mm = rect_rest ? s->rw : s->r1;
            u->rest_h_mm = rect_rest ? s->rh : s->r2;
            u->piece_triangle = d->tri && !rect_rest;
            if (u->piece_triangle) {
                u->piece_w_mm = d->t1;
                u->piece_h_mm = d->t2;
            }
            u->rotated = rotated;
            s->source = 1;
            d->served = 1;
            break;
        }
    }
    free(dem);
    free(sup);
    return APP_OK;
}

static void order_amounts(app_tile_quantity *t, double surplus)
{
    const app_tile_spec *s = &t->spec;
    t->pieces_needed = t->whole + t->cut - t->reused;
    t->surplus_percent = surplus;
    /* The tiny epsilon keeps 36 x 1.10 = 39.6000000001 from becoming 40 by rounding noise. */
    t->pieces_with_surplus = (int)ceil(t->pieces_needed * (1.0 + surplus / 100.0) - 1e-9);
    double work_m2 = s->work_w_mm * s->work_h_mm * 1e-6;
    if (s->pieces_per_box > 0) {
        t->boxes = (t->pieces_with_surplus + s->pieces_per_box - 1) / s->pieces_per_box;
        t->pieces_to_order = t->boxes * s->pieces_per_box;
        t->order_m2 = s->m2_per_box > 0 ? t->boxes * s->m2_per_box : t->pieces_to_order * work_m2;
    } else if (s->m2_per_box > 0) {
        t->boxes = (int)ceil(t->pieces_with_surplus * work_m2 / s->m2_per_box - 1e-9);
        t->order_m2 = t->boxes * s->m2_per_box;
        t->pieces_to_order = t->pieces_with_surplus;
    } else {
        t->boxes = 0;
        t->pieces_to_order = t->pieces_with_surplus;
        t->order_m2 = t->pieces_to_order * work_m2;
    }
}

app_result app_quantities_compute(const app_tile_layout *layouts, int n,
                                  const app_quantity_options *opts, app_quantities *out, char *err,
                                  size_t err_size)
{
    if (out)
        memset(out, 0, sizeof *out);
    if (!out || n < 0 || (n > 0 && !layouts)) {
        tl_set_err(err, err_size, "quantities", "no layouts");
        return APP_ERR_SCHEMA;
    }
    app_quantity_options o = opts ? *opts : app_quantity_options_default();
    if (!isfinite(o.surplus_percent) || o.surplus_percent < 0 || o.surplus_percent > 1000 ||
        !isfinite(o.kerf_mm) || o.kerf_mm < 0 || !isfinite(o.min_offcut_mm) ||
        o.min_offcut_mm < 0) {
        tl_set_err(err, err_size, "quantities",
                   "surplus must be 0..1000 %%, kerf and minimum "
                   "offcut >= 0");
        return APP_ERR_SCHEMA;
    }
    int cap = 0, ocap = 0;
    app_result res = APP_OK;
    /* Lines: one per product, in order of first appearance. */
    for (int li = 0; li < n; li++)
        for (int s = 0; s < layouts[li].spec_count; s++) {
            const app_tile_spec *sp = &layouts[li].specs[s];
            int found = 0;
            for (int k = 0; k < out->line_count && !found; k++)
                found = app_product_ref_equal(&out->lines[k].spec.product, &sp->product);
            if (found)
                continue;
            if (out->line_count == cap) {
                cap = cap ? 2 * cap : 8;
                app_tile_quantity *l = realloc(out->lines, sizeof *l * (size_t)cap);
                if (!l)
                    goto oom;
                out->lines = l;
            }
            app_tile_quantity *t = &out->lines[out->line_count++];
            memset(t, 0, sizeof *t);
            t->spec = *sp;
        }
    for (int k = 0; k < out->line_count; k++) {
        app_tile_quantity *t = &out->lines[k];
        int ncut = 0, icap = 0;
        cut_item *items = NULL;
        for (int li = 0; li < n; li++) {
            const app_tile_layout *L = &layouts[li];
            int map[1 + APP_TILING_MAX_BORDERS];
            for (int s = 0; s < L->spec_count; s++)
                map[s] = app_product_ref_equal(&L->specs[s].product, &t->spec.product);
            for (int i = 0; i < L->tile_count; i++) {
                const app_placed_tile *p = &L->tiles[i];
                if (p->product < 0 || p->product >= L->spec_count || !map[p->product])
                    continue;
                t->area_m2 += p->area_mm2 * 1e-6;
                /* Rows of borders, decors and inserts: the length laid along their long side. */
                if (t->spec.type != APP_TILE_UNI)
                    t->length_m +=
                        (t->spec.work_w_mm >= t->spec.work_h_mm ? p->cut_w_mm : p->cut_h_mm) * 1e-3;
                if (p->whole) {
                    t->whole++;
                    continue;
                }
                t->cut++;
                if (ncut == icap) {
                    icap = icap ? 2 * icap : 64;
                    cut_item *ni = realloc(items, sizeof *ni * (size_t)icap);
                    if (!ni) {
                        free(items);
                        goto oom;
                    }
                    items = ni;
                }
                cut_item *c = &items[ncut++];
                memset(c, 0, sizeof *c);
                c->layout = li;
                c->tile = i;
                c->w = p->cut_w_mm;
                c->h = p->cut_h_mm;
                offcut_rest(t->spec.work_w_mm, t->spec.work_h_mm, p->cut_u0_mm, p->cut_v0_mm, c->w,
                            c->h, &o, &c->rw, &c->rh);
                c->tri = corner_triangle(L, p, t->spec.work_w_mm, t->spec.work_h_mm, o.kerf_mm,
                                         &c->t1, &c->t2, &c->r1, &c->r2);
                c->rtri = c->tri && c->r1 >= o.min_offcut_mm && c->r2 >= o.min_offcut_mm;
            }
        }
        /* DOMAIN.md: decor tiles are never reused. */
        if (o.reuse_offcuts && t->spec.reusable_offcuts && t->spec.type != APP_TILE_DEK &&
            ncut > 1) {
            int before = out->offcut_count;
            res = match_offcuts(items, ncut, k, &t->spec, out, &ocap, err, err_size);
            t->reused = out->offcut_count - before;
        }
        free(items);
        if (res != APP_OK) {
            app_quantities_free(out);
            return res;
        }
        order_amounts(t, o.surplus_percent);
    }
    for (int li = 0; li < n; li++) {
        out->region_area_m2 += layouts[li].region_area_mm2 * 1e-6;
        out->tiled_area_m2 += layouts[li].tiled_area_mm2 * 1e-6;
        out->grout_area_m2 += layouts[li].grout_area_mm2 * 1e-6;
    }
    return APP_OK;
oom:
    app_quantities_free(out);
    tl_set_err(err, err_size, "quantities", "out of memory");
    return APP_ERR_OUT_OF_MEMORY;
}

void app_quantities_free(app_quantities *q)
{
    if (!q)
        return;
    free(q->lines);
    free(q->offcuts);
    memset(q, 0, sizeof *q);
}
