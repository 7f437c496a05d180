/* The tile findings of `tessera check`: every cut piece under the tiling's minimum cut
 * (app_tile_min_cut_mm, docs/tiling.md "Set-out"), on the layouts the quantities count. A sliver
 * is a warning: a tiler can lay it, but it breaks easily and looks like a mistake. */
#include "cli_check_tiles.h"

#include "app/design/quantities.h"
#include "app/design/room_surfaces.h"

#include <stdio.h>
#include <stdlib.h>

int cli_check_tile_cuts(const app_project *p, app_lazy_catalog *cat, int *warnings)
{
    *warnings = 0;
    if (p->tiling_count <= 0)
        return 0;
    char err[1024];
    if (!cat->db && !cat->failed &&
        app_placement_open_catalog(cat->db_path, &cat->db, cat->err, sizeof cat->err) != APP_OK)
        cat->failed = 1;
    if (cat->failed || !cat->db) {
        fprintf(stderr, "tessera check: %s: tiles not checked: %s\n", p->path, cat->err);
        return -1;
    }
    app_tile_layout *layouts = NULL;
    int count = 0;
    if (app_room_tile_layouts(p, cat->db, &layouts, &count, err, sizeof err) != APP_OK) {
        fprintf(stderr, "tessera check: %s: tiles not checked: %s\n", p->path, err);
        return -1;
    }
    for (int i = 0; i < count && i < p->tiling_count; i++) {
        const app_tile_layout *l = &layouts[i];
        const app_tiling *ti = &p->tilings[i];
        for (int k = 0; k < l->tile_count; k++) {
            const app_placed_tile *t = &l->tiles[k];
            if (t->whole || t->product < 0 || t->product >= l->spec_count)
                continue;
            const double side[2] = {l->specs[t->product].work_w_mm, l->specs[t->product].work_h_mm};
            const double cut[2] = {t->cut_w_mm, t->cut_h_mm};
            double width = 1e300, rule = 0;
            for (int a = 0; a < 2; a++) {
                double r = app_tile_min_cut_mm(ti, side[a]);
                if (cut[a] < side[a] - 0.05 && cut[a] < r && cut[a] < width)
                    width = cut[a], rule = r;
            }
            if (rule <= 0)
                continue;
            printf("%-7s %-12s on %s at (%6.0f, %6.0f) mm: tiling \"%s\": a %.1f mm cut piece "
                   "(row %d, column %d), under the minimum cut of %.0f mm\n",
                   "warning", "tile-cut", l->surface, t->centre.x, t->centre.y, ti->name, width,
                   t->row, t->col, rule);
            ++*warnings;
        }
    }
    app_tile_layouts_free(layouts, count);
    return 0;
}
