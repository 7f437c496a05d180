/* Trim profiles along the outside edges of tiled surfaces (app/design/trims.h, docs/tiling.md
 * "Trim profiles"): which edges a tiling's profile runs along, how many 2.5 m lengths they take,
 * and their lines in the bill of materials. */
#include "app/design/trims.h"
#include "app/design/room_surfaces.h"
#include "room_mesh_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The part of t0..t1 inside the tiling's band (walls: from..to, to 0 = the ceiling). */
static double in_band(const app_tiling *t, double t0, double t1)
{
    double lo = fmax(t0, t->from_mm), hi = t->to_mm > 0 ? fmin(t1, t->to_mm) : t1;
    return fmax(0.0, hi - lo);
}

static int push(double *out, int n, int max, double len)
{
    if (!(len > 0))
        return n;
    if (n < max)
        out[n] = len;
    return n + 1;
}

static const app_prewall *prewall_of(const app_room_plan *plan, const char *surface,
                                     const char **face)
{
    if (strncmp(surface, "prewall:", 8))
        return NULL;
    const char *name = surface + 8, *colon = strrchr(name, ':');
    if (!colon)
        return NULL;
    for (int k = 0; k < plan->prewall_count; k++)
        if (strlen(plan->prewalls[k].name) == (size_t)(colon - name) &&
            !strncmp(plan->prewalls[k].name, name, (size_t)(colon - name))) {
            *face = colon + 1;
            return &plan->prewalls[k];
        }
    return NULL;
}

int app_tiling_trim_edges(const app_room_plan *plan, const app_tiling *t, double *lengths_mm,
                          int max)
{
    int n = 0;
    app_room_reveal rv;
    if (app_room_reveal_find(plan, t->surface, &rv)) {
        if (rv.edge_axis == 0) /* a side: the opening's height, in the band */
            n = push(lengths_mm, n, max, in_band(t, rv.t0, rv.t1));
        else if (rv.edge_axis == 1) /* top or bottom: the opening's width */
            n = push(lengths_mm, n, max, rv.s1 - rv.s0);
        return n;
    }
    const char *face = NULL;
    const app_prewall *pw = prewall_of(plan, t->surface, &face);
    if (!pw || pw->wall < 0 || pw->wall >= plan->corner_count)
        return 0;
    rm_wall w;
    rm_wall_frame(plan, pw->wall, &w);
    /* A side standing in the corner at the wall's start or end meets the next wall: an
     * internal corner, no trim. */
    int free_side[2] = {pw->offset_mm > 1.0, pw->offset_mm + pw->width_mm < w.length - 1.0};
    if (!strcmp(face, "top")) {
        n = push(lengths_mm, n, max, pw->width_mm);
        for (int k = 0; k < 2; k++)
            if (free_side[k])
                n = push(lengths_mm, n, max, pw->depth_mm);
    } else if (!strcmp(face, "front")) {
        for (int k = 0; k < 2; k++)
            if (free_side[k])
                n = push(lengths_mm, n, max, in_band(t, 0, pw->height_mm));
    }
    return n;
}

static int cmp_desc(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x < y) - (x > y);
}

int app_trim_pieces(const double *lengths_mm, int n, double piece_mm)
{
    if (n <= 0 || !(piece_mm > 0))
        return 0;
    double *need = malloc((size_t)n * sizeof *need), *left = malloc((size_t)n * sizeof *left);
    int pieces = 0, open = 0;
    if (!need || !left) {
        free(need);
        free(left);
        return -1;
    }
    int m = 0;
    for (int i = 0; i < n; i++) {
        double len = lengths_mm[i];
        if (!(len > 0))
            continue;
        int whole = (int)floor(len / piece_mm + 1e-9); /* whole lengths laid end to end */
        pieces += whole;
        len -= whole * piece_mm;
        if (len > 1e-6)
            need[m++] = len;
    }
    qsort(need, (size_t)m, sizeof *need, cmp_desc);
    for (int i = 0; i < m; i++) {
        int k = 0;
        while (k < open && left[k] + 1e-9 < need[i])
            k++;
        if (k == open)
            left[open++] = piece_mm;
        left[k] -= need[i];
    }
    free(need);
    free(left);
    return pieces + open;
}

typedef struct trim_acc {
    app_product_ref product;
    double *lengths;
    int count, cap;
} trim_acc;

app_result app_trim_quantities(const app_project *p, app_trim_quantity **out, int *count, char *err,
                               size_t err_size)
{
    *out = NULL;
    *count = 0;
    trim_acc *acc = NULL;
    int n = 0;
    app_result r = APP_OK;
    for (int i = 0; i < p->tiling_count && r == APP_OK; i++) {
        const app_tiling *t = &p->tilings[i];
        if (!t->trim.article[0])
            continue;
        double len[APP_TRIM_MAX_EDGES];
        int e = app_tiling_trim_edges(&p->plan, t, len, APP_TRIM_MAX_EDGES);
        if (e > APP_TRIM_MAX_EDGES)
            e = APP_TRIM_MAX_EDGES;
        int k = 0;
        while (k < n && !app_product_ref_equal(&acc[k].product, &t->trim))
            k++;
        if (k == n) {
            trim_acc *grown = realloc(acc, (size_t)(n + 1) * sizeof *acc);
            if (!grown) {
                r = APP_ERR_OUT_OF_MEMORY;
                break;
            }
            acc = grown;
            memset(&acc[n], 0, sizeof acc[n]);
            acc[n++].product = t->trim;
        }
        trim_acc *a = &acc[k];
        if (a->count + e > a->cap) {
            int cap = 2 * (a->count + e) + 8;
            double *l = realloc(a->lengths, (size_t)cap * sizeof *l);
            if (!l) {
                r = APP_ERR_OUT_OF_MEMORY;
                break;
            }
            a->lengths = l;
            a->cap = cap;
        }
        memcpy(a->lengths + a->count, len, (size_t)e * sizeof *len);
        a->count += e;
    }
    app_trim_quantity *q = r == APP_OK && n > 0 ? calloc((size_t)n, sizeof *q) : NULL;
    if (n > 0 && !q)
        r = APP_ERR_OUT_OF_MEMORY;
    for (int k = 0; k < n; k++) {
        if (q) {
            q[k].product = acc[k].product;
            q[k].edges = acc[k].count;
            for (int i = 0; i < acc[k].count; i++)
                q[k].metres += acc[k].lengths[i] / 1000.0;
            q[k].pieces = app_trim_pieces(acc[k].lengths, acc[k].count, APP_TRIM_PIECE_MM);
            if (q[k].pieces < 0)
                r = APP_ERR_OUT_OF_MEMORY;
        }
        free(acc[k].lengths);
    }
    free(acc);
    if (r != APP_OK) {
        free(q);
        snprintf(err, err_size, "trims: out of memory");
        return r;
    }
    *out = q;
    *count = q ? n : 0;
    return APP_OK;
}

double app_trim_billed_metres(const app_trim_quantity *t)
{
    return t ? t->pieces * (APP_TRIM_PIECE_MM / 1000.0) : 0.0;
}

app_result app_bom_add_trims(cat_db *db, const app_trim_quantity *trims, int count, app_bom *b,
                             char *err, size_t err_size)
{
    if (count <= 0)
        return APP_OK;
    app_bom_line *lines = realloc(b->lines, (size_t)(b->line_count + count) * sizeof *lines);
    if (!lines) {
        snprintf(err, err_size, "trims: out of memory");
        return APP_ERR_OUT_OF_MEMORY;
    }
    b->lines = lines;
    for (int k = 0; k < count; k++) {
        app_bom_line *l = &b->lines[b->line_count++];
        memset(l, 0, sizeof *l);
        l->product = trims[k].product;
        app_bom_price_line(db, l);
        l->is_tile = 0;
        const app_trim_quantity *t = &trims[k];
        double piece_m = APP_TRIM_PIECE_MM / 1000.0;
        if (l->found && l->unit == CAT_UNIT_M) {
            /* DOMAIN.md "Setting out tiles": a profile is sold in whole lengths, so a price per
             * metre bills the metres of the lengths bought, not the metres set. */
            l->quantity = app_trim_billed_metres(t);
            snprintf(l->detail, sizeof l->detail, "%.2f m needed: %d x %.1f m = %.2f m billed",
                     t->metres, t->pieces, piece_m, l->quantity);
        } else {
            /* priced per length (or not in the catalog): one piece a length */
            l->unit = CAT_UNIT_PIECE;
            l->quantity = t->pieces;
            snprintf(l->detail, sizeof l->detail, "%.2f m needed: %d length%s of %.1f m", t->metres,
                     t->pieces, t->pieces == 1 ? "" : "s", piece_m);
        }
    }
    app_bom_total(b);
    return APP_OK;
}

app_result app_bom_add_project_trims(cat_db *db, const app_project *p, app_bom *b, char *err,
                                     size_t err_size)
{
    app_trim_quantity *trims = NULL;
    int count = 0;
    app_result r = app_trim_quantities(p, &trims, &count, err, err_size);
    if (r == APP_OK)
        r = app_bom_add_trims(db, trims, count, b, err, err_size);
    free(trims);
    return r;
}
