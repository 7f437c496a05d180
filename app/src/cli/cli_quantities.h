/* The tables of `tessera quantities` (cli_quantities.c) and its flat form (cli_quantities_flat.c):
 * a section per room, then the flat's total, each line the sum of the rooms' lines. */
#ifndef APP_CLI_QUANTITIES_H
#define APP_CLI_QUANTITIES_H

#include "app/design/quantities.h"
#include "app/design/trims.h"
#include "app/output/quote.h"
#include "app/project/flat.h"
#include "cli_options.h"

/* Everything `tessera quantities` reports for one room. */
typedef struct cli_room_quantities {
    app_tile_layout *layouts; /* one per tiling of the room (the offcut list names them) */
    int layout_count;
    app_quantities q;
    app_trim_quantity *trims;
    int trim_count;
    app_consumables cons;
    app_bom bom; /* tiles, products, trims, consumables and labour, priced and totalled */
} cli_room_quantities;

/* Lays out, counts and prices room p (the order surplus in percent); on failure *out is empty
 * and err says why. */
app_result cli_room_quantities_compute(const app_project *p, cat_db *db, double surplus_percent,
                                       cli_room_quantities *out, char *err, size_t err_size);
void cli_room_quantities_free_layouts(cli_room_quantities *r);
void cli_room_quantities_free(cli_room_quantities *r);

void cli_print_tiles(const app_quantities *q, const app_bom *b, int csv);
void cli_print_bom(const app_bom *b, int csv);
void cli_print_consumables(const app_consumables *c, int csv);
void cli_print_quote_head(const app_quote *q, int csv);
void cli_print_offcuts(const app_quantities *q, const app_tile_layout *layouts, int csv);

/* Opens the catalog at db_path (NULL: the default) built from the shipped data; prints why not. */
int cli_quantities_open_catalog(const char *db_path, cat_db **db);

/* Writes flat f's quotation (as `quantities FLAT --xlsx` with the default surplus, as the print
 * set counts) to path, for `print FLAT --xlsx`; returns the exit code. */
int cli_flat_quotation_xlsx(const cli_options *o, const app_flat *f, const char *path);

/* Every room of a flat, then the total (text, --csv or --json; --xlsx writes the flat's one
 * quotation); returns the exit code. */
int cli_quantities_flat(const cli_options *o, const app_flat *f, cat_db *db);

#endif
