/* A flat's quantities from its rooms' (cli_quantities_flat.c): the total, every figure the sum
 * of the rooms' figures (each room ordered alone: its own surplus, whole boxes, bags and
 * lengths, as the rooms are tiled one after another), and the flat's one quotation, every
 * room's positions in turn. */
#ifndef CLI_FLAT_TOTAL_H
#define CLI_FLAT_TOTAL_H

#include "cli_quantities.h"

/* Fills *total (no layouts) from rooms[0..n-1]: tile lines, trims and bill lines merged by
 * product in order of first appearance (bill: tiles, then products and trims, consumables,
 * labour), amounts and money summed. Returns APP_ERR_OUT_OF_MEMORY (total emptied) or APP_OK. */
app_result cli_flat_total(const cli_room_quantities *rooms, int n, cli_room_quantities *total);

/* The quotation over the flat: every room's lines in turn, each name led by its room's name
 * ("Kitchen: ..."), totalled (app_bom_total) so each line's amounts are those of its room. */
app_result cli_flat_quotation(const app_flat *f, const cli_room_quantities *rooms, app_bom *out);

#endif
