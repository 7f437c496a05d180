/* Counts of what a catalog holds, for `tessera catalog info` and the tests. */
#include "db_internal.h"

#include <string.h>

static int count(sqlite3 *sql, const char *text, long long *out)
{
    sqlite3_stmt *st = NULL;
    int ok =
        sqlite3_prepare_v2(sql, text, -1, &st, NULL) == SQLITE_OK && sqlite3_step(st) == SQLITE_ROW;
    if (ok)
        *out = sqlite3_column_int64(st, 0);
    sqlite3_finalize(st);
    return ok;
}

cat_db_result cat_db_get_stats(cat_db *db, cat_db_stats *out, char *err, size_t err_size)
{
    if (out)
        memset(out, 0, sizeof *out);
    if (!db || !out)
        return catdb_fail(err, err_size, CAT_DB_ERR_INVALID, "cat_db_get_stats: no catalog");
    catdb_recover(db);
    long long version = 0;
    int ok = count(db->sql, "PRAGMA user_version", &version) &&
             count(db->sql, "SELECT count(*) FROM manufacturers", &out->manufacturers) &&
             count(db->sql, "SELECT count(*) FROM series", &out->series) &&
             count(db->sql, "SELECT count(*) FROM products", &out->products) &&
             count(db->sql, "SELECT count(*) FROM variants", &out->variants) &&
             count(db->sql, "SELECT count(*) FROM tiles", &out->tiles);
    sqlite3_stmt *st = NULL;
    if (ok)
        ok =
            sqlite3_prepare_v2(db->sql, "SELECT category, count(*) FROM products GROUP BY category",
                               -1, &st, NULL) == SQLITE_OK;
    int rc = SQLITE_DONE;
    while (ok && (rc = sqlite3_step(st)) == SQLITE_ROW) {
        cat_category c;
        const char *name = (const char *)sqlite3_column_text(st, 0);
        if (name && cat_category_parse(name, &c))
            out->per_category[c] = sqlite3_column_int64(st, 1);
    }
    ok = ok && rc == SQLITE_DONE;
    sqlite3_finalize(st);
    if (!ok)
        return catdb_sql_fail(db->sql, db->path, err, err_size, "cannot count the catalog");
    out->schema_version = (int)version;
    char hash[64];
    cat_db_result r =
        catdb_meta_get(db->sql, db->path, "source_hash", hash, sizeof hash, err, err_size);
    if (r == CAT_DB_OK)
        catdb_copy_text(out->source_hash, sizeof out->source_hash, (const unsigned char *)hash);
    return r;
}
