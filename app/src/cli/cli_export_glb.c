/* tessera export-glb PROJECT [-o OUT.glb]: the whole project (room, tiles, objects, placed
 * products with their parts' materials) as one GLB file that other tools open
 * (app/output/project_glb.h, docs/catalog.md "Exporting a project"). */
#include "app/output/project_glb.h"
#include "cli_commands.h"

#include <stdio.h>
#include <string.h>

int cli_cmd_export_glb(const cli_options *o)
{
    const char *project = o->project, *out = o->output;
    char def[4096];
    if (!out) {
        size_t n = strlen(project);
        if (n > 5 && !strcmp(project + n - 5, ".json"))
            n -= 5;
        if (n + 5 > sizeof def) {
            fprintf(stderr, "tessera export-glb: %s: name too long; give -o\n", project);
            return CLI_USAGE;
        }
        snprintf(def, sizeof def, "%.*s.glb", (int)n, project);
        out = def;
    }
    app_project p;
    char err[4096];
    if (app_project_read(project, &p, err, sizeof err) != APP_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        return CLI_USAGE;
    }
    app_glb_stats s;
    app_result r = app_project_export_glb(&p, out, &s, err, sizeof err);
    app_project_free(&p);
    if (r != APP_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        return CLI_FAILED;
    }
    printf("%s: %d nodes, %d objects (%d left out), %d parts, %d materials, %d cameras, "
           "%ld vertices, %ld triangles\n",
           out, s.node_count, s.object_count, s.skipped_count, s.part_count, s.material_count,
           s.camera_count, s.vertex_count, s.triangle_count);
    printf("bounds: %.1f %.1f %.1f .. %.1f %.1f %.1f mm\n", s.bounds_min_mm[0], s.bounds_min_mm[1],
           s.bounds_min_mm[2], s.bounds_max_mm[0], s.bounds_max_mm[1], s.bounds_max_mm[2]);
    return CLI_OK;
}
