/* Trim profiles (app/design/trims.h, docs/tiling.md "Trim profiles"): the outside edges of
 * reveal, niche and pre-wall tilings on the L-shaped test room, the 2.5 m lengths they are cut
 * from, and the totals per product. Every expected value is worked out in the comments. */
#include "app/design/room_surfaces.h"
#include "app/design/trims.h"
#include "test_util.h"

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

int main(void)
{
    test_pieces();
    test_edges();
    test_project_totals();
    return check_report("trims");
}
