/* `tessera quantities FLAT`: the tile part list and the bill of materials of each room, then
 * the flat's total. A total line is the sum of the rooms' lines for that product (each room
 * ordered with its own surplus and whole boxes, as the rooms are tiled one after another), so
 * every figure of the total is the sum of the rooms' figures. */
#include "cli_quantities.h"

#include "app/design/room_surfaces.h"

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

/* Adds bill lines [from, to) of b to the total's lines, merged by product. */
static int add_bom_lines(app_bom *t, const app_bom *b, int from, int to)
{
    for (int i = from; i < to; i++) {
        const app_bom_line *l = &b->lines[i];
        int k = 0;
        while (k < t->line_count && !same_product(&t->lines[k].product, &l->product))
            k++;
        if (k == t->line_count) {
            app_bom_line *grown = realloc(t->lines, (size_t)(t->line_count + 1) * sizeof *grown);
            if (!grown)
                return 0;
            t->lines = grown;
            t->lines[k] = *l;
            t->line_count++;
            continue;
        }
        app_bom_line *s = &t->lines[k];
        s->quantity += l->quantity;
        s->net_cents += l->net_cents;
        s->vat_cents += l->vat_cents;
        s->gross_cents += l->gross_cents;
    }
    return 1;
}

static void print_heading(const char *what, const char *name, int csv)
{
    if (csv) {
        printf("%s,\"", what);
        for (const char *c = name; *c; c++) /* CSV: a quote inside a field is doubled */
            fputs(*c == '"' ? "\"\"" : (char[2]){*c, 0}, stdout);
        puts("\"");
    } else
        printf("\n== %s: %s ==\n", what, name);
}

typedef struct room_result {
    app_quantities q;
    app_bom bom;
} room_result;

int cli_quantities_flat(const cli_options *o, const app_flat *f, cat_db *db)
{
    room_result *rooms = calloc((size_t)f->room_count, sizeof *rooms);
    if (!rooms) {
        fprintf(stderr, "tessera: out of memory for %d rooms\n", f->room_count);
        return CLI_FAILED;
    }
    app_quantity_options qo = app_quantity_options_default();
    qo.surplus_percent = o->surplus;
    int rc = CLI_OK;
    char err[2048];
    for (int i = 0; rc == CLI_OK && i < f->room_count; i++) {
        const app_project *p = &f->rooms[i];
        app_tile_layout *layouts = NULL;
        int n = 0;
        app_result r = app_room_tile_layouts(p, db, &layouts, &n, err, sizeof err);
        if (r == APP_OK)
            r = app_quantities_compute(layouts, n, &qo, &rooms[i].q, err, sizeof err);
        if (r == APP_OK)
            r = app_bom_build(db, p, &rooms[i].q, &rooms[i].bom, err, sizeof err);
        app_tile_layouts_free(layouts, n);
        if (r != APP_OK) {
            fprintf(stderr, "tessera: %s: room \"%s\": %s\n", o->project, p->name, err);
            rc = r == APP_ERR_OUT_OF_MEMORY || r == APP_ERR_IO ? CLI_FAILED : CLI_USAGE;
            break;
        }
        if (!o->csv_table)
            fprintf(stderr, "tessera quantities: [%d/%d] %s\n", i + 1, f->room_count, p->name);
        print_heading("room", p->name, o->csv_table);
        cli_print_tiles(&rooms[i].q, &rooms[i].bom, o->csv_table);
        cli_print_bom(&rooms[i].bom, o->csv_table);
    }
    if (rc == CLI_OK) {
        app_quantities total_q;
        app_bom total_b;
        memset(&total_q, 0, sizeof total_q);
        memset(&total_b, 0, sizeof total_b);
        int ok = 1;
        /* Tiles first, in the order of the total's tile lines, as app_bom_build orders them. */
        for (int i = 0; ok && i < f->room_count; i++)
            ok = add_tiles(&total_q, &rooms[i].q) &&
                 add_bom_lines(&total_b, &rooms[i].bom, 0, rooms[i].q.line_count);
        for (int i = 0; ok && i < f->room_count; i++)
            ok = add_bom_lines(&total_b, &rooms[i].bom, rooms[i].q.line_count,
                               rooms[i].bom.line_count);
        for (int i = 0; i < f->room_count; i++) {
            total_b.net_cents += rooms[i].bom.net_cents;
            total_b.vat_cents += rooms[i].bom.vat_cents;
            total_b.gross_cents += rooms[i].bom.gross_cents;
            total_b.missing += rooms[i].bom.missing;
            total_b.foreign += rooms[i].bom.foreign;
            total_b.out_of_range += rooms[i].bom.out_of_range;
        }
        memcpy(total_b.currency, rooms[0].bom.currency, sizeof total_b.currency);
        if (!ok) {
            fprintf(stderr, "tessera: out of memory for the flat's total\n");
            rc = CLI_FAILED;
        } else {
            char what[160];
            snprintf(what, sizeof what, "%s (%d rooms)", f->name[0] ? f->name : "the flat",
                     f->room_count);
            print_heading("flat", what, o->csv_table);
            cli_print_tiles(&total_q, &total_b, o->csv_table);
            cli_print_bom(&total_b, o->csv_table);
        }
        free(total_q.lines);
        free(total_b.lines);
    }
    for (int i = 0; i < f->room_count; i++) {
        app_quantities_free(&rooms[i].q);
        app_bom_free(&rooms[i].bom);
    }
    free(rooms);
    return rc;
}
