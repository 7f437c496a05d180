/* tessera surfaces PROJECT [--csv]: the room's tileable surfaces (app/design/room_surfaces.h) with
 * their frames, outline and hole counts and net areas, as the tile layouts see them (the
 * project's baths and shower trays from the catalog covering what they stand against). */
#include "cli_commands.h"
#include "app/project/project.h"
#include "app/design/room_surfaces.h"
#include "scene/scene_build_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int cli_cmd_surfaces(const cli_options *o)
{
    const char *path = o->project;
    int csv = o->csv_table;
    app_project p;
    char err[1024];
    if (app_project_read(path, &p, err, sizeof err) != APP_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        return 2;
    }
    app_scene_products q;
    if (app_scene_resolve_products(&p, &q, err, sizeof err) != APP_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        app_project_free(&p);
        return 1;
    }
    app_surface_frame *frames = NULL;
    int count = 0, rc = 0;
    if (app_room_surface_list(&p, &frames, &count, err, sizeof err) != APP_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        rc = 1;
    }
    if (csv)
        printf("surface,kind,origin_x_mm,origin_y_mm,origin_z_mm,normal_x,normal_y,normal_z,"
               "outline_points,holes,area_m2\n");
    else if (!rc)
        printf("%-28s %-8s %-26s %-17s %6s %5s %9s\n", "surface", "kind", "origin (mm)", "normal",
               "points", "holes", "net m2");
    static const char *const kinds[] = {"wall", "floor", "ceiling", "side", "top"};
    for (int i = 0; i < count; i++) {
        app_surface_frame *f = &frames[i];
        for (int k = 0; k < 3; k++)
            f->normal[k] += 0.0; /* no "-0.00" */
        app_surface_region r;
        if (app_room_surface_region(&p, f->surface, q.covers, q.cover_count, &r, NULL, err,
                                    sizeof err) != APP_OK) {
            fprintf(stderr, "tessera: %s: %s\n", path, err);
            rc = 1;
            continue;
        }
        double area = app_surface_region_area(&r) * 1e-6;
        const char *kind = (unsigned)f->kind < 5 ? kinds[f->kind] : "?";
        if (csv)
            printf("%s,%s,%.1f,%.1f,%.1f,%.4f,%.4f,%.4f,%d,%d,%.4f\n", f->surface, kind,
                   f->origin_mm[0], f->origin_mm[1], f->origin_mm[2], f->normal[0], f->normal[1],
                   f->normal[2], r.outer.count, r.hole_count, area);
        else {
            char origin[64], normal[64];
            snprintf(origin, sizeof origin, "%.0f, %.0f, %.0f", f->origin_mm[0], f->origin_mm[1],
                     f->origin_mm[2]);
            snprintf(normal, sizeof normal, "%.2f, %.2f, %.2f", f->normal[0], f->normal[1],
                     f->normal[2]);
            printf("%-28s %-8s %-26s %-17s %6d %5d %9.3f\n", f->surface, kind, origin, normal,
                   r.outer.count, r.hole_count, area);
            for (int h = 0; h < r.hole_count; h++)
                printf("    hole: %s%s(%s)\n", r.holes[h].name, r.holes[h].name[0] ? " " : "",
                       r.holes[h].kind == APP_HOLE_OPENING   ? "opening"
                       : r.holes[h].kind == APP_HOLE_COVERED ? "covered"
                       : r.holes[h].kind == APP_HOLE_NICHE   ? "niche"
                                                             : "other");
        }
        app_surface_region_free(&r);
    }
    free(frames);
    app_scene_resolved_free(&q);
    app_project_free(&p);
    return rc;
}
