/* tessera catalog model ARTICLE [--manufacturer M] [-o OUT.glb] [--db PATH]: exports one
 * product's 3D model as GLB, generated from its catalog row by the same generators the build
 * uses for the shipped models (catalog/model_gen.h), with the first variant's material. Lets a
 * user open a product in any glTF viewer; the build's own copies live in cat_models_dir(). */
#include "catalog/catalog.h"
#include "catalog/model_gen.h"
#include "catalog/model_write.h"
#include "cli_commands.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

int cli_cmd_catalog_model(const cli_options *o)
{
    const char *article = o->project, *maker = o->manufacturer, *out = o->output, *db_path = o->db,
               *variant = o->variant;
    char path[4096], src[4096], err[4096];
    if (db_path)
        snprintf(path, sizeof path, "%s", db_path);
    else if (!cat_default_path(path, sizeof path)) {
        fprintf(stderr, "tessera catalog model: no place for the catalog: set TESSERA_CATALOG "
                        "or HOME, or give --db PATH\n");
        return CLI_FAILED;
    }
    const char *assets = getenv("TESSERA_ASSETS");
    snprintf(src, sizeof src, "%s/catalog",
             assets && *assets ? assets : TESSERA_SOURCE_DIR "/assets");
    cat_db *db = NULL;
    if (cat_catalog_open(path, src, &db, err, sizeof err) != CAT_DB_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        return CLI_FAILED;
    }
    cat_product p;
    cat_db_result r = cat_product_find(db, maker, article, &p, err, sizeof err);
    cat_db_close(db);
    if (r != CAT_DB_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        return r == CAT_DB_ERR_NOT_FOUND || r == CAT_DB_ERR_AMBIGUOUS ? CLI_USAGE : CLI_FAILED;
    }
    int rc = CLI_OK;
    char def[CAT_PATH_BYTES + 1];
    if (!out) {
        if (!cat_model_file_name(p.manufacturer, p.article, def, sizeof def)) {
            fprintf(stderr, "tessera catalog model: no file name for %s; give -o\n", p.article);
            cat_product_free(&p);
            return CLI_USAGE;
        }
        out = strrchr(def, '/') + 1;
    }
    const cat_render_material *finish = p.variant_count ? &p.variants[0].material : NULL;
    if (variant) {
        finish = NULL;
        for (int v = 0; v < p.variant_count; v++)
            if (!strcasecmp(p.variants[v].code, variant))
                finish = &p.variants[v].material;
        if (!finish) {
            fprintf(stderr, "tessera catalog model: %s %s has no variant \"%s\"\n", p.manufacturer,
                    p.article, variant);
            cat_product_free(&p);
            return CLI_USAGE;
        }
    }
    cat_gen_request req = {p.category, p.name,      p.series, p.width_mm,
                           p.depth_mm, p.height_mm, finish};
    cat_gen_model gm;
    cat_result g = cat_gen_product(&req, &gm, err, sizeof err);
    if (g != CAT_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        rc = g == CAT_ERR_UNSUPPORTED ? CLI_USAGE : CLI_FAILED;
    } else if (cat_model_write_glb(out, &gm.model, gm.extras, err, sizeof err) != CAT_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        rc = CLI_FAILED;
    } else {
        long vertices = 0;
        for (int i = 0; i < gm.model.mesh_count; i++)
            vertices += gm.model.meshes[i].vertex_count;
        printf("%s: %s %s, %d parts, %ld vertices, %g x %g x %g mm\n", out, p.manufacturer,
               p.article, gm.model.mesh_count, vertices, p.width_mm, p.depth_mm, p.height_mm);
    }
    cat_gen_model_free(&gm);
    cat_product_free(&p);
    return rc;
}
