/* One room's quantities as `tessera quantities` reports them (cli_quantities.h): the tile
 * layouts and part list, the priced bill with its trim profiles, consumables and labour. The
 * single-room command and each room of a flat go through here, so a flat's room is quantified
 * exactly as the same room on its own. */
#include "cli_quantities.h"

#include "app/design/room_surfaces.h"

#include <stdlib.h>
#include <string.h>

app_result cli_room_quantities_compute(const app_project *p, cat_db *db, double surplus_percent,
                                       cli_room_quantities *out, char *err, size_t err_size)
{
    memset(out, 0, sizeof *out);
    app_result r = app_room_tile_layouts(p, db, &out->layouts, &out->layout_count, err, err_size);
    app_quantity_options qo = app_quantity_options_default();
    qo.surplus_percent = surplus_percent;
    if (r == APP_OK)
        r = app_quantities_compute(out->layouts, out->layout_count, &qo, &out->q, err, err_size);
    if (r == APP_OK)
        r = app_bom_build(db, p, &out->q, &out->bom, err, err_size);
    if (r == APP_OK)
        r = app_trim_quantities(p, &out->trims, &out->trim_count, err, err_size);
    if (r == APP_OK)
        r = app_bom_add_trims(db, out->trims, out->trim_count, &out->bom, err, err_size);
    if (r == APP_OK)
        r = app_consumables_compute(p, db, out->layouts, out->layout_count, NULL, &out->cons, err,
                                    err_size);
    if (r == APP_OK)
        r = app_bom_add_consumables(db, &out->cons, NULL, &out->bom, err, err_size);
    if (r != APP_OK)
        cli_room_quantities_free(out);
    return r;
}

void cli_room_quantities_free_layouts(cli_room_quantities *r)
{
    app_tile_layouts_free(r->layouts, r->layout_count);
    r->layouts = NULL;
    r->layout_count = 0;
}

void cli_room_quantities_free(cli_room_quantities *r)
{
    if (!r)
        return;
    cli_room_quantities_free_layouts(r);
    app_quantities_free(&r->q);
    app_bom_free(&r->bom);
    free(r->trims);
    memset(r, 0, sizeof *r);
}
