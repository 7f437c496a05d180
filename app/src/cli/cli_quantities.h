/* The tables of `tessera quantities` (cli_quantities.c) and its flat form (cli_quantities_flat.c):
 * a section per room, then the flat's total, each line the sum of the rooms' lines. */
#ifndef APP_CLI_QUANTITIES_H
#define APP_CLI_QUANTITIES_H

#include "app/design/quantities.h"
#include "app/project/flat.h"
#include "cli_options.h"

void cli_print_tiles(const app_quantities *q, const app_bom *b, int csv);
void cli_print_bom(const app_bom *b, int csv);

/* Every room of a flat, then the total; returns the exit code. */
int cli_quantities_flat(const cli_options *o, const app_flat *f, cat_db *db);

#endif
