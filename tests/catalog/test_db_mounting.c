/* Mounting heights and companions as catalog data (docs/catalog.md "Mounting heights and
 * companions"): good values land in the product and survive an export; a negative height, one
 * above any room, a height without its reference (or the reverse), an unknown reference, a
 * product naming itself and a companion that is in neither the file nor the catalog are each
 * refused with the file, the line and the column, and nothing is imported; a companion may come
 * later in the file or be in the catalog already; the shipped vanity units name their basin,
 * mixer and mirror; a version-5 catalog with products is migrated. */
#include "test_db_util.h"

#define HEADER                                                                                     \
    "manufacturer,article,category,name,width_mm,depth_mm,height_mm,list_price,"                   \
    "mounting_height_mm,mounting_to,companions\n"
#define ROW(article, category, h, to, comp)                                                        \
    "Testbad," article "," category ",Test " article ",600,500,170,100.00," h "," to "," comp "\n"

static cat_db_result import_text(cat_db *db, const char *name, const char *text,
                                 cat_import_report *rep, char *err, size_t err_size)
{
    const char *path = write_text(name, text);
    cat_db_result r = cat_import_csv(db, path, NULL, rep, err, err_size);
    CHECK_MSG(r == CAT_DB_OK || strstr(err, path), "the message does not name the file: %s", err);
    return r;
}

static void test_good_values(void)
{
    cat_db *db = open_catalog("good.sqlite", 0);
    cat_import_report rep;
    char err[2048] = "";
    /* The vanity names its basin before the basin's row, and a tap of another maker that an
     * earlier import brought. */
    CHECK(import_text(db, "tap.csv",
                      "manufacturer,article,category,name,width_mm,depth_mm,"
                      "height_mm,list_price\nOtherTap,OT-1,taps_mixers,Mixer,50,135,"
                      "165,99.00\n",
                      &rep, err, sizeof err) == CAT_DB_OK);
    cat_import_report_free(&rep);
    const char *csv = HEADER ROW("V-1", "vanity_units", "680", "top", "B-1; OtherTap:OT-1")
        ROW("B-1", "basins", "900", "rim", "") ROW("W-1", "wcs_bidets", "460", "seat", "")
            ROW("M-1", "mirrors", "1200", "bottom", "") ROW("X-1", "accessories", "", "", "");
    CHECK_MSG(import_text(db, "good.csv", csv, &rep, err, sizeof err) == CAT_DB_OK, "%s", err);
    print_problems(&rep);
    CHECK(rep.products_added == 5);
    cat_import_report_free(&rep);

    cat_product p;
    CHECK(cat_product_find(db, "Testbad", "B-1", &p, err, sizeof err) == CAT_DB_OK);
    CHECK(p.mounting_to == CAT_MOUNT_RIM && p.mounting_height_mm == 900);
    cat_product_free(&p);
    CHECK(cat_product_find(db, "Testbad", "W-1", &p, err, sizeof err) == CAT_DB_OK);
    CHECK(p.mounting_to == CAT_MOUNT_SEAT && p.mounting_height_mm == 460);
    cat_product_free(&p);
    CHECK(cat_product_find(db, "Testbad", "X-1", &p, err, sizeof err) == CAT_DB_OK);
    CHECK(p.mounting_to == CAT_MOUNT_NONE && p.mounting_height_mm == 0 && !p.companions[0]);
    cat_product_free(&p);
    CHECK(cat_product_find(db, "Testbad", "V-1", &p, err, sizeof err) == CAT_DB_OK);
    CHECK(p.mounting_to == CAT_MOUNT_TOP && p.mounting_height_mm == 680);
    char maker[64], article[64];
    CHECK(cat_companion_get(p.companions, 0, maker, sizeof maker, article, sizeof article) == 1 &&
          !maker[0] && !strcmp(article, "B-1"));
    CHECK(cat_companion_get(p.companions, 1, maker, sizeof maker, article, sizeof article) == 1 &&
          !strcmp(maker, "OtherTap") && !strcmp(article, "OT-1"));
    CHECK(cat_companion_get(p.companions, 2, maker, sizeof maker, article, sizeof article) == 0);
    cat_product_free(&p);

    /* A price list without the columns keeps them. */
    CHECK(import_text(db, "prices.csv", "manufacturer,article,list_price\nTestbad,B-1,120.00\n",
                      &rep, err, sizeof err) == CAT_DB_OK);
    cat_import_report_free(&rep);
    CHECK(cat_product_find(db, "Testbad", "B-1", &p, err, sizeof err) == CAT_DB_OK);
    CHECK(p.mounting_to == CAT_MOUNT_RIM && p.mounting_height_mm == 900 && p.price_cents == 12000);
    cat_product_free(&p);

    /* The export writes the columns back. */
    const char *out = tmp_path("export.csv");
    CHECK(cat_export_csv_file(db, out, NULL, err, sizeof err) == CAT_DB_OK);
    FILE *f = fopen(out, "rb");
    char text[8192] = "";
    size_t n = f ? fread(text, 1, sizeof text - 1, f) : 0;
    text[n] = 0;
    if (f)
        fclose(f);
    CHECK(strstr(text, ",mounting_height_mm,mounting_to,companions,") != NULL);
    CHECK(strstr(text, ",900,rim,,") != NULL);
    CHECK(strstr(text, ",680,top,B-1; OtherTap:OT-1,") != NULL);
    cat_db_close(db);
}

static void test_nonsense_refused(void)
{
    cat_db *db = open_catalog("bad.sqlite", 0);
    cat_import_report rep;
    char err[2048] = "";
    const char *csv = HEADER ROW("A-2", "basins", "-5", "rim", "") /* line 2 */
        ROW("A-3", "mirrors", "4200", "bottom", "")                /* line 3 */
        ROW("A-4", "basins", "850", "", "")                        /* line 4 */
        ROW("A-5", "basins", "", "rim", "")                        /* line 5 */
        ROW("A-6", "basins", "850", "middle", "")                  /* line 6 */
        ROW("A-7", "vanity_units", "680", "top", "A-7")            /* line 7 */
        ROW("A-8", "vanity_units", "680", "top", "A-2;NOPE-1")     /* line 8 */
        ROW("A-9", "vanity_units", "680", "top", "A-2;;A-3")       /* line 9 */
        ROW("A-10", "vanity_units", "680", "top", "Nobody:A-2");   /* line 10 */
    CHECK(import_text(db, "bad.csv", csv, &rep, err, sizeof err) == CAT_DB_ERR_INVALID);
    print_problems(&rep);
    CHECK(has_problem(&rep, 2, "mounting_height_mm", "between 0 and 4000"));
    CHECK(has_problem(&rep, 3, "mounting_height_mm", "above any room"));
    CHECK(has_problem(&rep, 4, "mounting_to", "is empty, but the row has a mounting height"));
    CHECK(has_problem(&rep, 5, "mounting_height_mm", "is empty"));
    CHECK(has_problem(&rep, 6, "mounting_to", "unknown mounting reference \"middle\""));
    CHECK(has_problem(&rep, 7, "companions", "names the product itself"));
    CHECK(has_problem(&rep, 8, "companions", "Testbad NOPE-1, is neither in this file nor"));
    CHECK(has_problem(&rep, 9, "companions", "entry 2 is empty"));
    CHECK(has_problem(&rep, 10, "companions", "Nobody A-2"));
    CHECK(rep.problem_count == 9);
    check_refused_import(db, &rep, err, "bad.csv:2: column mounting_height_mm:");
}

/* The shipped data: the vanity unit CE419501 (800 mm) comes with the series' 800 mm furniture
 * basin, a basin mixer and an 800 mm mirror, its top where that basin's rim is at 850; a
 * floor-standing WC stands on the floor. */
static void test_shipped(void)
{
    cat_db *db = open_catalog("shipped.sqlite", 1);
    char err[2048] = "", maker[64], article[64];
    cat_product v, b;
    CHECK_MSG(cat_product_find(db, "Cerana", "CE419501", &v, err, sizeof err) == CAT_DB_OK, "%s",
              err);
    CHECK(cat_companion_get(v.companions, 0, maker, sizeof maker, article, sizeof article) == 1);
    CHECK_MSG(cat_product_find(db, maker[0] ? maker : "Cerana", article, &b, err, sizeof err) ==
                  CAT_DB_OK,
              "%s", err);
    CHECK(b.category == CAT_CATEGORY_BASINS && b.width_mm == v.width_mm);
    CHECK(v.mounting_to == CAT_MOUNT_TOP && b.mounting_to == CAT_MOUNT_RIM);
    CHECK_NEAR(v.mounting_height_mm + b.height_mm, 850, 1e-9);
    CHECK(cat_companion_get(v.companions, 1, maker, sizeof maker, article, sizeof article) == 1 &&
          !strcmp(maker, "Aquavera"));
    CHECK(cat_companion_get(v.companions, 2, maker, sizeof maker, article, sizeof article) == 1 &&
          !strcmp(maker, "Vitrelux"));
    cat_product_free(&v);
    cat_product_free(&b);
    CHECK(sql_int(tmp_path("shipped.sqlite"),
                  "SELECT count(*) FROM products WHERE category = 'vanity_units' AND companions "
                  "<> ''") >= 12);
    CHECK(sql_int(tmp_path("shipped.sqlite"), "SELECT count(*) FROM products WHERE name LIKE "
                                              "'%close-coupled%' AND mounting_to = 'bottom' AND "
                                              "mounting_height_mm = 0") > 0);
    cat_db_close(db);
}

/* A version-5 catalog with products (the mounting columns dropped by hand) is migrated: the
 * columns come back empty, its products keep their category's mounting, and an import can
 * give them their own. */
static void test_migration_from_v5(void)
{
    cat_db *db = open_catalog("v5.sqlite", 0);
    cat_import_report rep;
    char err[2048] = "";
    CHECK(import_text(db, "v5.csv", HEADER ROW("V5-1", "basins", "", "", ""), &rep, err,
                      sizeof err) == CAT_DB_OK);
    cat_import_report_free(&rep);
    cat_db_close(db);
    const char *path = tmp_path("v5.sqlite");
    CHECK(sql_run(path, "ALTER TABLE products DROP COLUMN mounting_height_mm;"
                        "ALTER TABLE products DROP COLUMN mounting_to;"
                        "ALTER TABLE products DROP COLUMN companions;"
                        "ALTER TABLE variants DROP COLUMN pattern;"
                        "ALTER TABLE variants DROP COLUMN grain_deg;"
                        "PRAGMA user_version = 5;"));
    CHECK(sql_int(path, "PRAGMA user_version") == 5);
    db = NULL;
    CHECK_MSG(cat_catalog_open(path, NULL, &db, err, sizeof err) == CAT_DB_OK, "%s", err);
    CHECK(sql_int(path, "PRAGMA user_version") == CAT_DB_SCHEMA_VERSION);
    CHECK(sql_int(path, "SELECT count(*) FROM products WHERE mounting_height_mm IS NULL AND "
                        "mounting_to = '' AND companions = ''") == 1);
    cat_product p;
    CHECK(db && cat_product_find(db, "Testbad", "V5-1", &p, err, sizeof err) == CAT_DB_OK);
    CHECK(p.mounting_to == CAT_MOUNT_NONE && p.price_cents == 10000);
    cat_product_free(&p);
    CHECK(db && import_text(db, "v5b.csv", HEADER ROW("V5-1", "basins", "880", "rim", ""), &rep,
                            err, sizeof err) == CAT_DB_OK);
    cat_import_report_free(&rep);
    CHECK(db && cat_product_find(db, "Testbad", "V5-1", &p, err, sizeof err) == CAT_DB_OK);
    CHECK(p.mounting_to == CAT_MOUNT_RIM && p.mounting_height_mm == 880);
    cat_product_free(&p);
    cat_db_close(db);
}

int main(void)
{
    tmp_make();
    test_migration_from_v5();
    test_good_values();
    test_nonsense_refused();
    test_shipped();
    tmp_remove();
    return check_report("test_db_mounting");
}
