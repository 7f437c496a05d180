/* tessera catalog lod MODEL.(glb|gltf) [--fraction F] [-o OUT.glb]: loads any glTF model,
 * validates its meshes (catalog/mesh_lod.h: degenerate triangles, non-manifold and open edges;
 * NaN/Inf and bad indices refused), prints the report and, with -o, writes a level of detail
 * with about F of its triangles (quadric decimation, OpenMesh) as GLB. */
#include "catalog/mesh_lod.h"
#include "catalog/model.h"
#include "catalog/model_write.h"
#include "cli_commands.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int cli_cmd_catalog_lod(const cli_options *o)
{
    const char *in = o->project, *out = o->output;
    double fraction = o->fraction > 0 ? o->fraction : 0.5;
    cat_model m;
    char err[2048];
    cat_result r = cat_model_load(in, &m, err, sizeof err);
    if (r != CAT_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        return r == CAT_ERR_IO ? CLI_FAILED : CLI_USAGE;
    }
    cat_mesh_report rep;
    r = cat_model_validate(&m, in, 0, &rep, err, sizeof err);
    if (r != CAT_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        cat_model_free(&m);
        return CLI_USAGE;
    }
    printf("%s: %d meshes, %ld triangles, %ld degenerate, %ld non-manifold edges, %ld open "
           "edges; box %.1f x %.1f x %.1f mm\n",
           in, m.mesh_count, rep.triangles, rep.degenerate_triangles, rep.non_manifold_edges,
           rep.open_edges, (double)(m.bounds_max[0] - m.bounds_min[0]),
           (double)(m.bounds_max[1] - m.bounds_min[1]),
           (double)(m.bounds_max[2] - m.bounds_min[2]));
    int rc = CLI_OK;
    if (out) {
        cat_model lod;
        double t0 = cli_now_ms();
        r = cat_model_make_lod(&m, (float)fraction, &lod, err, sizeof err);
        double ms = cli_now_ms() - t0;
        if (r == CAT_OK)
            r = cat_model_write_glb(out, &lod, NULL, err, sizeof err);
        if (r != CAT_OK) {
            fprintf(stderr, "tessera: %s\n", err);
            rc = r == CAT_ERR_IO ? CLI_FAILED : CLI_USAGE;
        } else {
            printf("%s: level of detail at %g: %ld triangles in %.1f ms; box %.1f x %.1f x %.1f "
                   "mm\n",
                   out, fraction, cat_model_triangle_count(&lod), ms,
                   (double)(lod.bounds_max[0] - lod.bounds_min[0]),
                   (double)(lod.bounds_max[1] - lod.bounds_min[1]),
                   (double)(lod.bounds_max[2] - lod.bounds_min[2]));
        }
        cat_model_free(&lod);
    }
    cat_model_free(&m);
    return rc;
}
