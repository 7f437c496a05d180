/* `tessera quantities --json`: the tile part list, offcuts, consumables, the quote's header and
 * the bill of materials as one JSON document (docs/cli.md "quantities"). */
#ifndef CLI_QUANTITIES_JSON_H
#define CLI_QUANTITIES_JSON_H

#include "app/design/quantities.h"
#include "app/output/quote.h"

#include <stdio.h>

/* Writes the document to f; layouts (may be NULL) adds the offcut uses. Returns 1 on success. */
int cli_quantities_json(FILE *f, const app_project *p, const app_quantities *q,
                        const app_consumables *c, const app_quote *quote, const app_bom *b,
                        const app_tile_layout *layouts);

#endif
