/* Search over the shipped catalog: a query's best hit is the product meant; prefixes match
 * ("therm" finds thermostats); article numbers and GTINs are found exactly, also without their
 * separators; the filters hold; and the latency is measured (printed, never judged). */
#include "test_db_util.h"

static cat_db *db;

/* The first hit of text (with an optional filter) must be named `name`. */
static void expect_best(const char *text, const cat_search_filter *f, const char *name)
{
    cat_search_hit hits[5];
    int n = 0;
    char err[512] = "";
    cat_db_result r = cat_search(db, text, f, 5, hits, &n, err, sizeof err);
    CHECK_MSG(r == CAT_DB_OK && n > 0 && !strcmp(hits[0].name, name),
              "\"%s\": expected \"%s\" first, got \"%s\" (%d hits) %s", text, name,
              n ? hits[0].name : "nothing", n, err);
}

static void test_ranking(void)
{
    expect_best("Orbis thermostatic bath mixer", NULL, "Orbis thermostatic bath mixer, exposed");
    expect_best("Arco double washbasin", NULL, "Arco double washbasin 1200 x 550");
    expect_best("Clara walk-in 1200", NULL, "Clara walk-in screen 1200");
    expect_best("Calacatta 1200 x 1200", NULL, "Calacatta Bianco field tile 1200 x 1200");
    expect_best("Pietra Antracite 600 x 600", NULL, "Pietra Antracite field tile 600 x 600");
    expect_best("zellige verde", NULL, "Zellige Verde field tile 100 x 100");
    expect_best("Ladder towel radiator 600 x 1775", NULL, "Ladder towel radiator 600 x 1775");
    expect_best("Ashby mirror cabinet 1300", NULL, "Ashby mirror cabinet 1300, 3 doors, LED");
    expect_best("Kensington towel bar 800", NULL, "Kensington towel bar 800");
    expect_best("Holmwood Kensington towel bar 800", NULL, "Kensington towel bar 800");
    /* Accents do not matter (remove_diacritics). */
    expect_best("hidr\xC3\xA1ulico liso gris", NULL, "Hidraulico Liso gris field tile 200 x 200");
    /* No product has every word: no hits, never some of the words (a dropped word would turn
     * "tile grey" into white tiles); the word to blame is named by cat_search_unmatched. */
    cat_search_hit hits[5];
    int n = -1;
    char err[512] = "";
    CHECK(cat_search(db, "Linea thermostatic bath mixer", NULL, 5, hits, &n, err, sizeof err) ==
          CAT_DB_OK);
    CHECK(n == 0);
    CHECK(cat_search(db, "Linea mixer", NULL, 5, hits, &n, err, sizeof err) == CAT_DB_OK);
    CHECK(n == 5);
    for (int i = 0; i < n; i++)
        CHECK_MSG(strstr(hits[i].name, "Linea") && strstr(hits[i].name, "mixer"), "%s",
                  hits[i].name);
}

static void test_prefix(void)
{
    cat_search_hit hits[50];
    int n = 0;
    char err[512];
    CHECK(cat_search(db, "therm", NULL, 50, hits, &n, err, sizeof err) == CAT_DB_OK);
    CHECK_MSG(n >= 20, "%d hits for \"therm\"", n);
    for (int i = 0; i < n; i++)
        CHECK_MSG(strstr(hits[i].name, "thermostat") || strstr(hits[i].name, "Thermostat"),
                  "\"therm\" found %s", hits[i].name);
    int whole = 0;
    CHECK(cat_search(db, "thermostatic", NULL, 50, hits, &whole, err, sizeof err) == CAT_DB_OK);
    CHECK(whole > 0 && whole <= n);
    CHECK(cat_search(db, "washb", NULL, 50, hits, &n, err, sizeof err) == CAT_DB_OK && n >= 10);
    CHECK(cat_search(db, "THERMO WALL", NULL, 50, hits, &n, err, sizeof err) == CAT_DB_OK);
    /* ("exposed thermostat" mixers are not wall-hung: nothing has both, so nothing) */
    CHECK(n == 0);
}

static void test_articles(void)
{
    cat_search_hit hits[10];
    int n = 0;
    char err[512];
    cat_product p;
    CHECK(cat_product_find(db, "Nordkeram", "NK-51244.00", &p, err, sizeof err) == CAT_DB_OK);
    const char *queries[] = {"NK-51244.00", "nk-51244.00", p.gtin, "NK5124400"};
    for (int i = 0; i < 4; i++) {
        CHECK(cat_search(db, queries[i], NULL, 10, hits, &n, err, sizeof err) == CAT_DB_OK);
        CHECK_MSG(n >= 1 && hits[0].product_id == p.id, "\"%s\": first hit %s", queries[i],
                  n ? hits[0].article : "none");
        CHECK(i == 3 || hits[0].exact == 1);
    }
    /* An article prefix finds that range. */
    CHECK(cat_search(db, "NK-512", NULL, 10, hits, &n, err, sizeof err) == CAT_DB_OK && n == 10);
    for (int i = 0; i < n; i++)
        CHECK(!strncmp(hits[i].article, "NK-512", 6));
    cat_product_free(&p);

    /* Looking up by GTIN and by article agree. */
    cat_product q;
    CHECK(cat_product_find(db, NULL, "4062345000158", &q, err, sizeof err) == CAT_DB_OK);
    CHECK(cat_product_find(db, NULL, q.article, &p, err, sizeof err) == CAT_DB_OK);
    CHECK(p.id == q.id && p.variant_count == q.variant_count);
    cat_product_free(&p);
    cat_product_free(&q);
}

static void test_filters(void)
{
    cat_search_hit hits[200];
    int n = 0;
    char err[512];
    cat_search_filter f = {.category = CAT_CATEGORY_BASINS, .max_width_mm = 600};
    CHECK(cat_search(db, "basin", &f, 200, hits, &n, err, sizeof err) == CAT_DB_OK && n >= 10);
    for (int i = 0; i < n; i++)
        CHECK(hits[i].category == CAT_CATEGORY_BASINS && hits[i].width_mm <= 600);
    f = (cat_search_filter){.manufacturer = "CERANA"};
    CHECK(cat_search(db, "arco", &f, 200, hits, &n, err, sizeof err) == CAT_DB_OK && n >= 10);
    for (int i = 0; i < n; i++)
        CHECK(!strcmp(hits[i].manufacturer, "Cerana"));
    f = (cat_search_filter){.manufacturer = "Nobody"};
    CHECK(cat_search(db, "arco", &f, 200, hits, &n, err, sizeof err) == CAT_DB_OK && n == 0);

    /* An empty text lists a category; limits hold. */
    f = (cat_search_filter){.category = CAT_CATEGORY_TILES};
    CHECK(cat_search(db, "", &f, 200, hits, &n, err, sizeof err) == CAT_DB_OK && n >= 60);
    for (int i = 0; i < n; i++)
        CHECK(hits[i].category == CAT_CATEGORY_TILES && hits[i].unit != CAT_UNIT_COUNT);
    CHECK(cat_search(db, "  ", NULL, 3, hits, &n, err, sizeof err) == CAT_DB_OK && n == 3);
    CHECK(cat_search(db, "mirror", NULL, 3, hits, &n, err, sizeof err) == CAT_DB_OK && n == 3);
    f = (cat_search_filter){.category = CAT_CATEGORY_SHOWER_TRAYS, .max_width_mm = 900};
    CHECK(cat_search(db, "shower tray", &f, 200, hits, &n, err, sizeof err) == CAT_DB_OK);
    CHECK(n >= 4);
    for (int i = 0; i < n; i++)
        CHECK(hits[i].width_mm <= 900 && hits[i].width_mm >= 800);
    /* An exact article number outside the filter is not shown. */
    f = (cat_search_filter){.category = CAT_CATEGORY_TILES};
    CHECK(cat_search(db, "NK-51244.00", &f, 10, hits, &n, err, sizeof err) == CAT_DB_OK && n == 0);
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* Latency over the shipped catalog: median of many queries. Printed; tests never judge time. */
static void test_latency(void)
{
    static const char *const words[] = {
        "mixer", "therm",         "basin 600",   "WC rimless",      "Pietra", "mirror",
        "towel", "Calacatta 600", "NK-51244.00", "shower tray 900", "lamp",   "oak"};
    enum { ROUNDS = 25 };
    double ms[ROUNDS * 12];
    int k = 0;
    cat_search_hit hits[20];
    char err[256];
    for (int r = 0; r < ROUNDS; r++)
        for (int i = 0; i < 12; i++) {
            int n;
            double t0 = now_ms();
            CHECK(cat_search(db, words[i], NULL, 20, hits, &n, err, sizeof err) == CAT_DB_OK);
            ms[k++] = now_ms() - t0;
        }
    qsort(ms, (size_t)k, sizeof ms[0], by_value);
    printf("search latency over the shipped catalog: median %.3f ms, p90 %.3f ms, max %.3f ms "
           "(%d queries)\n",
           ms[k / 2], ms[k * 9 / 10], ms[k - 1], k);
}

int main(void)
{
    tmp_make();
    db = open_catalog("shipped.sqlite", 1);
    test_ranking();
    test_prefix();
    test_articles();
    test_filters();
    test_latency();
    cat_db_close(db);
    tmp_remove();
    return check_report("test_db_search");
}
