/* Opening the catalog: the default place, building a new file from the shipped data into a
 * temporary file renamed into place, migrating an old file, and bringing a file whose shipped
 * data changed up to date (again in a copy renamed over it). */
#include "db_internal.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int cat_default_path(char *buf, size_t size)
{
    const char *env = getenv("TESSERA_CATALOG");
    int n;
    if (env && *env)
        n = snprintf(buf, size, "%s", env);
    else if ((env = getenv("XDG_CACHE_HOME")) && env[0] == '/')
        n = snprintf(buf, size, "%s/tessera/catalog.sqlite", env);
    else if ((env = getenv("HOME")) && *env)
        n = snprintf(buf, size, "%s/.cache/tessera/catalog.sqlite", env);
    else
        return 0;
    return n > 0 && (size_t)n < size;
}

/* A fresh catalog at tmp: the whole schema chain, then the shipped data (if any). */
static cat_db_result build_into(const char *tmp, const char *path, const catdb_source *src,
                                char *err, size_t err_size)
{
    sqlite3 *sql;
    cat_db_result r =
        catdb_connect(tmp, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, &sql, err, err_size);
    if (r != CAT_DB_OK)
        return r;
    /* The journal only has to serve rollbacks: a crash leaves just a temporary file. */
    r = catdb_exec(sql, path, "cannot set up the new catalog", "PRAGMA journal_mode = MEMORY", err,
                   err_size);
    if (r == CAT_DB_OK)
        r = catdb_migrate(sql, path, 0, err, err_size);
    if (r == CAT_DB_OK && src)
        r = catdb_sync_shipped(sql, path, src, err, err_size);
    if (sqlite3_close(sql) != SQLITE_OK && r == CAT_DB_OK)
        r = catdb_fail(err, err_size, CAT_DB_ERR_IO, "%s: cannot close the new catalog", path);
    return r;
}

static cat_db_result build_new(const char *path, const catdb_source *src, char *err,
                               size_t err_size)
{
    char tmp[4200];
    catdb_temp_name(path, tmp, sizeof tmp);
    cat_db_result r = build_into(tmp, path, src, err, err_size);
    if (r == CAT_DB_OK)
        r = catdb_rename_into_place(tmp, path, err, err_size);
    if (r != CAT_DB_OK)
        catdb_remove_db_file(tmp);
    return r;
}

/* The open catalog *sql, whose shipped data is stale, copied, brought up to date and renamed
 * over path; *sql is closed and reopened on the new file. */
static cat_db_result refresh(sqlite3 **sql, const char *path, const catdb_source *src, char *err,
                             size_t err_size)
{
    char tmp[4200];
    catdb_temp_name(path, tmp, sizeof tmp);
    sqlite3_stmt *st = NULL;
    int rc = sqlite3_prepare_v2(*sql, "VACUUM INTO ?1", -1, &st, NULL);
    if (rc == SQLITE_OK) {
        sqlite3_bind_text(st, 1, tmp, -1, SQLITE_STATIC);
        rc = sqlite3_step(st);
    }
    sqlite3_finalize(st);
    cat_db_result r = CAT_DB_OK;
    if (rc != SQLITE_DONE)
        r = catdb_sql_fail(*sql, path, err, err_size, "cannot copy the catalog to update it");
    sqlite3 *copy = NULL;
    if (r == CAT_DB_OK)
        r = catdb_connect(tmp, SQLITE_OPEN_READWRITE, &copy, err, err_size);
    if (r == CAT_DB_OK)
        r = catdb_exec(copy, path, "cannot set up the copy", "PRAGMA journal_mode = MEMORY", err,
                       err_size);
    if (r == CAT_DB_OK)
        r = catdb_sync_shipped(copy, path, src, err, err_size);
    if (copy && sqlite3_close(copy) != SQLITE_OK && r == CAT_DB_OK)
        r = catdb_fail(err, err_size, CAT_DB_ERR_IO, "%s: cannot close the updated copy", path);
    if (r == CAT_DB_OK) {
        sqlite3_close(*sql);
        *sql = NULL;
        r = catdb_rename_into_place(tmp, path, err, err_size);
        cat_db_result r2 = catdb_connect(path, SQLITE_OPEN_READWRITE, sql, err, err_size);
        if (r == CAT_DB_OK)
            r = r2;
    }
    if (r != CAT_DB_OK)
        catdb_remove_db_file(tmp);
    return r;
}

cat_db_result cat_catalog_open(const char *path, const char *source_dir, cat_db **out, char *err,
                               size_t err_size)
{
    if (err && err_size)
        err[0] = 0;
    if (!out)
        return catdb_fail(err, err_size, CAT_DB_ERR_INVALID, "cat_catalog_open: out is NULL");
    *out = NULL;
    char def[4096];
    if (!path || !*path) {
        if (!cat_default_path(def, sizeof def))
            return catdb_fail(err, err_size, CAT_DB_ERR_IO,
                              "no place for the catalog: set TESSERA_CATALOG or HOME");
        path = def;
    }
    cat_db_result r = catdb_make_parent_dirs(path, err, err_size);
    if (r != CAT_DB_OK)
        return r;

    catdb_source src = {0};
    char src_err[1024] = "";
    int have_src = 0;
    cat_db_result src_r = CAT_DB_OK;
    if (source_dir) {
        src_r = catdb_source_read(source_dir, &src, src_err, sizeof src_err);
        have_src = src_r == CAT_DB_OK;
    }

    struct stat st;
    if (stat(path, &st) != 0) {
        if (errno != ENOENT)
            r = catdb_fail(err, err_size, CAT_DB_ERR_IO, "%s: cannot open the catalog: %s", path,
                           strerror(errno));
        else if (source_dir && !have_src)
            r = catdb_fail(err, err_size, src_r, "%s: cannot build the catalog: %s", path, src_err);
        else
            r = build_new(path, have_src ? &src : NULL, err, err_size);
    } else if (!S_ISREG(st.st_mode)) {
        r = catdb_fail(err, err_size, CAT_DB_ERR_IO, "%s: cannot open the catalog: not a file",
                       path);
    }
    sqlite3 *sql = NULL;
    if (r == CAT_DB_OK)
        r = catdb_connect(path, SQLITE_OPEN_READWRITE, &sql, err, err_size);
    int version = 0;
    if (r == CAT_DB_OK)
        r = catdb_schema_check(sql, path, &version, err, err_size);
    if (r == CAT_DB_OK && version < CAT_DB_SCHEMA_VERSION)
        r = catdb_migrate(sql, path, version, err, err_size);
    if (r == CAT_DB_OK && have_src) {
        char stored[64];
        r = catdb_meta_get(sql, path, "source_hash", stored, sizeof stored, err, err_size);
        if (r == CAT_DB_OK && strcmp(stored, src.hash) != 0)
            r = refresh(&sql, path, &src, err, err_size);
    }
    catdb_source_free(&src);

    cat_db *db = NULL;
    if (r == CAT_DB_OK) {
        db = calloc(1, sizeof *db);
        if (db)
            db->path = strdup(path);
        if (!db || !db->path)
            r = catdb_fail(err, err_size, CAT_DB_ERR_OUT_OF_MEMORY, "%s: out of memory", path);
    }
    if (r != CAT_DB_OK) {
        sqlite3_close(sql);
        if (db)
            free(db->path);
        free(db);
        return r;
    }
    db->sql = sql;
    *out = db;
    return CAT_DB_OK;
}

void cat_db_close(cat_db *db)
{
    if (!db)
        return;
    sqlite3_finalize(db->search_fts);
    sqlite3_finalize(db->search_fts_filtered);
    sqlite3_finalize(db->search_exact);
    sqlite3_finalize(db->search_all);
    sqlite3_finalize(db->search_synonyms);
    sqlite3_finalize(db->search_any);
    catdb_query_words_free(db->words);
    free(db->match);
    sqlite3_close(db->sql);
    free(db->path);
    free(db);
}

const char *cat_db_path(const cat_db *db)
{
    return db ? db->path : "";
}
