/* cat_catalog_open_read: a current catalog is opened read-only (an import through the handle is
 * refused, the products stay as they were, searches work); a catalog whose shipped data or
 * search index is out of date, or that does not exist yet, is brought up to date as
 * cat_catalog_open would. */
#include "test_db_util.h"

static const char one_row[] =
    "manufacturer,article,gtin,category,name,width_mm,depth_mm,height_mm,list_price\n"
    "ReadOnly,RO-1,4006381333931,basins,Read-only basin,600,550,175,259.00\n";

static cat_db *open_read(const char *path, cat_db_result *result)
{
    cat_db *db = NULL;
    char err[4096] = "";
    *result = cat_catalog_open_read(path, TESSERA_CATALOG_SOURCE, &db, err, sizeof err);
    if (*result != CAT_DB_OK)
        fprintf(stderr, "cat_catalog_open_read %s: %s\n", path, err);
    return db;
}

static int import_row(cat_db *db)
{
    char err[1024] = "";
    return cat_import_csv_buffer(db, "one-row.csv", one_row, sizeof one_row - 1, NULL, NULL, err,
                                 sizeof err) == CAT_DB_OK;
}

static int finds_basins(cat_db *db)
{
    cat_search_hit hits[5];
    int n = 0;
    char err[1024];
    cat_search_filter f = {0};
    return cat_search(db, "Waschtisch", &f, 5, hits, &n, err, sizeof err) == CAT_DB_OK && n > 0;
}

static void test_current_is_read_only(void)
{
    cat_db_close(open_catalog("current.sqlite", 1));
    const char *path = tmp_path("current.sqlite");
    long long before = sql_int(path, "SELECT count(*) FROM products");
    cat_db_result r;
    cat_db *db = open_read(path, &r);
    CHECK(r == CAT_DB_OK && db);
    if (!db)
        return;
    CHECK(finds_basins(db));
    CHECK_MSG(!import_row(db), "an import through a read-only handle must be refused");
    cat_db_close(db);
    CHECK(sql_int(path, "SELECT count(*) FROM products") == before);
}

/* Shipped data or search index out of date: the read open brings the file up to date, through
 * a writable connection, as cat_catalog_open does. */
static void test_outdated_is_updated(const char *name, const char *key)
{
    cat_db_close(open_catalog(name, 1));
    const char *path = tmp_path(name);
    char stale[200];
    snprintf(stale, sizeof stale, "UPDATE meta SET value = 'stale' WHERE key = '%s'", key);
    CHECK(sql_run(path, stale));
    char query[200];
    snprintf(query, sizeof query, "SELECT count(*) FROM meta WHERE key = '%s' AND value = 'stale'",
             key);
    CHECK(sql_int(path, query) == 1);
    cat_db_result r;
    cat_db *db = open_read(path, &r);
    CHECK(r == CAT_DB_OK && db);
    CHECK_MSG(sql_int(path, query) == 0, "meta %s still stale after the read open", key);
    if (db) {
        CHECK(finds_basins(db));
        CHECK_MSG(import_row(db), "the updating open's handle takes imports");
    }
    cat_db_close(db);
    CHECK(fts_consistent(path));
}

static void test_missing_is_built(void)
{
    const char *path = tmp_path("new.sqlite");
    cat_db_result r;
    cat_db *db = open_read(path, &r);
    CHECK(r == CAT_DB_OK && db);
    CHECK(sql_int(path, "SELECT count(*) FROM products") > 300);
    if (db)
        CHECK(finds_basins(db));
    cat_db_close(db);
}

int main(void)
{
    tmp_make();
    test_current_is_read_only();
    test_outdated_is_updated("stale-source.sqlite", "source_hash");
    test_outdated_is_updated("stale-index.sqlite", "index_words");
    test_missing_is_built();
    tmp_remove();
    return check_report("test_db_open_read");
}
