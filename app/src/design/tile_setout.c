/* The set-out solver and the minimum-cut rule (docs/tiling.md "Set-out"). A tiler sets out a
 * surface so that no cut piece is a sliver: the usual rule of thumb is a cut of at least a third
 * of the tile (and never under about 50 mm, the smallest piece a wet saw holds safely), and
 * among set-outs that keep it, the one that lays the fewest tiles. The solver tries the named
 * set-outs (joint on the centre, tile on the centre, whole tile at the corner) and a sweep of
 * grid shifts along s and t, each evaluated by the real layout, so holes, bands, borders and
 * every pattern are judged by the pieces a tiler would cut. */
#include "tile_layout_internal.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define PI 3.14159265358979323846
#define MIN_CUT_FLOOR_MM 50.0
#define NO_CUT 1e9
/* Shifts tried per axis over one period (a few mm apart for usual tiles), then 1 mm steps
 * around the best. */
#define SWEEP_STEPS 60

double app_tile_min_cut_mm(const app_tiling *tiling, double side_mm)
{
    if (tiling && tiling->min_cut_mm > 0)
        return fmin(tiling->min_cut_mm, side_mm);
    return fmin(side_mm, fmax(side_mm / 3.0, MIN_CUT_FLOOR_MM));
}

double app_tile_layout_worst_cut(const app_tile_layout *l, const app_tiling *tiling, int *tile,
                                 double *width_mm, double *rule_mm)
{
    double worst = NO_CUT, width = 0, rule = 0;
    int at = -1;
    for (int i = 0; i < l->tile_count; i++) {
        const app_placed_tile *t = &l->tiles[i];
        if (t->whole || t->product < 0 || t->product >= l->spec_count)
            continue;
        const double side[2] = {l->specs[t->product].work_w_mm, l->specs[t->product].work_h_mm};
        const double cut[2] = {t->cut_w_mm, t->cut_h_mm};
        for (int k = 0; k < 2; k++) {
            if (cut[k] >= side[k] - 0.05) /* not cut across this side */
                continue;
            double r = app_tile_min_cut_mm(tiling, side[k]);
            double ratio = r > 0 ? cut[k] / r : NO_CUT;
            if (ratio < worst)
                worst = ratio, width = cut[k], rule = r, at = i;
        }
    }
    if (tile)
        *tile = at;
    if (width_mm)
        *width_mm = width;
    if (rule_mm)
        *rule_mm = rule;
    return worst;
}

typedef struct setout_eval {
    double worst; /* worst cut against the rule (app_tile_layout_worst_cut) */
    int tiles;    /* tiles laid, whole and cut */
    app_point2 origin;
} setout_eval;

/* Better: keeps the rule more (ratios capped at 1, so every set-out that keeps it ties), then
 * fewer tiles, then a larger worst cut. Ties keep the earlier candidate. */
static int better(const setout_eval *a, const setout_eval *b)
{
    double ka = fmin(a->worst, 1.0), kb = fmin(b->worst, 1.0);
    if (ka != kb)
        return ka > kb + 1e-9;
    if (a->tiles != b->tiles)
        return a->tiles < b->tiles;
    return fmin(a->worst, 10.0) > fmin(b->worst, 10.0) + 1e-9;
}

typedef struct setout_ctx {
    app_tile_layout_desc desc;
    app_tiling tiling;
    setout_eval best;
    app_result failed;
    char *err;
    size_t err_size;
} setout_ctx;

static void try_origin(setout_ctx *c, app_point2 o)
{
    if (c->failed != APP_OK)
        return;
    c->tiling.align = APP_ALIGN_LINE;
    c->tiling.origin_mm[0] = o.x;
    c->tiling.origin_mm[1] = o.y;
    app_tile_layout l;
    app_result r = tl_layout_region(&c->desc, &l, c->err, c->err_size);
    if (r != APP_OK) {
        c->failed = r;
        return;
    }
    setout_eval e = {app_tile_layout_worst_cut(&l, &c->tiling, NULL, NULL, NULL), l.tile_count, o};
    app_tile_layout_free(&l);
    if (c->best.tiles < 0 || better(&e, &c->best))
        c->best = e;
}

/* The grid point a named alignment gives (the layout computes it). */
static app_result named_origin(setout_ctx *c, app_tile_align align, app_point2 *o)
{
    c->tiling.align = align;
    app_tile_layout l;
    app_result r = tl_layout_region(&c->desc, &l, c->err, c->err_size);
    if (r == APP_OK)
        *o = l.origin;
    app_tile_layout_free(&l);
    return r;
}

/* Shifts of the best origin along axis (0 = s, 1 = t) over [-period / 2, period / 2). */
static void sweep(setout_ctx *c, int axis, double period, int steps)
{
    app_point2 base = c->best.origin;
    for (int k = 0; k < steps && c->failed == APP_OK; k++) {
        double d = -0.5 * period + period * k / steps;
        app_point2 o = base;
        if (axis == 0)
            o.x += d;
        else
            o.y += d;
        try_origin(c, o);
    }
}

app_result tl_setout_solve(const app_tile_layout_desc *desc, app_point2 *origin, char *err,
                           size_t err_size)
{
    setout_ctx c;
    memset(&c, 0, sizeof c);
    c.desc = *desc;
    c.tiling = *desc->tiling;
    c.desc.tiling = &c.tiling;
    c.best.tiles = -1;
    c.failed = APP_OK;
    c.err = err;
    c.err_size = err_size;
    const app_tiling *ti = desc->tiling;
    const app_tile_spec *f = desc->field;
    double g = ti->grout_mm > 0 ? ti->grout_mm : f->grout_mm;
    double lng = fmax(f->work_w_mm, f->work_h_mm) + g, sht = fmin(f->work_w_mm, f->work_h_mm) + g;
    double W = ti->pattern == APP_PATTERN_VERTICAL_STACK ? sht : lng;
    double H = ti->pattern == APP_PATTERN_VERTICAL_STACK ? lng : sht;
    double theta =
        ti->rotation_deg * PI / 180.0 + (ti->pattern == APP_PATTERN_DIAGONAL      ? PI / 4
                                         : ti->pattern == APP_PATTERN_HERRINGBONE ? -PI / 4
                                                                                  : 0.0);
    double ux = cos(theta), uy = sin(theta);

    app_point2 centred, corner;
    app_result r = named_origin(&c, APP_ALIGN_CENTRED, &centred);
    if (r == APP_OK)
        r = named_origin(&c, APP_ALIGN_CORNER, &corner);
    if (r != APP_OK)
        return r;
    /* joint on the centre, tile on the centre, each axis mixed, whole tile at the corner */
    try_origin(&c, centred);
    try_origin(
        &c, (app_point2){centred.x + 0.5 * (W * ux - H * uy), centred.y + 0.5 * (W * uy + H * ux)});
    try_origin(&c, (app_point2){centred.x + 0.5 * W * ux, centred.y + 0.5 * W * uy});
    try_origin(&c, (app_point2){centred.x - 0.5 * H * uy, centred.y + 0.5 * H * ux});
    try_origin(&c, corner);

    /* The periods of the grid along s and t: exact for the axis-aligned lattices, a full
     * lattice cell's reach otherwise. */
    int aligned = fabs(sin(2 * theta)) < 1e-9 && ti->pattern != APP_PATTERN_HERRINGBONE;
    int rows = ti->pattern == APP_PATTERN_HALF_OFFSET    ? 2
               : ti->pattern == APP_PATTERN_THIRD_OFFSET ? 3
                                                         : 1;
    int turned = aligned && fabs(uy) > 0.5;
    double ps = aligned ? (turned ? H : W) : W + H, pt = aligned ? (turned ? W : H * rows) : W + H;
    for (int pass = 0; pass < 2 && c.failed == APP_OK; pass++) {
        sweep(&c, 0, ps, SWEEP_STEPS);
        sweep(&c, 1, pt, SWEEP_STEPS);
    }
    /* 1 mm steps around the best, within one coarse step */
    double fs = ps / SWEEP_STEPS, ft = pt / SWEEP_STEPS;
    sweep(&c, 0, 2 * fs, (int)ceil(2 * fs));
    sweep(&c, 1, 2 * ft, (int)ceil(2 * ft));
    if (c.failed != APP_OK)
        return c.failed;
    *origin = c.best.origin;
    return APP_OK;
}
