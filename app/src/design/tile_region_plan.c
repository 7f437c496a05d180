/* The fallback surface regions of a plan (app_surface_region_from_plan): the floor and ceiling
 * as the plan polygon, a wall as length x height minus its openings, niche mouths and the
 * pre-walls standing against it. The room model may provide richer regions (covered areas of
 * fixtures, slopes) through app_region_provider (app/design/quantities.h). Pre-wall faces are
 * rectangles: front width x height, left/right depth x height, top width x depth. */
#include "tile_layout_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static app_result prewall_footprint(const app_room_plan *plan, const app_prewall *pw,
                                    app_point2 q[4])
{
    int n = plan->corner_count;
    if (pw->wall < 0 || pw->wall >= n)
        return APP_ERR_SCHEMA;
    app_point2 a = plan->corners[pw->wall], b = plan->corners[(pw->wall + 1) % n];
    double dx = b.x - a.x, dy = b.y - a.y, len = sqrt(dx * dx + dy * dy);
    if (!(len > 0))
        return APP_ERR_SCHEMA;
    dx /= len, dy /= len;
    double nx = -dy, ny = dx; /* inward: the along direction turned 90 degrees ccw (room.h) */
    double s0 = pw->offset_mm, s1 = pw->offset_mm + pw->width_mm, d = pw->depth_mm;
    q[0] = (app_point2){a.x + dx * s0, a.y + dy * s0};
    q[1] = (app_point2){a.x + dx * s1, a.y + dy * s1};
    q[2] = (app_point2){q[1].x + nx * d, q[1].y + ny * d};
    q[3] = (app_point2){q[0].x + nx * d, q[0].y + ny * d};
    return APP_OK;
}

app_result app_surface_region_from_plan(const app_room_plan *plan, const char *surface,
                                        app_surface_region *out, char *err, size_t err_size)
{
    if (!plan || !surface || !out || plan->corner_count < 3 || !plan->corners) {
        tl_set_err(err, err_size, "tile_layout", "%s: the plan has no corners",
                   surface ? surface : "(null)");
        return APP_ERR_SCHEMA;
    }
    app_result res;
    if (!strcmp(surface, "floor") || !strcmp(surface, "ceiling")) {
        int floor = surface[0] == 'f';
        app_surface_region_init(out, surface, floor ? APP_SURFACE_FLOOR : APP_SURFACE_CEILING);
        res = app_region_set_outer(out, plan->corners, plan->corner_count, err, err_size);
        for (int i = 0; floor && res == APP_OK && i < plan->prewall_count; i++) {
            app_point2 q[4];
            if (prewall_footprint(plan, &plan->prewalls[i], q) == APP_OK &&
                plan->prewalls[i].width_mm > 0 && plan->prewalls[i].depth_mm > 0)
                res = app_region_add_hole(out, q, 4, APP_HOLE_COVERED, plan->prewalls[i].name, err,
                                          err_size);
        }
        if (res != APP_OK)
            app_surface_region_free(out);
        return res;
    }
    if (!strncmp(surface, "prewall:", 8)) {
        /* prewall:NAME:front|left|right|top: rectangles; front width x height, sides depth x
         * height , top width x depth. */
        const char *name = surface + 8, *colon = strrchr(name, ':');
        for (int i = 0; colon && i < plan->prewall_count; i++) {
            const app_prewall *pw = &plan->prewalls[i];
            if (strlen(pw->name) != (size_t)(colon - name) ||
                strncmp(pw->name, name, (size_t)(colon - name)))
                continue;
            const char *face = colon + 1;
            int top = !strcmp(face, "top"), front = !strcmp(face, "front");
            int side = !strcmp(face, "left") || !strcmp(face, "right");
            if (!top && !front && !side)
                break;
            app_surface_region_init(out, surface,
                                    top ? APP_SURFACE_PREWALL_TOP : APP_SURFACE_PREWALL_SIDE);
            double w = side ? pw->depth_mm : pw->width_mm, h = top ? pw->depth_mm : pw->height_mm;
            res = app_region_set_outer_rect(out, 0, 0, w, h, err, err_size);
            if (res != APP_OK)
                app_surface_region_free(out);
            return res;
        }
        tl_set_err(err, err_size, "tile_layout",
                   "%s: no such pre-wall face (prewall:NAME:front|left|right|top)", surface);
        return APP_ERR_SCHEMA;
    }
    int wall = -1, used = 0;
    if (sscanf(surface, "wall:%d%n", &wall, &used) != 1 || surface[used] != '\0' || wall < 0 ||
        wall >= plan->corner_count) {
        tl_set_err(err, err_size, "tile_layout", "%s: not a surface of this plan", surface);
        return APP_ERR_SCHEMA;
    }
    app_point2 a = plan->corners[wall], b = plan->corners[(wall + 1) % plan->corner_count];
    double len = hypot(b.x - a.x, b.y - a.y), h = plan->height_mm;
    app_surface_region_init(out, surface, APP_SURFACE_WALL);
    res = app_region_set_outer_rect(out, 0, 0, len, h, err, err_size);
    for (int i = 0; res == APP_OK && i < plan->opening_count; i++) {
        const app_opening *o = &plan->openings[i];
        if (o->wall != wall || !(o->width_mm > 0) || !(o->height_mm > 0))
            continue;
        res = app_region_add_hole_rect(out, o->offset_mm, o->sill_mm, o->offset_mm + o->width_mm,
                                       o->sill_mm + o->height_mm, APP_HOLE_OPENING, o->name, err,
                                       err_size);
    }
    for (int i = 0; res == APP_OK && i < plan->niche_count; i++) {
        const app_niche *o = &plan->niches[i];
        if (o->wall != wall || !(o->width_mm > 0) || !(o->height_mm > 0))
            continue;
        res = app_region_add_hole_rect(out, o->offset_mm, o->sill_mm, o->offset_mm + o->width_mm,
                                       o->sill_mm + o->height_mm, APP_HOLE_NICHE, o->name, err,
                                       err_size);
    }
    for (int i = 0; res == APP_OK && i < plan->prewall_count; i++) {
        const app_prewall *o = &plan->prewalls[i];
        if (o->wall != wall || !(o->width_mm > 0) || !(o->height_mm > 0))
            continue;
        res = app_region_add_hole_rect(out, o->offset_mm, 0, o->offset_mm + o->width_mm,
                                       o->height_mm, APP_HOLE_COVERED, o->name, err, err_size);
    }
    if (res != APP_OK)
        app_surface_region_free(out);
    return res;
}
