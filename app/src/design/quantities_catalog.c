/* The catalog side of the quantities (app/design/quantities.h): tile specs from catalog records,
 * the layouts of every tiling of a project, and the priced bill of materials (DOMAIN.md "What the
 * best planners print": unit price, VAT, totals). */
#include "app/design/quantities.h"
#include "quantities_internal.h"
#include "tile_layout_internal.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

app_result app_tile_spec_from_catalog(cat_db *db, const app_product_ref *ref, app_tile_spec *spec,
                                      cat_product *product, char *err, size_t err_size)
{
    if (spec)
        memset(spec, 0, sizeof *spec);
    if (product)
        memset(product, 0, sizeof *product);
    if (!db || !ref || !spec) {
        tl_set_err(err, err_size, "quantities", "no catalog or product reference");
        return APP_ERR_SCHEMA;
    }
    cat_product p;
    char cerr[512] = "";
    if (cat_product_find(db, ref->manufacturer, ref->article, &p, cerr, sizeof cerr) != CAT_DB_OK) {
        tl_set_err(err, err_size, "quantities", "tile %s %s: %s", ref->manufacturer, ref->article,
                   cerr);
        return APP_ERR_NOT_FOUND;
    }
    if (!p.has_tile) {
        tl_set_err(err, err_size, "quantities", "%s %s is not a tile", ref->manufacturer,
                   ref->article);
        cat_product_free(&p);
        return APP_ERR_NOT_FOUND;
    }
    spec->product = *ref;
    spec->type = (app_tile_type)p.tile.type; /* the same order, see app_tile_type */
    spec->work_w_mm = p.tile.work_w_mm;
    spec->work_h_mm = p.tile.work_h_mm;
    spec->grout_mm = p.tile.grout_mm;
    spec->m2_per_box = p.tile.m2_per_box;
    spec->pieces_per_box = p.tile.pieces_per_box;
    /* DOMAIN.md: decor tiles are never reused; the others may be turned. */
    spec->reusable_offcuts = spec->rotatable = p.tile.type != CAT_TILE_DEK;
    snprintf(spec->texture, sizeof spec->texture, "%s", p.tile.texture);
    spec->matt = p.tile.surface != CAT_SURFACE_GLOSSY;
    if (product)
        *product = p;
    else
        cat_product_free(&p);
    return APP_OK;
}

void app_tile_layouts_free(app_tile_layout *layouts, int count)
{
    for (int i = 0; layouts && i < count; i++)
        app_tile_layout_free(&layouts[i]);
    free(layouts);
}

app_result app_project_tile_layouts(const app_project *p, cat_db *db, app_region_provider regions,
                                    void *regions_user, app_tile_layout **layouts, int *count,
                                    char *err, size_t err_size)
{
    if (layouts)
        *layouts = NULL;
    if (count)
        *count = 0;
    if (!p || !layouts || !count) {
        tl_set_err(err, err_size, "quantities", "no project");
        return APP_ERR_SCHEMA;
    }
    if (p->tiling_count == 0)
        return APP_OK;
    app_tile_layout *out = calloc((size_t)p->tiling_count, sizeof *out);
    if (!out) {
        tl_set_err(err, err_size, "quantities", "out of memory");
        return APP_ERR_OUT_OF_MEMORY;
    }
    app_result res = APP_OK;
    for (int i = 0; i < p->tiling_count && res == APP_OK; i++) {
        const app_tiling *t = &p->tilings[i];
        app_tile_spec field, borders[APP_TILING_MAX_BORDERS];
        res = app_tile_spec_from_catalog(db, &t->product, &field, NULL, err, err_size);
        for (int b = 0; res == APP_OK && b < t->border_count && b < APP_TILING_MAX_BORDERS; b++)
            res = app_tile_spec_from_catalog(db, &t->borders[b].product, &borders[b], NULL, err,
                                             err_size);
        app_surface_region r;
        memset(&r, 0, sizeof r);
        if (res == APP_OK)
            res = regions ? regions(regions_user, p, t->surface, &r, err, err_size)
                          : app_surface_region_from_plan(&p->plan, t->surface, &r, err, err_size);
        if (res == APP_OK) {
            app_tile_layout_desc d = {&r, t, &field, borders, 0};
            res = app_tile_layout_compute(&d, &out[i], err, err_size);
        }
        app_surface_region_free(&r);
        if (res != APP_OK && err && err_size > 0) {
            /* Name the tiling in front of the message. */
            char msg[512];
            snprintf(msg, sizeof msg, "%s", err);
            tl_set_err(err, err_size, "quantities", "tiling \"%s\" on %s: %s", t->name, t->surface,
                       msg);
        }
    }
    if (res != APP_OK) {
        app_tile_layouts_free(out, p->tiling_count);
        return res;
    }
    *layouts = out;
    *count = p->tiling_count;
    return APP_OK;
}

/* ---- bill of materials ---------------------------------------------------------------------- */

static app_result add_line(app_bom *b, int *cap, app_bom_line **line, char *err, size_t err_size)
{
    if (b->line_count == *cap) {
        int nc = *cap ? 2 * *cap : 16;
        app_bom_line *l = realloc(b->lines, sizeof *l * (size_t)nc);
        if (!l) {
            tl_set_err(err, err_size, "quantities", "out of memory");
            return APP_ERR_OUT_OF_MEMORY;
        }
        b->lines = l;
        *cap = nc;
    }
    *line = &b->lines[b->line_count++];
    memset(*line, 0, sizeof **line);
    return APP_OK;
}

void app_bom_price_line(cat_db *db, app_bom_line *l)
{
    cat_product p;
    char cerr[256];
    if (!db || cat_product_find(db, l->product.manufacturer, l->product.article, &p, cerr,
                                sizeof cerr) != CAT_DB_OK) {
        snprintf(l->name, sizeof l->name, "%s %s (not in the catalog)", l->product.manufacturer,
                 l->product.article);
        l->unit = CAT_UNIT_PIECE;
        return;
    }
    l->found = 1;
    snprintf(l->name, sizeof l->name, "%s", p.name);
    snprintf(l->series, sizeof l->series, "%s", p.series);
    l->category = p.category;
    l->is_tile = p.has_tile;
    if (p.has_tile)
        l->tile_type = (app_tile_type)p.tile.type;
    l->unit = p.unit;
    l->unit_price_cents = p.price_cents;
    for (int v = 0; v < p.variant_count; v++)
        if (l->product.variant[0] && !strcmp(p.variants[v].code, l->product.variant) &&
            __builtin_add_overflow(l->unit_price_cents, p.variants[v].surcharge_cents,
                                   &l->unit_price_cents))
            l->unit_price_cents = LLONG_MAX; /* too large to total: total_line refuses it */
    l->vat_percent = p.vat_percent;
    snprintf(l->currency, sizeof l->currency, "%s", p.currency);
    cat_product_free(&p);
}

/* The largest amount a line or total may have, in cents. The import bounds a price to
 * 100 000 000.00 (catalog/src/db_values.c), but a catalog file written by other means only
 * promises price_cents > 0, and a price near INT64_MAX times a quantity wraps to a negative
 * total. 2^61 keeps net + VAT (each at most this) inside long long, and is far above any
 * real bathroom. */
#define AMOUNT_MAX_CENTS 0x1p61

static void total_line(app_bom_line *l)
{
    l->net_cents = l->vat_cents = l->gross_cents = 0;
    l->out_of_range = 0;
    /* Rounded in double as before, but range-checked before the conversion to long long (which
     * is undefined when out of range); !(x <= max) also catches NaN. */
    double net = round(l->quantity * (double)l->unit_price_cents);
    double vat = round(net * l->vat_percent / 100.0);
    if (!(fabs(net) <= AMOUNT_MAX_CENTS) || !(fabs(vat) <= AMOUNT_MAX_CENTS)) {
        l->out_of_range = 1;
        return;
    }
    l->net_cents = (long long)net;
    l->vat_cents = (long long)vat;
    l->gross_cents = l->net_cents + l->vat_cents; /* both <= 2^61: cannot overflow */
}

double app_tile_billed_quantity(const app_tile_quantity *t, cat_unit unit)
{
    if (!t)
        return 0;
    /* DOMAIN.md "Products and catalog records": the unit is part of the price. A box or m2
     * price sells whole boxes; a piece price (borders, decors) sells single pieces, so the
     * customer pays for the pieces ordered, with the surplus for cutting and breakage
     * (DOMAIN.md: at least 10 %), not for the box they come in. */
    if (unit == CAT_UNIT_M2)
        return t->order_m2;
    if (unit == CAT_UNIT_BOX)
        return t->boxes > 0 ? t->boxes : t->pieces_to_order;
    return t->pieces_with_surplus;
}

/* The currency most found lines are priced in; ties go to the one that comes first (tiles come
 * before fixtures). */
static void project_currency(const app_bom *b, char cur[4])
{
    int best = 0;
    cur[0] = '\0';
    for (int i = 0; i < b->line_count; i++) {
        const app_bom_line *l = &b->lines[i];
        if (!l->found || !l->currency[0])
            continue;
        int n = 0;
        for (int k = 0; k < b->line_count; k++)
            n += b->lines[k].found && !strcmp(b->lines[k].currency, l->currency);
        if (n > best) {
            best = n;
            snprintf(cur, 4, "%s", l->currency);
        }
    }
}

void app_bom_total(app_bom *b)
{
    if (!b)
        return;
    b->net_cents = b->vat_cents = b->gross_cents = 0;
    b->missing = b->foreign = b->out_of_range = 0;
    int sum_overflow = 0;
    project_currency(b, b->currency);
    for (int k = 0; k < b->line_count; k++) {
        app_bom_line *l = &b->lines[k];
        total_line(l);
        b->missing += !l->found;
        /* DOMAIN.md "What the best planners print": a quotation has one currency. Adding a CHF
         * amount to EUR ones gives a wrong total, so such a line stays out of it (no rates are
         * known to convert it) and is reported instead. */
        l->foreign_currency = l->found && strcmp(l->currency, b->currency) != 0;
        if (l->foreign_currency) {
            b->foreign++;
            continue;
        }
        if (l->out_of_range) {
            b->out_of_range++;
            continue;
        }
        sum_overflow |= __builtin_add_overflow(b->net_cents, l->net_cents, &b->net_cents);
        sum_overflow |= __builtin_add_overflow(b->vat_cents, l->vat_cents, &b->vat_cents);
        sum_overflow |= __builtin_add_overflow(b->gross_cents, l->gross_cents, &b->gross_cents);
    }
    /* A wrapped sum is worse than none: a quotation must not print it. */
    if (sum_overflow)
        b->out_of_range++;
    if (b->out_of_range)
        b->net_cents = b->vat_cents = b->gross_cents = 0;
}

int app_bom_vat_by_rate(const app_bom *b, double *rates, long long *vat_cents, int max)
{
    int n = 0;
    for (int i = 0; b && i < b->line_count; i++) {
        const app_bom_line *l = &b->lines[i];
        if (l->foreign_currency || l->out_of_range)
            continue; /* not in the totals either */
        int k = 0;
        while (k < n && fabs(rates[k] - l->vat_percent) > 1e-9)
            k++;
        if (k == n && n < max) {
            rates[n] = l->vat_percent;
            vat_cents[n++] = 0;
        }
        if (k < n)
            vat_cents[k] += l->vat_cents;
    }
    return n;
}

const char *app_format_percent(double percent, char *buf, size_t size)
{
    if (!buf || size == 0)
        return buf;
    /* DOMAIN.md "Products and catalog records": the VAT rate is the record's, and rates such as
     * 8.1 % (CH) or 7.7 % must not print rounded to a rate that does not exist. */
    snprintf(buf, size, "%.2f", percent);
    char *dot = strchr(buf, '.');
    if (dot) {
        char *end = buf + strlen(buf);
        while (end > dot + 1 && end[-1] == '0')
            *--end = '\0';
        if (end == dot + 1)
            *dot = '\0';
    }
    return buf;
}

static int cmp_fixture(const void *a, const void *b)
{
    const app_bom_line *x = a, *y = b;
    int c = strcasecmp(x->name, y->name);
    return c ? c : strcasecmp(x->product.article, y->product.article);
}

app_result app_bom_build(cat_db *db, const app_project *p, const app_quantities *q, app_bom *out,
                         char *err, size_t err_size)
{
    if (out)
        memset(out, 0, sizeof *out);
    if (!out) {
        tl_set_err(err, err_size, "quantities", "no bill of materials to fill");
        return APP_ERR_SCHEMA;
    }
    int cap = 0;
    app_bom_line *l;
    for (int i = 0; q && i < q->line_count; i++) {
        const app_tile_quantity *t = &q->lines[i];
        if (add_line(out, &cap, &l, err, err_size) != APP_OK)
            goto oom;
        l->product = t->spec.product;
        app_bom_price_line(db, l);
        l->is_tile = 1;
        l->tile_type = t->spec.type;
        l->quantity = app_tile_billed_quantity(t, l->unit);
    }
    int first_fixture = out->line_count;
    for (int i = 0; p && i < p->object_count; i++) {
        const app_object *o = &p->objects[i];
        if (!o->has_product)
            continue;
        int k;
        for (k = first_fixture; k < out->line_count; k++)
            if (app_product_ref_equal(&out->lines[k].product, &o->product))
                break;
        if (k < out->line_count) {
            out->lines[k].quantity += 1;
            continue;
        }
        if (add_line(out, &cap, &l, err, err_size) != APP_OK)
            goto oom;
        l->product = o->product;
        l->quantity = 1;
    }
    for (int k = first_fixture; k < out->line_count; k++)
        app_bom_price_line(db, &out->lines[k]);
    if (out->line_count > first_fixture) /* qsort's array must not be NULL, even for 0 lines */
        qsort(out->lines + first_fixture, (size_t)(out->line_count - first_fixture),
              sizeof *out->lines, cmp_fixture);
    app_bom_total(out);
    if (out->out_of_range) {
        /* Name the line whose price cannot be totalled, so the catalog entry can be fixed. */
        const app_bom_line *bad = NULL;
        for (int k = 0; k < out->line_count && !bad; k++)
            if (out->lines[k].out_of_range)
                bad = &out->lines[k];
        if (bad)
            tl_set_err(err, err_size, "quantities",
                       "%s %s: %g x %lld cents does not fit in an amount; check the catalog price",
                       bad->product.manufacturer, bad->product.article, bad->quantity,
                       bad->unit_price_cents);
        else
            tl_set_err(err, err_size, "quantities",
                       "the total of the lines does not fit in an amount; check the catalog "
                       "prices");
        app_bom_free(out);
        return APP_ERR_SCHEMA;
    }
    return APP_OK;
oom:
    app_bom_free(out);
    return APP_ERR_OUT_OF_MEMORY;
}

void app_bom_free(app_bom *b)
{
    if (!b)
        return;
    free(b->lines);
    memset(b, 0, sizeof *b);
}

/* ---- consumables and labour lines ----------------------------------------------------------- */

app_result qty_bom_add_priced(cat_db *db, app_bom *b, int *cap, const app_product_ref *ref,
                              app_bom_kind kind, double quantity, const char *detail, char *err,
                              size_t err_size)
{
    if (!(quantity > 0) || !ref->article[0])
        return APP_OK;
    app_bom_line *l;
    if (add_line(b, cap, &l, err, err_size) != APP_OK)
        return APP_ERR_OUT_OF_MEMORY;
    l->product = *ref;
    l->kind = kind;
    app_bom_price_line(db, l);
    l->quantity = quantity;
    snprintf(l->detail, sizeof l->detail, "%s", detail);
    return APP_OK;
}
