/* The catalog's schema as a chain of migrations: migrations[k] takes a database from version k
 * to k + 1 (PRAGMA user_version). A new catalog runs the whole chain from 0, so the chain is
 * exercised on every build of the file and an old file ends with exactly the same schema.
 * docs/catalog.md describes every table; a change of the schema adds a step here and bumps
 * CAT_DB_SCHEMA_VERSION, it never edits an old step. */
#include "db_internal.h"

#include <stdio.h>
#include <string.h>

#define CATEGORY_CHECK                                                                             \
    "category IN ('taps_mixers', 'shower_sets', 'basins', 'wcs_bidets', 'baths', "                 \
    "'shower_trays', 'shower_screens', 'mirrors', 'mirror_cabinets', 'lamps', "                    \
    "'towel_radiators', 'vanity_units', 'accessories', 'tiles')"

/* Version 1: manufacturers, series, products, variants with their render materials, tiles. */
static const char schema_v1[] =
    "PRAGMA application_id = 1413829459;\n" /* 0x54455353, 'TESS' */
    "CREATE TABLE meta (\n"
    "    key   TEXT PRIMARY KEY,\n"
    "    value TEXT NOT NULL\n"
    ");\n"
    "CREATE TABLE manufacturers (\n"
    "    id   INTEGER PRIMARY KEY,\n"
    "    name TEXT NOT NULL UNIQUE COLLATE NOCASE\n"
    ");\n"
    "CREATE TABLE series (\n"
    "    id              INTEGER PRIMARY KEY,\n"
    "    manufacturer_id INTEGER NOT NULL REFERENCES manufacturers(id),\n"
    "    name            TEXT NOT NULL COLLATE NOCASE,\n"
    "    UNIQUE (manufacturer_id, name)\n"
    ");\n"
    "CREATE TABLE products (\n"
    "    id              INTEGER PRIMARY KEY,\n"
    "    manufacturer_id INTEGER NOT NULL REFERENCES manufacturers(id),\n"
    "    series_id       INTEGER REFERENCES series(id),\n"
    "    article         TEXT NOT NULL COLLATE NOCASE,\n"
    "    gtin            TEXT NOT NULL DEFAULT '',\n"
    "    category        TEXT NOT NULL CHECK (" CATEGORY_CHECK "),\n"
    "    name            TEXT NOT NULL,\n"
    "    short_text      TEXT NOT NULL DEFAULT '',\n"
    "    long_text       TEXT NOT NULL DEFAULT '',\n"
    "    width_mm        REAL NOT NULL CHECK (width_mm > 0),\n"
    "    depth_mm        REAL NOT NULL CHECK (depth_mm > 0),\n"
    "    height_mm       REAL NOT NULL CHECK (height_mm > 0),\n"
    "    price_cents     INTEGER NOT NULL CHECK (price_cents > 0),\n"
    "    vat_percent     REAL NOT NULL DEFAULT 19 CHECK (vat_percent BETWEEN 0 AND 100),\n"
    "    currency        TEXT NOT NULL DEFAULT 'EUR',\n"
    "    unit            TEXT NOT NULL DEFAULT 'piece' CHECK (unit IN ('piece', 'm2', 'box')),\n"
    "    UNIQUE (manufacturer_id, article)\n"
    ");\n"
    "CREATE INDEX products_by_article ON products (article);\n"
    "CREATE INDEX products_by_gtin ON products (gtin);\n"
    "CREATE INDEX products_by_category ON products (category, width_mm);\n"
    "CREATE TABLE variants (\n"
    "    id              INTEGER PRIMARY KEY,\n"
    "    product_id      INTEGER NOT NULL REFERENCES products(id) ON DELETE CASCADE,\n"
    "    code            TEXT NOT NULL,\n"
    "    name            TEXT NOT NULL,\n"
    "    surcharge_cents INTEGER NOT NULL DEFAULT 0 CHECK (surcharge_cents >= 0),\n"
    "    ambient_r REAL NOT NULL, ambient_g REAL NOT NULL, ambient_b REAL NOT NULL,\n"
    "    diffuse_r REAL NOT NULL, diffuse_g REAL NOT NULL, diffuse_b REAL NOT NULL,\n"
    "    specular_r REAL NOT NULL, specular_g REAL NOT NULL, specular_b REAL NOT NULL,\n"
    "    emissive_r REAL NOT NULL, emissive_g REAL NOT NULL, emissive_b REAL NOT NULL,\n"
    "    shininess    REAL NOT NULL CHECK (shininess >= 0),\n"
    "    reflectivity REAL NOT NULL CHECK (reflectivity BETWEEN 0 AND 1),\n"
    "    glossiness   REAL NOT NULL CHECK (glossiness BETWEEN 0 AND 1),\n"
    "    blend        TEXT NOT NULL DEFAULT 'mix' CHECK (blend IN ('mix', 'add', 'fresnel')),\n"
    "    transparency REAL NOT NULL DEFAULT 0 CHECK (transparency BETWEEN 0 AND 1),\n"
    "    ior          REAL NOT NULL DEFAULT 1.5 CHECK (ior BETWEEN 1 AND 3),\n"
    "    UNIQUE (product_id, code)\n"
    ");\n"
    "CREATE TABLE tiles (\n"
    "    product_id     INTEGER PRIMARY KEY REFERENCES products(id) ON DELETE CASCADE,\n"
    "    type           TEXT NOT NULL CHECK (type IN ('UNI', 'BOR', 'DEK', 'EIN')),\n"
    "    nominal_w_mm   REAL NOT NULL CHECK (nominal_w_mm > 0),\n"
    "    nominal_h_mm   REAL NOT NULL CHECK (nominal_h_mm > 0),\n"
    "    work_w_mm      REAL NOT NULL CHECK (work_w_mm > 0),\n"
    "    work_h_mm      REAL NOT NULL CHECK (work_h_mm > 0),\n"
    "    grout_mm       REAL NOT NULL CHECK (grout_mm >= 0),\n"
    "    thickness_mm   REAL NOT NULL CHECK (thickness_mm > 0),\n"
    "    calibre        TEXT NOT NULL DEFAULT '',\n"
    "    surface        TEXT NOT NULL CHECK (surface IN ('glossy', 'matt', 'structured')),\n"
    "    m2_per_box     REAL NOT NULL CHECK (m2_per_box > 0),\n"
    "    pieces_per_box INTEGER NOT NULL CHECK (pieces_per_box > 0),\n"
    "    texture        TEXT NOT NULL DEFAULT ''\n"
    ");\n";

/* Version 2: discount groups (price lists quote them) and the product's 3D model. */
static const char schema_v2[] =
    "ALTER TABLE products ADD COLUMN discount_group TEXT NOT NULL DEFAULT '';\n"
    "ALTER TABLE products ADD COLUMN model TEXT NOT NULL DEFAULT '';\n";

/* SQL composed from macros reads better laid out by hand. */
/* clang-format off */
/* The article number without separators, so "hg3120" finds "HG-3120.00". */
#define COMPACT(x)                                                                                 \
    "replace(replace(replace(replace(replace(" x ", '-', ''), '.', ''), ' ', ''), '/', ''), "     \
    "'_', '')"
#define CATEGORY_WORDS(x) "replace(" x ", '_', ' ')"
#define FTS_COLUMNS "name, series, manufacturer, article, article_compact, short_text, category"

/* Removes product `p` (a table alias or old) from the index; the values must be exactly those
 * indexed, so the series and manufacturer names are passed in by the caller. */
#define FTS_DELETE(p, series, manufacturer)                                                        \
    "INSERT INTO product_fts (product_fts, rowid, " FTS_COLUMNS ") VALUES ('delete', " p          \
    ".id, " p ".name, " series ", " manufacturer ", " p ".article, " COMPACT(p ".article")         \
    ", " p ".short_text, " CATEGORY_WORDS(p ".category") ");\n"
#define FTS_INSERT(where)                                                                          \
    "INSERT INTO product_fts (rowid, " FTS_COLUMNS ") SELECT id, " FTS_COLUMNS                     \
    " FROM product_search WHERE " where ";\n"

/* Version 3: full-text search (an FTS5 index over a view of products, manufacturers and series,
 * kept in step by triggers), and which products came from users' imports. */
/* The triggers stand still while an import defers the index to one rebuild at its end. */
#define LIVE "NOT EXISTS (SELECT 1 FROM meta WHERE key = 'fts_deferred')"
#define OLD_SERIES "coalesce((SELECT name FROM series WHERE id = old.series_id), '')"
#define OLD_MANUFACTURER "(SELECT name FROM manufacturers WHERE id = old.manufacturer_id)"

static const char schema_v3[] =
    "ALTER TABLE products ADD COLUMN origin TEXT NOT NULL DEFAULT 'shipped'"
    " CHECK (origin IN ('shipped', 'import'));\n"
    "CREATE VIEW product_search AS\n"
    "    SELECT p.id AS id, p.name AS name, coalesce(s.name, '') AS series,\n"
    "           m.name AS manufacturer, p.article AS article,\n"
    "           " COMPACT("p.article") " AS article_compact,\n"
    "           p.short_text AS short_text, " CATEGORY_WORDS("p.category") " AS category\n"
    "    FROM products p JOIN manufacturers m ON m.id = p.manufacturer_id\n"
    "    LEFT JOIN series s ON s.id = p.series_id;\n"
    "CREATE VIRTUAL TABLE product_fts USING fts5 (" FTS_COLUMNS ",\n"
    "    content = 'product_search', content_rowid = 'id',\n"
    "    tokenize = 'unicode61 remove_diacritics 2', prefix = '2 3');\n"
    /* products */
    "CREATE TRIGGER products_fts_insert AFTER INSERT ON products WHEN " LIVE " BEGIN\n"
    FTS_INSERT("id = new.id")
    "END;\n"
    "CREATE TRIGGER products_fts_delete AFTER DELETE ON products WHEN " LIVE " BEGIN\n"
    FTS_DELETE("old", OLD_SERIES, OLD_MANUFACTURER)
    "END;\n"
    "CREATE TRIGGER products_fts_update AFTER UPDATE OF name, series_id, manufacturer_id, "
    "article, short_text, category ON products\n"
    "WHEN (old.name IS NOT new.name OR old.series_id IS NOT new.series_id\n"
    "  OR old.manufacturer_id IS NOT new.manufacturer_id OR old.article IS NOT new.article\n"
    "  OR old.short_text IS NOT new.short_text OR old.category IS NOT new.category)\n"
    "  AND " LIVE " BEGIN\n"
    FTS_DELETE("old", OLD_SERIES, OLD_MANUFACTURER)
    FTS_INSERT("id = new.id")
    "END;\n"
    /* renamed manufacturers and series */
    "CREATE TRIGGER manufacturers_fts_rename AFTER UPDATE OF name ON manufacturers\n"
    "WHEN " LIVE " BEGIN\n"
    "INSERT INTO product_fts (product_fts, rowid, " FTS_COLUMNS ")\n"
    "    SELECT 'delete', p.id, p.name, coalesce(s.name, ''), old.name, p.article,\n"
    "           " COMPACT("p.article") ", p.short_text, " CATEGORY_WORDS("p.category") "\n"
    "    FROM products p LEFT JOIN series s ON s.id = p.series_id\n"
    "    WHERE p.manufacturer_id = old.id;\n"
    FTS_INSERT("id IN (SELECT id FROM products WHERE manufacturer_id = new.id)")
    "END;\n"
    "CREATE TRIGGER series_fts_rename AFTER UPDATE OF name ON series WHEN " LIVE " BEGIN\n"
    "INSERT INTO product_fts (product_fts, rowid, " FTS_COLUMNS ")\n"
    "    SELECT 'delete', p.id, p.name, old.name, m.name, p.article,\n"
    "           " COMPACT("p.article") ", p.short_text, " CATEGORY_WORDS("p.category") "\n"
    "    FROM products p JOIN manufacturers m ON m.id = p.manufacturer_id\n"
    "    WHERE p.series_id = old.id;\n"
    FTS_INSERT("id IN (SELECT id FROM products WHERE series_id = new.id)")
    "END;\n"
    "INSERT INTO product_fts (product_fts) VALUES ('rebuild');\n"
    /* listing a category by name (search with an empty text) */
    "CREATE INDEX products_by_category_name ON products (category, name);\n";

/* Version 4: the index reads words through the "tessera" tokenizer (folding, German and English
 * stems, db_words.c), rebuilt from the existing rows; the synonym table (db_synonyms.c). */
static const char schema_v4[] =
    "DROP TABLE product_fts;\n"
    "CREATE VIRTUAL TABLE product_fts USING fts5 (" FTS_COLUMNS ",\n"
    "    content = 'product_search', content_rowid = 'id',\n"
    "    tokenize = 'tessera', prefix = '2 3');\n"
    "INSERT INTO product_fts (product_fts) VALUES ('rebuild');\n"
    "CREATE TABLE search_synonyms (\n"
    "    form     TEXT NOT NULL,\n"
    "    group_id INTEGER NOT NULL,\n"
    "    term     TEXT NOT NULL,\n"
    "    PRIMARY KEY (form, group_id, term)\n"
    ") WITHOUT ROWID;\n"
    "CREATE INDEX search_synonyms_by_group ON search_synonyms (group_id);\n";

/* Version 5: colour words match finishes. A product's variant names ("White matt", "Antracite,
 * matt") are kept in products.finishes by triggers on variants and indexed as an eighth column,
 * so "Waschtisch weiss matt" finds a basin whose name says no colour but which comes in white
 * matt. The index is made again (the tokenizer now also indexes the parts of compound words,
 * db_words.c), so every trigger that feeds it is made again with the new column (IF EXISTS: a
 * trigger lost to a hand edit is made again too). */
#define FTS5_COLUMNS FTS_COLUMNS ", finishes"
#define FTS5_DELETE(p, series, manufacturer)                                                       \
    "INSERT INTO product_fts (product_fts, rowid, " FTS5_COLUMNS ") VALUES ('delete', " p         \
    ".id, " p ".name, " series ", " manufacturer ", " p ".article, " COMPACT(p ".article")         \
    ", " p ".short_text, " CATEGORY_WORDS(p ".category") ", " p ".finishes);\n"
#define FTS5_INSERT(where)                                                                         \
    "INSERT INTO product_fts (rowid, " FTS5_COLUMNS ") SELECT id, " FTS5_COLUMNS                   \
    " FROM product_search WHERE " where ";\n"
#define FINISHES_OF(id)                                                                            \
    "coalesce((SELECT group_concat(name, ' ') FROM (SELECT name FROM variants WHERE product_id = " \
    id " ORDER BY id)), '')"
#define SET_FINISHES(id)                                                                           \
    "UPDATE products SET finishes = " FINISHES_OF(id) " WHERE id = " id ";\n"

static const char schema_v5[] =
    "DROP TRIGGER IF EXISTS products_fts_insert;\n"
    "DROP TRIGGER IF EXISTS products_fts_delete;\n"
    "DROP TRIGGER IF EXISTS products_fts_update;\n"
    "DROP TRIGGER IF EXISTS manufacturers_fts_rename;\n"
    "DROP TRIGGER IF EXISTS series_fts_rename;\n"
    "DROP TABLE product_fts;\n"
    "DROP VIEW IF EXISTS product_search;\n"
    "ALTER TABLE products ADD COLUMN finishes TEXT NOT NULL DEFAULT '';\n"
    "UPDATE products SET finishes = " FINISHES_OF("products.id") ";\n"
    "CREATE TRIGGER variants_finishes_insert AFTER INSERT ON variants BEGIN\n"
    SET_FINISHES("new.product_id")
    "END;\n"
    "CREATE TRIGGER variants_finishes_delete AFTER DELETE ON variants BEGIN\n"
    SET_FINISHES("old.product_id")
    "END;\n"
    "CREATE TRIGGER variants_finishes_update AFTER UPDATE OF name, product_id ON variants BEGIN\n"
    SET_FINISHES("old.product_id")
    SET_FINISHES("new.product_id")
    "END;\n"
    "CREATE VIEW product_search AS\n"
    "    SELECT p.id AS id, p.name AS name, coalesce(s.name, '') AS series,\n"
    "           m.name AS manufacturer, p.article AS article,\n"
    "           " COMPACT("p.article") " AS article_compact,\n"
    "           p.short_text AS short_text, " CATEGORY_WORDS("p.category") " AS category,\n"
    "           p.finishes AS finishes\n"
    "    FROM products p JOIN manufacturers m ON m.id = p.manufacturer_id\n"
    "    LEFT JOIN series s ON s.id = p.series_id;\n"
    "CREATE VIRTUAL TABLE product_fts USING fts5 (" FTS5_COLUMNS ",\n"
    "    content = 'product_search', content_rowid = 'id',\n"
    "    tokenize = 'tessera', prefix = '2 3');\n"
    "CREATE TRIGGER products_fts_insert AFTER INSERT ON products WHEN " LIVE " BEGIN\n"
    FTS5_INSERT("id = new.id")
    "END;\n"
    "CREATE TRIGGER products_fts_delete AFTER DELETE ON products WHEN " LIVE " BEGIN\n"
    FTS5_DELETE("old", OLD_SERIES, OLD_MANUFACTURER)
    "END;\n"
    "CREATE TRIGGER products_fts_update AFTER UPDATE OF name, series_id, manufacturer_id, "
    "article, short_text, category, finishes ON products\n"
    "WHEN (old.name IS NOT new.name OR old.series_id IS NOT new.series_id\n"
    "  OR old.manufacturer_id IS NOT new.manufacturer_id OR old.article IS NOT new.article\n"
    "  OR old.short_text IS NOT new.short_text OR old.category IS NOT new.category\n"
    "  OR old.finishes IS NOT new.finishes)\n"
    "  AND " LIVE " BEGIN\n"
    FTS5_DELETE("old", OLD_SERIES, OLD_MANUFACTURER)
    FTS5_INSERT("id = new.id")
    "END;\n"
    "CREATE TRIGGER manufacturers_fts_rename AFTER UPDATE OF name ON manufacturers\n"
    "WHEN " LIVE " BEGIN\n"
    "INSERT INTO product_fts (product_fts, rowid, " FTS5_COLUMNS ")\n"
    "    SELECT 'delete', p.id, p.name, coalesce(s.name, ''), old.name, p.article,\n"
    "           " COMPACT("p.article") ", p.short_text, " CATEGORY_WORDS("p.category") ",\n"
    "           p.finishes\n"
    "    FROM products p LEFT JOIN series s ON s.id = p.series_id\n"
    "    WHERE p.manufacturer_id = old.id;\n"
    FTS5_INSERT("id IN (SELECT id FROM products WHERE manufacturer_id = new.id)")
    "END;\n"
    "CREATE TRIGGER series_fts_rename AFTER UPDATE OF name ON series WHEN " LIVE " BEGIN\n"
    "INSERT INTO product_fts (product_fts, rowid, " FTS5_COLUMNS ")\n"
    "    SELECT 'delete', p.id, p.name, old.name, m.name, p.article,\n"
    "           " COMPACT("p.article") ", p.short_text, " CATEGORY_WORDS("p.category") ",\n"
    "           p.finishes\n"
    "    FROM products p JOIN manufacturers m ON m.id = p.manufacturer_id\n"
    "    WHERE p.series_id = old.id;\n"
    FTS5_INSERT("id IN (SELECT id FROM products WHERE series_id = new.id)")
    "END;\n"
    "INSERT INTO product_fts (product_fts) VALUES ('rebuild');\n";

/* Version 7: where a product is mounted and what goes with it (docs/catalog.md "Mounting
 * heights"): its mounting height above the floor (NULL: not given, the placement uses the
 * category's), what that height is measured to, and its companions' article numbers. */
static const char schema_v7[] =
    "ALTER TABLE products ADD COLUMN mounting_height_mm REAL\n"
    "    CHECK (mounting_height_mm IS NULL OR mounting_height_mm BETWEEN 0 AND 4000);\n"
    "ALTER TABLE products ADD COLUMN mounting_to TEXT NOT NULL DEFAULT ''\n"
    "    CHECK (mounting_to IN ('', 'bottom', 'top', 'rim', 'seat'));\n"
    "ALTER TABLE products ADD COLUMN companions TEXT NOT NULL DEFAULT '';\n";

/* Version 8: a variant's procedural pattern (docs/rendering.md "Wood grain") and the grain's
 * direction on the product's front, in degrees from its width towards its height (NULL: along
 * its longer side). Existing variants are plain. */
static const char schema_v8[] =
    "ALTER TABLE variants ADD COLUMN pattern TEXT NOT NULL DEFAULT 'none'\n"
    "    CHECK (pattern IN ('none', 'wood'));\n"
    "ALTER TABLE variants ADD COLUMN grain_deg REAL\n"
    "    CHECK (grain_deg IS NULL OR grain_deg BETWEEN 0 AND 180);\n";

/* clang-format on */

typedef cat_db_result (*migration_fn)(sqlite3 *sql, const char *path, char *err, size_t err_size);

static cat_db_result pragma_int(sqlite3 *sql, const char *path, const char *pragma, int *out,
                                char *err, size_t err_size);

static cat_db_result migrate_0_to_1(sqlite3 *sql, const char *path, char *err, size_t err_size)
{
    return catdb_exec(sql, path, "cannot create the schema (version 1)", schema_v1, err, err_size);
}

static cat_db_result migrate_1_to_2(sqlite3 *sql, const char *path, char *err, size_t err_size)
{
    return catdb_exec(sql, path, "cannot migrate the schema from version 1 to 2", schema_v2, err,
                      err_size);
}

static cat_db_result migrate_2_to_3(sqlite3 *sql, const char *path, char *err, size_t err_size)
{
    return catdb_exec(sql, path, "cannot migrate the schema from version 2 to 3", schema_v3, err,
                      err_size);
}

static cat_db_result migrate_3_to_4(sqlite3 *sql, const char *path, char *err, size_t err_size)
{
    cat_db_result r = catdb_exec(sql, path, "cannot migrate the schema from version 3 to 4",
                                 schema_v4, err, err_size);
    if (r == CAT_DB_OK)
        r = catdb_synonyms_load(sql, path, err, err_size);
    return r;
}

static cat_db_result migrate_4_to_5(sqlite3 *sql, const char *path, char *err, size_t err_size)
{
    cat_db_result r = catdb_exec(sql, path, "cannot migrate the schema from version 4 to 5",
                                 schema_v5, err, err_size);
    if (r == CAT_DB_OK)
        r = catdb_synonyms_load(sql, path, err, err_size); /* the list gained groups */
    return r;
}

/* Version 6: products may be priced per metre (unit 'm': trim profiles, billed by the metres of
 * the whole lengths bought). SQLite cannot alter a CHECK constraint, and rebuilding products
 * would drop the search triggers and cascade into variants and tiles; widening the accepted
 * values changes no stored row, so the table's text in sqlite_schema is edited in place, the
 * procedure sqlite.org/lang_altertable.html ("Making Other Kinds Of Table Schema Changes")
 * gives for constraint changes that leave the data valid: writable_schema, then
 * schema_version + 1 so every connection reads the new text (test_db_schema.c runs
 * integrity_check on a migrated file). */
static cat_db_result migrate_5_to_6(sqlite3 *sql, const char *path, char *err, size_t err_size)
{
    const char *what = "cannot migrate the schema from version 5 to 6";
    int version = 0;
    cat_db_result r = pragma_int(sql, path, "PRAGMA schema_version", &version, err, err_size);
    if (r != CAT_DB_OK)
        return r;
    char bump[64];
    snprintf(bump, sizeof bump, "PRAGMA schema_version = %d", version + 1);
    r = catdb_exec(sql, path, what,
                   "PRAGMA writable_schema = ON;"
                   "UPDATE sqlite_schema SET sql = replace(sql,"
                   " 'CHECK (unit IN (''piece'', ''m2'', ''box''))',"
                   " 'CHECK (unit IN (''piece'', ''m2'', ''box'', ''m''))')"
                   " WHERE type = 'table' AND name = 'products';"
                   "PRAGMA writable_schema = OFF;",
                   err, err_size);
    if (r != CAT_DB_OK) /* the UPDATE failed: never leave the schema writable */
        sqlite3_exec(sql, "PRAGMA writable_schema = OFF", NULL, NULL, NULL);
    if (r == CAT_DB_OK)
        r = catdb_exec(sql, path, what, bump, err, err_size);
    int unchanged = 1;
    if (r == CAT_DB_OK)
        r = pragma_int(sql, path,
                       "SELECT count(*) FROM sqlite_schema WHERE name = 'products' AND sql NOT "
                       "LIKE '%''box'', ''m'')%'",
                       &unchanged, err, err_size);
    if (r == CAT_DB_OK && unchanged)
        return catdb_fail(err, err_size, CAT_DB_ERR_DATABASE,
                          "%s: %s: the products table does not have the unit check of version 1",
                          path, what);
    return r;
}

static cat_db_result migrate_6_to_7(sqlite3 *sql, const char *path, char *err, size_t err_size)
{
    return catdb_exec(sql, path, "cannot migrate the schema from version 6 to 7", schema_v7, err,
                      err_size);
}

static cat_db_result migrate_7_to_8(sqlite3 *sql, const char *path, char *err, size_t err_size)
{
    return catdb_exec(sql, path, "cannot migrate the schema from version 7 to 8", schema_v8, err,
                      err_size);
}

static const migration_fn migrations[CAT_DB_SCHEMA_VERSION] = {
    migrate_0_to_1, migrate_1_to_2, migrate_2_to_3, migrate_3_to_4,
    migrate_4_to_5, migrate_5_to_6, migrate_6_to_7, migrate_7_to_8};

static cat_db_result pragma_int(sqlite3 *sql, const char *path, const char *pragma, int *out,
                                char *err, size_t err_size)
{
    sqlite3_stmt *st = NULL;
    int rc = sqlite3_prepare_v2(sql, pragma, -1, &st, NULL);
    if (rc == SQLITE_OK)
        rc = sqlite3_step(st);
    if (rc != SQLITE_ROW) {
        sqlite3_finalize(st);
        return catdb_sql_fail(sql, path, err, err_size, "cannot read the catalog");
    }
    *out = sqlite3_column_int(st, 0);
    sqlite3_finalize(st);
    return CAT_DB_OK;
}

cat_db_result catdb_schema_check(sqlite3 *sql, const char *path, int *version, char *err,
                                 size_t err_size)
{
    int tables = 0, app = 0, v = 0;
    cat_db_result r =
        pragma_int(sql, path, "SELECT count(*) FROM sqlite_schema", &tables, err, err_size);
    if (r == CAT_DB_OK)
        r = pragma_int(sql, path, "PRAGMA application_id", &app, err, err_size);
    if (r == CAT_DB_OK)
        r = pragma_int(sql, path, "PRAGMA user_version", &v, err, err_size);
    if (r != CAT_DB_OK)
        return r;
    if (app != CATDB_APPLICATION_ID && (app != 0 || tables > 0 || v != 0))
        return catdb_fail(err, err_size, CAT_DB_ERR_DATABASE,
                          "%s: not a Tessera catalog (an SQLite database with application id "
                          "0x%08X, %d schema entries)",
                          path, (unsigned)app, tables);
    if (v > CAT_DB_SCHEMA_VERSION)
        return catdb_fail(err, err_size, CAT_DB_ERR_VERSION,
                          "%s: catalog schema version %d was written by a newer Tessera; this "
                          "build reads versions up to %d",
                          path, v, CAT_DB_SCHEMA_VERSION);
    if (v < 0)
        return catdb_fail(err, err_size, CAT_DB_ERR_DATABASE,
                          "%s: catalog schema version %d is not valid", path, v);
    *version = v;
    return CAT_DB_OK;
}

cat_db_result catdb_migrate(sqlite3 *sql, const char *path, int from, char *err, size_t err_size)
{
    (void)from; /* read again under the write lock: another process may have migrated */
    cat_db_result r =
        catdb_exec(sql, path, "cannot start the migration", "BEGIN IMMEDIATE", err, err_size);
    if (r != CAT_DB_OK)
        return r;
    int v = 0;
    r = catdb_schema_check(sql, path, &v, err, err_size);
    for (; r == CAT_DB_OK && v < CAT_DB_SCHEMA_VERSION; v++)
        r = migrations[v](sql, path, err, err_size);
    if (r == CAT_DB_OK) {
        char set[64];
        snprintf(set, sizeof set, "PRAGMA user_version = %d", CAT_DB_SCHEMA_VERSION);
        r = catdb_exec(sql, path, "cannot record the schema version", set, err, err_size);
    }
    if (r == CAT_DB_OK)
        r = catdb_exec(sql, path, "cannot commit the migration", "COMMIT", err, err_size);
    if (r != CAT_DB_OK)
        sqlite3_exec(sql, "ROLLBACK", NULL, NULL, NULL);
    return r;
}

cat_db_result catdb_fts_defer(sqlite3 *sql, const char *path, char *err, size_t err_size)
{
    return catdb_meta_set(sql, path, "fts_deferred", "1", err, err_size);
}

cat_db_result catdb_fts_resume(sqlite3 *sql, const char *path, char *err, size_t err_size)
{
    return catdb_exec(sql, path, "cannot rebuild the search index",
                      "DELETE FROM meta WHERE key = 'fts_deferred';"
                      "INSERT INTO product_fts (product_fts) VALUES ('rebuild');",
                      err, err_size);
}

cat_db_result catdb_meta_get(sqlite3 *sql, const char *path, const char *key, char *buf,
                             size_t size, char *err, size_t err_size)
{
    buf[0] = 0;
    sqlite3_stmt *st = NULL;
    int rc = sqlite3_prepare_v2(sql, "SELECT value FROM meta WHERE key = ?1", -1, &st, NULL);
    if (rc == SQLITE_OK) {
        sqlite3_bind_text(st, 1, key, -1, SQLITE_STATIC);
        rc = sqlite3_step(st);
    }
    if (rc == SQLITE_ROW) {
        catdb_copy_text(buf, size, sqlite3_column_text(st, 0));
        rc = SQLITE_DONE;
    }
    sqlite3_finalize(st);
    if (rc != SQLITE_DONE)
        return catdb_sql_fail(sql, path, err, err_size, "cannot read the meta table");
    return CAT_DB_OK;
}

cat_db_result catdb_meta_set(sqlite3 *sql, const char *path, const char *key, const char *value,
                             char *err, size_t err_size)
{
    sqlite3_stmt *st = NULL;
    int rc = sqlite3_prepare_v2(
        sql,
        "INSERT INTO meta (key, value) VALUES (?1, ?2) ON CONFLICT (key) DO UPDATE SET "
        "value = excluded.value",
        -1, &st, NULL);
    if (rc == SQLITE_OK) {
        sqlite3_bind_text(st, 1, key, -1, SQLITE_STATIC);
        sqlite3_bind_text(st, 2, value, -1, SQLITE_STATIC);
        rc = sqlite3_step(st);
    }
    sqlite3_finalize(st);
    if (rc != SQLITE_DONE)
        return catdb_sql_fail(sql, path, err, err_size, "cannot write the meta table");
    return CAT_DB_OK;
}
