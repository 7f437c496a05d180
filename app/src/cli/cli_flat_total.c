/* The total and the quotation of a flat (cli_flat_total.h). */
#include "cli_flat_total.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int same_product(const app_product_ref *a, const app_product_ref *b)
{
    return !strcmp(a->manufacturer, b->manufacturer) && !strcmp(a->article, b->article) &&
           !strcmp(a->variant, b->variant);
}

/* Adds the room's tile lines to the total (a new product at the end). */
static int add_tiles(app_quantities *t, const app_quantities *q)
{
    for (int i = 0; i < q->line_count; i++) {
        const app_tile_quantity *l = &q->lines[i];
        int k = 0;
        while (k < t->line_count && !same_product(&t->lines[k].spec.product, &l->spec.product))
            k++;
        if (k == t->line_count) {
            app_tile_quantity *grown =
                realloc(t->lines, (size_t)(t->line_count + 1) * sizeof *grown);
            if (!grown)
                return 0;
            t->lines = grown;
            t->lines[k] = *l;
            t->line_count++;
            continue;
        }
        app_tile_quantity *s = &t->lines[k];
        s->whole += l->whole;
        s->cut += l->cut;
        s->reused += l->reused;
        s->pieces_needed += l->pieces_needed;
        s->area_m2 += l->area_m2;
        s->length_m += l->length_m;
        s->pieces_with_surplus += l->pieces_with_surplus;
        s->boxes += l->boxes;
        s->pieces_to_order += l->pieces_to_order;
        s->order_m2 += l->order_m2;
    }
    t->region_area_m2 += q->region_area_m2;
    t->tiled_area_m2 += q->tiled_area_m2;
    t->grout_area_m2 += q->grout_area_m2;
    t->offcut_count += q->offcut_count;
    return 1;
}

static int add_trims(cli_room_quantities *t, const cli_room_quantities *r)
{
    for (int i = 0; i < r->trim_count; i++) {
        const app_trim_quantity *l = &r->trims[i];
        int k = 0;
        while (k < t->trim_count && !app_product_ref_equal(&t->trims[k].product, &l->product))
            k++;
        if (k == t->trim_count) {
            app_trim_quantity *grown = realloc(t->trims, (size_t)(k + 1) * sizeof *grown);
            if (!grown)
                return 0;
            t->trims = grown;
            t->trims[k] = *l;
            t->trim_count++;
            continue;
        }
        t->trims[k].edges += l->edges;
        t->trims[k].metres += l->metres;
        t->trims[k].pieces += l->pieces;
    }
    return 1;
}

static void add_consumables(app_consumables *t, const app_consumables *c)
{
    t->floor_m2 += c->floor_m2;
    t->wall_m2 += c->wall_m2;
    t->adhesive_kg += c->adhesive_kg;
    t->adhesive_bags += c->adhesive_bags;
    t->joint_length_m += c->joint_length_m;
    t->grout_dm3 += c->grout_dm3;
    t->grout_kg += c->grout_kg;
    t->grout_bags += c->grout_bags;
    t->edge_joint_m += c->edge_joint_m;
    t->silicone_ml += c->silicone_ml;
    t->silicone_cartridges += c->silicone_cartridges;
    t->waterproofing_m2 += c->waterproofing_m2;
    t->shower_zones += c->shower_zones;
    t->fixtures += c->fixtures;
}

/* The bill's groups in the order app_bom_build and the additions after it list them. */
enum { GROUP_TILES, GROUP_PRODUCTS, GROUP_TRIMS, GROUP_CONSUMABLES, GROUP_LABOUR, GROUP_COUNT };

static int is_trim(const app_bom_line *l, const cli_room_quantities *r)
{
    for (int i = 0; i < r->trim_count; i++)
        if (app_product_ref_equal(&r->trims[i].product, &l->product))
            return 1;
    return 0;
}

static int group_of(const app_bom_line *l, const cli_room_quantities *r)
{
    if (l->kind == APP_BOM_CONSUMABLE)
        return GROUP_CONSUMABLES;
    if (l->kind == APP_BOM_LABOUR)
        return GROUP_LABOUR;
    return l->is_tile ? GROUP_TILES : r && is_trim(l, r) ? GROUP_TRIMS : GROUP_PRODUCTS;
}

/* Adds the lines of group g of room r's bill to the total's (t, whose lines up to the end
 * hold only groups <= g), merged by product and kind from first_of_group on; rooms[k] counts
 * the rooms a total line came from. */
static int add_bom_lines(app_bom *t, int first_of_group, int **rooms, const cli_room_quantities *r,
                         int g)
{
    const app_bom *b = &r->bom;
    for (int i = 0; i < b->line_count; i++) {
        const app_bom_line *l = &b->lines[i];
        if (group_of(l, r) != g)
            continue;
        int k = first_of_group;
        while (k < t->line_count &&
               !(t->lines[k].kind == l->kind && same_product(&t->lines[k].product, &l->product)))
            k++;
        if (k == t->line_count) {
            app_bom_line *grown = realloc(t->lines, (size_t)(k + 1) * sizeof *grown);
            int *counts = realloc(*rooms, (size_t)(k + 1) * sizeof *counts);
            if (grown)
                t->lines = grown;
            if (counts)
                *rooms = counts;
            if (!grown || !counts)
                return 0;
            t->lines[k] = *l;
            (*rooms)[k] = 1;
            t->line_count++;
            continue;
        }
        app_bom_line *s = &t->lines[k];
        s->quantity += l->quantity;
        s->net_cents += l->net_cents;
        s->vat_cents += l->vat_cents;
        s->gross_cents += l->gross_cents;
        (*rooms)[k]++;
    }
    return 1;
}

app_result cli_flat_total(const cli_room_quantities *rooms, int n, cli_room_quantities *total)
{
    memset(total, 0, sizeof *total);
    int ok = 1, *from = NULL;
    for (int i = 0; ok && i < n; i++) {
        ok = add_tiles(&total->q, &rooms[i].q) && add_trims(total, &rooms[i]);
        add_consumables(&total->cons, &rooms[i].cons);
    }
    app_bom *b = &total->bom;
    for (int g = 0; ok && g < GROUP_COUNT; g++) {
        int first = b->line_count;
        for (int i = 0; ok && i < n; i++)
            ok = add_bom_lines(b, first, &from, &rooms[i], g);
    }
    /* A merged line's detail told how one room's amount came about; the total's is a sum. */
    for (int k = 0; ok && k < b->line_count; k++)
        if (from[k] > 1)
            snprintf(b->lines[k].detail, sizeof b->lines[k].detail,
                     "the sum of %d rooms' lines, each room ordered alone", from[k]);
    free(from);
    for (int i = 0; i < n; i++) {
        const app_bom *r = &rooms[i].bom;
        b->net_cents += r->net_cents;
        b->vat_cents += r->vat_cents;
        b->gross_cents += r->gross_cents;
        b->missing += r->missing;
        b->foreign += r->foreign;
        b->out_of_range += r->out_of_range;
    }
    if (n > 0)
        memcpy(b->currency, rooms[0].bom.currency, sizeof b->currency);
    if (!ok) {
        cli_room_quantities_free(total);
        return APP_ERR_OUT_OF_MEMORY;
    }
    return APP_OK;
}

app_result cli_flat_quotation(const app_flat *f, const cli_room_quantities *rooms, app_bom *out)
{
    memset(out, 0, sizeof *out);
    int count = 0;
    for (int i = 0; i < f->room_count; i++)
        count += rooms[i].bom.line_count;
    if (count == 0)
        return APP_OK;
    out->lines = calloc((size_t)count, sizeof *out->lines);
    if (!out->lines)
        return APP_ERR_OUT_OF_MEMORY;
    for (int i = 0; i < f->room_count; i++)
        for (int k = 0; k < rooms[i].bom.line_count; k++) {
            app_bom_line *l = &out->lines[out->line_count++];
            *l = rooms[i].bom.lines[k];
            char name[sizeof l->name];
            memcpy(name, l->name, sizeof name);
            /* cut to the field when long: the article number still names the product */
            if (snprintf(l->name, sizeof l->name, "%s: %s", f->rooms[i].name, name) >=
                (int)sizeof l->name)
                l->name[sizeof l->name - 1] = '\0';
        }
    app_bom_total(out);
    return APP_OK;
}
