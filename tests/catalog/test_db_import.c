/* CSV import: a good file lands completely; a file with one bad row changes nothing (the
 * database file keeps its bytes) and names the row and column; several bad rows are all
 * reported; re-importing updates prices and texts without duplicating products; quoting, CRLF,
 * a byte order mark and UTF-8 are handled. */
#include "test_db_util.h"

#define HEADER                                                                                     \
    "manufacturer,article,gtin,category,series,name,short_text,long_text,width_mm,depth_mm,"       \
    "height_mm,list_price,vat_percent,unit,variant_code,variant_name,variant_surcharge,diffuse,"   \
    "specular,shininess,reflectivity,glossiness,blend,transparency,ior,tile_type,nominal_w_mm,"    \
    "nominal_h_mm,work_w_mm,work_h_mm,grout_mm,thickness_mm,surface,m2_per_box,pieces_per_box,"    \
    "texture\n"
#define NO_TILE ",,,,,,,,,,,"
#define CHROME ",CP,Chrome,0,0.05 0.05 0.05,0.95 0.95 0.95,2000,0.8,0.9,mix,0,1.5"
#define BLACK ",BM,Black matt,45.00,0.03 0.03 0.03,0.15 0.15 0.15,40,0.04,0.3,fresnel,0,1.5"
#define WHITE ",WH,White alpine,0,0.92 0.92 0.9,0.6 0.6 0.6,256,0.1,0.6,fresnel,0,1.5"
#define TAP                                                                                        \
    "Testbad,TB-1,4006381333931,taps_mixers,Uno,Uno basin mixer 100,\"Basin mixer, 5 l/min\","     \
    "A mixer.,50,135,165,149.00,19,piece"
#define BASIN                                                                                      \
    "Testbad,TB-2,,basins,Uno,Uno washbasin 600 x 550,Washbasin,,600,550,175,259.00,19,piece"
#define TILE                                                                                       \
    "Testtile,TT-1,8712345000011,tiles,Pietra,Pietra Grigio field tile 300 x 600,,,,,,39.90,19,"   \
    "m2,MT,\"Grigio, matt\",0,0.52 0.52 0.5,0.1 0.1 0.1,16,0.03,0.25,fresnel,0,1.5,UNI,300,600,"   \
    "297,597,3,10,matt,1.44,8,textures/tiles/pietra.png"

/* Lines 2-5: two products with 3 variants, a tile with one. */
static const char base_csv[] =
    HEADER TAP CHROME NO_TILE "\n" TAP BLACK NO_TILE "\n" BASIN WHITE NO_TILE "\n" TILE "\n";

static cat_db_result import_text(cat_db *db, const char *name, const char *text,
                                 cat_import_report *rep, const cat_import_desc *desc)
{
    char err[2048];
    const char *path = write_text(name, text);
    cat_db_result r = cat_import_csv(db, path, desc, rep, err, sizeof err);
    if (r != CAT_DB_OK && !strstr(err, path))
        fprintf(stderr, "%s: the message does not name the file: %s\n", name, err);
    CHECK(r == CAT_DB_OK || strstr(err, path));
    return r;
}

static long long count(cat_db *db, const char *what)
{
    cat_db_stats s;
    if (cat_db_get_stats(db, &s, NULL, 0) != CAT_DB_OK)
        return -1;
    return !strcmp(what, "products")   ? s.products
           : !strcmp(what, "variants") ? s.variants
                                       : s.tiles;
}

static void test_good_file(void)
{
    cat_db *db = open_catalog("good.sqlite", 0);
    cat_import_report rep;
    CHECK(import_text(db, "base.csv", base_csv, &rep, NULL) == CAT_DB_OK);
    print_problems(&rep);
    CHECK(rep.rows == 4 && rep.products_added == 3 && rep.products_updated == 0 &&
          rep.variants_written == 4 && rep.problem_count == 0);
    cat_import_report_free(&rep);
    CHECK(count(db, "products") == 3 && count(db, "variants") == 4 && count(db, "tiles") == 1);

    cat_product p;
    char err[512];
    CHECK(cat_product_find(db, "Testbad", "TB-1", &p, err, sizeof err) == CAT_DB_OK);
    CHECK(!strcmp(p.short_text, "Basin mixer, 5 l/min") && p.price_cents == 14900);
    CHECK(p.width_mm == 50 && p.depth_mm == 135 && p.height_mm == 165 && p.vat_percent == 19);
    CHECK(!strcmp(p.gtin, "4006381333931") && !strcmp(p.currency, "EUR") && p.shipped == 0);
    CHECK(p.variant_count == 2 && !strcmp(p.variants[0].code, "BM") &&
          p.variants[0].surcharge_cents == 4500);
    const cat_render_material *chrome = &p.variants[1].material;
    CHECK_NEAR(chrome->reflectivity, 0.8, 1e-6);
    CHECK_NEAR(chrome->glossiness, 0.9, 1e-6);
    CHECK_NEAR(chrome->ambient[0], 0.05, 1e-6); /* ambient follows diffuse when not given */
    CHECK(chrome->blend == CAT_BLEND_MIX && p.variants[0].material.blend == CAT_BLEND_FRESNEL);
    cat_product_free(&p);

    /* A tile without width, depth and height takes them from its work size and thickness. */
    CHECK(cat_product_find(db, NULL, "tt-1", &p, err, sizeof err) == CAT_DB_OK);
    CHECK(p.has_tile && p.width_mm == 297 && p.depth_mm == 10 && p.height_mm == 597);
    CHECK(p.tile.grout_mm == 3 && p.tile.pieces_per_box == 8 && p.tile.surface == CAT_SURFACE_MATT);
    CHECK(!strcmp(p.tile.texture, "textures/tiles/pietra.png") && p.unit == CAT_UNIT_M2);
    CHECK(!strcmp(p.variants[0].name, "Grigio, matt"));
    cat_product_free(&p);
    CHECK(fts_consistent(tmp_path("good.sqlite")));
    cat_db_close(db);
}

static void test_one_bad_row(void)
{
    cat_db *db = open_catalog("onebad.sqlite", 0);
    const char *path = tmp_path("onebad.sqlite");
    cat_import_report rep;
    CHECK(import_text(db, "base1.csv", base_csv, &rep, NULL) == CAT_DB_OK);
    cat_import_report_free(&rep);
    size_t size_before;
    char *before = read_all(path, &size_before);

    /* Prices change in every row, a new product comes, but line 6 has a broken GTIN. */
    static const char bad[] =
        HEADER "Testbad,TB-1,4006381333931,taps_mixers,Uno,Uno basin mixer 100,x,,50,135,165,"
               "999.00,19,piece" CHROME NO_TILE "\n"
               "Testbad,TB-1,4006381333931,taps_mixers,Uno,Uno basin mixer 100,x,,50,135,165,"
               "999.00,19,piece" BLACK NO_TILE "\n" BASIN WHITE NO_TILE "\n"
               "Testbad,TB-3,,basins,Uno,Uno hand basin 450 x 350,,,450,350,140,139.00,19,"
               "piece" WHITE NO_TILE "\n"
               "Testbad,TB-4,4006381333932,basins,Uno,Uno hand basin 360,,,360,250,130,119.00,19,"
               "piece" WHITE NO_TILE "\n";
    char err[2048];
    const char *csv = write_text("onebad.csv", bad);
    cat_db_result r = cat_import_csv(db, csv, NULL, &rep, err, sizeof err);
    CHECK_MSG(r == CAT_DB_ERR_INVALID, "%s", cat_db_result_name(r));
    CHECK(rep.problem_count == 1 && rep.problems_kept == 1);
    CHECK(has_problem(&rep, 6, "gtin", "check digit of 4006381333932 is 2, expected 1"));
    print_problems(&rep);
    CHECK_MSG(strstr(err, "onebad.csv:6: column gtin:") && strstr(err, "nothing was imported"),
              "%s", err);
    CHECK(rep.products_added == 0 && rep.products_updated == 0);
    cat_import_report_free(&rep);

    /* Row for row and byte for byte what it was. */
    CHECK(count(db, "products") == 3 && count(db, "variants") == 4);
    cat_product p;
    CHECK(cat_product_find(db, "Testbad", "TB-1", &p, err, sizeof err) == CAT_DB_OK);
    CHECK(p.price_cents == 14900);
    cat_product_free(&p);
    size_t size_after;
    char *after = read_all(path, &size_after);
    CHECK(before && after && size_before == size_after && memcmp(before, after, size_before) == 0);
    free(before);
    free(after);
    cat_db_close(db);
}

static void test_many_bad_rows(void)
{
    cat_db *db = open_catalog("manybad.sqlite", 0);
    static const char bad[] = HEADER
        /* 2 */
        "A,A-1,,sinks,S,Basin,,,600,550,175,259.00,19,piece" WHITE NO_TILE "\n"
        /* 3 */ "A,A-2,,basins,S,Basin,,,nan,550,175,259.00,19,piece" WHITE NO_TILE "\n"
        /* 4 */ "A,A-3,,basins,S,Basin,,,600,550,175,-5,19,piece" WHITE NO_TILE "\n"
        /* 5 */ "A,A-4,,basins,S,Basin,,,600,550,175,259.00,19,piece"
        ",WH,White,0,0.9 0.9 0.9,0.5 0.5 0.5,100,0.1,0.6,shiny,0,1.5" NO_TILE "\n"
        /* 6 */ "A,A-5,,tiles,S,Tile,,,,,,39.90,19,m2,MT,Matt,0,0.5 0.5 0.5,0.1 0.1 0.1,16,0.03,"
        "0.25,fresnel,0,1.5,UNI,300,600,297,597,2,10,matt,1.44,8,\n"
        /* 7 */ "A,A-6,,basins,S,Basin,,,600,550\n"
        /* 8 */ "A,A-7,,basins,S,Basin,,,600,550,175,259.00,19,piece"
        ",WH,White,0,0.9 0.9 0.9,0.5 0.5 0.5,100,1.5,0.6,mix,0,1.5" NO_TILE "\n"
        /* 9 */ "A,A-8,,basins,S,Basin,,,600,550,175,259.00,abc,piece" WHITE NO_TILE "\n"
        /* 10 */ "A,A-9,,basins,S,Basin,,,600,inf,175,\"1,259.00\",19,piece" WHITE NO_TILE "\n"
        /* 11 */ "A,A-10,,basins,S,Basin,,,1e999,550,175,259.001,19,pieces" WHITE NO_TILE "\n"
        /* 12 */ "A,A-11,,basins,S,Basin,,,600,550,175,259.00,19,piece,WH,,0,0.9 0.9,,,,,,," NO_TILE
        "\n"
        /* 13 */ "A,A-12,,basins,S,,,,600,550,175,259.00,19,piece" WHITE NO_TILE "\n"
        /* 14 */ "A,A-13,,basins,S,Basin,,,600,550,175,259.00,19,piece" WHITE
        ",UNI,300,600,297,597,3,10,matt,1.44,8,\n"
        /* 15 */ "A,A-14,,basins,S,Basin,,,600,550,175,259.00,19,piece" WHITE NO_TILE "\n"
        /* 16 */ "A,A-14,,basins,S,Basin,,,600,550,175,269.00,19,piece" WHITE NO_TILE "\n"
        /* 17 */ "A,A-15,,tiles,S,Tile,,,,,,39.90,19,m2,MT,Matt,0,0.5 0.5 0.5,0.1 0.1 0.1,16,"
        "0.03,0.25,fresnel,0,1.5,UNI,300,600,297,597,3,10,matt,9.5,8,../../etc/passwd\n";
    cat_import_report rep;
    CHECK(import_text(db, "manybad.csv", bad, &rep, NULL) == CAT_DB_ERR_INVALID);
    print_problems(&rep);
    CHECK(has_problem(&rep, 2, "category", "unknown category \"sinks\""));
    CHECK(has_problem(&rep, 3, "width_mm", "finite"));
    CHECK(has_problem(&rep, 4, "list_price", "must be positive"));
    CHECK(has_problem(&rep, 5, "blend", "unknown blend mode \"shiny\""));
    CHECK(has_problem(&rep, 6, "nominal_w_mm", "grout"));
    CHECK(has_problem(&rep, 6, "nominal_h_mm", "grout"));
    CHECK(has_problem(&rep, 7, "", "10 fields, the header has 36"));
    CHECK(has_problem(&rep, 8, "reflectivity", "between 0 and 1"));
    CHECK(has_problem(&rep, 9, "vat_percent", "expected a number"));
    CHECK(has_problem(&rep, 10, "depth_mm", "finite"));
    CHECK(has_problem(&rep, 10, "list_price", "decimal point, no thousands separator"));
    CHECK(has_problem(&rep, 11, "width_mm", "finite"));
    CHECK(has_problem(&rep, 11, "list_price", "more than two decimals"));
    CHECK(has_problem(&rep, 11, "unit", "unknown unit"));
    CHECK(has_problem(&rep, 12, "variant_name", "needs a name"));
    CHECK(has_problem(&rep, 12, "diffuse", "three numbers"));
    CHECK(has_problem(&rep, 13, "name", "is empty"));
    CHECK(has_problem(&rep, 14, "tile_type", "only for products of category tiles"));
    CHECK(has_problem(&rep, 16, "list_price", "differs from line 15"));
    CHECK(has_problem(&rep, 16, "variant_code", "already on line 15"));
    CHECK(has_problem(&rep, 17, "m2_per_box", "does not match 8 pieces"));
    CHECK(has_problem(&rep, 17, "texture", "inside the assets folder"));
    CHECK_MSG(rep.problem_count == 22, "%ld problems", rep.problem_count);
    CHECK(rep.rows == 16);
    cat_import_report_free(&rep);
    CHECK(count(db, "products") == 0);
    cat_db_close(db);
}

static void test_reimport(void)
{
    cat_db *db = open_catalog("reimport.sqlite", 0);
    cat_import_report rep;
    CHECK(import_text(db, "base2.csv", base_csv, &rep, NULL) == CAT_DB_OK);
    cat_import_report_free(&rep);

    /* The same file with new prices and texts, keys in another case: updated, not added. */
    char *changed = strdup(base_csv);
    for (char *p; (p = strstr(changed, "149.00"));)
        memcpy(p, "159.50", 6);
    for (char *p; (p = strstr(changed, "Testbad,TB-"));)
        memcpy(p, "TESTBAD,tb-", 11);
    for (char *p; (p = strstr(changed, "A mixer."));)
        memcpy(p, "B mixer!", 8);
    CHECK(import_text(db, "changed.csv", changed, &rep, NULL) == CAT_DB_OK);
    print_problems(&rep);
    CHECK(rep.products_added == 0 && rep.products_updated == 3 && rep.variants_written == 4);
    cat_import_report_free(&rep);
    free(changed);
    CHECK(count(db, "products") == 3 && count(db, "variants") == 4 && count(db, "tiles") == 1);
    cat_product p;
    char err[512];
    CHECK(cat_product_find(db, "testbad", "TB-1", &p, err, sizeof err) == CAT_DB_OK);
    CHECK(p.price_cents == 15950 && !strcmp(p.long_text, "B mixer!") &&
          !strcmp(p.article, "tb-1") && !strcmp(p.manufacturer, "Testbad"));
    cat_product_free(&p);

    /* A price list: only the price changes; texts, variants and tile data stay. */
    CHECK(import_text(db, "prices.csv",
                      "manufacturer,article,list_price\n"
                      "Testbad,TB-2,199.00\nTesttile,TT-1,41.50\n",
                      &rep, NULL) == CAT_DB_OK);
    CHECK(rep.products_updated == 2 && rep.products_added == 0);
    cat_import_report_free(&rep);
    CHECK(cat_product_find(db, "Testbad", "TB-2", &p, err, sizeof err) == CAT_DB_OK);
    CHECK(p.price_cents == 19900 && !strcmp(p.name, "Uno washbasin 600 x 550") &&
          p.variant_count == 1 && !strcmp(p.series, "Uno"));
    cat_product_free(&p);
    CHECK(cat_product_find(db, "Testtile", "TT-1", &p, err, sizeof err) == CAT_DB_OK);
    CHECK(p.price_cents == 4150 && p.has_tile && p.tile.nominal_h_mm == 600 && p.height_mm == 597);
    cat_product_free(&p);
    CHECK(count(db, "products") == 3 && count(db, "variants") == 4 && count(db, "tiles") == 1);

    /* A price list naming a product the catalog does not have cannot create it. */
    CHECK(import_text(db, "unknown.csv", "manufacturer,article,list_price\nTestbad,TB-9,10.00\n",
                      &rep, NULL) == CAT_DB_ERR_INVALID);
    CHECK(has_problem(&rep, 2, "category", "not in the catalog yet"));
    CHECK(has_problem(&rep, 2, "name", "not in the catalog yet"));
    cat_import_report_free(&rep);

    /* Variant columns replace a product's variants: here the tap keeps only chrome. */
    static const char one_variant[] = HEADER TAP CHROME NO_TILE "\n";
    CHECK(import_text(db, "one-variant.csv", one_variant, &rep, NULL) == CAT_DB_OK);
    cat_import_report_free(&rep);
    CHECK(cat_product_find(db, "Testbad", "TB-1", &p, err, sizeof err) == CAT_DB_OK);
    CHECK(p.variant_count == 1 && !strcmp(p.variants[0].code, "CP"));
    cat_product_free(&p);
    CHECK(fts_consistent(tmp_path("reimport.sqlite")));
    cat_db_close(db);
}

static void test_csv_forms(void)
{
    cat_db *db = open_catalog("forms.sqlite", 0);
    /* BOM, CRLF, quoted commas, quotes and line breaks, UTF-8, blanks around cells, empty
     * lines, columns in another order and case, no final line break. */
    static const char text[] =
        "\xEF\xBB\xBF"
        "Name,Manufacturer,ARTICLE,category,width_mm,depth_mm,height_mm,list_price,long_text\r\n"
        "\"Gr\xC3\xB6\xC3\x9F"
        "e \"\"XL\"\", matt\",M\xC3\xBCller Bad,MB-1,accessories,600,75,50,59.00,\"Line one\r\n"
        "Line two, with a comma\"\r\n"
        "\r\n"
        "  Towel bar 800  ,M\xC3\xBCller Bad, MB-2 ,accessories,800,75,50,69,plain";
    cat_import_report rep;
    CHECK(import_text(db, "forms.csv", text, &rep, NULL) == CAT_DB_OK);
    print_problems(&rep);
    CHECK(rep.rows == 2 && rep.products_added == 2);
    cat_import_report_free(&rep);
    cat_product p;
    char err[512];
    CHECK(cat_product_find(db, "m\xC3\xBCller bad", "MB-1", &p, err, sizeof err) == CAT_DB_OK);
    CHECK(!strcmp(p.name, "Gr\xC3\xB6\xC3\x9F"
                          "e \"XL\", matt"));
    CHECK(!strcmp(p.long_text, "Line one\nLine two, with a comma"));
    CHECK(p.price_cents == 5900 && p.variant_count == 0 && !p.has_tile);
    cat_product_free(&p);
    CHECK(cat_product_find(db, NULL, "MB-2", &p, err, sizeof err) == CAT_DB_OK);
    CHECK(!strcmp(p.name, "Towel bar 800") && p.price_cents == 6900);
    cat_product_free(&p);

    /* Problems inside a multi-line quoted row name the line the row starts on. */
    static const char late[] = "manufacturer,article,category,name,width_mm,depth_mm,height_mm,"
                               "list_price\n"
                               "M,X-1,accessories,\"two\nlines\",1,1,1,1.00\n"
                               "M,X-2,accessories,ok,1,1,1,0\n";
    CHECK(import_text(db, "late.csv", late, &rep, NULL) == CAT_DB_ERR_INVALID);
    CHECK(has_problem(&rep, 2, "name", "control character"));
    CHECK(has_problem(&rep, 4, "list_price", "positive"));
    cat_import_report_free(&rep);
    cat_db_close(db);
}

static void progress(void *user, long done, long total)
{
    long *last = user;
    last[0] = done;
    last[1] = total;
    last[2]++;
}

static void test_dry_run_and_progress(void)
{
    cat_db *db = open_catalog("dry.sqlite", 0);
    long seen[3] = {0, 0, 0};
    cat_import_desc desc = {.dry_run = 1, .progress = progress, .user = seen};
    cat_import_report rep;
    CHECK(import_text(db, "dry.csv", base_csv, &rep, &desc) == CAT_DB_OK);
    CHECK(rep.products_added == 3 && rep.rows == 4);
    cat_import_report_free(&rep);
    CHECK(count(db, "products") == 0);
    CHECK(seen[0] == 4 && seen[1] == 4 && seen[2] >= 1);

    /* A big file reports progress on the way. */
    size_t cap = 5200 * 120, n = 0;
    char *big = malloc(cap);
    n += (size_t)snprintf(big, cap,
                          "manufacturer,article,category,name,width_mm,depth_mm,"
                          "height_mm,list_price\n");
    for (int i = 0; i < 5000; i++)
        n += (size_t)snprintf(big + n, cap - n, "Big,B-%d,accessories,Robe hook %d,40,50,40,9.90\n",
                              i, i);
    seen[2] = 0;
    desc.dry_run = 0;
    CHECK(import_text(db, "big.csv", big, &rep, &desc) == CAT_DB_OK);
    free(big);
    CHECK(rep.products_added == 5000);
    cat_import_report_free(&rep);
    CHECK(seen[0] == 5000 && seen[1] == 5000 && seen[2] >= 3);
    CHECK(count(db, "products") == 5000);
    cat_db_close(db);
}

/* A price per metre (unit m): a trim profile sold by the length takes it; a tile cannot (its
 * quantities are pieces, m2 and boxes), and a unit the catalog does not know names the known
 * ones. */
static void test_unit_metre(void)
{
    cat_db *db = open_catalog("metre.sqlite", 0);
    static const char good[] = HEADER
        "Testbad,TB-P,,accessories,S,L profile 2.5 m,,,2500,10,10,7.56,19,m" CHROME NO_TILE "\n";
    cat_import_report rep;
    CHECK(import_text(db, "metre.csv", good, &rep, NULL) == CAT_DB_OK);
    print_problems(&rep);
    cat_import_report_free(&rep);
    cat_product p;
    char err[512];
    CHECK(cat_product_find(db, "Testbad", "TB-P", &p, err, sizeof err) == CAT_DB_OK);
    CHECK(p.unit == CAT_UNIT_M && p.price_cents == 756 && !strcmp(cat_unit_name(p.unit), "m"));
    cat_product_free(&p);
    static const char bad[] = HEADER
        /* 2 */ "A,A-1,,tiles,S,Tile,,,,,,39.90,19,m,MT,Matt,0,0.5 0.5 0.5,0.1 0.1 0.1,16,0.03,"
                "0.25,fresnel,0,1.5,UNI,300,600,297,597,3,10,matt,1.44,8,\n"
                /* 3 */ "A,A-2,,accessories,S,Profile,,,2500,10,10,7.56,19,metre" CHROME NO_TILE
                "\n";
    CHECK(import_text(db, "metre-bad.csv", bad, &rep, NULL) == CAT_DB_ERR_INVALID);
    print_problems(&rep);
    CHECK(has_problem(&rep, 2, "unit", "a tile is priced per piece, m2 or box, not per metre"));
    CHECK(has_problem(&rep, 3, "unit", "unknown unit \"metre\" (known: piece, m2, box, m)"));
    CHECK_MSG(rep.problem_count == 2, "%ld problems", rep.problem_count);
    cat_import_report_free(&rep);
    cat_db_close(db);
}

int main(void)
{
    tmp_make();
    test_good_file();
    test_one_bad_row();
    test_many_bad_rows();
    test_reimport();
    test_csv_forms();
    test_dry_run_and_progress();
    test_unit_metre();
    tmp_remove();
    return check_report("test_db_import");
}
