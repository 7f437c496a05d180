/* The product lookup of the placement checks and edit scripts, backed by the SQLite catalog
 * (catalog/catalog.h), and opening that catalog for the CLI. */
#include "app/design/placement.h"

#include "catalog/catalog.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef TESSERA_SOURCE_DIR
#define TESSERA_SOURCE_DIR "."
#endif

const char *app_placement_assets_dir(void)
{
    const char *env = getenv("TESSERA_ASSETS");
    return env && *env ? env : TESSERA_SOURCE_DIR "/assets";
}

app_result app_placement_open_catalog(const char *db_path, struct cat_db **out, char *err,
                                      size_t err_size)
{
    char path[4096], src[4096];
    *out = NULL;
    if (db_path)
        snprintf(path, sizeof path, "%s", db_path);
    else if (!cat_default_path(path, sizeof path)) {
        snprintf(err, err_size, "no place for the catalog: set TESSERA_CATALOG or HOME");
        return APP_ERR_IO;
    }
    snprintf(src, sizeof src, "%s/catalog", app_placement_assets_dir());
    cat_db_result r = cat_catalog_open(path, src, out, err, err_size);
    return r == CAT_DB_OK                  ? APP_OK
           : r == CAT_DB_ERR_OUT_OF_MEMORY ? APP_ERR_OUT_OF_MEMORY
                                           : APP_ERR_IO;
}

static void copy3(float dst[3], const float src[3])
{
    memcpy(dst, src, 3 * sizeof *dst);
}

app_result app_placement_catalog_lookup(void *user, const app_product_ref *ref,
                                        app_product_info *out, char *err, size_t err_size)
{
    cat_db *db = user;
    memset(out, 0, sizeof *out);
    if (!db) {
        if (err && err_size)
            snprintf(err, err_size, "no catalog open");
        return APP_ERR_NOT_FOUND;
    }
    cat_product prod;
    cat_db_result r = cat_product_find(db, ref->manufacturer, ref->article, &prod, err, err_size);
    if (r != CAT_DB_OK)
        return r == CAT_DB_ERR_NOT_FOUND || r == CAT_DB_ERR_AMBIGUOUS ? APP_ERR_NOT_FOUND
                                                                      : APP_ERR_IO;
    const cat_variant *v = prod.variant_count > 0 && !ref->variant[0] ? &prod.variants[0] : NULL;
    for (int i = 0; i < prod.variant_count && !v; i++)
        if (!strcmp(prod.variants[i].code, ref->variant))
            v = &prod.variants[i];
    if (ref->variant[0] && !v) {
        if (err && err_size) {
            int n =
                snprintf(err, err_size, "%s %s has no variant \"%s\" (it has:", prod.manufacturer,
                         prod.article, ref->variant);
            for (int i = 0; i < prod.variant_count && n > 0 && (size_t)n < err_size; i++)
                n += snprintf(err + n, err_size - (size_t)n, " %s", prod.variants[i].code);
            if (n > 0 && (size_t)n < err_size)
                snprintf(err + n, err_size - (size_t)n, ")");
        }
        cat_product_free(&prod);
        return APP_ERR_NOT_FOUND;
    }
    out->width_mm = prod.width_mm;
    out->depth_mm = prod.depth_mm;
    out->height_mm = prod.height_mm;
    out->category = (int)prod.category;
    snprintf(out->model, sizeof out->model, "%s", prod.model);
    if (prod.mounting_to != CAT_MOUNT_NONE) {
        out->has_mounting = 1;
        out->mounting_height_mm = prod.mounting_height_mm;
        out->mounting_of = prod.mounting_to == CAT_MOUNT_BOTTOM ? APP_MOUNT_BOTTOM : APP_MOUNT_TOP;
    }
    snprintf(out->companions, sizeof out->companions, "%s", prod.companions);
    if (v) {
        const cat_render_material *m = &v->material;
        out->has_material = 1;
        snprintf(out->variant, sizeof out->variant, "%.15s", v->code);
        copy3(out->ambient, m->ambient);
        copy3(out->diffuse, m->diffuse);
        copy3(out->specular, m->specular);
        copy3(out->emissive, m->emissive);
        out->shininess = m->shininess;
        out->reflectivity = m->reflectivity;
        out->glossiness = m->glossiness;
        out->transparency = m->transparency;
        out->ior = m->ior;
        /* cat_blend and APP_BLEND_* share the order mix, add, fresnel. */
        out->blend = (int)m->blend;
        out->pattern = m->pattern == CAT_PATTERN_WOOD ? APP_PATTERN_WOOD : APP_PATTERN_NONE;
        /* A front's grain runs along its long side unless the catalog says otherwise: the
         * width is the model's x, the height its z (the grain's 0 and 90 degrees). */
        out->grain_deg = out->pattern != APP_PATTERN_WOOD ? 0.0f
                         : m->grain_deg >= 0.0f           ? m->grain_deg
                         : prod.height_mm > prod.width_mm ? 90.0f
                                                          : 0.0f;
    }
    cat_product_free(&prod);
    return APP_OK;
}

app_result app_placement_lazy_lookup(void *user, const app_product_ref *ref, app_product_info *out,
                                     char *err, size_t err_size)
{
    app_lazy_catalog *l = user;
    if (!l->db && !l->failed &&
        app_placement_open_catalog(l->db_path, &l->db, l->err, sizeof l->err) != APP_OK)
        l->failed = 1;
    if (l->failed) {
        memset(out, 0, sizeof *out);
        snprintf(err, err_size, "%s", l->err);
        return APP_ERR_IO;
    }
    return app_placement_catalog_lookup(l->db, ref, out, err, err_size);
}

void app_placement_lazy_close(app_lazy_catalog *l)
{
    if (!l)
        return;
    cat_db_close(l->db);
    l->db = NULL;
}
