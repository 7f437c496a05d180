/* The catalog schema: a new file gets the whole chain of migrations; a hand-made version-1
 * database (frozen here as it was released) is migrated to the current version with its data
 * kept and searchable, and ends with the same tables and columns as a new one; newer versions,
 * foreign databases and junk files are refused with a message naming the file. */
#include "test_db_util.h"

/* Schema version 1 exactly as released; do not update it with the schema. */
static const char v1_schema[] =
    "PRAGMA application_id = 1413829459;"
    "CREATE TABLE meta (key TEXT PRIMARY KEY, value TEXT NOT NULL);"
    "CREATE TABLE manufacturers (id INTEGER PRIMARY KEY, name TEXT NOT NULL UNIQUE COLLATE "
    "NOCASE);"
    "CREATE TABLE series (id INTEGER PRIMARY KEY, manufacturer_id INTEGER NOT NULL REFERENCES "
    "manufacturers(id), name TEXT NOT NULL COLLATE NOCASE, UNIQUE (manufacturer_id, name));"
    "CREATE TABLE products (id INTEGER PRIMARY KEY, manufacturer_id INTEGER NOT NULL REFERENCES "
    "manufacturers(id), series_id INTEGER REFERENCES series(id), article TEXT NOT NULL COLLATE "
    "NOCASE, gtin TEXT NOT NULL DEFAULT '', category TEXT NOT NULL CHECK (category IN "
    "('taps_mixers', 'shower_sets', 'basins', 'wcs_bidets', 'baths', 'shower_trays', "
    "'shower_screens', 'mirrors', 'mirror_cabinets', 'lamps', 'towel_radiators', "
    "'vanity_units', 'accessories', 'tiles')), name TEXT NOT NULL, short_text TEXT NOT NULL "
    "DEFAULT '', long_text TEXT NOT NULL DEFAULT '', width_mm REAL NOT NULL CHECK (width_mm > "
    "0), depth_mm REAL NOT NULL CHECK (depth_mm > 0), height_mm REAL NOT NULL CHECK (height_mm "
    "> 0), price_cents INTEGER NOT NULL CHECK (price_cents > 0), vat_percent REAL NOT NULL "
    "DEFAULT 19 CHECK (vat_percent BETWEEN 0 AND 100), currency TEXT NOT NULL DEFAULT 'EUR', "
    "unit TEXT NOT NULL DEFAULT 'piece' CHECK (unit IN ('piece', 'm2', 'box')), UNIQUE "
    "(manufacturer_id, article));"
    "CREATE INDEX products_by_article ON products (article);"
    "CREATE INDEX products_by_gtin ON products (gtin);"
    "CREATE INDEX products_by_category ON products (category, width_mm);"
    "CREATE TABLE variants (id INTEGER PRIMARY KEY, product_id INTEGER NOT NULL REFERENCES "
    "products(id) ON DELETE CASCADE, code TEXT NOT NULL, name TEXT NOT NULL, surcharge_cents "
    "INTEGER NOT NULL DEFAULT 0 CHECK (surcharge_cents >= 0), ambient_r REAL NOT NULL, ambient_g "
    "REAL NOT NULL, ambient_b REAL NOT NULL, diffuse_r REAL NOT NULL, diffuse_g REAL NOT NULL, "
    "diffuse_b REAL NOT NULL, specular_r REAL NOT NULL, specular_g REAL NOT NULL, specular_b "
    "REAL NOT NULL, emissive_r REAL NOT NULL, emissive_g REAL NOT NULL, emissive_b REAL NOT "
    "NULL, shininess REAL NOT NULL CHECK (shininess >= 0), reflectivity REAL NOT NULL CHECK "
    "(reflectivity BETWEEN 0 AND 1), glossiness REAL NOT NULL CHECK (glossiness BETWEEN 0 AND "
    "1), blend TEXT NOT NULL DEFAULT 'mix' CHECK (blend IN ('mix', 'add', 'fresnel')), "
    "transparency REAL NOT NULL DEFAULT 0 CHECK (transparency BETWEEN 0 AND 1), ior REAL NOT "
    "NULL DEFAULT 1.5 CHECK (ior BETWEEN 1 AND 3), UNIQUE (product_id, code));"
    "CREATE TABLE tiles (product_id INTEGER PRIMARY KEY REFERENCES products(id) ON DELETE "
    "CASCADE, type TEXT NOT NULL CHECK (type IN ('UNI', 'BOR', 'DEK', 'EIN')), nominal_w_mm "
    "REAL NOT NULL CHECK (nominal_w_mm > 0), nominal_h_mm REAL NOT NULL CHECK (nominal_h_mm > "
    "0), work_w_mm REAL NOT NULL CHECK (work_w_mm > 0), work_h_mm REAL NOT NULL CHECK (work_h_mm "
    "> 0), grout_mm REAL NOT NULL CHECK (grout_mm >= 0), thickness_mm REAL NOT NULL CHECK "
    "(thickness_mm > 0), calibre TEXT NOT NULL DEFAULT '', surface TEXT NOT NULL CHECK (surface "
    "IN ('glossy', 'matt', 'structured')), m2_per_box REAL NOT NULL CHECK (m2_per_box > 0), "
    "pieces_per_box INTEGER NOT NULL CHECK (pieces_per_box > 0), texture TEXT NOT NULL DEFAULT "
    "'');"
    "PRAGMA user_version = 1;";

static const char v1_data[] =
    "INSERT INTO manufacturers VALUES (1, 'Oldtap'), (2, 'Tilery');"
    "INSERT INTO series VALUES (1, 1, 'Vintage'), (2, 2, 'Classico');"
    "INSERT INTO products (id, manufacturer_id, series_id, article, gtin, category, name, "
    "short_text, width_mm, depth_mm, height_mm, price_cents, unit) VALUES "
    "(1, 1, 1, 'OT-100', '4006381333931', 'taps_mixers', 'Vintage thermostatic bath mixer', "
    "'Exposed thermostat', 300, 190, 110, 32900, 'piece'),"
    "(2, 2, 2, 'TL-300600', '', 'tiles', 'Classico bianco 300 x 600', '', 297, 8, 597, 2490, "
    "'m2');"
    "INSERT INTO variants (product_id, code, name, ambient_r, ambient_g, ambient_b, diffuse_r, "
    "diffuse_g, diffuse_b, specular_r, specular_g, specular_b, emissive_r, emissive_g, "
    "emissive_b, shininess, reflectivity, glossiness, blend) VALUES "
    "(1, 'CP', 'Chrome', 0.05, 0.05, 0.05, 0.05, 0.05, 0.05, 0.95, 0.95, 0.95, 0, 0, 0, 2000, "
    "0.8, 0.9, 'mix');"
    "INSERT INTO tiles VALUES (2, 'UNI', 300, 600, 297, 597, 3, 8, 'C1', 'glossy', 1.44, 8, "
    "'textures/x.png');";

/* "name type notnull default pk" of every column of every table and view, and the names of
 * indexes and triggers, in one text: two databases with the same text have the same schema. */
static char *schema_text(const char *path)
{
    sqlite3 *s = NULL;
    size_t cap = 1 << 16, n = 0;
    char *out = calloc(1, cap);
    if (sqlite3_open_v2(path, &s, SQLITE_OPEN_READONLY, NULL) != SQLITE_OK || !out) {
        sqlite3_close(s);
        return out;
    }
    sqlite3_stmt *st = NULL;
    sqlite3_prepare_v2(s,
                       "SELECT m.type, m.name, coalesce(p.name, ''), coalesce(p.type, ''), "
                       "coalesce(p.\"notnull\", 0), coalesce(p.dflt_value, ''), coalesce(p.pk, 0) "
                       "FROM sqlite_schema m LEFT JOIN pragma_table_info(m.name) p "
                       "WHERE m.name NOT LIKE 'sqlite_%' ORDER BY m.type, m.name, p.cid",
                       -1, &st, NULL);
    while (st && sqlite3_step(st) == SQLITE_ROW && n + 512 < cap) {
        n += (size_t)snprintf(
            out + n, cap - n, "%s %s %s %s %d %s %d\n", sqlite3_column_text(st, 0),
            sqlite3_column_text(st, 1), sqlite3_column_text(st, 2), sqlite3_column_text(st, 3),
            sqlite3_column_int(st, 4), sqlite3_column_text(st, 5), sqlite3_column_int(st, 6));
    }
    sqlite3_finalize(st);
    sqlite3_close(s);
    return out;
}

static void test_new_catalog(void)
{
    cat_db *db = open_catalog("new.sqlite", 0);
    const char *path = tmp_path("new.sqlite");
    CHECK(sql_int(path, "PRAGMA user_version") == CAT_DB_SCHEMA_VERSION);
    CHECK(sql_int(path, "PRAGMA application_id") == 0x54455353);
    CHECK(sql_int(path, "SELECT count(*) FROM sqlite_schema WHERE name IN ('manufacturers', "
                        "'series', 'products', 'variants', 'tiles', 'meta', 'product_fts', "
                        "'product_search')") == 8);
    CHECK(fts_consistent(path));
    cat_db_stats s;
    char err[512];
    CHECK(cat_db_get_stats(db, &s, err, sizeof err) == CAT_DB_OK);
    CHECK(s.schema_version == CAT_DB_SCHEMA_VERSION && s.products == 0 && s.source_hash[0] == 0);
    CHECK(!strcmp(cat_db_path(db), path));
    cat_db_close(db);

    /* Opening again changes nothing. */
    write_file("copy.sqlite", "", 0);
    char *before = read_all(path, NULL);
    size_t size = 0;
    free(read_all(path, &size));
    write_file("copy.sqlite", before, size);
    db = open_catalog("new.sqlite", 0);
    cat_db_close(db);
    CHECK(same_bytes(path, tmp_path("copy.sqlite")));
    free(before);
}

static void test_migration_from_v1(void)
{
    const char *path = tmp_path("v1.sqlite");
    CHECK(sql_run(path, v1_schema));
    CHECK(sql_run(path, v1_data));
    CHECK(sql_int(path, "PRAGMA user_version") == 1);

    cat_db *db = open_catalog("v1.sqlite", 0);
    CHECK(sql_int(path, "PRAGMA user_version") == CAT_DB_SCHEMA_VERSION);
    CHECK(fts_consistent(path));

    /* The data is all there, with the new columns at their defaults. */
    cat_product p;
    char err[512];
    CHECK(cat_product_find(db, "oldtap", "ot-100", &p, err, sizeof err) == CAT_DB_OK);
    CHECK(!strcmp(p.name, "Vintage thermostatic bath mixer") && !strcmp(p.series, "Vintage"));
    CHECK(p.price_cents == 32900 && p.vat_percent == 19 && !strcmp(p.currency, "EUR"));
    CHECK(p.discount_group[0] == 0 && p.model[0] == 0 && p.shipped == 1);
    CHECK(p.variant_count == 1 && !strcmp(p.variants[0].code, "CP"));
    CHECK_NEAR(p.variants[0].material.reflectivity, 0.8, 1e-6);
    cat_product_free(&p);
    CHECK(cat_product_find(db, NULL, "TL-300600", &p, err, sizeof err) == CAT_DB_OK);
    CHECK(p.has_tile && p.tile.nominal_w_mm == 300 && p.tile.work_h_mm == 597 &&
          p.tile.type == CAT_TILE_UNI && p.unit == CAT_UNIT_M2);
    cat_product_free(&p);

    /* ... and searchable: the migration built the full-text index. */
    cat_search_hit hits[4];
    int n = 0;
    CHECK(cat_search(db, "therm", NULL, 4, hits, &n, err, sizeof err) == CAT_DB_OK);
    CHECK(n == 1 && !strcmp(hits[0].article, "OT-100"));
    CHECK(cat_search(db, "Classico", NULL, 4, hits, &n, err, sizeof err) == CAT_DB_OK);
    CHECK(n == 1 && !strcmp(hits[0].article, "TL-300600"));
    CHECK(cat_search(db, "Oldtap", NULL, 4, hits, &n, err, sizeof err) == CAT_DB_OK && n == 1);
    cat_db_close(db);
    /* Version 6 widened the unit check in place: a price per metre is taken, nonsense is not,
     * and the edited schema passes SQLite's own check. */
    CHECK(sql_run(path, "UPDATE products SET unit = 'm' WHERE article = 'OT-100'"));
    CHECK(!sql_run(path, "UPDATE products SET unit = 'metre' WHERE article = 'OT-100'"));
    CHECK(sql_int(path, "SELECT count(*) FROM products WHERE unit = 'm'") == 1);
    CHECK(sql_int(path, "SELECT count(*) FROM pragma_integrity_check WHERE "
                        "integrity_check = 'ok'") == 1);

    /* The migrated schema is the new one, table for table, column for column. */
    cat_db_close(open_catalog("fresh.sqlite", 0));
    char *a = schema_text(path), *b = schema_text(tmp_path("fresh.sqlite"));
    CHECK_MSG(a && b && !strcmp(a, b), "migrated:\n%s\nnew:\n%s", a ? a : "", b ? b : "");
    free(a);
    free(b);
}

static void check_open_fails(const char *name, cat_db_result code, const char *needle)
{
    cat_db *db = (cat_db *)&db; /* must be set to NULL */
    char err[1024] = "";
    const char *path = tmp_path(name);
    cat_db_result r = cat_catalog_open(path, NULL, &db, err, sizeof err);
    CHECK_MSG(r == code && db == NULL && strstr(err, path) && strstr(err, needle),
              "%s: expected %s with \"%s\", got %s: %s", name, cat_db_result_name(code), needle,
              cat_db_result_name(r), err);
    if (r == CAT_DB_OK)
        cat_db_close(db);
}

static void test_refused_files(void)
{
    const char *newer = tmp_path("newer.sqlite");
    CHECK(sql_run(newer, v1_schema));
    CHECK(sql_run(newer, "PRAGMA user_version = 99"));
    check_open_fails("newer.sqlite", CAT_DB_ERR_VERSION, "newer Tessera");
    CHECK(sql_int(newer, "PRAGMA user_version") == 99); /* left alone */

    CHECK(sql_run(tmp_path("other.sqlite"), "CREATE TABLE accounts (id INTEGER)"));
    check_open_fails("other.sqlite", CAT_DB_ERR_DATABASE, "not a Tessera catalog");

    char junk[4096];
    for (size_t i = 0; i < sizeof junk; i++)
        junk[i] = (char)(i * 37 + 11);
    write_file("junk.sqlite", junk, sizeof junk);
    check_open_fails("junk.sqlite", CAT_DB_ERR_DATABASE, "not a database");

    mkdir(tmp_path("folder.sqlite"), 0777);
    check_open_fails("folder.sqlite", CAT_DB_ERR_IO, "not a file");

    write_file("blocker", "x", 1);
    check_open_fails("blocker/sub/catalog.sqlite", CAT_DB_ERR_IO, "cannot make folder");

    /* An empty file is an empty database: it becomes a catalog. */
    write_file("empty.sqlite", "", 0);
    cat_db_close(open_catalog("empty.sqlite", 0));
    CHECK(sql_int(tmp_path("empty.sqlite"), "PRAGMA user_version") == CAT_DB_SCHEMA_VERSION);

    /* A missing shipped-data folder is an error only when the file has to be built. */
    cat_db *db = NULL;
    char err[1024];
    cat_db_result r = cat_catalog_open(tmp_path("nosource.sqlite"), tmp_path("no-such-folder"), &db,
                                       err, sizeof err);
    CHECK_MSG(r == CAT_DB_ERR_IO && strstr(err, "no-such-folder"), "%s", err);
    CHECK(access(tmp_path("nosource.sqlite"), F_OK) != 0);
    r = cat_catalog_open(tmp_path("new.sqlite"), tmp_path("no-such-folder"), &db, err, sizeof err);
    CHECK_MSG(r == CAT_DB_OK, "%s", err);
    cat_db_close(db);
}

static void test_paths(void)
{
    char buf[4096];
    setenv("TESSERA_CATALOG", "/x/y.sqlite", 1);
    CHECK(cat_default_path(buf, sizeof buf) && !strcmp(buf, "/x/y.sqlite"));
    unsetenv("TESSERA_CATALOG");
    setenv("XDG_CACHE_HOME", "/cache", 1);
    CHECK(cat_default_path(buf, sizeof buf) && !strcmp(buf, "/cache/tessera/catalog.sqlite"));
    setenv("XDG_CACHE_HOME", "relative", 1); /* not absolute: ignored (XDG spec) */
    setenv("HOME", "/home/u", 1);
    CHECK(cat_default_path(buf, sizeof buf) &&
          !strcmp(buf, "/home/u/.cache/tessera/catalog.sqlite"));
    CHECK(!cat_default_path(buf, 8)); /* too small */
    unsetenv("XDG_CACHE_HOME");

    /* Missing folders are made, and NULL means the default path. */
    char home[4200];
    snprintf(home, sizeof home, "%s/home", g_tmp);
    setenv("HOME", home, 1);
    cat_db *db = NULL;
    char err[1024];
    CHECK(cat_catalog_open(NULL, NULL, &db, err, sizeof err) == CAT_DB_OK);
    CHECK(db && strstr(cat_db_path(db), "/home/.cache/tessera/catalog.sqlite"));
    cat_db_close(db);
    CHECK(access(tmp_path("home/.cache/tessera/catalog.sqlite"), F_OK) == 0);
    CHECK(cat_catalog_open(tmp_path("a/b/c/deep.sqlite"), NULL, &db, err, sizeof err) == CAT_DB_OK);
    cat_db_close(db);
}

static void test_names(void)
{
    for (int c = 1; c < CAT_CATEGORY_COUNT; c++) {
        cat_category back = CAT_CATEGORY_ANY;
        CHECK(cat_category_parse(cat_category_name((cat_category)c), &back) && (int)back == c);
    }
    cat_category c = CAT_CATEGORY_BASINS;
    CHECK(!cat_category_parse("sinks", &c) && c == CAT_CATEGORY_BASINS);
    CHECK(!cat_category_parse("", &c) && !cat_category_parse(NULL, &c));
    CHECK(!strcmp(cat_category_name(CAT_CATEGORY_COUNT), "") &&
          !strcmp(cat_category_name((cat_category)-1), ""));
    cat_tile_type t;
    CHECK(cat_tile_type_parse("dek", &t) && t == CAT_TILE_DEK);
    cat_blend b;
    CHECK(cat_blend_parse("Fresnel", &b) && b == CAT_BLEND_FRESNEL);
    CHECK(cat_gtin_valid("4006381333931") && cat_gtin_valid("96385074") &&
          cat_gtin_valid("036000291452") && cat_gtin_valid("10012345678902"));
    CHECK(!cat_gtin_valid("4006381333932") && !cat_gtin_valid("400638133393") &&
          !cat_gtin_valid("400638133393a") && !cat_gtin_valid("") && !cat_gtin_valid(NULL));
    for (int r = CAT_DB_OK; r <= CAT_DB_ERR_TOO_LARGE; r++)
        CHECK(strlen(cat_db_result_name((cat_db_result)r)) > 1);
}

int main(void)
{
    tmp_make();
    test_new_catalog();
    test_migration_from_v1();
    test_refused_files();
    test_paths();
    test_names();
    tmp_remove();
    return check_report("test_db_schema");
}
