/* Opening the catalog: the default place, building a new file from the shipped data into a
 * temporary file linked into place, migrating an old file, and bringing a file whose shipped
 * data changed up to date (in place, in one transaction).
 *
 * The catalog is in WAL mode, so a search in one process goes on while another imports: a
 * reader keeps the snapshot its transaction started with and never waits for the writer
 * (https://sqlite.org/wal.html, "Concurrency"). That is also why a finished file is never renamed
 * over a catalog that exists: the -wal and -shm files beside a path belong to whichever database
 * was there, and a connection that opens the new file would read the old file's WAL frames as its
 * own pages, and the old file's last connection would delete the new one's WAL on close
 * (https://sqlite.org/howtocorrupt.html, section 2.4 "Unlinking or renaming a database file
 * while in use"). */
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
    /* Written into the file's header, so the first connection on the finished file is in WAL. */
    if (r == CAT_DB_OK)
        r = catdb_exec(sql, path, "cannot set up the new catalog", "PRAGMA journal_mode = WAL", err,
                       err_size);
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
        r = catdb_link_into_place(tmp, path, err, err_size);
    catdb_remove_db_file(tmp); /* linked, or failed: the temporary name goes either way */
    return r;
}

/* A catalog in the rollback journal mode (made by an older Tessera) is switched to WAL; one that
 * cannot be (a read-only folder has no room for the -wal file) still works, with readers
 * waiting for writers up to the busy timeout. */
static void use_wal(sqlite3 *sql)
{
    sqlite3_exec(sql, "PRAGMA journal_mode = WAL", NULL, NULL, NULL);
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
    if (r == CAT_DB_OK)
        use_wal(sql);
    int version = 0;
    if (r == CAT_DB_OK)
        r = catdb_schema_check(sql, path, &version, err, err_size);
    if (r == CAT_DB_OK && version < CAT_DB_SCHEMA_VERSION)
        r = catdb_migrate(sql, path, version, err, err_size);
    if (r == CAT_DB_OK && have_src) {
        char stored[64];
        r = catdb_meta_get(sql, path, "source_hash", stored, sizeof stored, err, err_size);
        if (r == CAT_DB_OK && strcmp(stored, src.hash) != 0)
            r = catdb_sync_shipped(sql, path, &src, err, err_size);
    }
    catdb_source_free(&src);
    if (r == CAT_DB_OK)
        r = catdb_words_check(sql, path, err, err_size);

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
    sqlite3_finalize(db->known_synonym);
    sqlite3_finalize(db->known_word);
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
