/* The shipped catalog: it loads; it has at least 8 manufacturers, 300 fixtures and 60 tiles,
 * every category; every GTIN is valid (checked here independently) and unique; sizes follow
 * DOMAIN.md and materials RENDERING.md. Opening again does not rebuild; a change of the
 * shipped data is imported into a copy renamed into place, keeping users' imports; broken
 * shipped data is refused with its file and line, leaving the catalog as it was. */
#include "test_db_util.h"

#include <dirent.h>

/* GS1 mod-10, written out again so that the test does not trust the code it tests. */
static int gtin_ok(const char *g)
{
    size_t n = strlen(g);
    if (n != 8 && n != 12 && n != 13 && n != 14)
        return 0;
    int sum = 0;
    for (size_t i = 0; i < n; i++) {
        if (g[i] < '0' || g[i] > '9')
            return 0;
        int from_right = (int)(n - 1 - i); /* 0 = the check digit */
        if (from_right > 0)
            sum += (g[i] - '0') * (from_right % 2 ? 3 : 1);
    }
    return (sum + (g[n - 1] - '0')) % 10 == 0;
}

static int near(double a, double b, double tol)
{
    return fabs(a - b) <= tol;
}

static void check_sizes(const cat_product *p)
{
    double w = p->width_mm, d = p->depth_mm;
    switch (p->category) {
    case CAT_CATEGORY_WCS_BIDETS: /* DOMAIN.md: WC about 360-430 wide, 480-770 deep */
        CHECK_MSG(w >= 360 && w <= 430 && d >= 480 && d <= 770, "%s %g x %g", p->name, w, d);
        break;
    case CAT_CATEGORY_BASINS:
        if (strstr(p->name, "washbasin 600 x 550"))
            CHECK(w == 600 && d == 550);
        if (strstr(p->name, "hand basin 450 x 350"))
            CHECK(w == 450 && d == 350);
        if (strstr(p->name, "double washbasin"))
            CHECK(w == 1200 && d == 550);
        CHECK(w >= 300 && w <= 1200 && d >= 250 && d <= 600);
        break;
    case CAT_CATEGORY_BATHS: {
        static const double sizes[][2] = {{1700, 750}, {1600, 700}, {1800, 800},  {1900, 900},
                                          {1700, 800}, {1800, 850}, {1400, 1400}, {1600, 1000}};
        int known = 0;
        for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++)
            known |= w == sizes[i][0] && d == sizes[i][1];
        CHECK_MSG(known, "bath %s %g x %g", p->name, w, d);
        break;
    }
    case CAT_CATEGORY_SHOWER_TRAYS: /* 800 x 800 minimum */
        CHECK_MSG(w >= 800 && d >= 800, "tray %s %g x %g", p->name, w, d);
        break;
    default:
        break;
    }
}

static void check_tile(const cat_product *p)
{
    CHECK_MSG(p->has_tile, "%s has no tile data", p->name);
    if (!p->has_tile)
        return;
    const cat_tile *t = &p->tile;
    /* nominal = work + grout (597 + 3 = 600) */
    CHECK_MSG(near(t->nominal_w_mm, t->work_w_mm + t->grout_mm, 1e-9) &&
                  near(t->nominal_h_mm, t->work_h_mm + t->grout_mm, 1e-9),
              "%s", p->name);
    double big = t->nominal_w_mm > t->nominal_h_mm ? t->nominal_w_mm : t->nominal_h_mm;
    CHECK_MSG(big <= 150 ? t->grout_mm == 2 : t->grout_mm >= 2 && t->grout_mm <= 8, "%s: grout %g",
              p->name, t->grout_mm);
    double m2 = t->pieces_per_box * t->nominal_w_mm * t->nominal_h_mm / 1e6;
    CHECK_MSG(near(t->m2_per_box, m2, 0.01 * m2), "%s: %g m2 per box, %d pieces", p->name,
              t->m2_per_box, t->pieces_per_box);
    CHECK(!strncmp(t->texture, "textures/tiles/", 15) && strstr(t->texture, ".png"));
    CHECK(t->thickness_mm >= 6 && t->thickness_mm <= 12);
    CHECK(p->width_mm == t->work_w_mm && p->height_mm == t->work_h_mm &&
          p->depth_mm == t->thickness_mm);
    if (t->type == CAT_TILE_UNI) {
        static const int formats[][2] = {{300, 600}, {600, 600},   {600, 1200}, {300, 300},
                                         {800, 800}, {1200, 1200}, {200, 1200}, {100, 100},
                                         {150, 150}, {200, 200},   {200, 333},  {75, 150}};
        int known = 0;
        for (size_t i = 0; i < sizeof formats / sizeof formats[0]; i++)
            known |= t->nominal_w_mm == formats[i][0] && t->nominal_h_mm == formats[i][1];
        CHECK_MSG(known, "%s: format %g x %g", p->name, t->nominal_w_mm, t->nominal_h_mm);
        CHECK(p->unit == CAT_UNIT_M2 || p->unit == CAT_UNIT_BOX);
    } else {
        CHECK(p->unit == CAT_UNIT_PIECE);
    }
}

static void check_materials(const cat_product *p)
{
    for (int i = 0; i < p->variant_count; i++) {
        const cat_variant *v = &p->variants[i];
        const cat_render_material *m = &v->material;
        if (!strcmp(v->code, "CP")) { /* chrome */
            CHECK(near(m->reflectivity, 0.8, 1e-6) && near(m->glossiness, 0.9, 1e-6));
        }
        if (!strcmp(v->code, "WH") &&
            (p->category == CAT_CATEGORY_BASINS || p->category == CAT_CATEGORY_WCS_BIDETS)) {
            CHECK(near(m->reflectivity, 0.1, 1e-6) && near(m->glossiness, 0.6, 1e-6) &&
                  m->blend == CAT_BLEND_FRESNEL); /* glazed ceramic */
        }
        if (!strcmp(v->code, "MI")) { /* mirror */
            CHECK(near(m->reflectivity, 0.95, 1e-6) && m->glossiness == 1);
        }
        if (!strcmp(v->code, "CL")) { /* clear glass */
            CHECK(near(m->transparency, 0.9, 1e-6) && near(m->ior, 1.5, 1e-6));
        }
        if (p->category == CAT_CATEGORY_LAMPS)
            CHECK(m->emissive[0] > 1 && m->emissive[1] > 1 && m->emissive[2] > 1);
        else
            CHECK(m->emissive[0] == 0 && m->emissive[1] == 0 && m->emissive[2] == 0);
        CHECK(m->reflectivity >= 0 && m->reflectivity <= 1 && m->glossiness >= 0 &&
              m->glossiness <= 1 && m->transparency >= 0 && m->transparency <= 1);
        CHECK(v->surcharge_cents >= 0 && v->surcharge_cents <= p->price_cents);
    }
}

static void test_contents(void)
{
    cat_db *db = open_catalog("shipped.sqlite", 1);
    cat_db_stats s;
    char err[1024];
    CHECK(cat_db_get_stats(db, &s, err, sizeof err) == CAT_DB_OK);
    printf("shipped catalog: %lld manufacturers, %lld series, %lld products, %lld variants, %lld "
           "tiles\n",
           s.manufacturers, s.series, s.products, s.variants, s.tiles);
    CHECK(s.manufacturers >= 8);
    CHECK(s.products - s.per_category[CAT_CATEGORY_TILES] >= 300);
    CHECK(s.tiles >= 60 && s.per_category[CAT_CATEGORY_TILES] == s.tiles);
    for (int c = 1; c < CAT_CATEGORY_COUNT; c++)
        CHECK_MSG(s.per_category[c] >= 5, "%s: %lld", cat_category_name((cat_category)c),
                  s.per_category[c]);
    CHECK(strlen(s.source_hash) == 16);
    CHECK(fts_consistent(tmp_path("shipped.sqlite")));

    static cat_search_hit all[10000];
    int n = 0;
    CHECK(cat_search(db, "", NULL, 10000, all, &n, err, sizeof err) == CAT_DB_OK);
    CHECK(n == s.products);
    char(*gtins)[16] = calloc((size_t)n, sizeof *gtins);
    for (int i = 0; i < n; i++) {
        cat_product p;
        if (cat_product_get(db, all[i].product_id, &p, err, sizeof err) != CAT_DB_OK) {
            CHECK_MSG(0, "%s", err);
            continue;
        }
        CHECK_MSG(gtin_ok(p.gtin), "%s %s: GTIN \"%s\"", p.manufacturer, p.article, p.gtin);
        snprintf(gtins[i], sizeof gtins[i], "%s", p.gtin);
        CHECK(p.shipped && p.price_cents > 0 && !strcmp(p.currency, "EUR") && p.vat_percent == 19);
        CHECK(p.name[0] && p.short_text[0] && p.long_text[0] && p.series[0]);
        CHECK(p.width_mm > 0 && p.depth_mm > 0 && p.height_mm > 0);
        CHECK(p.variant_count >= 1);
        if (p.category == CAT_CATEGORY_TILES) {
            check_tile(&p);
            CHECK(p.price_cents < 20000);
        } else {
            CHECK(!p.has_tile && p.price_cents >= 500 && p.price_cents <= 1000000);
            check_sizes(&p);
        }
        check_materials(&p);
        cat_product_free(&p);
    }
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++)
            CHECK_MSG(strcmp(gtins[i], gtins[j]), "GTIN %s twice", gtins[i]);
    free(gtins);
    cat_db_close(db);
}

/* Copies every *.csv of the shipped folder to tmp/src. */
static void copy_source(void)
{
    mkdir(tmp_path("src"), 0777);
    DIR *d = opendir(TESSERA_CATALOG_SOURCE);
    struct dirent *e;
    while (d && (e = readdir(d))) {
        size_t n = strlen(e->d_name);
        if (n < 5 || strcmp(e->d_name + n - 4, ".csv"))
            continue;
        char from[4200], to[600];
        snprintf(from, sizeof from, "%s/%s", TESSERA_CATALOG_SOURCE, e->d_name);
        snprintf(to, sizeof to, "src/%s", e->d_name);
        size_t size = 0;
        char *data = read_all(from, &size);
        write_file(to, data, size);
        free(data);
    }
    if (d)
        closedir(d);
}

static cat_db_result open_with_source(const char *name, cat_db **db, char *err, size_t size)
{
    return cat_catalog_open(tmp_path(name), tmp_path("src"), db, err, size);
}

static long long price_of(cat_db *db, const char *article)
{
    cat_product p;
    if (cat_product_find(db, NULL, article, &p, NULL, 0) != CAT_DB_OK)
        return -1;
    long long cents = p.price_cents;
    cat_product_free(&p);
    return cents;
}

static void test_refresh(void)
{
    copy_source();
    cat_db *db = NULL;
    char err[4096];
    CHECK(open_with_source("sync.sqlite", &db, err, sizeof err) == CAT_DB_OK);
    long long shipped = 0;
    cat_db_stats s;
    cat_db_get_stats(db, &s, NULL, 0);
    shipped = s.products;
    /* A user's own product, and a user's price for a shipped one. */
    static const char mine[] = "manufacturer,article,category,name,width_mm,depth_mm,height_mm,"
                               "list_price\nMy shop,MY-1,accessories,Hook,40,50,40,9.90\n"
                               "Aquavera,31000000,,,,,,140.00\n";
    static const char prices[] = "manufacturer,article,list_price\nAquavera,31000000,140.00\n";
    cat_import_report rep;
    CHECK(cat_import_csv_buffer(db, "mine.csv", mine, strlen(mine), NULL, &rep, err, sizeof err) ==
          CAT_DB_ERR_INVALID); /* empty required cells */
    cat_import_report_free(&rep);
    CHECK(cat_import_csv_buffer(db, "mine.csv", mine,
                                strlen(mine) - strlen("Aquavera,31000000,,,"
                                                      ",,,140.00\n"),
                                NULL, &rep, err, sizeof err) == CAT_DB_OK);
    cat_import_report_free(&rep);
    CHECK(cat_import_csv_buffer(db, "prices.csv", prices, strlen(prices), NULL, &rep, err,
                                sizeof err) == CAT_DB_OK);
    cat_import_report_free(&rep);
    CHECK(price_of(db, "31000000") == 14000);
    cat_db_close(db);

    /* Opening again with the same data neither rebuilds nor rewrites the file. */
    struct stat a, b;
    stat(tmp_path("sync.sqlite"), &a);
    CHECK(open_with_source("sync.sqlite", &db, err, sizeof err) == CAT_DB_OK);
    cat_db_close(db);
    stat(tmp_path("sync.sqlite"), &b);
    CHECK(a.st_ino == b.st_ino && a.st_mtim.tv_sec == b.st_mtim.tv_sec &&
          a.st_mtim.tv_nsec == b.st_mtim.tv_nsec && a.st_size == b.st_size);

    /* New shipped prices, and one product dropped from the shipped data. */
    size_t size = 0;
    char *csv = read_all(tmp_path("src/fixtures.csv"), &size);
    for (char *p = csv; (p = strstr(p, ",259.00,EUR,")); p++)
        memcpy(p, ",265.00,EUR,", 12);
    char *last = csv + size - 1;
    while (last > csv && last[-1] != '\n')
        last--;
    char dropped[64];
    snprintf(dropped, sizeof dropped, "%.*s", (int)strcspn(strchr(last, ',') + 1, ","),
             strchr(last, ',') + 1);
    for (char *line; (line = strstr(csv, dropped));) { /* remove every row of it */
        while (line > csv && line[-1] != '\n')
            line--;
        char *end = strchr(line, '\n');
        memmove(line, end + 1, strlen(end + 1) + 1);
    }
    char *modified_price = strstr(csv, ",265.00,EUR,");
    CHECK(modified_price != NULL);
    write_text("src/fixtures.csv", csv);
    CHECK(price_of(db = open_catalog("sync.sqlite", 0), dropped) > 0);
    cat_db_close(db);

    CHECK(open_with_source("sync.sqlite", &db, err, sizeof err) == CAT_DB_OK);
    stat(tmp_path("sync.sqlite"), &b);
    /* Updated in place, in one transaction: a file renamed over a catalog in WAL mode would
     * leave the readers of the old one on a stranded -wal (docs/catalog.md). */
    CHECK(a.st_ino == b.st_ino);
    cat_db_get_stats(db, &s, NULL, 0);
    CHECK_MSG(s.products == shipped + 1 - 1, "%lld products, was %lld", s.products, shipped);
    CHECK(price_of(db, dropped) == -1);
    CHECK(price_of(db, "MY-1") == 990);       /* the user's product stays */
    CHECK(price_of(db, "31000000") == 14000); /* and the user's price */
    /* some product whose shipped price was 259.00 now costs 265.00 */
    cat_search_hit hits[400];
    int n = 0;
    cat_search_filter basins = {.category = CAT_CATEGORY_BASINS};
    CHECK(cat_search(db, "", &basins, 400, hits, &n, err, sizeof err) == CAT_DB_OK);
    int found = 0;
    for (int i = 0; i < n; i++) {
        CHECK(hits[i].price_cents != 25900);
        found |= hits[i].price_cents == 26500;
    }
    CHECK(found);
    CHECK(fts_consistent(tmp_path("sync.sqlite")));
    cat_db_close(db);
    CHECK(access(tmp_path("sync.sqlite-journal"), F_OK) != 0);

    /* Broken shipped data: refused with file, line and column; the catalog stays. */
    size_t before_size;
    char *before = read_all(tmp_path("sync.sqlite"), &before_size);
    size_t len = strlen(csv);
    long lines = 0;
    for (size_t i = 0; i < len; i++)
        lines += csv[i] == '\n';
    char *broken = malloc(len + 200);
    memcpy(broken, csv, len);
    int k = snprintf(broken + len, 200,
                     "Aquavera,99999,,taps_mixers,Linea,x,,,1,1,1,nan,EUR,"
                     "19,piece");
    for (int i = 0; i < 32; i++) /* discount group .. grain: empty */
        broken[len + (size_t)k++] = ',';
    memcpy(broken + len + k, "\n", 2);
    write_text("src/fixtures.csv", broken);
    CHECK(open_with_source("sync.sqlite", &db, err, sizeof err) != CAT_DB_OK && db == NULL);
    char where[64];
    snprintf(where, sizeof where, "fixtures.csv:%ld: column", lines + 1);
    CHECK_MSG(strstr(err, where) && strstr(err, "sync.sqlite"), "%s (expected %s)", err, where);
    size_t after_size;
    char *after = read_all(tmp_path("sync.sqlite"), &after_size);
    CHECK(before && after && before_size == after_size && !memcmp(before, after, after_size));
    free(before);
    free(after);
    free(broken);
    free(csv);
    db = open_catalog("sync.sqlite", 0); /* without the shipped data it still opens */
    CHECK(price_of(db, "MY-1") == 990);
    cat_db_close(db);

    /* Nothing temporary is left behind. */
    DIR *d = opendir(g_tmp);
    struct dirent *e;
    while (d && (e = readdir(d)))
        CHECK_MSG(!strstr(e->d_name, ".tmp-"), "left behind: %s", e->d_name);
    if (d)
        closedir(d);
}

int main(void)
{
    tmp_make();
    test_contents();
    test_refresh();
    tmp_remove();
    return check_report("test_db_shipped");
}
