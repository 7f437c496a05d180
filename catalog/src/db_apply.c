/* Writing checked import rows: manufacturers and series on first sight, products inserted or
 * updated (keyed by manufacturer + article number), their variants and tile data. */
#include "db_internal.h"

#include <stdio.h>
#include <string.h>

static const char insert_product_sql[] =
    "INSERT INTO products (manufacturer_id, series_id, article, gtin, category, name, "
    "short_text, long_text, width_mm, depth_mm, height_mm, price_cents, vat_percent, currency, "
    "unit, discount_group, model, origin, mounting_height_mm, mounting_to, companions) "
    "VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14, ?15, ?16, ?17, ?18, "
    "?21, coalesce(?22, ''), coalesce(?23, ''))";

/* Same parameter numbers as the insert; a NULL parameter keeps the stored value (series:
 * ?19 says whether ?2 applies, since NULL is a valid series). */
static const char update_product_sql[] =
    "UPDATE products SET "
    "series_id = CASE WHEN ?19 THEN ?2 ELSE series_id END, article = ?3, "
    "gtin = coalesce(?4, gtin), category = coalesce(?5, category), name = coalesce(?6, name), "
    "short_text = coalesce(?7, short_text), long_text = coalesce(?8, long_text), "
    "width_mm = coalesce(?9, width_mm), depth_mm = coalesce(?10, depth_mm), "
    "height_mm = coalesce(?11, height_mm), price_cents = coalesce(?12, price_cents), "
    "vat_percent = coalesce(?13, vat_percent), currency = coalesce(?14, currency), "
    "unit = coalesce(?15, unit), discount_group = coalesce(?16, discount_group), "
    "model = coalesce(?17, model), origin = ?18, "
    "mounting_height_mm = CASE WHEN ?22 IS NULL THEN mounting_height_mm ELSE ?21 END, "
    "mounting_to = coalesce(?22, mounting_to), companions = coalesce(?23, companions) "
    "WHERE id = ?20";

static const char insert_variant_sql[] =
    "INSERT INTO variants (product_id, code, name, surcharge_cents, "
    "ambient_r, ambient_g, ambient_b, diffuse_r, diffuse_g, diffuse_b, "
    "specular_r, specular_g, specular_b, emissive_r, emissive_g, emissive_b, "
    "shininess, reflectivity, glossiness, blend, transparency, ior, pattern, grain_deg) "
    "VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14, ?15, ?16, ?17, ?18, "
    "?19, ?20, ?21, ?22, ?23, ?24)";

static const char upsert_tile_sql[] =
    "INSERT OR REPLACE INTO tiles (product_id, type, nominal_w_mm, nominal_h_mm, work_w_mm, "
    "work_h_mm, grout_mm, thickness_mm, calibre, surface, m2_per_box, pieces_per_box, texture) "
    "VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13)";

static int prepare(sqlite3 *sql, const char *text, sqlite3_stmt **st)
{
    return sqlite3_prepare_v3(sql, text, -1, SQLITE_PREPARE_PERSISTENT, st, NULL) == SQLITE_OK;
}

static cat_db_result sql_problem(sqlite3 *sql, const char *what, char *msg, size_t msg_size)
{
    snprintf(msg, msg_size, "%s: %s", what, sqlite3_errmsg(sql));
    cat_db_result r = catdb_result_of(sqlite3_extended_errcode(sql));
    return r == CAT_DB_OK ? CAT_DB_ERR_DATABASE : r;
}

cat_db_result catdb_apply_prepare(catdb_apply *a, sqlite3 *sql, const char *origin,
                                  const unsigned char *header_has, char *msg, size_t msg_size)
{
    memset(a, 0, sizeof *a);
    a->sql = sql;
    a->origin = origin;
    a->header_has = header_has;
    int ok = prepare(sql,
                     "SELECT p.id, p.category, p.origin FROM products p JOIN manufacturers m ON "
                     "m.id = p.manufacturer_id WHERE m.name = ?1 AND p.article = ?2",
                     &a->find_product) &&
             prepare(sql, "SELECT id FROM manufacturers WHERE name = ?1", &a->find_manufacturer) &&
             prepare(sql, "INSERT INTO manufacturers (name) VALUES (?1)", &a->add_manufacturer) &&
             prepare(sql, "SELECT id FROM series WHERE manufacturer_id = ?1 AND name = ?2",
                     &a->find_series) &&
             prepare(sql, "INSERT INTO series (manufacturer_id, name) VALUES (?1, ?2)",
                     &a->add_series) &&
             prepare(sql, insert_product_sql, &a->insert_product) &&
             prepare(sql, update_product_sql, &a->update_product) &&
             prepare(sql, "DELETE FROM variants WHERE product_id = ?1", &a->delete_variants) &&
             prepare(sql, insert_variant_sql, &a->insert_variant) &&
             prepare(sql, upsert_tile_sql, &a->upsert_tile) &&
             prepare(sql, "DELETE FROM tiles WHERE product_id = ?1", &a->delete_tile);
    if (!ok) {
        cat_db_result r = sql_problem(sql, "cannot prepare the import", msg, msg_size);
        catdb_apply_finish(a);
        return r;
    }
    return CAT_DB_OK;
}

void catdb_apply_finish(catdb_apply *a)
{
    sqlite3_stmt **all[] = {&a->find_product,   &a->find_manufacturer, &a->add_manufacturer,
                            &a->find_series,    &a->add_series,        &a->insert_product,
                            &a->update_product, &a->delete_variants,   &a->insert_variant,
                            &a->upsert_tile,    &a->delete_tile};
    for (size_t i = 0; i < sizeof all / sizeof all[0]; i++) {
        sqlite3_finalize(*all[i]);
        *all[i] = NULL;
    }
}

/* Runs a statement that returns nothing (or whose rows are not wanted) and resets it. */
static int run(sqlite3_stmt *st)
{
    int rc = sqlite3_step(st);
    sqlite3_reset(st);
    sqlite3_clear_bindings(st);
    return rc == SQLITE_DONE || rc == SQLITE_ROW;
}

/* The id of the first row of a one-column query, 0 when there is none, -1 on failure. */
static long long query_id(sqlite3_stmt *st)
{
    int rc = sqlite3_step(st);
    long long id = rc == SQLITE_ROW ? sqlite3_column_int64(st, 0) : rc == SQLITE_DONE ? 0 : -1;
    sqlite3_reset(st);
    sqlite3_clear_bindings(st);
    return id;
}

cat_db_result catdb_apply_lookup(catdb_apply *a, const char *manufacturer, const char *article,
                                 catdb_existing *out, char *msg, size_t msg_size)
{
    memset(out, 0, sizeof *out);
    sqlite3_stmt *st = a->find_product;
    sqlite3_bind_text(st, 1, manufacturer, -1, SQLITE_STATIC);
    sqlite3_bind_text(st, 2, article, -1, SQLITE_STATIC);
    int rc = sqlite3_step(st);
    if (rc == SQLITE_ROW) {
        out->id = sqlite3_column_int64(st, 0);
        const char *cat = (const char *)sqlite3_column_text(st, 1);
        if (!cat || !cat_category_parse(cat, &out->category))
            out->category = CAT_CATEGORY_ANY;
        const char *origin = (const char *)sqlite3_column_text(st, 2);
        out->from_import = origin && !strcmp(origin, CATDB_ORIGIN_IMPORT);
    }
    cat_db_result r = rc == SQLITE_ROW || rc == SQLITE_DONE
                          ? CAT_DB_OK
                          : sql_problem(a->sql, "cannot look the product up", msg, msg_size);
    sqlite3_reset(st);
    sqlite3_clear_bindings(st);
    return r;
}

static long long manufacturer_id(catdb_apply *a, const char *name)
{
    if (a->last_manufacturer_id > 0 && !strcmp(a->last_manufacturer, name))
        return a->last_manufacturer_id;
    sqlite3_bind_text(a->find_manufacturer, 1, name, -1, SQLITE_STATIC);
    long long id = query_id(a->find_manufacturer);
    if (id == 0) {
        sqlite3_bind_text(a->add_manufacturer, 1, name, -1, SQLITE_STATIC);
        id = run(a->add_manufacturer) ? sqlite3_last_insert_rowid(a->sql) : -1;
    }
    if (id > 0) {
        a->last_manufacturer_id = id;
        snprintf(a->last_manufacturer, sizeof a->last_manufacturer, "%s", name);
    }
    return id;
}

static long long series_id(catdb_apply *a, long long manufacturer, const char *name)
{
    sqlite3_bind_int64(a->find_series, 1, manufacturer);
    sqlite3_bind_text(a->find_series, 2, name, -1, SQLITE_STATIC);
    long long id = query_id(a->find_series);
    if (id == 0) {
        sqlite3_bind_int64(a->add_series, 1, manufacturer);
        sqlite3_bind_text(a->add_series, 2, name, -1, SQLITE_STATIC);
        id = run(a->add_series) ? sqlite3_last_insert_rowid(a->sql) : -1;
    }
    return id;
}

static void bind_product(catdb_apply *a, sqlite3_stmt *st, const catdb_row *row, int update)
{
    const cat_product *p = &row->product;
    const unsigned char *has = a->header_has;
    /* On update, a column the file does not have stays NULL, which keeps the stored value. */
#define SET(col) (!update || has[col])
    if (SET(COL_GTIN))
        sqlite3_bind_text(st, 4, p->gtin, -1, SQLITE_STATIC);
    if (SET(COL_CATEGORY) && row->given[COL_CATEGORY])
        sqlite3_bind_text(st, 5, cat_category_name(p->category), -1, SQLITE_STATIC);
    if (SET(COL_NAME) && row->given[COL_NAME])
        sqlite3_bind_text(st, 6, p->name, -1, SQLITE_STATIC);
    if (SET(COL_SHORT_TEXT))
        sqlite3_bind_text(st, 7, p->short_text, -1, SQLITE_STATIC);
    if (SET(COL_LONG_TEXT))
        sqlite3_bind_text(st, 8, p->long_text, -1, SQLITE_STATIC);
    const int dims[3] = {COL_WIDTH, COL_DEPTH, COL_HEIGHT};
    const double dim_values[3] = {p->width_mm, p->depth_mm, p->height_mm};
    for (int i = 0; i < 3; i++)
        if (row->given[dims[i]] || (row->dims_from_tile & 1 << i))
            sqlite3_bind_double(st, 9 + i, dim_values[i]);
    if (SET(COL_LIST_PRICE) && row->given[COL_LIST_PRICE])
        sqlite3_bind_int64(st, 12, p->price_cents);
    if (SET(COL_VAT))
        sqlite3_bind_double(st, 13, p->vat_percent);
    if (SET(COL_CURRENCY))
        sqlite3_bind_text(st, 14, p->currency, -1, SQLITE_STATIC);
    if (SET(COL_UNIT))
        sqlite3_bind_text(st, 15, cat_unit_name(p->unit), -1, SQLITE_STATIC);
    if (SET(COL_DISCOUNT_GROUP))
        sqlite3_bind_text(st, 16, p->discount_group, -1, SQLITE_STATIC);
    if (SET(COL_MODEL))
        sqlite3_bind_text(st, 17, p->model, -1, SQLITE_STATIC);
    /* A height and its reference are given together (db_row.c); an update without them keeps
     * the stored pair. */
    if (row->given[COL_MOUNTING_HEIGHT] && row->given[COL_MOUNTING_TO]) {
        sqlite3_bind_double(st, 21, p->mounting_height_mm);
        sqlite3_bind_text(st, 22, cat_mount_to_name(p->mounting_to), -1, SQLITE_STATIC);
    }
    if (SET(COL_COMPANIONS))
        sqlite3_bind_text(st, 23, p->companions, -1, SQLITE_STATIC);
#undef SET
    sqlite3_bind_text(st, 3, p->article, -1, SQLITE_STATIC);
    sqlite3_bind_text(st, 18, a->origin, -1, SQLITE_STATIC);
}

static int insert_variant(catdb_apply *a, long long product, const catdb_row *row)
{
    sqlite3_stmt *st = a->insert_variant;
    const cat_variant *v = &row->variant;
    sqlite3_bind_int64(st, 1, product);
    sqlite3_bind_text(st, 2, v->code, -1, SQLITE_STATIC);
    sqlite3_bind_text(st, 3, v->name, -1, SQLITE_STATIC);
    sqlite3_bind_int64(st, 4, v->surcharge_cents);
    /* ambient .. emissive, shininess, k_r, g: parameters 5 .. 19 in the order of row->material */
    for (int i = 0; i <= CATDB_M_GLOSSINESS; i++)
        sqlite3_bind_double(st, 5 + i, row->material[i]);
    sqlite3_bind_text(st, 20, cat_blend_name(v->material.blend), -1, SQLITE_STATIC);
    sqlite3_bind_double(st, 21, row->material[CATDB_M_TRANSPARENCY]);
    sqlite3_bind_double(st, 22, row->material[CATDB_M_IOR]);
    sqlite3_bind_text(st, 23, cat_pattern_name(v->material.pattern), -1, SQLITE_STATIC);
    if (row->material[CATDB_M_GRAIN] >= 0.0) /* NULL: along the longer side */
        sqlite3_bind_double(st, 24, row->material[CATDB_M_GRAIN]);
    else
        sqlite3_bind_null(st, 24);
    return run(st);
}

static int upsert_tile(catdb_apply *a, long long product, const cat_tile *t)
{
    sqlite3_stmt *st = a->upsert_tile;
    sqlite3_bind_int64(st, 1, product);
    sqlite3_bind_text(st, 2, cat_tile_type_name(t->type), -1, SQLITE_STATIC);
    sqlite3_bind_double(st, 3, t->nominal_w_mm);
    sqlite3_bind_double(st, 4, t->nominal_h_mm);
    sqlite3_bind_double(st, 5, t->work_w_mm);
    sqlite3_bind_double(st, 6, t->work_h_mm);
    sqlite3_bind_double(st, 7, t->grout_mm);
    sqlite3_bind_double(st, 8, t->thickness_mm);
    sqlite3_bind_text(st, 9, t->calibre, -1, SQLITE_STATIC);
    sqlite3_bind_text(st, 10, cat_surface_name(t->surface), -1, SQLITE_STATIC);
    sqlite3_bind_double(st, 11, t->m2_per_box);
    sqlite3_bind_int(st, 12, t->pieces_per_box);
    sqlite3_bind_text(st, 13, t->texture, -1, SQLITE_STATIC);
    return run(st);
}

cat_db_result catdb_apply_row(catdb_apply *a, const catdb_row *row, const catdb_existing *ex,
                              int first_of_product, long long *product_id, char *msg,
                              size_t msg_size)
{
    const cat_product *p = &row->product;
    const unsigned char *has = a->header_has;
    long long mid = manufacturer_id(a, p->manufacturer);
    if (mid <= 0)
        return sql_problem(a->sql, "cannot add the manufacturer", msg, msg_size);
    long long sid = 0;
    if (has[COL_SERIES] && p->series[0]) {
        sid = series_id(a, mid, p->series);
        if (sid <= 0)
            return sql_problem(a->sql, "cannot add the series", msg, msg_size);
    }
    sqlite3_stmt *st = ex->id ? a->update_product : a->insert_product;
    bind_product(a, st, row, ex->id != 0);
    sqlite3_bind_int64(st, 1, mid);
    if (sid)
        sqlite3_bind_int64(st, 2, sid);
    if (ex->id) {
        sqlite3_bind_int(st, 19, has[COL_SERIES]);
        sqlite3_bind_int64(st, 20, ex->id);
    }
    if (!run(st))
        return sql_problem(a->sql, ex->id ? "cannot update the product" : "cannot add the product",
                           msg, msg_size);
    long long id = ex->id ? ex->id : sqlite3_last_insert_rowid(a->sql);
    *product_id = id;

    if (has[COL_VARIANT_CODE]) {
        if (first_of_product) {
            sqlite3_bind_int64(a->delete_variants, 1, id);
            if (!run(a->delete_variants))
                return sql_problem(a->sql, "cannot replace the variants", msg, msg_size);
        }
        if (row->has_variant && !insert_variant(a, id, row))
            return sql_problem(a->sql, "cannot add the variant", msg, msg_size);
    }
    cat_category category = row->given[COL_CATEGORY] ? p->category : ex->category;
    int tile = category == CAT_CATEGORY_TILES;
    if (tile && row->has_tile) {
        if (!upsert_tile(a, id, &row->tile))
            return sql_problem(a->sql, "cannot write the tile data", msg, msg_size);
    } else if (!tile && ex->id && ex->category == CAT_CATEGORY_TILES) {
        sqlite3_bind_int64(a->delete_tile, 1, id);
        if (!run(a->delete_tile))
            return sql_problem(a->sql, "cannot remove the tile data", msg, msg_size);
    }
    return CAT_DB_OK;
}
