/* Search for a German and an English showroom, on the shipped catalog (English names with Italian
 * colour names) and on an imported one with German names: folding ("Weiß" is "weiss"), German
 * and English stems ("Waschtische", "basins"), the synonym table (Waschtisch finds basins, grau
 * finds grigio), every word required ("tile grey" is grey tiles only), the word that matches
 * nothing named, and the migration of a catalog whose index was built before all this. */
#include "test_db_util.h"

#include <ctype.h>

static cat_db *db;

enum { MAX_HITS = 200 };
static cat_search_hit hits[MAX_HITS];

static int search(cat_db *d, const char *text)
{
    int n = -1;
    char err[512] = "";
    cat_db_result r = cat_search(d, text, NULL, MAX_HITS, hits, &n, err, sizeof err);
    CHECK_MSG(r == CAT_DB_OK, "\"%s\": %s", text, err);
    return n;
}

/* Case-blind substring. */
static int has(const char *text, const char *needle)
{
    size_t n = strlen(needle);
    for (const char *p = text; *p; p++) {
        size_t i = 0;
        while (i < n && p[i] && tolower((unsigned char)p[i]) == tolower((unsigned char)needle[i]))
            i++;
        if (i == n)
            return 1;
    }
    return 0;
}

/* One of the words is in the hit's name or, for a colour, in one of its finishes (the names of
 * its variants, which the search reads too). */
static int named(cat_db *d, const cat_search_hit *h, const char *const *words)
{
    for (int w = 0; words[w]; w++)
        if (has(h->name, words[w]))
            return 1;
    cat_product p;
    char err[512];
    if (cat_product_get(d, h->product_id, &p, err, sizeof err) != CAT_DB_OK) {
        fprintf(stderr, "%s\n", err);
        return 0;
    }
    int ok = 0;
    for (int v = 0; v < p.variant_count && !ok; v++)
        for (int w = 0; words[w] && !ok; w++)
            ok = has(p.variants[v].name, words[w]);
    cat_product_free(&p);
    return ok;
}

/* Every hit of text (at least `min` of them) has one of the words in its name or finishes. */
static void expect_all_named(cat_db *d, const char *text, int min, const char *const *words)
{
    int n = search(d, text);
    CHECK_MSG(n >= min, "\"%s\": %d hits, expected at least %d", text, n, min);
    for (int i = 0; i < n; i++)
        CHECK_MSG(named(d, &hits[i], words), "\"%s\" found \"%s\"", text, hits[i].name);
}

/* The first hit of text is in category `cat`, and at least `min` hits are. */
static void expect_category(const char *text, cat_category cat, int min)
{
    int n = search(db, text);
    int in = 0;
    for (int i = 0; i < n; i++)
        in += hits[i].category == cat;
    CHECK_MSG(n > 0 && hits[0].category == cat && in >= min,
              "\"%s\": first hit \"%s\" (%s), %d of %d in %s, expected %d", text,
              n ? hits[0].name : "none", n ? cat_category_name(hits[0].category) : "-", in, n,
              cat_category_name(cat), min);
}

static void test_folding(void)
{
    int weiss = search(db, "weiss");
    CHECK_MSG(weiss >= 7, "\"weiss\": %d hits", weiss);
    const char *same[] = {"Wei\xC3\x9F", "WEISS", "wei\xC3\x9F", "Weiss"};
    for (int i = 0; i < 4; i++) {
        int n = search(db, same[i]);
        CHECK_MSG(n == weiss, "\"%s\": %d hits, \"weiss\" has %d", same[i], n, weiss);
    }
    const char *white[] = {"weiss", "white", "bianco", NULL};
    expect_all_named(db, "Wei\xC3\x9F", 7, white);
}

static void test_german_words(void)
{
    expect_category("Waschtisch", CAT_CATEGORY_BASINS, 5);
    expect_category("Waschbecken", CAT_CATEGORY_BASINS, 5);
    expect_category("Badewanne", CAT_CATEGORY_BATHS, 3);
    const char *tray[] = {"shower tray", NULL};
    expect_all_named(db, "Duschwanne", 5, tray);
    const char *mirror[] = {"mirror", NULL};
    expect_all_named(db, "Spiegel", 5, mirror);
    expect_category("Armatur", CAT_CATEGORY_TAPS_MIXERS, 10);
    const char *grey[] = {"grigio", "grey", "gray", "gris", NULL};
    expect_all_named(db, "grau", 10, grey);
    const char *anthracite[] = {"antracite", "anthracite", NULL};
    expect_all_named(db, "anthrazit", 4, anthracite);
    /* two German words, both required */
    const char *grey_tile[] = {"grigio", "grey", "gris", NULL};
    expect_all_named(db, "Fliese grau", 10, grey_tile);
}

static void test_every_word(void)
{
    /* "grey" is never dropped: grey tiles only, no white ones. */
    const char *grey[] = {"grigio", "grey", "gris", NULL};
    expect_all_named(db, "tile grey", 10, grey);
    int n = search(db, "tile grey");
    for (int i = 0; i < n; i++)
        CHECK_MSG(hits[i].category == CAT_CATEGORY_TILES, "\"tile grey\" found %s", hits[i].name);
    /* A word that matches nothing: no hits, and that word is named. */
    CHECK(search(db, "tile purpleish") == 0);
    char word[64], err[512];
    CHECK(cat_search_unmatched(db, "tile purpleish", word, sizeof word, err, sizeof err) ==
          CAT_DB_OK);
    CHECK_MSG(!strcmp(word, "purpleish"), "unmatched word \"%s\"", word);
    CHECK(cat_search_unmatched(db, "Wei\xC3\x9F Zzyzx", word, sizeof word, err, sizeof err) ==
          CAT_DB_OK);
    CHECK_MSG(!strcmp(word, "Zzyzx"), "unmatched word \"%s\"", word);
    /* Every word matches something, only not together: no word to blame. */
    CHECK(search(db, "Linea thermostatic bath mixer") == 0);
    CHECK(cat_search_unmatched(db, "Linea thermostatic bath mixer", word, sizeof word, err,
                               sizeof err) == CAT_DB_OK);
    CHECK_MSG(word[0] == 0, "unmatched word \"%s\"", word);
}

static void test_stems(void)
{
    /* English plurals against singular names, and back */
    expect_category("basins", CAT_CATEGORY_BASINS, 10);
    const char *mirror[] = {"mirror", NULL};
    expect_all_named(db, "mirrors", 5, mirror);
    /* German inflections through the synonym table */
    CHECK(search(db, "Waschtische") == search(db, "Waschtisch"));
    CHECK(search(db, "Badewannen") == search(db, "Badewanne"));
    CHECK(search(db, "Spiegels") == search(db, "Spiegel"));

    /* German names in the index: stems and transcribed umlauts on both sides. */
    cat_db *de = open_catalog("german.sqlite", 0);
    static const char csv[] =
        "manufacturer,article,category,name,short_text,width_mm,depth_mm,height_mm,list_price\n"
        "Hausmarke,HM-1,basins,Waschtisch Nova 600,Waschtische aus Keramik,600,450,160,199.00\n"
        "Hausmarke,HM-2,baths,Badewanne Nova 1700,Acryl,1700,750,580,499.00\n"
        "Hausmarke,HM-3,accessories,Bodenfliese Grau 600,Feinsteinzeug,600,10,600,39.00\n"
        "Hausmarke,HM-4,accessories,Zubeh\xC3\xB6r-Set Wei\xC3\x9F,Haken und "
        "Halter,100,50,50,29.00\n"
        "Hausmarke,HM-5,taps_mixers,Waschtischmischer,Einhebel,50,120,160,89.00\n";
    char err[1024];
    CHECK_MSG(cat_import_csv_buffer(de, "german.csv", csv, sizeof csv - 1, NULL, NULL, err,
                                    sizeof err) == CAT_DB_OK,
              "%s", err);
    const char *nova_basin[] = {"Waschtisch Nova", NULL};
    expect_all_named(de, "Waschtische", 1, nova_basin);
    expect_all_named(de, "basin", 1, nova_basin);
    const char *bath[] = {"Badewanne", NULL};
    expect_all_named(de, "Badewannen", 1, bath);
    expect_all_named(de, "bathtubs", 1, bath);
    /* (the tile row is in category accessories, which "Zubehör" also finds: name first) */
    CHECK(search(de, "Zubehoer") == 2 && has(hits[0].name, "Zubeh"));
    const char *set[] = {"Zubeh", NULL};
    expect_all_named(de, "zubehor weiss", 1, set);
    expect_all_named(de, "ZUBEH\xC3\x96R white", 1, set);
    const char *tile[] = {"Bodenfliese", NULL};
    expect_all_named(de, "Bodenfliese grey", 1, tile);
    cat_db_close(de);
}

/* A version-3 catalog (the index read by plain unicode61, no synonym table) is migrated: its
 * index is rebuilt with the new words and the synonyms are there. */
static void test_migration_from_v3(void)
{
    cat_db_close(open_catalog("v3.sqlite", 1));
    const char *path = tmp_path("v3.sqlite");
    /* Back to version 3: without the variants' pattern and grain (version 8), the mounting
     * columns (7), the finishes (5) and the synonyms and tokenizer (4). */
    CHECK(sql_run(path, "DROP TRIGGER variants_finishes_insert;"
                        "DROP TRIGGER variants_finishes_delete;"
                        "DROP TRIGGER variants_finishes_update;"
                        "DROP TRIGGER products_fts_insert;"
                        "DROP TRIGGER products_fts_delete;"
                        "DROP TRIGGER products_fts_update;"
                        "DROP TRIGGER manufacturers_fts_rename;"
                        "DROP TRIGGER series_fts_rename;"
                        "DROP VIEW product_search;"
                        "ALTER TABLE products DROP COLUMN finishes;"
                        "ALTER TABLE products DROP COLUMN mounting_height_mm;"
                        "ALTER TABLE products DROP COLUMN mounting_to;"
                        "ALTER TABLE products DROP COLUMN companions;"
                        "ALTER TABLE variants DROP COLUMN pattern;"
                        "ALTER TABLE variants DROP COLUMN grain_deg;"
                        "CREATE VIEW product_search AS SELECT p.id AS id, p.name AS name, "
                        "coalesce(s.name, '') AS series, m.name AS manufacturer, p.article AS "
                        "article, replace(replace(replace(replace(replace(p.article, '-', ''), "
                        "'.', ''), ' ', ''), '/', ''), '_', '') AS article_compact, p.short_text "
                        "AS short_text, replace(p.category, '_', ' ') AS category FROM products p "
                        "JOIN manufacturers m ON m.id = p.manufacturer_id LEFT JOIN series s ON "
                        "s.id = p.series_id;"
                        "DROP TABLE search_synonyms;"
                        "DROP TABLE product_fts;"
                        "CREATE VIRTUAL TABLE product_fts USING fts5 (name, series, manufacturer, "
                        "article, article_compact, short_text, category, content = "
                        "'product_search', content_rowid = 'id', tokenize = 'unicode61 "
                        "remove_diacritics 2', prefix = '2 3');"
                        "INSERT INTO product_fts (product_fts) VALUES ('rebuild');"
                        "PRAGMA user_version = 3;"));
    CHECK(sql_int(path, "SELECT count(*) FROM product_fts WHERE product_fts MATCH 'Waschtisch'") ==
          0);
    cat_db *old = NULL;
    char err[1024];
    CHECK(cat_catalog_open(path, NULL, &old, err, sizeof err) == CAT_DB_OK);
    CHECK(sql_int(path, "PRAGMA user_version") == CAT_DB_SCHEMA_VERSION);
    CHECK(sql_int(path, "SELECT count(*) FROM sqlite_schema WHERE name = 'product_fts' AND "
                        "sql LIKE '%tokenize = ''tessera''%'") == 1);
    CHECK(sql_int(path, "SELECT count(DISTINCT group_id) FROM search_synonyms") >= 30);
    CHECK(fts_consistent(path));
    CHECK(search(old, "basins") >= 10);
    CHECK(search(old, "Wei\xC3\x9F") >= 7);
    expect_all_named(old, "anthrazit", 4, (const char *const[]){"antracite", "anthracite", NULL});
    cat_db_close(old);
}

int main(void)
{
    tmp_make();
    db = open_catalog("shipped.sqlite", 1);
    test_folding();
    test_german_words();
    test_every_word();
    test_stems();
    test_migration_from_v3();
    cat_db_close(db);
    tmp_remove();
    return check_report("test_db_search_words");
}
