/* tessera export-glb PROJECT [-o OUT.glb]: the whole project (room, tiles, objects, placed
 * products with their parts' materials) as one GLB file that other tools open
 * (app/output/project_glb.h, docs/catalog.md "Exporting a project"). */
#include "app/cli/cli.h"
#include "app/output/project_glb.h"
#include "cli_options.h"

#include <stdio.h>
#include <string.h>

static const char usage_text[] =
    "usage: tessera export-glb PROJECT [-o OUT.glb]\n"
    "Writes the project (room surfaces and tiles, every object, catalog products with their\n"
    "own part materials) as one GLB file, Y up, metres, as glTF wants (default: PROJECT with\n"
    ".glb for .json). Products come from the catalog ($TESSERA_CATALOG, else\n"
    "~/.cache/tessera/catalog.sqlite). docs/catalog.md, \"Exporting a project\".\n";

int app_cli_export_glb(int argc, char **argv)
{
    const char *project = NULL, *out = NULL;
    for (int i = 2; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            fputs(usage_text, stdout);
            return CLI_OK;
        }
        if (!strcmp(a, "-o") || !strcmp(a, "--output")) {
            if (i + 1 >= argc) {
                fprintf(stderr, "tessera export-glb: option %s needs a value\n", a);
                return CLI_USAGE;
            }
            out = argv[++i];
        } else if (a[0] == '-' && a[1]) {
            fprintf(stderr, "tessera export-glb: unknown option \"%s\"\n", a);
            return CLI_USAGE;
        } else if (!project) {
            project = a;
        } else {
            fprintf(stderr, "tessera export-glb: one project at a time\n");
            return CLI_USAGE;
        }
    }
    if (!project) {
        fputs(usage_text, stderr);
        return CLI_USAGE;
    }
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
