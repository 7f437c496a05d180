/* Which placed products cover a surface, so the tile layout leaves it free
 * (app/design/room_surfaces.h): baths and shower trays cover the wall behind them below their rim
 * and the floor under them. One rule for the renderer (scene_products.c), the quantities and the
 * printed elevations, so what is rendered, counted and printed agree. */
#include "app/design/room_surfaces.h"

#include "app/design/quantities.h"

#include "catalog/catalog.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int app_room_fixture_box(const app_object *o, const app_product_info *info, app_fixture_box *b)
{
    if (info->category != CAT_CATEGORY_BATHS && info->category != CAT_CATEGORY_SHOWER_TRAYS)
        return 0;
    /* The catalog box in the product frame (origin at the bottom centre of the back face,
     * depth along +y), turned by R = Rz * Ry * Rx and bounded in the room. */
    const double deg = 3.14159265358979323846 / 180.0;
    double cx = cos(o->rotation_deg[0] * deg), sx = sin(o->rotation_deg[0] * deg);
    double cy = cos(o->rotation_deg[1] * deg), sy = sin(o->rotation_deg[1] * deg);
    double cz = cos(o->rotation_deg[2] * deg), sz = sin(o->rotation_deg[2] * deg);
    const double r[3][3] = {{cz * cy, cz * sy * sx - sz * cx, cz * sy * cx + sz * sx},
                            {sz * cy, sz * sy * sx + cz * cx, sz * sy * cx - cz * sx},
                            {-sy, cy * sx, cy * cx}};
    snprintf(b->name, sizeof b->name, "%s", o->name);
    for (int k = 0; k < 3; k++) {
        b->min_mm[k] = HUGE_VAL;
        b->max_mm[k] = -HUGE_VAL;
    }
    for (int c = 0; c < 8; c++) {
        double l[3] = {((c & 1) ? 0.5 : -0.5) * info->width_mm * o->scale[0],
                       ((c & 2) ? info->depth_mm : 0) * o->scale[1],
                       ((c & 4) ? info->height_mm : 0) * o->scale[2]};
        for (int k = 0; k < 3; k++) {
            double v = o->position_mm[k] + r[k][0] * l[0] + r[k][1] * l[1] + r[k][2] * l[2];
            b->min_mm[k] = fmin(b->min_mm[k], v);
            b->max_mm[k] = fmax(b->max_mm[k], v);
        }
    }
    return 1;
}

app_result app_room_fixture_boxes(const app_project *p, app_product_lookup lookup, void *user,
                                  app_fixture_box **out, int *count, char *err, size_t err_size)
{
    *out = NULL;
    *count = 0;
    if (p->object_count == 0)
        return APP_OK;
    app_fixture_box *boxes = calloc((size_t)p->object_count, sizeof *boxes);
    if (!boxes) {
        snprintf(err, err_size, "%s: out of memory", p->path);
        return APP_ERR_OUT_OF_MEMORY;
    }
    int n = 0;
    for (int i = 0; i < p->object_count; i++) {
        const app_object *o = &p->objects[i];
        if (!o->has_product || !lookup)
            continue;
        app_product_info info;
        char lerr[1024];
        if (lookup(user, &o->product, &info, lerr, sizeof lerr) != APP_OK) {
            snprintf(err, err_size, "%s: $.objects[%d] (\"%s\"): %s", p->path, i, o->name, lerr);
            free(boxes);
            return APP_ERR_NOT_FOUND;
        }
        n += app_room_fixture_box(o, &info, &boxes[n]);
    }
    *out = boxes;
    *count = n;
    return APP_OK;
}

app_result app_room_tile_layouts(const app_project *p, struct cat_db *db, app_tile_layout **out,
                                 int *count, char *err, size_t err_size)
{
    app_fixture_box *boxes = NULL;
    int n = 0;
    app_result r = app_room_fixture_boxes(p, db ? app_placement_catalog_lookup : NULL, db, &boxes,
                                          &n, err, err_size);
    if (r != APP_OK)
        return r;
    app_room_regions regions = {boxes, n};
    app_tiling *room = NULL;
    r = app_room_setout_tilings(p, db, boxes, n, &room, err, err_size);
    app_project set_out = *p; /* shallow: only the tilings differ */
    if (room)
        set_out.tilings = room;
    if (r == APP_OK)
        r = app_project_tile_layouts(&set_out, db, app_room_region_provider, &regions, out, count,
                                     err, err_size);
    free(room);
    free(boxes);
    return r;
}
