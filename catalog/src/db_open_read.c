/* Opening the catalog for reading: a current file gets a read-only connection and no schema
 * work; anything else takes cat_catalog_open's way (db_open.c), which writes. A search in a
 * fresh process (`tessera catalog search`) pays for the checks below, a few reads of the
 * file's header and meta table, and not for a write lock or a journal-mode change. */
#include "db_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static int meta_is(sqlite3 *sql, const char *path, const char *key, const char *want)
{
    char have[64];
    return catdb_meta_get(sql, path, key, have, sizeof have, NULL, 0) == CAT_DB_OK &&
           !strcmp(have, want);
}

static int in_wal_mode(sqlite3 *sql)
{
    sqlite3_stmt *st = NULL;
    int wal = sqlite3_prepare_v2(sql, "PRAGMA journal_mode", -1, &st, NULL) == SQLITE_OK &&
              sqlite3_step(st) == SQLITE_ROW &&
              !sqlite3_stricmp((const char *)sqlite3_column_text(st, 0), "wal");
    sqlite3_finalize(st);
    return wal;
}

/* 1 if the file needs nothing from cat_catalog_open: the same conditions under which that
 * would neither migrate, switch to WAL, refresh the shipped data nor rebuild the index. */
static int is_current(sqlite3 *sql, const char *path, const char *source_dir)
{
    int version = 0;
    if (catdb_schema_check(sql, path, &version, NULL, 0) != CAT_DB_OK ||
        version != CAT_DB_SCHEMA_VERSION || !in_wal_mode(sql))
        return 0;
    char words[32];
    catdb_words_stamp(words, sizeof words);
    if (!meta_is(sql, path, "index_words", words))
        return 0;
    if (!source_dir)
        return 1;
    catdb_source src;
    if (catdb_source_read(source_dir, &src, NULL, 0) != CAT_DB_OK)
        return 1; /* cat_catalog_open too leaves an existing file alone without shipped data */
    int same = meta_is(sql, path, "source_hash", src.hash);
    catdb_source_free(&src);
    return same;
}

cat_db_result cat_catalog_open_read(const char *path, const char *source_dir, cat_db **out,
                                    char *err, size_t err_size)
{
    char def[4096];
    if (out && (!path || !*path) && cat_default_path(def, sizeof def))
        path = def;
    struct stat st;
    if (!out || !path || !*path || stat(path, &st) != 0 || !S_ISREG(st.st_mode))
        return cat_catalog_open(path, source_dir, out, err, err_size);

    sqlite3 *sql = NULL;
    if (catdb_connect(path, SQLITE_OPEN_READONLY, &sql, NULL, 0) != CAT_DB_OK ||
        !is_current(sql, path, source_dir)) {
        sqlite3_close(sql);
        return cat_catalog_open(path, source_dir, out, err, err_size);
    }
    cat_db *db = calloc(1, sizeof *db);
    if (db)
        db->path = strdup(path);
    if (!db || !db->path) {
        free(db);
        sqlite3_close(sql);
        return catdb_fail(err, err_size, CAT_DB_ERR_OUT_OF_MEMORY, "%s: out of memory", path);
    }
    if (err && err_size)
        err[0] = 0;
    db->sql = sql;
    *out = db;
    return CAT_DB_OK;
}
