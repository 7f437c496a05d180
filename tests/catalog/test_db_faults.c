/* Failures on purpose (STYLE.md, after SQLite's own tests): SQLite's allocator fails after N
 * allocations, for every N until the operation gets through. Each failed open, import or
 * search must return an error with a message, and leave the catalog exactly as it was: the
 * same products and prices, a consistent full-text index, no temporary files. */
#include "test_db_util.h"

#include <dirent.h>

static sqlite3_mem_methods real;
static long budget = -1; /* allocations left before failing; -1: no limit */
static long failed;

static void *fail_malloc(int n)
{
    if (budget == 0) {
        failed++;
        return NULL;
    }
    if (budget > 0)
        budget--;
    return real.xMalloc(n);
}

static void *fail_realloc(void *p, int n)
{
    if (budget == 0) {
        failed++;
        return NULL;
    }
    if (budget > 0)
        budget--;
    return real.xRealloc(p, n);
}

static const char base[] =
    "manufacturer,article,category,name,width_mm,depth_mm,height_mm,list_price,variant_code,"
    "variant_name,diffuse\n"
    "Fault,F-1,basins,Fault washbasin 600,600,550,175,259.00,WH,White,0.9 0.9 0.9\n"
    "Fault,F-1,basins,Fault washbasin 600,600,550,175,259.00,WM,Matt,0.8 0.8 0.8\n"
    "Fault,F-2,accessories,Fault towel bar,600,75,50,59.00,CP,Chrome,0.05 0.05 0.05\n";
static const char change[] =
    "manufacturer,article,category,name,width_mm,depth_mm,height_mm,list_price,variant_code,"
    "variant_name,diffuse\n"
    "Fault,F-1,basins,Fault washbasin 600,600,550,175,299.00,WH,White,0.9 0.9 0.9\n"
    "Fault,F-2,accessories,Fault towel bar 800,800,75,50,69.00,CP,Chrome,0.05 0.05 0.05\n"
    "Fault,F-3,accessories,Fault robe hook,40,50,40,19.00,CP,Chrome,0.05 0.05 0.05\n";

static long long price(cat_db *db, const char *article)
{
    cat_product p;
    if (cat_product_find(db, "Fault", article, &p, NULL, 0) != CAT_DB_OK)
        return -1;
    long long c = p.price_cents;
    cat_product_free(&p);
    return c;
}

static int no_temporary_files(void)
{
    int clean = 1;
    DIR *d = opendir(g_tmp);
    struct dirent *e;
    while (d && (e = readdir(d)))
        clean &= strstr(e->d_name, ".tmp-") == NULL;
    if (d)
        closedir(d);
    return clean;
}

static void test_import(void)
{
    cat_db *db = open_catalog("faults.sqlite", 0);
    char err[1024];
    cat_import_report rep;
    CHECK(cat_import_csv_buffer(db, "base.csv", base, strlen(base), NULL, &rep, err, sizeof err) ==
          CAT_DB_OK);
    cat_import_report_free(&rep);
    char path[8200];
    snprintf(path, sizeof path, "%s", tmp_path("faults.sqlite"));
    int done = 0, failures = 0;
    for (long n = 0; n < 50000 && !done; n += n < 200 ? 1 : 11) {
        budget = n;
        failed = 0;
        err[0] = 0;
        cat_db_result r = cat_import_csv_buffer(db, "change.csv", change, strlen(change), NULL,
                                                &rep, err, sizeof err);
        budget = -1;
        cat_import_report_free(&rep);
        if (r == CAT_DB_OK) {
            done = 1;
            break;
        }
        failures++;
        CHECK_MSG(failed > 0 && strstr(err, "change.csv"), "budget %ld: %s: %s", n,
                  cat_db_result_name(r), err);
        /* Nothing changed: old prices, no new product, a consistent index. */
        CHECK_MSG(price(db, "F-1") == 25900 && price(db, "F-2") == 5900 && price(db, "F-3") == -1,
                  "budget %ld: the failed import left changes", n);
        CHECK(sql_int(path, "SELECT count(*) FROM variants") == 3);
    }
    CHECK(done && failures > 20);
    printf("import: %d failed allocations tried before it went through\n", failures);
    CHECK(price(db, "F-1") == 29900 && price(db, "F-3") == 1900);
    CHECK(fts_consistent(path));
    CHECK(sql_int(path, "SELECT count(*) FROM pragma_integrity_check WHERE integrity_check <> "
                        "'ok'") == 0);

    /* Searches under failing allocations fail cleanly. */
    cat_search_hit hits[10];
    int n = 0, search_failures = 0;
    for (long b = 0; b < 5000; b++) {
        budget = b;
        failed = 0;
        cat_db_result r = cat_search(db, "fault towel", NULL, 10, hits, &n, err, sizeof err);
        budget = -1;
        if (r == CAT_DB_OK && failed == 0)
            break;
        search_failures += r != CAT_DB_OK;
    }
    CHECK(cat_search(db, "fault towel", NULL, 10, hits, &n, err, sizeof err) == CAT_DB_OK &&
          n == 1);
    printf("search: %d failed runs\n", search_failures);
    cat_db_close(db);
}

static void test_open(void)
{
    /* Building a catalog from shipped data: afterwards it is there and complete, or there is
     * nothing at all. */
    mkdir(tmp_path("src"), 0777);
    write_text("src/base.csv", base);
    char path[8200], src[8200];
    snprintf(path, sizeof path, "%s", tmp_path("built.sqlite"));
    snprintf(src, sizeof src, "%s", tmp_path("src"));
    int done = 0, failures = 0;
    for (long n = 0; n < 50000 && !done; n += n < 100 ? 1 : 41) {
        remove(path);
        cat_db *db = NULL;
        char err[1024] = "";
        budget = n;
        failed = 0;
        cat_db_result r = cat_catalog_open(path, src, &db, err, sizeof err);
        budget = -1;
        if (r == CAT_DB_OK) {
            done = 1;
            CHECK(price(db, "F-1") == 25900);
            cat_db_close(db);
            break;
        }
        failures++;
        CHECK_MSG(db == NULL && err[0] && failed > 0, "budget %ld: %s", n, err);
        if (access(path, F_OK) == 0) /* the rename happened: then the file must be complete */
            CHECK_MSG(sql_int(path, "SELECT count(*) FROM products") == 2, "budget %ld", n);
        CHECK_MSG(no_temporary_files(), "budget %ld left a temporary file", n);
    }
    CHECK(done && failures > 20);
    printf("open: %d failed allocations tried before it went through\n", failures);
}

int main(void)
{
    sqlite3_config(SQLITE_CONFIG_GETMALLOC, &real);
    sqlite3_mem_methods failing = real;
    failing.xMalloc = fail_malloc;
    failing.xRealloc = fail_realloc;
    if (sqlite3_config(SQLITE_CONFIG_MALLOC, &failing) != SQLITE_OK) {
        fprintf(stderr, "cannot install the failing allocator\n");
        return 1;
    }
    tmp_make();
    test_import();
    test_open();
    tmp_remove();
    return check_report("test_db_faults");
}
