/* Reading one product with its variants and tile data, by row id or by article number / GTIN. */
#include "db_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void catdb_copy_text(char *dst, size_t size, const unsigned char *src)
{
    snprintf(dst, size, "%s", src ? (const char *)src : "");
}

void cat_product_free(cat_product *p)
{
    if (!p)
        return;
    free(p->variants);
    memset(p, 0, sizeof *p);
}

#define TEXT(st, i, field) catdb_copy_text(field, sizeof field, sqlite3_column_text(st, i))

static const char product_sql[] =
    "SELECT p.id, m.name, p.article, p.gtin, p.category, coalesce(s.name, ''), p.name, "
    "p.short_text, p.long_text, p.width_mm, p.depth_mm, p.height_mm, p.price_cents, "
    "p.vat_percent, p.currency, p.unit, p.discount_group, p.model, p.origin, "
    "p.mounting_height_mm, p.mounting_to, p.companions "
    "FROM products p JOIN manufacturers m ON m.id = p.manufacturer_id "
    "LEFT JOIN series s ON s.id = p.series_id WHERE p.id = ?1";

static const char variants_sql[] =
    "SELECT code, name, surcharge_cents, ambient_r, ambient_g, ambient_b, diffuse_r, diffuse_g, "
    "diffuse_b, specular_r, specular_g, specular_b, emissive_r, emissive_g, emissive_b, "
    "shininess, reflectivity, glossiness, blend, transparency, ior, pattern, grain_deg "
    "FROM variants WHERE product_id = ?1 ORDER BY code";

static const char tile_sql[] =
    "SELECT type, nominal_w_mm, nominal_h_mm, work_w_mm, work_h_mm, grout_mm, thickness_mm, "
    "calibre, surface, m2_per_box, pieces_per_box, texture FROM tiles WHERE product_id = ?1";

static void read_product(sqlite3_stmt *st, cat_product *p)
{
    p->id = sqlite3_column_int64(st, 0);
    TEXT(st, 1, p->manufacturer);
    TEXT(st, 2, p->article);
    TEXT(st, 3, p->gtin);
    const char *cat = (const char *)sqlite3_column_text(st, 4);
    if (!cat || !cat_category_parse(cat, &p->category))
        p->category = CAT_CATEGORY_ANY;
    TEXT(st, 5, p->series);
    TEXT(st, 6, p->name);
    TEXT(st, 7, p->short_text);
    TEXT(st, 8, p->long_text);
    p->width_mm = sqlite3_column_double(st, 9);
    p->depth_mm = sqlite3_column_double(st, 10);
    p->height_mm = sqlite3_column_double(st, 11);
    p->price_cents = sqlite3_column_int64(st, 12);
    p->vat_percent = sqlite3_column_double(st, 13);
    TEXT(st, 14, p->currency);
    const char *unit = (const char *)sqlite3_column_text(st, 15);
    if (!unit || !cat_unit_parse(unit, &p->unit))
        p->unit = CAT_UNIT_PIECE;
    TEXT(st, 16, p->discount_group);
    TEXT(st, 17, p->model);
    const char *origin = (const char *)sqlite3_column_text(st, 18);
    p->shipped = origin && !strcmp(origin, CATDB_ORIGIN_SHIPPED);
    const char *to = (const char *)sqlite3_column_text(st, 20);
    if (sqlite3_column_type(st, 19) != SQLITE_NULL && to && cat_mount_to_parse(to, &p->mounting_to))
        p->mounting_height_mm = sqlite3_column_double(st, 19);
    TEXT(st, 21, p->companions);
}

static void read_variant(sqlite3_stmt *st, cat_variant *v)
{
    TEXT(st, 0, v->code);
    TEXT(st, 1, v->name);
    v->surcharge_cents = sqlite3_column_int64(st, 2);
    cat_render_material *m = &v->material;
    float *rgb[4] = {m->ambient, m->diffuse, m->specular, m->emissive};
    for (int k = 0; k < 4; k++)
        for (int i = 0; i < 3; i++)
            rgb[k][i] = (float)sqlite3_column_double(st, 3 + 3 * k + i);
    m->shininess = (float)sqlite3_column_double(st, 15);
    m->reflectivity = (float)sqlite3_column_double(st, 16);
    m->glossiness = (float)sqlite3_column_double(st, 17);
    const char *blend = (const char *)sqlite3_column_text(st, 18);
    if (!blend || !cat_blend_parse(blend, &m->blend))
        m->blend = CAT_BLEND_MIX;
    m->transparency = (float)sqlite3_column_double(st, 19);
    m->ior = (float)sqlite3_column_double(st, 20);
    const char *pattern = (const char *)sqlite3_column_text(st, 21);
    if (!pattern || !cat_pattern_parse(pattern, &m->pattern))
        m->pattern = CAT_PATTERN_NONE;
    m->grain_deg = sqlite3_column_type(st, 22) == SQLITE_NULL
                       ? CAT_GRAIN_LONG
                       : (float)sqlite3_column_double(st, 22);
}

static void read_tile(sqlite3_stmt *st, cat_tile *t)
{
    const char *type = (const char *)sqlite3_column_text(st, 0);
    if (!type || !cat_tile_type_parse(type, &t->type))
        t->type = CAT_TILE_UNI;
    t->nominal_w_mm = sqlite3_column_double(st, 1);
    t->nominal_h_mm = sqlite3_column_double(st, 2);
    t->work_w_mm = sqlite3_column_double(st, 3);
    t->work_h_mm = sqlite3_column_double(st, 4);
    t->grout_mm = sqlite3_column_double(st, 5);
    t->thickness_mm = sqlite3_column_double(st, 6);
    TEXT(st, 7, t->calibre);
    const char *surface = (const char *)sqlite3_column_text(st, 8);
    if (!surface || !cat_surface_parse(surface, &t->surface))
        t->surface = CAT_SURFACE_GLOSSY;
    t->m2_per_box = sqlite3_column_double(st, 9);
    t->pieces_per_box = sqlite3_column_int(st, 10);
    TEXT(st, 11, t->texture);
}

cat_db_result catdb_product_load(sqlite3 *sql, const char *path, long long id, cat_product *out,
                                 char *err, size_t err_size)
{
    memset(out, 0, sizeof *out);
    sqlite3_stmt *st = NULL;
    cat_db_result r = CAT_DB_OK;
    int rc = sqlite3_prepare_v2(sql, product_sql, -1, &st, NULL);
    if (rc == SQLITE_OK) {
        sqlite3_bind_int64(st, 1, id);
        rc = sqlite3_step(st);
    }
    if (rc == SQLITE_ROW)
        read_product(st, out);
    else if (rc == SQLITE_DONE)
        r = catdb_fail(err, err_size, CAT_DB_ERR_NOT_FOUND, "%s: no product with id %lld", path,
                       id);
    else
        r = catdb_sql_fail(sql, path, err, err_size, "cannot read the product");
    sqlite3_finalize(st);
    st = NULL;

    int cap = 0;
    if (r == CAT_DB_OK && sqlite3_prepare_v2(sql, variants_sql, -1, &st, NULL) == SQLITE_OK) {
        sqlite3_bind_int64(st, 1, id);
        while ((rc = sqlite3_step(st)) == SQLITE_ROW) {
            if (out->variant_count == cap) {
                int ncap = cap ? cap * 2 : 4;
                cat_variant *v = realloc(out->variants, (size_t)ncap * sizeof *v);
                if (!v) {
                    r = catdb_fail(err, err_size, CAT_DB_ERR_OUT_OF_MEMORY, "%s: out of memory",
                                   path);
                    break;
                }
                out->variants = v;
                cap = ncap;
            }
            cat_variant *v = &out->variants[out->variant_count++];
            memset(v, 0, sizeof *v);
            read_variant(st, v);
        }
        if (r == CAT_DB_OK && rc != SQLITE_DONE)
            r = catdb_sql_fail(sql, path, err, err_size, "cannot read the variants");
    } else if (r == CAT_DB_OK) {
        r = catdb_sql_fail(sql, path, err, err_size, "cannot read the variants");
    }
    sqlite3_finalize(st);
    st = NULL;

    if (r == CAT_DB_OK && sqlite3_prepare_v2(sql, tile_sql, -1, &st, NULL) == SQLITE_OK) {
        sqlite3_bind_int64(st, 1, id);
        rc = sqlite3_step(st);
        if (rc == SQLITE_ROW) {
            out->has_tile = 1;
            read_tile(st, &out->tile);
        } else if (rc != SQLITE_DONE) {
            r = catdb_sql_fail(sql, path, err, err_size, "cannot read the tile data");
        }
    } else if (r == CAT_DB_OK) {
        r = catdb_sql_fail(sql, path, err, err_size, "cannot read the tile data");
    }
    sqlite3_finalize(st);
    if (r != CAT_DB_OK)
        cat_product_free(out);
    return r;
}

cat_db_result cat_product_get(cat_db *db, long long id, cat_product *out, char *err,
                              size_t err_size)
{
    if (!db || !out)
        return catdb_fail(err, err_size, CAT_DB_ERR_INVALID, "cat_product_get: no catalog");
    catdb_recover(db);
    return catdb_product_load(db->sql, db->path, id, out, err, err_size);
}

cat_db_result cat_product_find(cat_db *db, const char *manufacturer, const char *article,
                               cat_product *out, char *err, size_t err_size)
{
    if (out)
        memset(out, 0, sizeof *out);
    if (!db || !out || !article)
        return catdb_fail(err, err_size, CAT_DB_ERR_INVALID, "cat_product_find: no catalog");
    catdb_recover(db);
    int any = !manufacturer || !*manufacturer;
    sqlite3_stmt *st = NULL;
    /* Article numbers first, then GTINs; at most a few rows either way. */
    int rc = sqlite3_prepare_v2(
        db->sql,
        "SELECT p.id, m.name FROM products p JOIN manufacturers m ON m.id = p.manufacturer_id "
        "WHERE (p.article = ?1 OR p.gtin = ?1) AND (?2 IS NULL OR m.name = ?2) "
        "ORDER BY p.article = ?1 DESC, m.name LIMIT 8",
        -1, &st, NULL);
    if (rc != SQLITE_OK) {
        sqlite3_finalize(st);
        return catdb_sql_fail(db->sql, db->path, err, err_size, "cannot look the product up");
    }
    sqlite3_bind_text(st, 1, article, -1, SQLITE_STATIC);
    if (!any)
        sqlite3_bind_text(st, 2, manufacturer, -1, SQLITE_STATIC);
    long long ids[8];
    char names[8][CAT_MANUFACTURER_BYTES + 1];
    int n = 0;
    while (n < 8 && (rc = sqlite3_step(st)) == SQLITE_ROW) {
        ids[n] = sqlite3_column_int64(st, 0);
        catdb_copy_text(names[n], sizeof names[n], sqlite3_column_text(st, 1));
        n++;
    }
    if (n < 8 && rc != SQLITE_DONE) {
        sqlite3_finalize(st);
        return catdb_sql_fail(db->sql, db->path, err, err_size, "cannot look the product up");
    }
    sqlite3_finalize(st);
    if (n == 0) {
        if (any)
            return catdb_fail(err, err_size, CAT_DB_ERR_NOT_FOUND,
                              "%s: no product with article number or GTIN \"%.64s\"", db->path,
                              article);
        return catdb_fail(err, err_size, CAT_DB_ERR_NOT_FOUND,
                          "%s: no product with article number or GTIN \"%.64s\" at \"%.64s\"",
                          db->path, article, manufacturer);
    }
    if (n > 1 && ids[0] != ids[1]) {
        char list[600] = "";
        for (int i = 0; i < n; i++) {
            size_t len = strlen(list);
            snprintf(list + len, sizeof list - len, "%s%s", i ? ", " : "", names[i]);
        }
        return catdb_fail(err, err_size, CAT_DB_ERR_AMBIGUOUS,
                          "%s: article number \"%.64s\" exists at %d manufacturers (%s): name "
                          "one",
                          db->path, article, n, list);
    }
    return catdb_product_load(db->sql, db->path, ids[0], out, err, err_size);
}
