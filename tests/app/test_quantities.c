/* Quantities (app/design/quantities.h): boxes with the surplus rounded up, offcut reuse (a decor
 * tile refused, a remainder turned), tile specs and the bill of materials from the real shipped
 * catalog (built into a temporary SQLite file), a project's layouts. Expected numbers are
 * derived by hand in the comments. */
#include "test_util.h" /* first: it sets _XOPEN_SOURCE for mkdtemp */

#include "app/design/quantities.h"

#include <limits.h>
#include <math.h>

static app_tile_spec spec(double w, double h, app_tile_type type, int per_box, double m2_box)
{
    app_tile_spec s;
    memset(&s, 0, sizeof s);
    snprintf(s.product.manufacturer, sizeof s.product.manufacturer, "Test");
    snprintf(s.product.article, sizeof s.product.article, "T-%s",
             type == APP_TILE_DEK ? "DEK" : "UNI");
    s.type = type;
    s.work_w_mm = w;
    s.work_h_mm = h;
    s.grout_mm = 3;
    s.pieces_per_box = per_box;
    s.m2_per_box = m2_box;
    s.reusable_offcuts = s.rotatable = type != APP_TILE_DEK;
    return s;
}

static app_result lay(double width, double height, app_tile_pattern pat, const app_tile_spec *f,
                      const app_point2 *window, app_tile_layout *l, char *err, size_t es)
{
    app_surface_region r;
    app_surface_region_init(&r, "wall:0", APP_SURFACE_WALL);
    app_region_set_outer_rect(&r, 0, 0, width, height, err, es);
    if (window)
        app_region_add_hole_rect(&r, window[0].x, window[0].y, window[1].x, window[1].y,
                                 APP_HOLE_OPENING, "window", err, es);
    app_tiling t;
    memset(&t, 0, sizeof t);
    t.pattern = pat;
    t.align = APP_ALIGN_CORNER;
    t.grout_mm = 3;
    app_tile_layout_desc d = {&r, &t, f, NULL, 0};
    app_result res = app_tile_layout_compute(&d, l, err, es);
    app_surface_region_free(&r);
    return res;
}

/* The wall (test_tile_layout.c): 12 whole + 24 cut = 36 tiles of 597 x 297. Without
 * offcut reuse: 36 x 1.10 = 39.6 -> 40 pieces -> 8 per box: 5 boxes = 40 pieces. 15 %: 41.4 ->
 * 42 -> 6 boxes = 48. 0 %: 36 -> 5 boxes (4.5 up) = 40. Boxes by m2 only (1.44 m2, pieces per
 * box unknown): 40 x 0.597 x 0.297 = 7.09 m2 -> 4.93 -> 5 boxes = 7.20 m2. */
static void test_boxes(void)
{
    char err[256] = "";
    app_tile_spec f = spec(597, 297, APP_TILE_UNI, 8, 1.44);
    app_point2 win[2] = {{700, 1000}, {1300, 1900}};
    app_tile_layout l;
    CHECK_MSG(lay(2000, 2500, APP_PATTERN_HALF_OFFSET, &f, win, &l, err, sizeof err) == APP_OK,
              "%s", err);
    app_quantity_options o = app_quantity_options_default();
    CHECK(o.surplus_percent == 10.0 && o.reuse_offcuts == 1);
    o.reuse_offcuts = 0;
    app_quantities q;
    CHECK_MSG(app_quantities_compute(&l, 1, &o, &q, err, sizeof err) == APP_OK, "%s", err);
    CHECK(q.line_count == 1);
    const app_tile_quantity *t = &q.lines[0];
    CHECK(t->whole == 12 && t->cut == 24 && t->reused == 0 && t->pieces_needed == 36);
    CHECK(t->pieces_with_surplus == 40);
    CHECK(t->boxes == 5 && t->pieces_to_order == 40);
    CHECK(fabs(t->order_m2 - 7.2) < 1e-9);
    CHECK(fabs(t->area_m2 - 4.397789) < 1e-6);
    app_quantities_free(&q);
    o.surplus_percent = 15;
    CHECK(app_quantities_compute(&l, 1, &o, &q, err, sizeof err) == APP_OK);
    CHECK(q.lines[0].pieces_with_surplus == 42 && q.lines[0].boxes == 6 &&
          q.lines[0].pieces_to_order == 48);
    app_quantities_free(&q);
    o.surplus_percent = 0;
    CHECK(app_quantities_compute(&l, 1, &o, &q, err, sizeof err) == APP_OK);
    CHECK(q.lines[0].pieces_with_surplus == 36 && q.lines[0].boxes == 5);
    app_quantities_free(&q);
    l.specs[0].pieces_per_box = 0;
    o.surplus_percent = 10;
    CHECK(app_quantities_compute(&l, 1, &o, &q, err, sizeof err) == APP_OK);
    CHECK(q.lines[0].boxes == 5 && fabs(q.lines[0].order_m2 - 7.2) < 1e-9);
    app_quantities_free(&q);
    /* Two layouts of the same product add up: 72 tiles -> 79.2 -> 80 -> 10 boxes of 8. */
    l.specs[0].pieces_per_box = 8;
    app_tile_layout two[2] = {l, l};
    CHECK(app_quantities_compute(two, 2, &o, &q, err, sizeof err) == APP_OK);
    CHECK(q.line_count == 1 && q.lines[0].pieces_needed == 72 && q.lines[0].boxes == 10);
    app_quantities_free(&q);
    /* 30 x 1.10 is 33.000000000000004 in doubles: still 33, not 34. */
    l.tile_count = 30;
    for (int i = 0; i < 30; i++)
        l.tiles[i].whole = 1;
    CHECK(app_quantities_compute(&l, 1, &o, &q, err, sizeof err) == APP_OK);
    CHECK(q.lines[0].pieces_with_surplus == 33);
    app_quantities_free(&q);
    o.surplus_percent = -1;
    CHECK(app_quantities_compute(&l, 1, &o, &q, err, sizeof err) != APP_OK);
    CHECK(tu_contains(err, "quantities"));
    app_tile_layout_free(&l);
}

/* A wall 1000 x 600, 597 x 297 tiles half offset from the corner (2 rows):
 *   row 0: 0..597 whole, 600..1197 cut to 400 wide (rest 597 - 400 - 3 kerf = 194 x 297);
 *   row 1: -300..297 cut to 297 (rest 297 x 297), 300..897 whole, 900..1497 cut to 100 (rest
 *          494 x 297).
 * Largest cut first, best fit: the 400 piece takes the 494 rest of the 100 cut. The 297 piece
 * has only its own rest and the 400 cut's (that tile is not bought: no rest); the 100 cut's
 * tile is bought whole. So 1 reuse: 2 whole + 3 cut - 1 = 4 tiles. A decor tile: none. */
static void test_offcuts(void)
{
    char err[256] = "";
    app_tile_spec f = spec(597, 297, APP_TILE_UNI, 8, 1.44);
    app_tile_layout l;
    CHECK_MSG(lay(1000, 600, APP_PATTERN_HALF_OFFSET, &f, NULL, &l, err, sizeof err) == APP_OK,
              "%s", err);
    CHECK(l.whole_count == 2 && l.cut_count == 3);
    app_quantities q;
    CHECK_MSG(app_quantities_compute(&l, 1, NULL, &q, err, sizeof err) == APP_OK, "%s", err);
    CHECK(q.lines[0].reused == 1 && q.lines[0].pieces_needed == 4);
    CHECK(q.offcut_count == 1);
    if (q.offcut_count == 1) {
        const app_offcut_use *u = &q.offcuts[0];
        CHECK(fabs(u->piece_w_mm - 400) < 1e-6 && fabs(u->piece_h_mm - 297) < 1e-6);
        CHECK(fabs(u->rest_w_mm - 494) < 1e-6 && fabs(u->rest_h_mm - 297) < 1e-6);
        CHECK(!u->rotated);
        CHECK(fabs(l.tiles[u->source_tile].cut_w_mm - 100) < 1e-6);
        CHECK(u->source_tile != u->target_tile);
    }
    app_quantities_free(&q);
    app_tile_layout_free(&l);

    /* The same wall in a decor tile: DOMAIN.md, decor tiles cannot be reused. */
    f = spec(597, 297, APP_TILE_DEK, 8, 1.44);
    f.reusable_offcuts = 1; /* even when a caller says so */
    CHECK(lay(1000, 600, APP_PATTERN_HALF_OFFSET, &f, NULL, &l, err, sizeof err) == APP_OK);
    CHECK(app_quantities_compute(&l, 1, NULL, &q, err, sizeof err) == APP_OK);
    CHECK(q.lines[0].reused == 0 && q.offcut_count == 0 && q.lines[0].pieces_needed == 5);
    CHECK(fabs(q.lines[0].length_m - (597 + 400 + 297 + 597 + 100) * 1e-3) < 1e-9);
    app_quantities_free(&q);
    app_tile_layout_free(&l);
}

/* Turning a remainder: tile A cut 400 x 297 (rest 194 x 297), tile B cut 250 x 150 (rests
 * 344 x 297 or 597 x 144: the larger, 344 x 297). A's piece (118 800 mm2) finds no rest as large
 * but B's own; B's piece 250 x 150 fits A's rest 194 x 297 only turned (150 <= 194, 250 <=
 * 297). Not rotatable: no reuse. */
static void test_rotation(void)
{
    char err[256] = "";
    app_tile_layout l;
    memset(&l, 0, sizeof l);
    l.specs[0] = spec(597, 297, APP_TILE_UNI, 8, 1.44);
    l.spec_count = 1;
    app_placed_tile tiles[2];
    memset(tiles, 0, sizeof tiles);
    tiles[0].cut_w_mm = 400, tiles[0].cut_h_mm = 297, tiles[0].area_mm2 = 400 * 297;
    tiles[1].cut_w_mm = 250, tiles[1].cut_h_mm = 150, tiles[1].area_mm2 = 250 * 150;
    l.tiles = tiles;
    l.tile_count = 2;
    app_quantities q;
    CHECK(app_quantities_compute(&l, 1, NULL, &q, err, sizeof err) == APP_OK);
    CHECK(q.offcut_count == 1 && q.lines[0].reused == 1);
    if (q.offcut_count == 1)
        CHECK(q.offcuts[0].rotated && q.offcuts[0].source_tile == 0 &&
              q.offcuts[0].target_tile == 1);
    app_quantities_free(&q);
    l.specs[0].rotatable = 0;
    CHECK(app_quantities_compute(&l, 1, NULL, &q, err, sizeof err) == APP_OK);
    CHECK(q.offcut_count == 0);
    app_quantities_free(&q);

    /* A piece from the middle of a tile (u 200..397 of 597) leaves two strips of 200 - 3 and
     * 200 - 3 = 197 mm, not one of 597 - 197 - 3 = 397: a 300 mm piece finds no rest (its own
     * rest is 597 - 300 - 3 = 294 x 297, and a tile never serves itself). */
    l.specs[0].rotatable = 1;
    memset(tiles, 0, sizeof tiles);
    tiles[0].cut_w_mm = 197, tiles[0].cut_h_mm = 297, tiles[0].cut_u0_mm = 200;
    tiles[0].area_mm2 = 197 * 297;
    tiles[1].cut_w_mm = 300, tiles[1].cut_h_mm = 297, tiles[1].area_mm2 = 300 * 297;
    CHECK(app_quantities_compute(&l, 1, NULL, &q, err, sizeof err) == APP_OK);
    /* The 300 piece is larger; it finds only tile 0's 197 rest: none. Then the 197 piece takes
     * tile 1's 294 x 297 rest. */
    CHECK(q.offcut_count == 1);
    if (q.offcut_count == 1)
        CHECK(q.offcuts[0].source_tile == 1 && q.offcuts[0].target_tile == 0 &&
              fabs(q.offcuts[0].rest_w_mm - 294) < 1e-9);
    app_quantities_free(&q);
}

/* The diagonal floor of test_tile_layout.c (1800 x 1200, 600 mm diagonals, no joint, from the
 * corner): 7 whole tiles and 10 half tiles cut on their diagonal. Without a kerf each half's
 * rest is the other half, so 5 halves come from the rests of the other 5: 7 + 10 - 5 = 12 tiles,
 * exactly the floor's 2 160 000 mm2 of 180 000 mm2 tiles. With a 3 mm kerf the rest's legs are
 * 1 % short (3 mm of the 300 mm from the right angle to the cut): no reuse. */
static void test_diagonal_halves(void)
{
    char err[256] = "";
    double a = 600.0 / sqrt(2.0);
    app_tile_spec f = spec(a, a, APP_TILE_UNI, 10, 1.8);
    f.grout_mm = 0;
    app_surface_region r;
    app_surface_region_init(&r, "floor", APP_SURFACE_FLOOR);
    CHECK(app_region_set_outer_rect(&r, 0, 0, 1800, 1200, err, sizeof err) == APP_OK);
    app_tiling t;
    memset(&t, 0, sizeof t);
    t.pattern = APP_PATTERN_DIAGONAL;
    t.align = APP_ALIGN_CORNER;
    app_tile_layout_desc d = {&r, &t, &f, NULL, 0};
    app_tile_layout l;
    CHECK_MSG(app_tile_layout_compute(&d, &l, err, sizeof err) == APP_OK, "%s", err);
    CHECK(l.whole_count == 7 && l.cut_count == 10);
    app_quantity_options o = app_quantity_options_default();
    o.kerf_mm = 0;
    app_quantities q;
    CHECK(app_quantities_compute(&l, 1, &o, &q, err, sizeof err) == APP_OK);
    CHECK(q.lines[0].reused == 5 && q.lines[0].pieces_needed == 12);
    for (int i = 0; i < q.offcut_count; i++) {
        CHECK(q.offcuts[i].piece_triangle && q.offcuts[i].rest_triangle && q.offcuts[i].rotated);
        CHECK(fabs(q.offcuts[i].piece_w_mm - a) < 1e-6 && fabs(q.offcuts[i].rest_w_mm - a) < 1e-6);
    }
    app_quantities_free(&q);
    o.kerf_mm = 3;
    CHECK(app_quantities_compute(&l, 1, &o, &q, err, sizeof err) == APP_OK);
    CHECK(q.lines[0].reused == 0 && q.lines[0].pieces_needed == 17);
    app_quantities_free(&q);
    /* Not rotatable: the opposite half cannot be turned into place. */
    o.kerf_mm = 0;
    l.specs[0].rotatable = 0;
    CHECK(app_quantities_compute(&l, 1, &o, &q, err, sizeof err) == APP_OK);
    CHECK(q.lines[0].reused == 0);
    app_quantities_free(&q);
    app_tile_layout_free(&l);
    app_surface_region_free(&r);
}

/* The shipped catalog and a version 2 project with tilings. */
static void test_catalog_and_bom(void)
{
    char err[1024] = "", dir[] = "/tmp/tessera-quantities-XXXXXX", path[512];
    CHECK(mkdtemp(dir) != NULL);
    snprintf(path, sizeof path, "%s/catalog.sqlite", dir);
    cat_db *db = NULL;
    CHECK_MSG(cat_catalog_open(path, TESSERA_SOURCE_DIR "/assets/catalog", &db, err, sizeof err) ==
                  CAT_DB_OK,
              "%s", err);
    if (!db)
        return;
    app_product_ref ref;
    memset(&ref, 0, sizeof ref);
    snprintf(ref.manufacturer, sizeof ref.manufacturer, "Terrazza Ceramiche");
    snprintf(ref.article, sizeof ref.article, "TZ61000");
    app_tile_spec s;
    cat_product p;
    CHECK_MSG(app_tile_spec_from_catalog(db, &ref, &s, &p, err, sizeof err) == APP_OK, "%s", err);
    CHECK(s.type == APP_TILE_UNI && s.work_w_mm == 297 && s.work_h_mm == 597 && s.grout_mm == 3);
    CHECK(s.pieces_per_box == 8 && fabs(s.m2_per_box - 1.44) < 1e-9 && s.rotatable);
    CHECK(p.has_tile && !strcmp(p.article, "TZ61000"));
    cat_product_free(&p);
    snprintf(ref.article, sizeof ref.article, "TZ61049"); /* a decor */
    CHECK(app_tile_spec_from_catalog(db, &ref, &s, NULL, err, sizeof err) == APP_OK);
    CHECK(s.type == APP_TILE_DEK && !s.rotatable && !s.reusable_offcuts);
    snprintf(ref.manufacturer, sizeof ref.manufacturer, "Cerana");
    snprintf(ref.article, sizeof ref.article, "CE412901"); /* a WC: not a tile */
    CHECK(app_tile_spec_from_catalog(db, &ref, &s, NULL, err, sizeof err) == APP_ERR_NOT_FOUND);
    snprintf(ref.article, sizeof ref.article, "NO-SUCH");
    CHECK(app_tile_spec_from_catalog(db, &ref, &s, NULL, err, sizeof err) == APP_ERR_NOT_FOUND);

    app_project pr;
    CHECK_MSG(app_project_read(TESSERA_SOURCE_DIR "/tests/data/tiles/tiled_bathroom.json", &pr, err,
                               sizeof err) == APP_OK,
              "%s", err);
    app_tile_layout *ls = NULL;
    int n = 0;
    CHECK_MSG(app_project_tile_layouts(&pr, db, NULL, NULL, &ls, &n, err, sizeof err) == APP_OK,
              "%s", err);
    CHECK(n == pr.tiling_count && n == 7);
    app_quantities q;
    memset(&q, 0, sizeof q);
    CHECK(app_quantities_compute(ls, n, NULL, &q, err, sizeof err) == APP_OK);
    /* Products: TZ61002 floor, TZ61000 walls, FA-10128 border, TZ61049 decor on the box top. */
    CHECK(q.line_count == 4);
    double region = 0;
    for (int i = 0; i < n; i++) {
        region += ls[i].region_area_mm2;
        double cells = ls[i].unassigned_grout_mm2;
        for (int k = 0; k < ls[i].tile_count; k++)
            cells += ls[i].tiles[k].cell_area_mm2;
        CHECK(fabs(cells - ls[i].region_area_mm2) < 1e-3 * ls[i].region_area_mm2);
    }
    /* Floor 2800 x 2400 minus the box 1000 x 200 = 6 520 000; walls 2500 high: 2 x 2800 + 2 x
     * 2400 = 10 400 long = 26 000 000, minus window 990 000, door 1 608 000, box behind 1 100 000
     * = 22 302 000; box front 1 100 000, top 200 000. Sum 30 122 000 mm2 of surface.
     * A tiler leaves the 3 mm elastic edge joint open along every boundary, so the tiled
     * regions are those surfaces shrunk by 3 mm (openings and covered areas grown by 3 mm):
     * floor 2794 x 2394 minus the box grown to 1006 wide, 200 deep inside = 6 487 636; walls
     * 2494 high x (2 x 2794 + 2 x 2394) = 25 877 744, minus window 906 x 1106 = 1 002 036,
     * door 806 x 2010 = 1 620 060, box behind 1006 x 1100 = 1 106 600 = 22 149 048; box front
     * 994 x 1094 = 1 087 436, top 994 x 194 = 192 836. Sum 29 916 956 mm2. */
    CHECK_MSG(fabs(region - 29916956.0) < 1.0, "tiled region %.1f mm2", region);
    app_bom b;
    CHECK(app_bom_build(db, &pr, &q, &b, err, sizeof err) == APP_OK);
    CHECK(b.line_count == 5 && b.missing == 0 && !strcmp(b.currency, "EUR"));
    long long net = 0, vat = 0;
    for (int i = 0; i < b.line_count; i++) {
        net += b.lines[i].net_cents;
        vat += b.lines[i].vat_cents;
        CHECK(b.lines[i].gross_cents == b.lines[i].net_cents + b.lines[i].vat_cents);
        CHECK(llabs(b.lines[i].net_cents -
                    llround(b.lines[i].quantity * (double)b.lines[i].unit_price_cents)) <= 0);
    }
    CHECK(net == b.net_cents && vat == b.vat_cents && b.gross_cents == net + vat);
    /* The wall tile is priced per m2: the order is whole boxes of 1.44 m2. */
    CHECK(!strcmp(b.lines[1].product.article, "TZ61000") && b.lines[1].unit == CAT_UNIT_M2);
    CHECK(fabs(b.lines[1].quantity - q.lines[1].boxes * 1.44) < 1e-9);
    /* The border is priced per piece (20 to a box): billed for the pieces ordered (needed plus
     * the surplus), not the box. */
    for (int i = 0; i < q.line_count; i++)
        if (!strcmp(q.lines[i].spec.product.article, "FA-10128")) {
            CHECK(b.lines[i].unit == CAT_UNIT_PIECE);
            CHECK_MSG(b.lines[i].quantity == q.lines[i].pieces_with_surplus &&
                          q.lines[i].pieces_with_surplus < q.lines[i].pieces_to_order,
                      "%g billed, %d with the surplus, %d in whole boxes", b.lines[i].quantity,
                      q.lines[i].pieces_with_surplus, q.lines[i].pieces_to_order);
        }
    /* The WC: one piece at its list price (419.00 EUR, 19 % VAT). */
    CHECK(!strcmp(b.lines[4].product.article, "CE412901") && b.lines[4].quantity == 1);
    CHECK(b.lines[4].unit_price_cents == 41900 && b.lines[4].vat_cents == 7961);
    app_bom_free(&b);
    app_quantities_free(&q);
    app_tile_layouts_free(ls, n);
    app_project_free(&pr);
    cat_db_close(db);
    unlink(path);
    rmdir(dir);
}

/* A piece-priced border or decor is billed per piece; box and m2 prices sell whole boxes. */
static void test_billed_unit(void)
{
    app_tile_quantity t;
    memset(&t, 0, sizeof t);
    t.spec = spec(297, 47, APP_TILE_BOR, 20, 0);
    t.whole = 6;
    t.cut = 3;
    t.reused = 1;
    t.pieces_needed = 8;
    t.pieces_with_surplus = 9;
    t.boxes = 1;
    t.pieces_to_order = 20;
    t.order_m2 = 20 * 0.297 * 0.047;
    CHECK_MSG(app_tile_billed_quantity(&t, CAT_UNIT_PIECE) == 9, "8 needed + 10 %%, %g billed",
              app_tile_billed_quantity(&t, CAT_UNIT_PIECE));
    CHECK(app_tile_billed_quantity(&t, CAT_UNIT_BOX) == 1);
    CHECK(fabs(app_tile_billed_quantity(&t, CAT_UNIT_M2) - t.order_m2) < 1e-12);
}

static void test_vat_label(void)
{
    char b[16];
    CHECK_MSG(!strcmp(app_format_percent(8.1, b, sizeof b), "8.1"), "8.1 -> %s", b);
    CHECK_MSG(!strcmp(app_format_percent(19, b, sizeof b), "19"), "19 -> %s", b);
    CHECK_MSG(!strcmp(app_format_percent(7.7, b, sizeof b), "7.7"), "7.7 -> %s", b);
    CHECK_MSG(!strcmp(app_format_percent(2.55, b, sizeof b), "2.55"), "2.55 -> %s", b);
    CHECK_MSG(!strcmp(app_format_percent(0, b, sizeof b), "0"), "0 -> %s", b);
}

/* A line in another currency is not summed into the project's total. */
static void test_mixed_currency(void)
{
    app_bom_line lines[3];
    memset(lines, 0, sizeof lines);
    const char *cur[3] = {"EUR", "CHF", "EUR"};
    for (int i = 0; i < 3; i++) {
        lines[i].found = 1;
        lines[i].quantity = 2;
        lines[i].unit_price_cents = 1000;
        lines[i].vat_percent = i == 1 ? 8.1 : 19;
        snprintf(lines[i].currency, sizeof lines[i].currency, "%s", cur[i]);
        snprintf(lines[i].product.article, sizeof lines[i].product.article, "A%d", i);
    }
    app_bom b;
    memset(&b, 0, sizeof b);
    b.lines = lines;
    b.line_count = 3;
    app_bom_total(&b);
    CHECK_MSG(!strcmp(b.currency, "EUR"), "project currency %s", b.currency);
    CHECK(b.foreign == 1 && lines[1].foreign_currency && !lines[0].foreign_currency);
    CHECK(lines[1].net_cents == 2000 && lines[1].vat_cents == 162);
    CHECK_MSG(b.net_cents == 4000 && b.vat_cents == 760 && b.gross_cents == 4760,
              "net %lld vat %lld gross %lld", b.net_cents, b.vat_cents, b.gross_cents);
}

/* A price near INT64_MAX (a catalog file not written by the import) must not wrap to a negative
 * quotation: the line is out of range, left out, and the totals say so instead of wrapping. */
static void test_price_overflow(void)
{
    app_bom_line lines[4];
    memset(lines, 0, sizeof lines);
    for (int i = 0; i < 4; i++) {
        lines[i].found = 1;
        lines[i].quantity = 2;
        lines[i].unit_price_cents = 1000;
        lines[i].vat_percent = 19;
        snprintf(lines[i].currency, sizeof lines[i].currency, "EUR");
    }
    lines[1].unit_price_cents = LLONG_MAX - 5;
    app_bom b;
    memset(&b, 0, sizeof b);
    b.lines = lines;
    b.line_count = 2;
    app_bom_total(&b);
    CHECK(lines[1].out_of_range && !lines[0].out_of_range);
    CHECK_MSG(lines[1].net_cents == 0 && lines[1].gross_cents == 0, "line net %lld gross %lld",
              lines[1].net_cents, lines[1].gross_cents);
    CHECK(b.out_of_range == 1);
    CHECK_MSG(b.net_cents == 0 && b.gross_cents == 0, "net %lld gross %lld", b.net_cents,
              b.gross_cents);

    /* Each line fits, their sum does not: still no wrapped total. */
    for (int i = 0; i < 4; i++) {
        lines[i].unit_price_cents = 1LL << 60;
        lines[i].vat_percent = 0;
    }
    b.line_count = 4;
    app_bom_total(&b);
    CHECK(!lines[0].out_of_range && lines[0].net_cents == 1LL << 61);
    CHECK(b.out_of_range == 1);
    CHECK_MSG(b.net_cents == 0 && b.gross_cents == 0, "net %lld gross %lld", b.net_cents,
              b.gross_cents);
}

int main(void)
{
    test_price_overflow();
    test_billed_unit();
    test_vat_label();
    test_mixed_currency();
    test_boxes();
    test_offcuts();
    test_rotation();
    test_diagonal_halves();
    test_catalog_and_bom();
    return check_report("quantities");
}
