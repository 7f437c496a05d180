/* The trim section of `tessera quantities` (docs/tiling.md "Trim profiles"). */
#ifndef CLI_QUANTITIES_TRIMS_H
#define CLI_QUANTITIES_TRIMS_H

#include "app/design/trims.h"

/* Prints one line per trim product: edges, the metres needed, the pieces of 2.5 m, the metres
 * billed (the pieces' length), the price of a piece and per metre (from its bill line in b,
 * matched by product, whether the catalog prices a metre or a length). csv: rows of section
 * "trims". */
void cli_print_trims(const app_trim_quantity *trims, int count, const app_bom *b, int csv);

#endif
