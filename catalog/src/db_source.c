/* The shipped data: the *.csv files of a folder (assets/catalog), in name order, and a hash of
 * their names and contents that tells whether a catalog file was built from them. */
#include "db_internal.h"

#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* Bump when the import starts to store something differently from the same CSV files, so that
 * every catalog is built again. */
#define IMPORT_LOGIC_VERSION 1

static int by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

void catdb_source_free(catdb_source *s)
{
    for (int i = 0; i < s->count; i++)
        free(s->files[i]);
    free(s->files);
    memset(s, 0, sizeof *s);
}

static int is_csv(const char *name)
{
    size_t n = strlen(name);
    return n > 4 && name[0] != '.' && !strcmp(name + n - 4, ".csv");
}

cat_db_result catdb_source_read(const char *dir, catdb_source *out, char *err, size_t err_size)
{
    memset(out, 0, sizeof *out);
    DIR *d = opendir(dir);
    if (!d)
        return catdb_fail(err, err_size, CAT_DB_ERR_IO,
                          "%s: cannot read the shipped catalog folder: %s", dir, strerror(errno));
    int cap = 0;
    cat_db_result r = CAT_DB_OK;
    struct dirent *e;
    while (r == CAT_DB_OK && (e = readdir(d))) {
        if (!is_csv(e->d_name))
            continue;
        if (out->count == cap) {
            int ncap = cap ? cap * 2 : 8;
            char **f = realloc(out->files, (size_t)ncap * sizeof *f);
            if (!f) {
                r = catdb_fail(err, err_size, CAT_DB_ERR_OUT_OF_MEMORY, "%s: out of memory", dir);
                break;
            }
            out->files = f;
            cap = ncap;
        }
        size_t n = strlen(dir) + strlen(e->d_name) + 2;
        char *path = malloc(n);
        if (!path) {
            r = catdb_fail(err, err_size, CAT_DB_ERR_OUT_OF_MEMORY, "%s: out of memory", dir);
            break;
        }
        snprintf(path, n, "%s/%s", dir, e->d_name);
        out->files[out->count++] = path;
    }
    closedir(d);
    if (r == CAT_DB_OK && out->count == 0)
        r = catdb_fail(err, err_size, CAT_DB_ERR_IO,
                       "%s: the shipped catalog folder has no *.csv files", dir);
    if (r != CAT_DB_OK) {
        catdb_source_free(out);
        return r;
    }
    qsort(out->files, (size_t)out->count, sizeof *out->files, by_name);

    uint64_t h = CATDB_HASH64_INIT;
    int versions[2] = {CAT_DB_SCHEMA_VERSION, IMPORT_LOGIC_VERSION};
    h = catdb_hash64(h, versions, sizeof versions);
    h = catdb_synonyms_hash(h);
    for (int i = 0; i < out->count && r == CAT_DB_OK; i++) {
        unsigned char *data;
        size_t size;
        r = catdb_read_file(out->files[i], CAT_IMPORT_MAX_FILE_BYTES, &data, &size, err, err_size);
        if (r != CAT_DB_OK)
            break;
        const char *base = strrchr(out->files[i], '/') + 1;
        h = catdb_hash64(h, base, strlen(base) + 1);
        unsigned long long n = size;
        h = catdb_hash64(h, &n, sizeof n);
        h = catdb_hash64(h, data, size);
        free(data);
    }
    if (r != CAT_DB_OK) {
        catdb_source_free(out);
        return r;
    }
    snprintf(out->hash, sizeof out->hash, "%016llx", (unsigned long long)h);
    return CAT_DB_OK;
}
