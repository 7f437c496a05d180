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

/* "file:PATH?immutable=1" (https://sqlite.org/uri.html): '%', '?' and '#' in the path are
 * percent-encoded, the rest is taken as it is. 0 when it does not fit. */
static int immutable_uri(const char *path, char *uri, size_t size)
{
    size_t n = (size_t)snprintf(uri, size, "file:");
    for (const unsigned char *c = (const unsigned char *)path; *c && n + 4 < size; c++) {
        if (*c == '%' || *c == '?' || *c == '#')
            n += (size_t)snprintf(uri + n, size - n, "%%%02X", *c);
        else
            uri[n++] = (char)*c;
    }
    uri[n] = 0;
    return n + sizeof "?immutable=1" <= size &&
           snprintf(uri + n, size - n, "?immutable=1") == (int)sizeof "?immutable=1" - 1;
}

/* The catalog when it cannot be opened for writing (a read-only folder, a full disk): a reader
 * of a WAL database needs the -shm index, which it makes or grows by writing
 * (https://sqlite.org/wal.html, "Read-Only Databases"). With no -wal file, or an empty one,
 * every committed page is in the main file (the last connection checkpointed it), so the file
 * is read as immutable=1, which never touches -wal or -shm. A -wal file with frames holds pages
 * the main file lacks: then only a plain read-only opening can read it, and that needs -shm.
 * Catalog writes are refused on such a handle (db->read_only). */
static cat_db_result open_read_only(const char *path, sqlite3 **out, char *err, size_t err_size)
{
    *out = NULL;
    char wal[4200], uri[13000];
    snprintf(wal, sizeof wal, "%s-wal", path);
    struct stat st;
    int has_wal = stat(wal, &st) == 0 && st.st_size > 0;
    if (!has_wal && !immutable_uri(path, uri, sizeof uri))
        return catdb_fail(err, err_size, CAT_DB_ERR_IO, "the path is too long");
    sqlite3 *sql = NULL;
    cat_db_result r =
        catdb_connect(has_wal ? path : uri, SQLITE_OPEN_READONLY | (has_wal ? 0 : SQLITE_OPEN_URI),
                      &sql, err, err_size);
    /* Sorts spill to memory, never to a temporary file on the full disk. */
    if (r == CAT_DB_OK)
        r = catdb_exec(sql, path, "cannot set up the connection", "PRAGMA temp_store = MEMORY", err,
                       err_size);
    int version = 0;
    if (r == CAT_DB_OK)
        r = catdb_schema_check(sql, path, &version, err, err_size);
    if (r == CAT_DB_OK && version < CAT_DB_SCHEMA_VERSION)
        r = catdb_fail(err, err_size, CAT_DB_ERR_IO,
                       "its schema %d needs an update to %d, which needs writing", version,
                       CAT_DB_SCHEMA_VERSION);
    if (r != CAT_DB_OK && has_wal)
        r = catdb_fail(err, err_size, r,
                       "%s holds changes not yet in the catalog file, and reading them needs "
                       "%s-shm",
                       wal, path);
    if (r != CAT_DB_OK) {
        sqlite3_close(sql);
        return r;
    }
    *out = sql;
    return CAT_DB_OK;
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
    int existed = 0;
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
    } else {
        existed = 1;
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

    /* A file that cannot be written (or whose -shm cannot be made) is still read. */
    char *read_only = NULL;
    if (r == CAT_DB_ERR_IO && existed) {
        sqlite3_close(sql);
        char why[1024], ro_err[1024] = "";
        snprintf(why, sizeof why, "%s", err && err_size ? err : "cannot write");
        r = open_read_only(path, &sql, ro_err, sizeof ro_err);
        if (r == CAT_DB_OK && !(read_only = strdup(why)))
            r = catdb_fail(err, err_size, CAT_DB_ERR_OUT_OF_MEMORY, "%s: out of memory", path);
        else if (r != CAT_DB_OK)
            r = catdb_fail(err, err_size, CAT_DB_ERR_IO, "%s; read-only: %s", why, ro_err);
    }

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
        free(read_only);
        return r;
    }
    db->sql = sql;
    db->read_only = read_only;
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
    free(db->read_only);
    free(db);
}

const char *cat_db_read_only_reason(const cat_db *db)
{
    return db ? db->read_only : NULL;
}

const char *cat_db_path(const cat_db *db)
{
    return db ? db->path : "";
}
