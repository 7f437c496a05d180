/* Helpers of the catalog database tests: a temporary folder, files in it, a catalog built from
 * the shipped CSV files or empty, and a raw SQLite handle to look behind the API. */
#ifndef TESSERA_TESTS_CATALOG_TEST_DB_UTIL_H
#define TESSERA_TESTS_CATALOG_TEST_DB_UTIL_H

#define _XOPEN_SOURCE 700 /* mkdtemp, nftw, setenv */
#include "catalog/catalog.h"
#include "check.h"

#include <ftw.h>
#include <math.h>
#include <sqlite3.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

static char g_tmp[4096];

static inline int rm_entry(const char *path, const struct stat *st, int flag, struct FTW *ftw)
{
    (void)st;
    (void)flag;
    (void)ftw;
    return remove(path);
}

static inline void tmp_make(void)
{
    const char *base = getenv("TMPDIR");
    snprintf(g_tmp, sizeof g_tmp, "%s/tessera-db-XXXXXX", base && *base ? base : "/tmp");
    if (!mkdtemp(g_tmp)) {
        perror("mkdtemp");
        exit(2);
    }
}

static inline void tmp_remove(void)
{
    nftw(g_tmp, rm_entry, 16, FTW_DEPTH | FTW_PHYS);
}

/* Path of name inside the temporary folder (a rotating set of buffers). */
static inline const char *tmp_path(const char *name)
{
    static char buf[8][8200];
    static int next;
    char *p = buf[next++ % 8];
    size_t n = strlen(g_tmp);
    memcpy(p, g_tmp, n);
    p[n] = '/';
    snprintf(p + n + 1, sizeof buf[0] - n - 1, "%s", name);
    return p;
}

static inline const char *write_file(const char *name, const void *data, size_t size)
{
    const char *path = tmp_path(name);
    FILE *f = fopen(path, "wb");
    if (!f || (size && fwrite(data, 1, size, f) != size) || fclose(f) != 0) {
        perror(path);
        exit(2);
    }
    return path;
}

static inline const char *write_text(const char *name, const char *text)
{
    return write_file(name, text, strlen(text));
}

/* The whole file, zero-terminated; *size (may be NULL) gets its length. NULL if unreadable. */
static inline char *read_all(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    size_t cap = 4096, n = 0;
    char *buf = malloc(cap);
    if (size)
        *size = 0;
    size_t got;
    while (buf && (got = fread(buf + n, 1, cap - n - 1, f)) > 0) {
        n += got;
        if (cap - n - 1 == 0) {
            char *b = realloc(buf, cap *= 2);
            if (!b) {
                free(buf);
                buf = NULL;
            }
            buf = b;
        }
    }
    fclose(f);
    if (buf)
        buf[n] = 0;
    if (size)
        *size = n;
    return buf;
}

/* 1 when both files hold the same bytes. */
static inline int same_bytes(const char *a, const char *b)
{
    size_t na, nb;
    char *x = read_all(a, &na), *y = read_all(b, &nb);
    int same = x && y && na == nb && memcmp(x, y, na) == 0;
    free(x);
    free(y);
    return same;
}

/* A catalog at tmp/name: built from the shipped data (shipped = 1) or empty. Exits on failure,
 * since nothing else can be tested then. */
static inline cat_db *open_catalog(const char *name, int shipped)
{
    cat_db *db = NULL;
    char err[4096];
    cat_db_result r = cat_catalog_open(tmp_path(name), shipped ? TESSERA_CATALOG_SOURCE : NULL, &db,
                                       err, sizeof err);
    if (r != CAT_DB_OK) {
        fprintf(stderr, "cannot open the catalog %s: %s\n", name, err);
        exit(1);
    }
    return db;
}

/* One integer from SQL run on the file directly (-1 on failure). */
static inline long long sql_int(const char *path, const char *query)
{
    sqlite3 *s = NULL;
    long long v = -1;
    if (sqlite3_open_v2(path, &s, SQLITE_OPEN_READONLY, NULL) == SQLITE_OK) {
        sqlite3_stmt *st = NULL;
        if (sqlite3_prepare_v2(s, query, -1, &st, NULL) == SQLITE_OK &&
            sqlite3_step(st) == SQLITE_ROW)
            v = sqlite3_column_int64(st, 0);
        sqlite3_finalize(st);
    }
    sqlite3_close(s);
    return v;
}

/* Runs SQL on the file directly; returns 1 when it worked. */
static inline int sql_run(const char *path, const char *text)
{
    sqlite3 *s = NULL;
    int ok =
        sqlite3_open_v2(path, &s, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, NULL) == SQLITE_OK &&
        sqlite3_exec(s, text, NULL, NULL, NULL) == SQLITE_OK;
    if (!ok)
        fprintf(stderr, "sql_run on %s: %s\n", path, s ? sqlite3_errmsg(s) : "cannot open");
    sqlite3_close(s);
    return ok;
}

/* FTS5's own check that the index matches the products (external content). */
static inline int fts_consistent(const char *path)
{
    return sql_run(path, "INSERT INTO product_fts (product_fts) VALUES ('integrity-check')");
}

/* 1 when the report has a problem on `line` in `column` whose message contains needle. */
static inline int has_problem(const cat_import_report *r, long line, const char *column,
                              const char *needle)
{
    for (int i = 0; i < r->problems_kept; i++) {
        const cat_import_problem *p = &r->problems[i];
        if (p->line == line && !strcmp(p->column, column) &&
            (!needle || strstr(p->message, needle)))
            return 1;
    }
    return 0;
}

static inline void print_problems(const cat_import_report *r)
{
    for (int i = 0; i < r->problems_kept; i++)
        fprintf(stderr, "  line %ld, column '%s': %s\n", r->problems[i].line, r->problems[i].column,
                r->problems[i].message);
}

/* A refused import: the error names the first bad cell (`first`, "FILE:LINE: column NAME")
 * and says nothing was imported, and the catalog holds no product. Frees the report and
 * closes db. */
static inline void check_refused_import(cat_db *db, cat_import_report *rep, const char *err,
                                        const char *first)
{
    CHECK_MSG(strstr(err, first) && strstr(err, "nothing was imported"), "%s", err);
    cat_import_report_free(rep);
    cat_db_stats s;
    CHECK(cat_db_get_stats(db, &s, NULL, 0) == CAT_DB_OK && s.products == 0);
    cat_db_close(db);
}

static inline double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

#endif
