/* Trim profiles (app/design/trims.h, docs/tiling.md "Trim profiles"): the outside edges of
 * reveal, niche and pre-wall tilings on the L-shaped test room, the 2.5 m lengths they are cut
 * from, and the totals per product. Every expected value is worked out in the comments. */
#include "app/design/room_surfaces.h"
#include "app/design/trims.h"
#include "test_util.h"

#include "catalog/catalog.h"

#include <math.h>
#include <stdlib.h>

#define DATA TESSERA_SOURCE_DIR "/tests/data"

static void test_pieces(void)
{
    /* first-fit decreasing into 2500 mm lengths */
    const double window[4] = {1200, 800, 1200, 800};
    /* 1200 + 1200 = 2400 in the first, 800 + 800 in the second */
    CHECK(app_trim_pieces(window, 4, 2500) == 2);
    const double both[8] = {400, 1200, 600, 800, 1200, 400, 800, 600};
    /* 1200 + 1200 (100 left); 800 + 800 + 600 (300 left); 600 + 400 + 400: 6.0 m in 3 */
    CHECK(app_trim_pieces(both, 8, 2500) == 3);
    const double lng[1] = {3000}; /* a whole length and 500 mm of a second */
    CHECK(app_trim_pieces(lng, 1, 2500) == 2);
    const double two[2] = {3000, 2000}; /* 2500 + (2000 and the 500 rest in one) */
    CHECK(app_trim_pieces(two, 2, 2500) == 2);
    const double exact[1] = {2500};
    CHECK(app_trim_pieces(exact, 1, 2500) == 1);
    CHECK(app_trim_pieces(NULL, 0, 2500) == 0);
    const double three[3] = {1300, 1300, 1300}; /* no two fit in one length */
    CHECK(app_trim_pieces(three, 3, 2500) == 3);
}

static app_tiling tiling_on(const char *surface)
{
    app_tiling t;
    memset(&t, 0, sizeof t);
    snprintf(t.surface, sizeof t.surface, "%s", surface);
    return t;
}

static int edges(const app_room_plan *plan, const app_tiling *t, double *len)
{
    return app_tiling_trim_edges(plan, t, len, APP_TRIM_MAX_EDGES);
}

static void test_edges(void)
{
    app_project p;
    char err[1024];
    if (app_project_read(DATA "/projects/v2_l_room.json", &p, err, sizeof err) != APP_OK) {
        CHECK_MSG(0, "%s", err);
        return;
    }
    const app_room_plan *plan = &p.plan;
    double len[APP_TRIM_MAX_EDGES];
    /* the window: 800 wide, 1200 high from the sill at 900 */
    app_tiling t = tiling_on("reveal:window:left");
    CHECK(edges(plan, &t, len) == 1 && len[0] == 1200);
    t.from_mm = 0, t.to_mm = 1500; /* a band to 1500 trims 900..1500 */
    CHECK(edges(plan, &t, len) == 1 && len[0] == 600);
    t.from_mm = 0, t.to_mm = 800; /* below the sill: nothing tiled, no edge */
    CHECK(edges(plan, &t, len) == 0);
    t = tiling_on("reveal:window:bottom");
    CHECK(edges(plan, &t, len) == 1 && len[0] == 800);
    t = tiling_on("reveal:door:top");
    CHECK(edges(plan, &t, len) == 1 && len[0] == 800);
    t = tiling_on("niche:shower-niche:right");
    CHECK(edges(plan, &t, len) == 1 && len[0] == 400);
    t = tiling_on("niche:shower-niche:back"); /* internal corners only */
    CHECK(edges(plan, &t, len) == 0);
    t = tiling_on("wall:0");
    CHECK(edges(plan, &t, len) == 0);
    /* the pre-wall: 1200 wide, 200 deep, 1200 high, at 1000 on the 3000 mm wall 5: both sides
     * free; the top's front and its two ends, the front's two upright corners */
    t = tiling_on("prewall:wc-box:top");
    CHECK(edges(plan, &t, len) == 3 && len[0] == 1200 && len[1] == 200 && len[2] == 200);
    t = tiling_on("prewall:wc-box:front");
    CHECK(edges(plan, &t, len) == 2 && len[0] == 1200 && len[1] == 1200);
    t = tiling_on("prewall:wc-box:left"); /* the front owns the corner */
    CHECK(edges(plan, &t, len) == 0);
    /* moved into the wall's start corner: that side meets wall 4, an internal corner */
    p.plan.prewalls[0].offset_mm = 0;
    t = tiling_on("prewall:wc-box:front");
    CHECK(edges(plan, &t, len) == 1 && len[0] == 1200);
    t = tiling_on("prewall:wc-box:top");
    CHECK(edges(plan, &t, len) == 2 && len[0] == 1200 && len[1] == 200);
    app_project_free(&p);
}

static void test_project_totals(void)
{
    app_project p;
    char err[1024];
    if (app_project_read(DATA "/tiles/reveals_room.json", &p, err, sizeof err) != APP_OK) {
        CHECK_MSG(0, "%s", err);
        return;
    }
    app_trim_quantity *q = NULL;
    int n = 0;
    CHECK(app_trim_quantities(&p, &q, &n, err, sizeof err) == APP_OK);
    CHECK(n == 2);
    if (n == 2) {
        /* the window's L profile: 1200 + 1200 + 800 + 800 = 4.0 m in 2 lengths */
        CHECK(!strcmp(q[0].product.article, "KT-L10") && q[0].edges == 4);
        CHECK_NEAR(q[0].metres, 4.0, 1e-9);
        CHECK(q[0].pieces == 2);
        /* the niche's quarter circle: 400 + 400 + 600 + 600 = 2.0 m in 1 (the back has none) */
        CHECK(!strcmp(q[1].product.article, "KT-R10") && q[1].edges == 4);
        CHECK_NEAR(q[1].metres, 2.0, 1e-9);
        CHECK(q[1].pieces == 1);
        /* without a catalog: listed at 0, counted missing, billed by the length */
        app_bom b;
        memset(&b, 0, sizeof b);
        CHECK(app_bom_add_trims(NULL, q, n, &b, err, sizeof err) == APP_OK);
        CHECK(b.line_count == 2 && b.missing == 2 && b.lines[0].quantity == 2 &&
              b.lines[1].quantity == 1 && b.net_cents == 0);
        app_bom_free(&b);
    }
    free(q);
    app_project_free(&p);
}

/* A profile priced per metre (catalog unit m) is billed by the metres of the whole lengths
 * bought; one priced per length (unit piece) by its pieces. The catalog: the shipped trims.csv
 * (KT-L10 7.56 EUR/m, brushed stainless +1.20; KT-R10 9.96 EUR/m) and one profile priced per
 * length (KT-X10, 20.00 EUR a length). */
static void test_priced_per_metre(void)
{
    char *dir = tu_make_temp_dir(), src[600], path[700], err[1024];
    if (!dir) {
        CHECK_MSG(0, "no temporary folder");
        return;
    }
    snprintf(src, sizeof src, "%s/catalog", dir);
    mkdir(src, 0777);
    size_t len = 0;
    char *trims = tu_read_file(TESSERA_SOURCE_DIR "/assets/catalog/trims.csv", &len);
    snprintf(path, sizeof path, "%s/trims.csv", src);
    CHECK(trims && tu_write_file(path, trims, len));
    free(trims);
    static const char per_length[] =
        "manufacturer,article,category,name,width_mm,depth_mm,height_mm,list_price,unit\n"
        "Kantec,KT-X10,accessories,Kantec profile priced per length,2500,10,10,20.00,piece\n";
    snprintf(path, sizeof path, "%s/x.csv", src);
    CHECK(tu_write_file(path, per_length, sizeof per_length - 1));
    snprintf(path, sizeof path, "%s/catalog.sqlite", dir);
    cat_db *db = NULL;
    if (cat_catalog_open(path, src, &db, err, sizeof err) != CAT_DB_OK) {
        CHECK_MSG(0, "%s", err);
        tu_remove_tree(dir);
        free(dir);
        return;
    }
    app_trim_quantity q[3] = {
        /* the reveals of reveals_room.json: 4.0 m from 2 lengths, and the niche's 2.0 m from 1 */
        {.product = {"Kantec", "KT-L10", "CP"}, .edges = 4, .metres = 4.0, .pieces = 2},
        {.product = {"Kantec", "KT-R10", "CP"}, .edges = 4, .metres = 2.0, .pieces = 1},
        {.product = {"Kantec", "KT-X10", ""}, .edges = 2, .metres = 3.0, .pieces = 2},
    };
    app_bom b;
    memset(&b, 0, sizeof b);
    CHECK(app_bom_add_trims(db, q, 3, &b, err, sizeof err) == APP_OK);
    CHECK(b.line_count == 3 && b.missing == 0);
    if (b.line_count == 3) {
        /* KT-L10: 2 lengths x 2.5 m = 5.00 m billed (not the 4.00 m set) x 7.56 = 37.80 EUR,
         * the price of 2 lengths at 18.90; VAT 19 %: 7.182 -> 7.18 */
        const app_bom_line *l = &b.lines[0];
        CHECK(l->unit == CAT_UNIT_M && l->unit_price_cents == 756);
        CHECK_NEAR(l->quantity, 5.0, 1e-12);
        CHECK(l->net_cents == 3780 && l->vat_cents == 718);
        CHECK_MSG(!strcmp(l->detail, "4.00 m needed: 2 x 2.5 m = 5.00 m billed"), "%s", l->detail);
        /* KT-R10: 1 length = 2.50 m x 9.96 = 24.90 EUR */
        CHECK(b.lines[1].unit == CAT_UNIT_M && b.lines[1].net_cents == 2490);
        CHECK_NEAR(b.lines[1].quantity, 2.5, 1e-12);
        /* KT-X10, priced per length: 2 pieces x 20.00 = 40.00 EUR */
        CHECK(b.lines[2].unit == CAT_UNIT_PIECE && b.lines[2].quantity == 2);
        CHECK(b.lines[2].net_cents == 4000);
        CHECK_MSG(!strcmp(b.lines[2].detail, "3.00 m needed: 2 lengths of 2.5 m"), "%s",
                  b.lines[2].detail);
        /* 37.80 + 24.90 + 40.00 = 102.70 EUR */
        CHECK(b.net_cents == 10270);
    }
    app_bom_free(&b);
    /* brushed stainless: (7.56 + 1.20) EUR/m x 5.00 m = 43.80 EUR = 2 x (18.90 + 3.00) */
    snprintf(q[0].product.variant, sizeof q[0].product.variant, "BS");
    CHECK(app_bom_add_trims(db, q, 1, &b, err, sizeof err) == APP_OK);
    CHECK(b.line_count == 1 && b.lines[0].unit_price_cents == 876 && b.lines[0].net_cents == 4380);
    app_bom_free(&b);
    /* the metres billed: pieces x 2.5 m */
    CHECK_NEAR(app_trim_billed_metres(&q[0]), 5.0, 1e-12);
    CHECK(app_trim_billed_metres(NULL) == 0);
    cat_db_close(db);
    tu_remove_tree(dir);
    free(dir);
}

int main(void)
{
    test_pieces();
    test_edges();
    test_project_totals();
    test_priced_per_metre();
    return check_report("trims");
}
