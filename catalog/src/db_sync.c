/* Bringing a catalog's shipped products in step with the shipped CSV files. */
#include "db_internal.h"

#include <stdlib.h>

cat_db_result catdb_sync_shipped(sqlite3 *sql, const char *path, const catdb_source *src, char *err,
                                 size_t err_size)
{
    cat_db_result r = catdb_exec(sql, path, "cannot start updating the shipped products",
                                 "BEGIN IMMEDIATE", err, err_size);
    if (r != CAT_DB_OK)
        return r;
    /* Most of the catalog changes: one index rebuild at the end beats per-row triggers. */
    r = catdb_fts_defer(sql, path, err, err_size);
    /* Variants and tiles go with their products (ON DELETE CASCADE). Products of users'
     * imports stay. */
    if (r == CAT_DB_OK)
        r = catdb_exec(sql, path, "cannot remove the old shipped products",
                       "DELETE FROM products WHERE origin = '" CATDB_ORIGIN_SHIPPED "'", err,
                       err_size);
    for (int i = 0; r == CAT_DB_OK && i < src->count; i++) {
        unsigned char *data;
        size_t size;
        r = catdb_read_file(src->files[i], CAT_IMPORT_MAX_FILE_BYTES, &data, &size, err, err_size);
        if (r != CAT_DB_OK)
            break;
        char msg[1024];
        r = catdb_import_buffer(sql, path, CATDB_ORIGIN_SHIPPED, src->files[i], data, size, NULL,
                                NULL, msg, sizeof msg);
        free(data);
        if (r != CAT_DB_OK)
            catdb_fail(err, err_size, r, "%s: cannot take in the shipped data: %s", path, msg);
    }
    if (r == CAT_DB_OK)
        r = catdb_exec(sql, path, "cannot remove unused series and manufacturers",
                       "DELETE FROM series WHERE id NOT IN "
                       "(SELECT series_id FROM products WHERE series_id IS NOT NULL);"
                       "DELETE FROM manufacturers WHERE id NOT IN "
                       "(SELECT manufacturer_id FROM products);",
                       err, err_size);
    if (r == CAT_DB_OK)
        r = catdb_fts_resume(sql, path, err, err_size);
    if (r == CAT_DB_OK)
        r = catdb_synonyms_load(sql, path, err, err_size);
    if (r == CAT_DB_OK)
        r = catdb_meta_set(sql, path, "source_hash", src->hash, err, err_size);
    if (r == CAT_DB_OK)
        r = catdb_exec(sql, path, "cannot commit the shipped products", "COMMIT", err, err_size);
    if (r != CAT_DB_OK)
        sqlite3_exec(sql, "ROLLBACK", NULL, NULL, NULL);
    return r;
}
