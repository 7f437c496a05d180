/* `tessera quantities FLAT`: each room's quantities as the room alone would print them (tiles,
 * offcuts, trim profiles, consumables and labour, its priced bill), then the flat's total, every
 * figure the sum of the rooms' (cli_flat_total.h), and the flat's one quotation: --json writes
 * the rooms, the total and the quotation as one document, --xlsx the quotation as a
 * spreadsheet with every room's positions in turn (docs/cli.md "quantities"). */
#include "cli_flat_total.h"
#include "cli_quantities.h"
#include "cli_quantities_json.h"
#include "cli_quantities_trims.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

/* The flat's quote: the shared customer and quote number of the file (every room carries
 * them), numbered by the flat's name when the file gives no number. */
static app_result flat_quote(const cli_options *o, const app_flat *f, app_quote *quote, char *err,
                             size_t err_size)
{
    app_project named = f->rooms[0]; /* a shallow copy: read only */
    if (f->name[0])
        snprintf(named.name, sizeof named.name, "%s", f->name);
    return app_quote_make(&named, o->company, o->date, quote, err, err_size);
}

static int print_flat(const cli_options *o, const app_flat *f, const cli_room_quantities *rooms,
                      const cli_room_quantities *total, const app_quote *quote)
{
    int csv = o->csv_table;
    for (int i = 0; i < f->room_count; i++) {
        const cli_room_quantities *r = &rooms[i];
        print_heading("room", f->rooms[i].name, csv);
        cli_print_tiles(&r->q, &r->bom, csv);
        if (o->offcuts && r->layout_count > 0)
            cli_print_offcuts(&r->q, r->layouts, csv);
        cli_print_trims(r->trims, r->trim_count, &r->bom, csv);
        cli_print_consumables(&r->cons, csv);
        cli_print_bom(&r->bom, csv);
    }
    char what[160];
    snprintf(what, sizeof what, "%s (%d rooms)", f->name[0] ? f->name : "the flat", f->room_count);
    print_heading("flat", what, csv);
    cli_print_tiles(&total->q, &total->bom, csv);
    cli_print_trims(total->trims, total->trim_count, &total->bom, csv);
    cli_print_consumables(&total->cons, csv);
    cli_print_quote_head(quote, csv);
    cli_print_bom(&total->bom, csv);
    return CLI_OK;
}

/* Everything the flat's outputs need. */
typedef struct flat_result {
    cli_room_quantities *rooms;
    cli_room_quantities total;
    app_quote quote;
    app_bom quotation;
} flat_result;

static void flat_result_free(const app_flat *f, flat_result *r)
{
    app_bom_free(&r->quotation);
    cli_room_quantities_free(&r->total);
    for (int i = 0; r->rooms && i < f->room_count; i++)
        cli_room_quantities_free(&r->rooms[i]);
    free(r->rooms);
    memset(r, 0, sizeof *r);
}

/* Quantifies every room with the order surplus in percent (keep_layouts: for the offcut list),
 * then the total, the quote and the quotation; returns the exit code (the message is
 * printed). */
static int flat_compute(const cli_options *o, const app_flat *f, cat_db *db, double surplus,
                        int keep_layouts, flat_result *out)
{
    memset(out, 0, sizeof *out);
    out->rooms = calloc((size_t)f->room_count, sizeof *out->rooms);
    if (!out->rooms) {
        fprintf(stderr, "tessera: out of memory for %d rooms\n", f->room_count);
        return CLI_FAILED;
    }
    char err[2048];
    for (int i = 0; i < f->room_count; i++) {
        const app_project *p = &f->rooms[i];
        app_result r = cli_room_quantities_compute(p, db, surplus, &out->rooms[i], err, sizeof err);
        if (r != APP_OK) {
            fprintf(stderr, "tessera: %s: room \"%s\": %s\n", o->project, p->name, err);
            return r == APP_ERR_OUT_OF_MEMORY || r == APP_ERR_IO ? CLI_FAILED : CLI_USAGE;
        }
        if (!keep_layouts)
            cli_room_quantities_free_layouts(&out->rooms[i]);
        fprintf(stderr, "tessera quantities: [%d/%d] %s\n", i + 1, f->room_count, p->name);
    }
    if (flat_quote(o, f, &out->quote, err, sizeof err) != APP_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        return CLI_USAGE;
    }
    if (cli_flat_total(out->rooms, f->room_count, &out->total) != APP_OK ||
        cli_flat_quotation(f, out->rooms, &out->quotation) != APP_OK) {
        fprintf(stderr, "tessera: out of memory for the flat's total\n");
        return CLI_FAILED;
    }
    if (out->quotation.out_of_range) {
        fprintf(stderr,
                "tessera: %s: the flat's total does not fit in an amount; check the catalog "
                "prices\n",
                o->project);
        return CLI_USAGE;
    }
    return CLI_OK;
}

static int write_xlsx(const app_flat *f, const flat_result *r, const char *path)
{
    char err[2048];
    app_project named = f->rooms[0]; /* the sheet's "Project" row: the flat's name */
    if (f->name[0])
        snprintf(named.name, sizeof named.name, "%s", f->name);
    if (app_quote_write_xlsx(path, &named, &r->quote, &r->quotation, err, sizeof err) != APP_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        return CLI_FAILED;
    }
    return CLI_OK;
}

int cli_quantities_flat(const cli_options *o, const app_flat *f, cat_db *db)
{
    flat_result r;
    int rc = flat_compute(o, f, db, o->surplus, o->offcuts, &r);
    if (rc == CLI_OK && o->xlsx)
        rc = write_xlsx(f, &r, o->xlsx);
    if (rc == CLI_OK) {
        if (o->json_table)
            rc = cli_quantities_json_flat(stdout, f, r.rooms, &r.total, &r.quote, &r.quotation,
                                          o->offcuts)
                     ? CLI_OK
                     : CLI_FAILED;
        else
            rc = print_flat(o, f, r.rooms, &r.total, &r.quote);
    }
    flat_result_free(f, &r);
    return rc;
}

int cli_flat_quotation_xlsx(const cli_options *o, const app_flat *f, const char *path)
{
    /* the print set's quantities: the default surplus, as app_print_pdf counts a room */
    cat_db *db = NULL;
    int rc = cli_quantities_open_catalog(o->db, &db);
    flat_result r;
    memset(&r, 0, sizeof r);
    if (rc == CLI_OK)
        rc = flat_compute(o, f, db, app_quantity_options_default().surplus_percent, 0, &r);
    if (rc == CLI_OK)
        rc = write_xlsx(f, &r, path);
    flat_result_free(f, &r);
    cat_db_close(db);
    return rc;
}
