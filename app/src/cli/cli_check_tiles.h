/* Tile findings of `tessera check` (cli_check_tiles.c). */
#ifndef CLI_CHECK_TILES_H
#define CLI_CHECK_TILES_H

#include "app/design/placement.h"
#include "app/project/project.h"

/* Prints a warning for every cut piece under its tiling's minimum cut and counts them in
 * *warnings. Returns 0, or -1 when the tiles could not be laid (said on stderr). */
int cli_check_tile_cuts(const app_project *p, app_lazy_catalog *cat, int *warnings);

#endif
