/* Two processes on one catalog: `tessera catalog import` of a large CSV in one while this one
 * searches in a loop (a long-lived connection, and fresh opens) sees the catalog from before the
 * import or after it, never an error and never a count in between; and processes racing to build
 * a missing catalog all end up on the same file (each one's import lands in it).
 *
 * Usage: test_db_concurrent TESSERA_BINARY */
#define _GNU_SOURCE /* posix_spawn with environ */
#include "test_db_util.h"

#include <spawn.h>
#include <sys/wait.h>

extern char **environ;

#define MARKER "zorblat"
#define OLD_MARKED 3
#define BIG_ROWS 20000
#define BIG_MARKED 400 /* under the search's rank cap (1000), so the count is exact */

static const char header[] =
    "manufacturer,article,gtin,category,name,width_mm,depth_mm,height_mm,list_price\n";

/* rows products of "Concur" named "MARKER basin N" for the first `marked`, else "plain basin N". */
static const char *write_csv(const char *name, int first, int rows, int marked)
{
    const char *path = tmp_path(name);
    FILE *f = fopen(path, "w");
    if (!f) {
        perror(path);
        exit(2);
    }
    fputs(header, f);
    for (int i = 0; i < rows; i++)
        fprintf(f, "Concur,CC-%06d,,basins,%s basin %d,%d,450,150,%d.50\n", first + i,
                i < marked ? MARKER : "plain", first + i, 400 + i % 400, 100 + i % 900);
    if (fclose(f) != 0) {
        perror(path);
        exit(2);
    }
    return path;
}

static int count_marked(cat_db *db, char *err, size_t err_size)
{
    static cat_search_hit hits[2000];
    int n = -1;
    if (cat_search(db, MARKER, NULL, 2000, hits, &n, err, err_size) != CAT_DB_OK)
        return -1;
    return n;
}

static long long product_count(cat_db *db, char *err, size_t err_size)
{
    cat_db_stats st;
    return cat_db_get_stats(db, &st, err, err_size) == CAT_DB_OK ? st.products : -1;
}

static int journal_mode_is_wal(const char *path)
{
    sqlite3 *s = NULL;
    sqlite3_stmt *st = NULL;
    int wal = sqlite3_open_v2(path, &s, SQLITE_OPEN_READONLY, NULL) == SQLITE_OK &&
              sqlite3_prepare_v2(s, "PRAGMA journal_mode", -1, &st, NULL) == SQLITE_OK &&
              sqlite3_step(st) == SQLITE_ROW &&
              strcmp((const char *)sqlite3_column_text(st, 0), "wal") == 0;
    sqlite3_finalize(st);
    sqlite3_close(s);
    return wal;
}

static void search_during_import(const char *tessera)
{
    cat_db *db = open_catalog("live.sqlite", 1);
    char err[4096];
    cat_import_report rep = {0};
    CHECK_MSG(cat_import_csv(db, write_csv("old.csv", 0, OLD_MARKED, OLD_MARKED), NULL, &rep, err,
                             sizeof err) == CAT_DB_OK,
              "%s", err);
    cat_import_report_free(&rep);
    const char *big = write_csv("big.csv", 1000, BIG_ROWS, BIG_MARKED);
    long long old_products = product_count(db, err, sizeof err);
    long long new_products = old_products + BIG_ROWS;
    CHECK(count_marked(db, err, sizeof err) == OLD_MARKED);

    char *argv[] = {(char *)tessera,
                    "catalog",
                    "import",
                    (char *)big,
                    "--db",
                    (char *)tmp_path("live.sqlite"),
                    NULL};
    pid_t pid;
    CHECK(posix_spawn(&pid, tessera, NULL, NULL, argv, environ) == 0);
    int searches = 0, failures = 0, wrong = 0, saw_old = 0, saw_new = 0, status = 0;
    double slowest = 0, t_start = now_ms();
    for (int done = 0; !done;) {
        done = waitpid(pid, &status, WNOHANG) == pid; /* one more round after the exit */
        double t0 = now_ms();
        /* Every fourth round a fresh open, as a new window or `tessera catalog search` does. */
        cat_db *use = db;
        if (searches % 4 == 3 && cat_catalog_open(tmp_path("live.sqlite"), TESSERA_CATALOG_SOURCE,
                                                  &use, err, sizeof err) != CAT_DB_OK) {
            fprintf(stderr, "open during the import failed: %s\n", err);
            failures++;
            searches++;
            continue;
        }
        int n = count_marked(use, err, sizeof err);
        long long products = product_count(use, err, sizeof err);
        if (use != db)
            cat_db_close(use);
        double t = now_ms() - t0;
        slowest = t > slowest ? t : slowest;
        searches++;
        if (n < 0 || products < 0) {
            fprintf(stderr, "search %d during the import failed: %s\n", searches, err);
            failures++;
        } else if (!(n == OLD_MARKED || n == OLD_MARKED + BIG_MARKED) ||
                   !(products == old_products || products == new_products)) {
            /* the search and the counts are separate reads: each must see a whole catalog */
            fprintf(stderr, "search %d saw %d marked of %lld products (old %d/%lld, new %d/%lld)\n",
                    searches, n, products, OLD_MARKED, old_products, OLD_MARKED + BIG_MARKED,
                    new_products);
            wrong++;
        }
        saw_old += n == OLD_MARKED;
        saw_new += n == OLD_MARKED + BIG_MARKED;
    }
    double total = now_ms() - t_start;
    printf("%d searches in %.0f ms during the import (%d saw the old catalog, %d the new); "
           "slowest %.1f ms\n",
           searches, total, saw_old, saw_new, slowest);
    CHECK_MSG(WIFEXITED(status) && WEXITSTATUS(status) == 0, "the import exited with status %d",
              status);
    CHECK_MSG(failures == 0, "%d of %d searches failed", failures, searches);
    CHECK_MSG(wrong == 0, "%d of %d searches saw half a catalog", wrong, searches);
    CHECK_MSG(saw_old >= 3, "only %d searches ran while the import was under way", saw_old);
    CHECK(saw_new >= 1);
    CHECK(count_marked(db, err, sizeof err) == OLD_MARKED + BIG_MARKED);
    CHECK(product_count(db, err, sizeof err) == new_products);
    /* A reader never waits for the writer: a search is milliseconds even while the import's
     * transaction is open (a rollback-journal catalog makes it wait for the commit). */
    CHECK_MSG(slowest < 2000, "a search took %.0f ms during the import", slowest);
    cat_db_close(db);
    CHECK(journal_mode_is_wal(tmp_path("live.sqlite")));
}

/* Children build the same missing catalog at once, each imports one product of its own and
 * reports the products it then sees; every import must be in the one file that stays. */
#define RACERS 4

static void racing_builds(int round)
{
    char race_name[64];
    snprintf(race_name, sizeof race_name, "race-%d.sqlite", round);
    const char *path = tmp_path(race_name);
    int ready[2];
    if (pipe(ready) != 0) {
        perror("pipe");
        exit(2);
    }
    pid_t kids[RACERS];
    for (int k = 0; k < RACERS; k++) {
        char name[32];
        snprintf(name, sizeof name, "race-%d-%d.csv", round, k);
        const char *csv = tmp_path(name);
        FILE *f = fopen(csv, "w");
        if (!f)
            exit(2);
        fprintf(f, "%sRace,R-%d,,basins,racer %d basin,500,400,150,99.00\n", header, k, k);
        fclose(f);
        kids[k] = fork();
        if (kids[k] == 0) {
            close(ready[1]);
            char go;
            if (read(ready[0], &go, 1) != 1) /* all start together */
                _exit(3);
            cat_db *db = NULL;
            char err[4096];
            if (cat_catalog_open(path, TESSERA_CATALOG_SOURCE, &db, err, sizeof err) != CAT_DB_OK) {
                fprintf(stderr, "racer %d: %s\n", k, err);
                _exit(4);
            }
            int rc = cat_import_csv(db, csv, NULL, NULL, err, sizeof err) == CAT_DB_OK ? 0 : 5;
            if (rc)
                fprintf(stderr, "racer %d: %s\n", k, err);
            cat_db_close(db);
            _exit(rc);
        }
    }
    close(ready[0]);
    char go[RACERS] = {0};
    if (write(ready[1], go, RACERS) != RACERS)
        perror("write");
    close(ready[1]);
    for (int k = 0; k < RACERS; k++) {
        int status = 0;
        waitpid(kids[k], &status, 0);
        CHECK_MSG(WIFEXITED(status) && WEXITSTATUS(status) == 0, "racer %d: status %d", k, status);
    }
    CHECK_MSG(sql_int(path, "SELECT count(*) FROM products WHERE article LIKE 'R-%'") == RACERS,
              "%lld of %d racers' products are in the catalog",
              sql_int(path, "SELECT count(*) FROM products WHERE article LIKE 'R-%'"), RACERS);
    char tmp_left[8200];
    snprintf(tmp_left, sizeof tmp_left, "ls %s | grep -q tmp-", g_tmp);
    CHECK_MSG(system(tmp_left) != 0, "a temporary catalog was left in %s", g_tmp);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: %s TESSERA_BINARY\n", argv[0]);
        return 2;
    }
    tmp_make();
    search_during_import(argv[1]);
    for (int round = 0; round < 3; round++) /* the race is a matter of timing: three tries */
        racing_builds(round);
    tmp_remove();
    return check_report("db_concurrent");
}
