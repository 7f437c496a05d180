/* The set-out of a whole room (docs/tiling.md "Set-out of a room"): a tiler sets out the walls
 * of a room together, so that the rows run on at one height around the room and a vertical
 * joint turns the corner (the cut piece at the end of one wall and the first piece of the next
 * make one tile), and lines the floor's joints up with the walls' where the tile sizes match.
 * The tilings marked "setout": "room" share one grid: wall I's grid point is (phi - P_I, psi),
 * P_I the length of the walls before it (the walls unfolded into one strip), and the floor's
 * joints lie where the first wall along x and the first wall along y put theirs. phi and psi are
 * chosen like one surface's set-out (tile_setout.c): coarse sweeps over one period, then 1 mm
 * steps, judged by the real layouts of every member: the smallest cut against the minimum-cut
 * rule first, then the fewest tiles. */
#include "app/design/room_surfaces.h"
#include "app/design/quantities.h"
#include "tile_layout_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SWEEP_STEPS 60

typedef struct member {
    int tiling; /* index into the project's tilings */
    app_tiling t;
    app_tile_spec field, borders[APP_TILING_MAX_BORDERS];
    app_surface_region region; /* shrunk by the edge joint */
    int wall;                  /* -1: the floor */
    double perim, a[2], d[2];  /* walls: the length before it, start corner, direction */
} member;

typedef struct room_ctx {
    member *m;
    int n;
    int floor_x_wall, floor_y_wall; /* members giving the floor's joints along x and y */
    double ps, pt;                  /* the walls' grid periods along s and t */
    double best_phi, best_psi, best_worst;
    int best_tiles;
    app_result failed;
    char *err;
    size_t err_size;
} room_ctx;

static int is_room_wall(const app_tiling *t)
{
    return t->setout_room && !strncmp(t->surface, "wall:", 5) &&
           t->pattern != APP_PATTERN_DIAGONAL && t->pattern != APP_PATTERN_HERRINGBONE &&
           fabs(t->rotation_deg) < 1e-9;
}

/* The lattice cell (along s, along t) of a tiling with field tile f (tile_layout.c). */
static void cell_of(const app_tiling *t, const app_tile_spec *f, double *w, double *h)
{
    double g = t->grout_mm > 0 ? t->grout_mm : f->grout_mm;
    double lng = fmax(f->work_w_mm, f->work_h_mm) + g, sht = fmin(f->work_w_mm, f->work_h_mm) + g;
    int upright = t->pattern == APP_PATTERN_VERTICAL_STACK;
    *w = upright ? sht : lng;
    *h = upright ? lng : sht;
}

static void place(const room_ctx *c, const member *m, double phi, double psi, app_tiling *t)
{
    *t = m->t;
    t->align = APP_ALIGN_LINE;
    if (m->wall >= 0) {
        t->origin_mm[0] = phi - m->perim;
        t->origin_mm[1] = psi;
        return;
    }
    const member *wx = &c->m[c->floor_x_wall], *wy = &c->m[c->floor_y_wall];
    t->origin_mm[0] = wx->a[0] + wx->d[0] * (phi - wx->perim);
    t->origin_mm[1] = wy->a[1] + wy->d[1] * (phi - wy->perim);
}

static void try_phase(room_ctx *c, double phi, double psi)
{
    double worst = 1e9;
    int tiles = 0;
    for (int k = 0; k < c->n && c->failed == APP_OK; k++) {
        const member *m = &c->m[k];
        if (m->wall < 0 && c->floor_x_wall < 0)
            continue;
        app_tiling t;
        place(c, m, phi, psi, &t);
        app_tile_layout_desc d = {&m->region, &t, &m->field, m->borders, 0};
        app_tile_layout l;
        c->failed = tl_layout_region(&d, &l, c->err, c->err_size);
        if (c->failed != APP_OK)
            return;
        worst = fmin(worst, app_tile_layout_worst_cut(&l, &t, NULL, NULL, NULL));
        tiles += l.tile_count;
        app_tile_layout_free(&l);
    }
    double kw = fmin(worst, 1.0), kb = fmin(c->best_worst, 1.0);
    int better =
        c->best_tiles < 0 || kw > kb + 1e-9 ||
        (fabs(kw - kb) <= 1e-9 &&
         (tiles < c->best_tiles ||
          (tiles == c->best_tiles && fmin(worst, 10.0) > fmin(c->best_worst, 10.0) + 1e-9)));
    if (better) {
        c->best_phi = phi, c->best_psi = psi;
        c->best_worst = worst, c->best_tiles = tiles;
    }
}

static void sweep(room_ctx *c, int axis, double period, int steps)
{
    double phi = c->best_phi, psi = c->best_psi;
    for (int k = 0; k < steps && c->failed == APP_OK; k++) {
        double dlt = -0.5 * period + period * k / steps;
        try_phase(c, axis == 0 ? phi + dlt : phi, axis == 1 ? psi + dlt : psi);
    }
}

static app_result add_member(const app_project *p, cat_db *db, const app_fixture_box *fx, int nfx,
                             int index, int wall, room_ctx *c)
{
    member *m = &c->m[c->n];
    memset(m, 0, sizeof *m);
    m->tiling = index;
    m->t = p->tilings[index];
    m->wall = wall;
    app_result r =
        app_tile_spec_from_catalog(db, &m->t.product, &m->field, NULL, c->err, c->err_size);
    for (int b = 0; r == APP_OK && b < m->t.border_count && b < APP_TILING_MAX_BORDERS; b++)
        r = app_tile_spec_from_catalog(db, &m->t.borders[b].product, &m->borders[b], NULL, c->err,
                                       c->err_size);
    app_surface_region full;
    memset(&full, 0, sizeof full);
    if (r == APP_OK)
        r = app_room_surface_region(p, m->t.surface, fx, nfx, &full, NULL, c->err, c->err_size);
    if (r == APP_OK) {
        double g = m->t.grout_mm > 0 ? m->t.grout_mm : m->field.grout_mm;
        double e = app_tile_edge_joint_mm(&m->t, g);
        if (e > 0)
            r = tl_region_shrink(&full, e, &m->region, c->err, c->err_size);
        else {
            m->region = full;
            memset(&full, 0, sizeof full);
        }
    }
    app_surface_region_free(&full);
    if (r != APP_OK) {
        app_surface_region_free(&m->region);
        return r;
    }
    c->n++;
    return APP_OK;
}

app_result app_room_setout_tilings(const app_project *p, cat_db *db, const app_fixture_box *fx,
                                   int nfx, app_tiling **out, char *err, size_t err_size)
{
    *out = NULL;
    const app_room_plan *plan = &p->plan;
    int walls = 0, floor = -1;
    for (int i = 0; i < p->tiling_count; i++) {
        walls += is_room_wall(&p->tilings[i]);
        if (p->tilings[i].setout_room && !strcmp(p->tilings[i].surface, "floor") && floor < 0 &&
            p->tilings[i].pattern != APP_PATTERN_DIAGONAL &&
            p->tilings[i].pattern != APP_PATTERN_HERRINGBONE &&
            fabs(p->tilings[i].rotation_deg) < 1e-9)
            floor = i;
    }
    if (walls == 0 || plan->corner_count < 3)
        return APP_OK;
    room_ctx c;
    memset(&c, 0, sizeof c);
    c.m = calloc((size_t)walls + 1, sizeof *c.m);
    c.err = err, c.err_size = err_size;
    c.floor_x_wall = c.floor_y_wall = -1;
    c.best_tiles = -1;
    c.failed = c.m ? APP_OK : APP_ERR_OUT_OF_MEMORY;
    double perim[APP_ROOM_MAX_CORNERS + 1];
    perim[0] = 0;
    for (int i = 0; i < plan->corner_count; i++) {
        app_point2 a = plan->corners[i], b = plan->corners[(i + 1) % plan->corner_count];
        perim[i + 1] = perim[i] + hypot(b.x - a.x, b.y - a.y);
    }
    /* the walls in the order they run round the room */
    for (int w = 0; w < plan->corner_count && c.failed == APP_OK; w++)
        for (int i = 0; i < p->tiling_count && c.failed == APP_OK; i++) {
            const app_tiling *t = &p->tilings[i];
            if (!is_room_wall(t) || atoi(t->surface + 5) != w)
                continue;
            c.failed = add_member(p, db, fx, nfx, i, w, &c);
            if (c.failed != APP_OK)
                break;
            member *m = &c.m[c.n - 1];
            app_point2 a = plan->corners[w], b = plan->corners[(w + 1) % plan->corner_count];
            double len = perim[w + 1] - perim[w];
            m->perim = perim[w];
            m->a[0] = a.x, m->a[1] = a.y;
            m->d[0] = len > 0 ? (b.x - a.x) / len : 1;
            m->d[1] = len > 0 ? (b.y - a.y) / len : 0;
            break; /* one tiling per wall sets its grid */
        }
    if (c.failed == APP_OK && c.n > 0) {
        double w0, h0;
        cell_of(&c.m[0].t, &c.m[0].field, &w0, &h0);
        int rows = c.m[0].t.pattern == APP_PATTERN_HALF_OFFSET    ? 2
                   : c.m[0].t.pattern == APP_PATTERN_THIRD_OFFSET ? 3
                                                                  : 1;
        c.ps = w0;
        c.pt = h0 * rows;
        /* The floor joins when its cell matches the walls' along x and y (plan axes). */
        if (floor >= 0 && (c.failed = add_member(p, db, fx, nfx, floor, -1, &c)) == APP_OK) {
            member *f = &c.m[c.n - 1];
            double fw, fh;
            cell_of(&f->t, &f->field, &fw, &fh);
            for (int k = 0; k < c.n - 1; k++) {
                double wk, hk;
                cell_of(&c.m[k].t, &c.m[k].field, &wk, &hk);
                if (c.floor_x_wall < 0 && fabs(fabs(c.m[k].d[0]) - 1) < 1e-9 &&
                    fabs(wk - fw) < 1e-6)
                    c.floor_x_wall = k;
                if (c.floor_y_wall < 0 && fabs(fabs(c.m[k].d[1]) - 1) < 1e-9 &&
                    fabs(wk - fh) < 1e-6)
                    c.floor_y_wall = k;
            }
            if (c.floor_x_wall < 0 || c.floor_y_wall < 0) {
                app_surface_region_free(&f->region); /* set out on its own */
                c.n--;
                c.floor_x_wall = c.floor_y_wall = -1;
            }
        }
        /* start from a joint at the first wall's start corner and on the floor, then sweep */
        for (int pass = 0; pass < 2 && c.failed == APP_OK; pass++) {
            sweep(&c, 0, c.ps, SWEEP_STEPS);
            sweep(&c, 1, c.pt, SWEEP_STEPS);
        }
        double fs = c.ps / SWEEP_STEPS, ft = c.pt / SWEEP_STEPS;
        sweep(&c, 0, 2 * fs, (int)ceil(2 * fs));
        sweep(&c, 1, 2 * ft, (int)ceil(2 * ft));
    }
    app_tiling *tilings = NULL;
    if (c.failed == APP_OK && c.n > 0) {
        tilings = malloc((size_t)p->tiling_count * sizeof *tilings);
        if (!tilings)
            c.failed = APP_ERR_OUT_OF_MEMORY;
        else {
            memcpy(tilings, p->tilings, (size_t)p->tiling_count * sizeof *tilings);
            for (int k = 0; k < c.n; k++)
                place(&c, &c.m[k], c.best_phi, c.best_psi, &tilings[c.m[k].tiling]);
        }
    }
    for (int k = 0; c.m && k < c.n; k++)
        app_surface_region_free(&c.m[k].region);
    free(c.m);
    if (c.failed == APP_ERR_OUT_OF_MEMORY)
        snprintf(err, err_size, "room set-out: out of memory");
    if (c.failed != APP_OK) {
        free(tilings);
        return c.failed;
    }
    *out = tilings;
    return APP_OK;
}
