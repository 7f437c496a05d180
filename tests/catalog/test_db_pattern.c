/* A variant's pattern and grain as catalog data (docs/catalog.md "The import format"): good
 * values land in the variant and an export writes them back (export -> import -> export gives
 * the same bytes); an unknown pattern word, a grain that is neither a word nor an angle of 0 to
 * 180, and a pattern on a row without a variant are each refused with the file, the line and
 * the column, and nothing is imported; the shipped oak and walnut finishes are wood; a
 * version-7 catalog is migrated with its variants plain. */
#include "test_db_util.h"

#define HEADER                                                                                     \
    "manufacturer,article,category,name,width_mm,depth_mm,height_mm,list_price,variant_code,"      \
    "variant_name,diffuse,pattern,grain\n"
#define ROW(article, code, pattern, grain)                                                         \
    "Testbad," article ",vanity_units,Test " article ",600,460,520,599.00," code ",Finish " code   \
    ",0.55 0.4 0.26," pattern "," grain "\n"

static cat_db_result import_text(cat_db *db, const char *name, const char *text,
                                 cat_import_report *rep, char *err, size_t err_size)
{
    const char *path = write_text(name, text);
    cat_db_result r = cat_import_csv(db, path, NULL, rep, err, err_size);
    CHECK_MSG(r == CAT_DB_OK || strstr(err, path), "the message does not name the file: %s", err);
    return r;
}

static const cat_variant *variant_of(const cat_product *p, const char *code)
{
    for (int i = 0; i < p->variant_count; i++)
        if (!strcmp(p->variants[i].code, code))
            return &p->variants[i];
    return NULL;
}

static void test_good_values_and_round_trip(void)
{
    cat_db *db = open_catalog("good.sqlite", 0);
    cat_import_report rep;
    char err[2048] = "";
    const char *csv = HEADER ROW("V-1", "OK", "wood", "") ROW("V-1", "WG", "", "")
        ROW("V-1", "WN", "wood", "vertical") ROW("V-2", "OK", "Wood", "horizontal")
            ROW("V-2", "SL", "wood", "30") ROW("V-2", "XX", "none", "");
    CHECK_MSG(import_text(db, "good.csv", csv, &rep, err, sizeof err) == CAT_DB_OK, "%s", err);
    print_problems(&rep);
    cat_import_report_free(&rep);

    cat_product p;
    CHECK(cat_product_find(db, "Testbad", "V-1", &p, err, sizeof err) == CAT_DB_OK);
    const cat_variant *ok = variant_of(&p, "OK"), *wg = variant_of(&p, "WG"),
                      *wn = variant_of(&p, "WN");
    CHECK(ok && ok->material.pattern == CAT_PATTERN_WOOD &&
          ok->material.grain_deg == CAT_GRAIN_LONG);
    CHECK(wg && wg->material.pattern == CAT_PATTERN_NONE);
    CHECK(wn && wn->material.pattern == CAT_PATTERN_WOOD && wn->material.grain_deg == 90.0f);
    cat_product_free(&p);
    CHECK(cat_product_find(db, "Testbad", "V-2", &p, err, sizeof err) == CAT_DB_OK);
    const cat_variant *h = variant_of(&p, "OK"), *sl = variant_of(&p, "SL"),
                      *xx = variant_of(&p, "XX");
    CHECK(h && h->material.pattern == CAT_PATTERN_WOOD && h->material.grain_deg == 0.0f);
    CHECK(sl && sl->material.grain_deg == 30.0f);
    CHECK(xx && xx->material.pattern == CAT_PATTERN_NONE);
    cat_product_free(&p);

    /* The export writes both columns back, none and "along the longer side" as empty cells. */
    const char *out = tmp_path("export.csv");
    CHECK(cat_export_csv_file(db, out, NULL, err, sizeof err) == CAT_DB_OK);
    char *text = read_all(out, NULL);
    CHECK(text && strstr(text, ",ior,pattern,grain,tile_type,"));
    CHECK(text && strstr(text, ",WN,Finish WN,0.00,") && strstr(text, ",1.5,wood,vertical,"));
    CHECK(text && strstr(text, ",1.5,wood,horizontal,") && strstr(text, ",1.5,wood,30,"));
    CHECK(text && strstr(text, ",1.5,wood,,"));
    cat_db_close(db);

    /* Into an empty catalog and out again: the same bytes. */
    cat_db *again = open_catalog("again.sqlite", 0);
    CHECK_MSG(import_text(again, "export-copy.csv", text ? text : "", &rep, err, sizeof err) ==
                  CAT_DB_OK,
              "%s", err);
    cat_import_report_free(&rep);
    const char *out2 = tmp_path("export2.csv");
    CHECK(cat_export_csv_file(again, out2, NULL, err, sizeof err) == CAT_DB_OK);
    char *text2 = read_all(out2, NULL);
    CHECK_MSG(text && text2 && !strcmp(text, text2), "the second export differs");
    free(text);
    free(text2);
    cat_db_close(again);
}

static void test_nonsense_refused(void)
{
    cat_db *db = open_catalog("bad.sqlite", 0);
    cat_import_report rep;
    char err[2048] = "";
    const char *csv = HEADER ROW("B-1", "OK", "marble", "")                /* line 2 */
        ROW("B-2", "OK", "wood", "diagonal")                               /* line 3 */
        ROW("B-3", "OK", "wood", "200")                                    /* line 4 */
        "Testbad,B-4,vanity_units,Test B-4,600,460,520,599.00,,,,wood,\n"; /* line 5 */
    CHECK(import_text(db, "bad.csv", csv, &rep, err, sizeof err) == CAT_DB_ERR_INVALID);
    print_problems(&rep);
    CHECK(has_problem(&rep, 2, "pattern", "unknown pattern \"marble\" (known: none, wood)"));
    CHECK(has_problem(&rep, 3, "grain", "must be horizontal, vertical or an angle of 0 to 180"));
    CHECK(has_problem(&rep, 3, "grain", "\"diagonal\""));
    CHECK(has_problem(&rep, 4, "grain", "\"200\""));
    CHECK(has_problem(&rep, 5, "variant_code", "is empty, but the row has other variant values"));
    CHECK(rep.problem_count == 4);
    check_refused_import(db, &rep, err, "bad.csv:2: column pattern: unknown pattern \"marble\"");
}

/* The shipped furniture: every oak and walnut veneer is wood, the lacquers are not. */
static void test_shipped(void)
{
    cat_db *db = open_catalog("shipped.sqlite", 1);
    cat_db_close(db);
    const char *path = tmp_path("shipped.sqlite");
    long long wooden = sql_int(path, "SELECT count(*) FROM variants WHERE pattern = 'wood'");
    long long veneers =
        sql_int(path, "SELECT count(*) FROM variants WHERE name LIKE '%oak veneer%' OR "
                      "name LIKE '%walnut veneer%'");
    printf("shipped: %lld wooden variants, %lld oak and walnut veneers\n", wooden, veneers);
    CHECK(veneers >= 20 && wooden == veneers);
    CHECK(sql_int(path, "SELECT count(*) FROM variants WHERE pattern = 'wood' AND name NOT LIKE "
                        "'%veneer%'") == 0);
}

/* A version-7 catalog (the two columns dropped by hand) is migrated: its variants are plain. */
static void test_migration_from_v7(void)
{
    cat_db *db = open_catalog("v7.sqlite", 0);
    cat_import_report rep;
    char err[2048] = "";
    CHECK(import_text(db, "v7.csv", HEADER ROW("V7-1", "OK", "wood", "vertical"), &rep, err,
                      sizeof err) == CAT_DB_OK);
    cat_import_report_free(&rep);
    cat_db_close(db);
    const char *path = tmp_path("v7.sqlite");
    CHECK(sql_run(path, "ALTER TABLE variants DROP COLUMN pattern;"
                        "ALTER TABLE variants DROP COLUMN grain_deg;"
                        "PRAGMA user_version = 7;"));
    db = NULL;
    CHECK_MSG(cat_catalog_open(path, NULL, &db, err, sizeof err) == CAT_DB_OK, "%s", err);
    CHECK(sql_int(path, "PRAGMA user_version") == CAT_DB_SCHEMA_VERSION);
    CHECK(sql_int(path, "SELECT count(*) FROM variants WHERE pattern = 'none' AND grain_deg IS "
                        "NULL") == 1);
    cat_product p;
    CHECK(db && cat_product_find(db, "Testbad", "V7-1", &p, err, sizeof err) == CAT_DB_OK);
    CHECK(p.variant_count == 1 && p.variants[0].material.pattern == CAT_PATTERN_NONE);
    cat_product_free(&p);
    cat_db_close(db);
}

int main(void)
{
    tmp_make();
    test_good_values_and_round_trip();
    test_nonsense_refused();
    test_shipped();
    test_migration_from_v7();
    tmp_remove();
    return check_report("test_db_pattern");
}
