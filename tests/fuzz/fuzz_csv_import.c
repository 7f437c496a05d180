/* Fuzz target for the catalog's CSV import (tests/fuzz/CMakeLists.txt, docs/fuzzing.md).
 * Every input is imported as a dry run into one catalog in a temporary folder, so the
 * whole import path runs (CSV reader, header, row checks, writes) and is rolled back. The
 * import must return a result and a message naming the input, whatever the bytes. */
#define _XOPEN_SOURCE 700 /* mkdtemp */
#include "catalog/catalog.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static cat_db *db;

static void open_once(void)
{
    static char dir[] = "/tmp/tessera-fuzz-csv-XXXXXX";
    char path[64], err[1024];
    if (!mkdtemp(dir))
        abort();
    snprintf(path, sizeof path, "%s/catalog.sqlite", dir);
    if (cat_catalog_open(path, NULL, &db, err, sizeof err) != CAT_DB_OK) {
        fprintf(stderr, "%s\n", err);
        abort();
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (!db)
        open_once();
    cat_import_desc desc = {.dry_run = 1};
    cat_import_report rep;
    char err[2048] = "";
    cat_db_result r =
        cat_import_csv_buffer(db, "fuzz.csv", data, size, &desc, &rep, err, sizeof err);
    if (r != CAT_DB_OK && strncmp(err, "fuzz.csv", 8) != 0)
        abort(); /* every failure names its input */
    if ((r == CAT_DB_ERR_INVALID || r == CAT_DB_ERR_PARSE) && rep.problem_count == 0)
        abort(); /* and says what is wrong */
    cat_import_report_free(&rep);
    return 0;
}
