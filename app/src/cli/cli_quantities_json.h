/* `tessera quantities --json`: the tile part list, offcuts, trim profiles, consumables, the
 * quote's header and the bill of materials as one JSON document (docs/cli.md "quantities"); for
 * a flat, one such part per room, the flat's total and the flat's quotation. */
#ifndef CLI_QUANTITIES_JSON_H
#define CLI_QUANTITIES_JSON_H

#include "cli_quantities.h"

#include <stdio.h>

/* Writes the document of room p to f; offcuts adds the offcut uses. Returns 1 on success. */
int cli_quantities_json(FILE *f, const app_project *p, const cli_room_quantities *r,
                        const app_quote *quote, int offcuts);

/* Writes the document of flat fl: "rooms" (each room's part, as the room alone would print
 * it, without a quote), "total" (tiles, trims, consumables and bill summed over the rooms;
 * total's layouts are not used), "quote" and "quotation" (the bill the spreadsheet holds:
 * every room's positions in turn). Returns 1 on success. */
int cli_quantities_json_flat(FILE *f, const app_flat *fl, const cli_room_quantities *rooms,
                             const cli_room_quantities *total, const app_quote *quote,
                             const app_bom *quotation, int offcuts);

#endif
