/* One SQLite connection with Tessera's settings, and running SQL with a message on failure. */
#include "db_internal.h"

#include <stdio.h>

/* sqlite3_auto_extension's entry point: every connection this process opens afterwards, also one
 * opened with sqlite3_open directly (tests, tools looking behind the API), reads product_fts
 * through the same tokenizer. */
static int words_everywhere(sqlite3 *sql, char **err, const void *api)
{
    (void)err;
    (void)api;
    catdb_register_words(sql);
    return SQLITE_OK;
}

cat_db_result catdb_connect(const char *path, int flags, sqlite3 **out, char *err, size_t err_size)
{
    *out = NULL;
    sqlite3_auto_extension((void (*)(void))words_everywhere); /* once; later calls do nothing */
    sqlite3 *sql = NULL;
    int rc = sqlite3_open_v2(path, &sql, flags | SQLITE_OPEN_NOMUTEX, NULL);
    if (rc != SQLITE_OK) {
        cat_db_result r = catdb_sql_fail(sql, path, err, err_size, "cannot open the catalog");
        sqlite3_close(sql);
        return r;
    }
    sqlite3_extended_result_codes(sql, 1);
    sqlite3_busy_timeout(sql, 10000);
    /* Foreign keys keep variants and tiles tied to their product (ON DELETE CASCADE). */
    cat_db_result r =
        catdb_exec(sql, path, "cannot set up the connection",
                   "PRAGMA foreign_keys = ON; PRAGMA cache_size = -65536", err, err_size);
    if (r == CAT_DB_OK && !catdb_register_rank(sql))
        r = catdb_fail(err, err_size, CAT_DB_ERR_DATABASE,
                       "%s: this SQLite has no FTS5 full-text search (SQLite %s)", path,
                       sqlite3_libversion());
    if (r == CAT_DB_OK && !catdb_register_words(sql))
        r = catdb_fail(err, err_size, CAT_DB_ERR_DATABASE,
                       "%s: cannot set up the search's word tokenizer", path);
    if (r != CAT_DB_OK) {
        sqlite3_close(sql);
        return r;
    }
    *out = sql;
    return CAT_DB_OK;
}

cat_db_result catdb_exec(sqlite3 *sql, const char *path, const char *what, const char *text,
                         char *err, size_t err_size)
{
    if (sqlite3_exec(sql, text, NULL, NULL, NULL) != SQLITE_OK)
        return catdb_sql_fail(sql, path, err, err_size, what);
    return CAT_DB_OK;
}

/* The handle's cached statements and query tokenizer belong to its connection. */
static void forget_statements(cat_db *db)
{
    sqlite3_stmt **cached[] = {&db->search_fts,    &db->search_fts_filtered, &db->search_exact,
                               &db->search_all,    &db->search_synonyms,     &db->search_any,
                               &db->known_synonym, &db->known_word};
    for (size_t i = 0; i < sizeof cached / sizeof cached[0]; i++) {
        sqlite3_finalize(*cached[i]);
        *cached[i] = NULL;
    }
    catdb_query_words_free(db->words);
    db->words = NULL;
}

void catdb_reconnect(cat_db *db)
{
    if (!db || !db->sql || db->read_only)
        return;
    sqlite3 *fresh = NULL;
    if (catdb_connect(db->path, SQLITE_OPEN_READWRITE, &fresh, NULL, 0) != CAT_DB_OK)
        return;
    forget_statements(db);
    sqlite3_exec(db->sql, "ROLLBACK", NULL, NULL, NULL);
    sqlite3_close(db->sql);
    db->sql = fresh;
}

void catdb_recover(cat_db *db)
{
    if (db && db->sql && !sqlite3_get_autocommit(db->sql))
        sqlite3_exec(db->sql, "ROLLBACK", NULL, NULL, NULL);
}
