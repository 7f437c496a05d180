/* Colour words against finishes, and German compound words, on an imported catalog:
 * - finishes (argument "finishes"): a product's variant names are searched, so "Waschtisch weiß
 *   matt" finds the basin that comes in white matt although its name says no colour, and not the
 *   one that comes in white gloss; "tile anthracite" finds the tile whose finish is anthracite;
 *   a re-import that changes the variants changes what is found;
 * - compounds (argument "compounds"): "Badewanne" finds "Eckbadewanne" (indexed in its parts),
 *   "Spiegelschrank" finds "Spiegel mit Schrank" (the query split in its parts), "Bodenfliese"
 *   and "Wandfliese" find tiles "for Boden und Wand", "bath" finds "Eckbadewanne". */
#include "test_db_util.h"

static cat_db *db;

enum { MAX_HITS = 100 };
static cat_search_hit hits[MAX_HITS];

static const char catalog_csv[] =
#include "test_db_search_finishes.inc"
    ;

static int search(const char *text)
{
    int n = -1;
    char err[512] = "";
    cat_db_result r = cat_search(db, text, NULL, MAX_HITS, hits, &n, err, sizeof err);
    CHECK_MSG(r == CAT_DB_OK, "\"%s\": %s", text, err);
    return n;
}

static int found(int n, const char *article)
{
    for (int i = 0; i < n; i++)
        if (!strcmp(hits[i].article, article))
            return 1;
    return 0;
}

/* text finds every article of `want` and none of `not_want` (NULL-terminated lists). */
static void expect(const char *text, const char *const *want, const char *const *not_want)
{
    int n = search(text);
    for (int i = 0; want[i]; i++)
        CHECK_MSG(found(n, want[i]), "\"%s\" does not find %s (%d hits)", text, want[i], n);
    for (int i = 0; not_want && not_want[i]; i++)
        CHECK_MSG(!found(n, not_want[i]), "\"%s\" finds %s", text, not_want[i]);
}

static void import(const char *name, const char *csv)
{
    char err[1024];
    CHECK_MSG(cat_import_csv_buffer(db, name, csv, strlen(csv), NULL, NULL, err, sizeof err) ==
                  CAT_DB_OK,
              "%s", err);
}

static void test_finishes(void)
{
    expect("Waschtisch wei\xC3\x9F matt", (const char *[]){"F-600", NULL},
           (const char *[]){"F-800", "F-500", "K-3", NULL});
    expect("Waschtisch weiss", (const char *[]){"F-600", "F-800", NULL},
           (const char *[]){"F-500", NULL});
    expect("tile anthracite", (const char *[]){"F-T1", NULL}, (const char *[]){"F-T2", NULL});
    expect("Fliese anthrazit", (const char *[]){"F-T1", NULL}, (const char *[]){"F-T2", NULL});
    expect("Waschtisch anthrazit", (const char *[]){"F-500", NULL},
           (const char *[]){"F-600", "F-800", NULL});
    /* The name outranks the finish: a colour in the name comes first. */
    int n = search("schwarz");
    CHECK(n >= 1 && found(n, "F-600"));

    /* A price list with variant columns replaces the variants: what is found follows. */
    const char *header = strchr(catalog_csv, '\n');
    size_t header_len = (size_t)(header - catalog_csv) + 1;
    char csv[8192];
    const char *t2 = strstr(catalog_csv, "Finitura,F-T2,");
    const char *t2_end = t2 ? strchr(t2, '\n') : NULL;
    CHECK(t2 && t2_end);
    if (!t2 || !t2_end)
        return;
    snprintf(csv, sizeof csv, "%.*s%.*s\n", (int)header_len, catalog_csv, (int)(t2_end - t2), t2);
    char *white = strstr(csv, "\"White, matt\"");
    CHECK(white != NULL);
    if (!white)
        return;
    memcpy(white, "\"Anthracite\" ", 13);
    import("reprice.csv", csv);
    expect("tile anthracite", (const char *[]){"F-T1", "F-T2", NULL}, NULL);
    expect("tile white", (const char *[]){NULL}, (const char *[]){"F-T2", "F-T1", NULL});
}

static void test_compounds(void)
{
    /* Indexed in its parts: the product's compound. */
    expect("Badewanne", (const char *[]){"K-2", NULL}, NULL);
    expect("bath", (const char *[]){"K-2", NULL}, NULL);
    expect("Schrank", (const char *[]){"K-1", "K-5", NULL}, NULL);
    /* Split in the query: the parts in any order and place, each through its synonyms. */
    expect("Spiegelschrank", (const char *[]){"K-1", "K-5", NULL},
           (const char *[]){"K-2", "K-3", NULL});
    expect("Bodenfliese", (const char *[]){"F-T1", "F-T2", NULL},
           (const char *[]){"F-600", "K-1", NULL});
    expect("Wandfliesen", (const char *[]){"F-T1", "F-T2", NULL}, (const char *[]){"K-4", NULL});
    expect("Waschtischunterschrank", (const char *[]){"K-3", NULL},
           (const char *[]){"F-600", NULL});
    expect("Duschwand", (const char *[]){"K-4", NULL}, NULL);
    /* Not a compound of known words: one word, as before. */
    char word[64];
    CHECK(cat_search_unmatched(db, "Quarkfliese", word, sizeof word, NULL, 0) == CAT_DB_OK);
    CHECK_MSG(!strcmp(word, "Quarkfliese"), "unmatched word: \"%s\"", word);
}

int main(int argc, char **argv)
{
    const char *which = argc > 1 ? argv[1] : "all";
    tmp_make();
    db = open_catalog("finishes.sqlite", 0);
    import("finishes.csv", catalog_csv);
    if (!strcmp(which, "all") || !strcmp(which, "finishes"))
        test_finishes();
    if (!strcmp(which, "all") || !strcmp(which, "compounds"))
        test_compounds();
    cat_db_close(db);
    tmp_remove();
    return check_report(which);
}
