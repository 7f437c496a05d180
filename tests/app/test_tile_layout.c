/* Tile layout (app/design/tile_layout.h): hand-computed whole/cut counts and areas for worked
 * cases, and the area balance "tiles + grout = surface - openings - covered areas" for every
 * pattern. The expected numbers are derived in the comments, not taken from the code. */
#include "test_util.h"

#include "app/design/tile_layout.h"

#include <math.h>

static app_tile_spec spec(double w, double h, double grout, app_tile_type type)
{
    app_tile_spec s;
    memset(&s, 0, sizeof s);
    snprintf(s.product.manufacturer, sizeof s.product.manufacturer, "Test");
    snprintf(s.product.article, sizeof s.product.article, "T-%gx%g", w, h);
    s.type = type;
    s.work_w_mm = w;
    s.work_h_mm = h;
    s.grout_mm = grout;
    s.reusable_offcuts = s.rotatable = type != APP_TILE_DEK;
    return s;
}

static app_tiling tiling(app_tile_pattern pattern, app_tile_align align, double grout)
{
    app_tiling t;
    memset(&t, 0, sizeof t);
    snprintf(t.name, sizeof t.name, "test");
    t.pattern = pattern;
    t.align = align;
    t.grout_mm = grout;
    return t;
}

/* Sum of the clipped tiles' areas recomputed from their pieces (independent of area_mm2). */
static double pieces_area(const app_tile_layout *l)
{
    double a = 0;
    for (int i = 0; i < l->piece_count; i++)
        a += app_polygon_signed_area(l->points + l->pieces[i].first, l->pieces[i].count);
    return a;
}

/* Tiles plus their share of grout must cover the region exactly: no overlaps, no gaps. */
static void check_balance(const app_tile_layout *l, double expected_region, const char *what)
{
    double cells = l->unassigned_grout_mm2;
    for (int i = 0; i < l->tile_count; i++)
        cells += l->tiles[i].cell_area_mm2;
    double tol = 1e-3 * expected_region; /* 0.1 % */
    if (fabs(cells - expected_region) > tol || fabs(l->region_area_mm2 - expected_region) > tol ||
        fabs(pieces_area(l) - l->tiled_area_mm2) > 1e-6 * expected_region) {
        fprintf(stderr, "%s: region %.1f expected %.1f, tiles+grout %.1f, pieces %.1f tiled %.1f\n",
                what, l->region_area_mm2, expected_region, cells, pieces_area(l),
                l->tiled_area_mm2);
        CHECK(0);
    } else
        CHECK(1);
    CHECK(fabs(l->tiled_area_mm2 + l->grout_area_mm2 - l->region_area_mm2) < 1e-6);
}

/* A 2000 x 2500 wall, 300 x 600 tiles (nominal: work 597 x 297 + 3 mm grout) laid
 * landscape in half offset from the bottom-left corner, with a window 600 wide x 900 high at
 * s 700..1300, sill 1000.
 *
 * Rows j (work t ranges): j = 0..7 at 300 j .. 300 j + 297, j = 8 at 2400..2697 cut to 2500.
 * Even rows: tiles at s 0..597, 600..1197, 1200..1797 (whole) and 1800..2397 (cut at 2000);
 * odd rows (shifted 300): -300..297 (cut), 300..897, 900..1497 (whole), 1500..2097 (cut).
 * Without the window: rows 0..7 give 4 x 3 + 4 x 2 = 20 whole and 4 x 1 + 4 x 2 = 12 cut, row
 * 8 gives 4 cut: 20 whole, 16 cut, 36 tiles.
 * The window (t 1000..1900) meets rows 3, 4, 5, 6 and in each exactly the two middle tiles
 * (even: 600..1197, 1200..1797; odd: 300..897, 900..1497), all whole before, none inside the
 * window entirely: 8 more cuts. Expected: 12 whole, 24 cut.
 * Tiled area: each row covers 1991 mm of s (even 3 x 597 + 200, odd 297 + 2 x 597 + 500), rows
 * 8 x 297 + 100 = 2476 mm high: 1991 x 2476 = 4 929 716 mm2; the window takes 597 mm of s per
 * row (even 497 + 100, odd 197 + 400) over 197 + 297 + 297 + 100 = 891 mm of t: 531 927 mm2.
 * Tiled: 4 397 789 mm2. Region: 2000 x 2500 - 600 x 900 = 4 460 000 mm2. */
static void test_wall_half_offset_window(void)
{
    char err[256] = "";
    app_surface_region r;
    app_surface_region_init(&r, "wall:0", APP_SURFACE_WALL);
    CHECK(app_region_set_outer_rect(&r, 0, 0, 2000, 2500, err, sizeof err) == APP_OK);
    CHECK(app_region_add_hole_rect(&r, 700, 1000, 1300, 1900, APP_HOLE_OPENING, "window", err,
                                   sizeof err) == APP_OK);
    CHECK(fabs(app_surface_region_area(&r) - 4460000.0) < 1e-3);
    app_tile_spec f = spec(597, 297, 3, APP_TILE_UNI);
    app_tiling t = tiling(APP_PATTERN_HALF_OFFSET, APP_ALIGN_CORNER, 3);
    app_tile_layout_desc d = {&r, &t, &f, NULL, 0};
    app_tile_layout l;
    app_result res = app_tile_layout_compute(&d, &l, err, sizeof err);
    CHECK_MSG(res == APP_OK, "%s", err);
    printf("wall: %d whole, %d cut, tiled %.1f mm2, grout %.1f mm2\n", l.whole_count, l.cut_count,
           l.tiled_area_mm2, l.grout_area_mm2);
    CHECK(l.whole_count == 12);
    CHECK(l.cut_count == 24);
    CHECK(l.tile_count == 36);
    CHECK(fabs(l.tiled_area_mm2 - 4397789.0) < 0.01);
    check_balance(&l, 4460000.0, "wall");
    /* The L-shaped cut under the window's lower left corner: row 3 (odd), tile 300..897
     * keeps s 300..700 full height and 700..897 below the sill: 400 x 297 + 197 x 100. */
    int found = 0;
    for (int i = 0; i < l.tile_count; i++) {
        const app_placed_tile *p = &l.tiles[i];
        if (p->row == 3 && fabs(p->cell[0].x - 300) < 1e-6) {
            found = 1;
            CHECK(!p->whole);
            CHECK(fabs(p->area_mm2 - (400.0 * 297 + 197.0 * 100)) < 1e-6);
            CHECK(fabs(p->cut_w_mm - 597) < 1e-6 && fabs(p->cut_h_mm - 297) < 1e-6);
            /* Its pieces' edges: the sill and the window's side are cuts. */
            int cuts = 0;
            for (int k = p->first_piece; k < p->first_piece + p->piece_count; k++)
                for (int e = 0; e < l.pieces[k].count; e++)
                    cuts += l.edges[l.pieces[k].first + e] == APP_EDGE_CUT;
            CHECK(cuts >= 2);
        }
        /* The cut in the last column of even rows is 200 wide. */
        if (p->row == 0 && fabs(p->cell[0].x - 1800) < 1e-6)
            CHECK(!p->whole && fabs(p->cut_w_mm - 200) < 1e-6 && fabs(p->cut_h_mm - 297) < 1e-6);
    }
    CHECK(found);
    app_tile_layout_free(&l);

    /* The catalog gives this tile as 297 wide x 597 high (portrait): row patterns still lay
     * the long side along the rows, turned 90 degrees, with the same counts and area. */
    f = spec(297, 597, 3, APP_TILE_UNI);
    CHECK_MSG(app_tile_layout_compute(&d, &l, err, sizeof err) == APP_OK, "%s", err);
    CHECK(l.whole_count == 12 && l.cut_count == 24);
    CHECK(fabs(l.tiled_area_mm2 - 4397789.0) < 0.01);
    for (int i = 0; i < l.tile_count; i++)
        CHECK(fabs(l.tiles[i].rotation_deg - 90) < 1e-9);
    app_tile_layout_free(&l);
    app_surface_region_free(&r);
}

/* A floor 1800 x 1200, square tiles with a 600 mm diagonal (side 600 / sqrt 2), no grout, laid
 * diagonally from the corner: diamonds centred at (300 p, 300 q + 300), p + q even. Centres
 * that meet the floor: p = 0..6, q = -1..3 with p + q even: 4 x 2 + 3 x 3 = 17 (none at a
 * corner). Whole when 300 <= x <= 1500 and 300 <= y <= 900: q = 0: p = 2, 4; q = 1: p = 1, 3, 5;
 * q = 2: p = 2, 4 -> 7 whole; the other 10 sit on an edge and are cut in half. */
static void test_floor_diagonal(void)
{
    char err[256] = "";
    app_surface_region r;
    app_surface_region_init(&r, "floor", APP_SURFACE_FLOOR);
    CHECK(app_region_set_outer_rect(&r, 0, 0, 1800, 1200, err, sizeof err) == APP_OK);
    double a = 600.0 / sqrt(2.0);
    app_tile_spec f = spec(a, a, 0, APP_TILE_UNI);
    app_tiling t = tiling(APP_PATTERN_DIAGONAL, APP_ALIGN_CORNER, 0);
    app_tile_layout_desc d = {&r, &t, &f, NULL, 0};
    app_tile_layout l;
    CHECK_MSG(app_tile_layout_compute(&d, &l, err, sizeof err) == APP_OK, "%s", err);
    printf("diagonal: %d whole, %d cut\n", l.whole_count, l.cut_count);
    CHECK(l.whole_count == 7);
    CHECK(l.cut_count == 10);
    for (int i = 0; i < l.tile_count; i++)
        if (!l.tiles[i].whole)
            CHECK(fabs(l.tiles[i].area_mm2 - 0.5 * a * a) < 1e-6);
    CHECK(fabs(l.tiled_area_mm2 - 1800.0 * 1200) < 1e-3);
    check_balance(&l, 1800.0 * 1200, "diagonal");
    app_tile_layout_free(&l);

    /* The same floor with 300 x 300 tiles and 3 mm grout, centred: the balance must hold. */
    f = spec(297, 297, 3, APP_TILE_UNI);
    t = tiling(APP_PATTERN_DIAGONAL, APP_ALIGN_CENTRED, 3);
    CHECK_MSG(app_tile_layout_compute(&d, &l, err, sizeof err) == APP_OK, "%s", err);
    check_balance(&l, 1800.0 * 1200, "diagonal grout");
    for (int i = 0; i < l.tile_count; i++)
        CHECK(fabs(l.tiles[i].rotation_deg - 45) < 1e-9);
    app_tile_layout_free(&l);
    app_surface_region_free(&r);
}

/* An L-shaped floor: (0,0) (3000,0) (3000,1500) (1500,1500) (1500,3000) (0,3000); 600 x 600
 * (597 + 3) straight from the corner. Columns and rows i, j = 0..4 at 600 i .. 600 i + 597.
 * Rows 0, 1: 5 whole each. Row 2 (1200..1797): i = 0, 1 whole; i = 2 loses its corner above and
 * right of (1500,1500) (L-shaped cut); i = 3, 4 cut to 300 high. Rows 3, 4: i = 0, 1 whole,
 * i = 2 cut to 300 wide, i = 3, 4 outside. Whole 16, cut 5.
 * Area: 16 x 597^2 = 5 702 544; cuts 597^2 - 297^2 = 268 200, 2 x 597 x 300, 2 x 300 x 597:
 * 984 600; tiled 6 687 144 of 3000 x 1500 + 1500 x 1500 = 6 750 000 mm2. */
static void test_floor_l_shape(void)
{
    char err[256] = "";
    app_point2 L[6] = {{0, 0}, {3000, 0}, {3000, 1500}, {1500, 1500}, {1500, 3000}, {0, 3000}};
    app_surface_region r;
    app_surface_region_init(&r, "floor", APP_SURFACE_FLOOR);
    CHECK(app_region_set_outer(&r, L, 6, err, sizeof err) == APP_OK);
    app_tile_spec f = spec(597, 597, 3, APP_TILE_UNI);
    app_tiling t = tiling(APP_PATTERN_STRAIGHT, APP_ALIGN_CORNER, 3);
    app_tile_layout_desc d = {&r, &t, &f, NULL, 0};
    app_tile_layout l;
    CHECK_MSG(app_tile_layout_compute(&d, &l, err, sizeof err) == APP_OK, "%s", err);
    printf("L floor: %d whole, %d cut, tiled %.1f\n", l.whole_count, l.cut_count, l.tiled_area_mm2);
    CHECK(l.whole_count == 16);
    CHECK(l.cut_count == 5);
    CHECK(fabs(l.tiled_area_mm2 - 6687144.0) < 0.01);
    check_balance(&l, 6750000.0, "L floor");
    app_tile_layout_free(&l);

    /* Every pattern on the L with a covered area (a pre-wall footprint) and a rotation. */
    CHECK(app_region_add_hole_rect(&r, 0, 2000, 300, 3000, APP_HOLE_COVERED, "box", err,
                                   sizeof err) == APP_OK);
    double expect = 6750000.0 - 300.0 * 1000;
    for (int p = APP_PATTERN_STRAIGHT; p <= APP_PATTERN_HERRINGBONE; p++)
        for (int rot = 0; rot < 2; rot++) {
            f = spec(297, 147, 3, APP_TILE_UNI);
            t = tiling((app_tile_pattern)p, rot ? APP_ALIGN_LINE : APP_ALIGN_CENTRED, 3);
            t.rotation_deg = rot ? 17.0 : 0.0;
            t.origin_mm[0] = 123;
            t.origin_mm[1] = 77;
            CHECK_MSG(app_tile_layout_compute(&d, &l, err, sizeof err) == APP_OK, "%s", err);
            char what[64];
            snprintf(what, sizeof what, "L %s rot %d", app_tile_pattern_name((app_tile_pattern)p),
                     rot);
            check_balance(&l, expect, what);
            /* Tiles cover w h / ((w + g)(h + g)) of the inside; the edges add a little. */
            double ratio = l.tiled_area_mm2 / expect, ideal = 297.0 * 147 / (300.0 * 150);
            CHECK(ratio > ideal - 0.002 && ratio < ideal + 0.01);
            app_tile_layout_free(&l);
        }
    app_surface_region_free(&r);
}

/* Third offset: row j shifted by j mod 3 thirds; herringbone: two orientations, the same
 * number of each far from the edges, none overlapping (the balance). */
static void test_third_offset_and_herringbone(void)
{
    char err[256] = "";
    app_surface_region r;
    app_surface_region_init(&r, "wall:1", APP_SURFACE_WALL);
    CHECK(app_region_set_outer_rect(&r, 0, 0, 3000, 2400, err, sizeof err) == APP_OK);
    app_tile_spec f = spec(597, 297, 3, APP_TILE_UNI);
    app_tiling t = tiling(APP_PATTERN_THIRD_OFFSET, APP_ALIGN_CORNER, 3);
    app_tile_layout_desc d = {&r, &t, &f, NULL, 0};
    app_tile_layout l;
    CHECK_MSG(app_tile_layout_compute(&d, &l, err, sizeof err) == APP_OK, "%s", err);
    /* 8 rows of 300. Row shifts 0, 200, 400: row 0 five whole tiles (0..2997); shifted rows
     * have 4 whole and 2 cut (200 + 400 = 600 of s in cut pieces). 3 rows shift 0 (j = 0, 3,
     * 6), 5 shifted: whole 3 x 5 + 5 x 4 = 35, cut 5 x 2 = 10. */
    CHECK(l.whole_count == 35);
    CHECK(l.cut_count == 10);
    for (int i = 0; i < l.tile_count; i++)
        if (l.tiles[i].row % 3 == 1 && !l.tiles[i].whole)
            CHECK(fabs(l.tiles[i].cut_w_mm - 197) < 1e-6 || fabs(l.tiles[i].cut_w_mm - 400) < 1e-6);
    check_balance(&l, 3000.0 * 2400, "third");
    app_tile_layout_free(&l);

    t = tiling(APP_PATTERN_HERRINGBONE, APP_ALIGN_CENTRED, 3);
    f = spec(597, 147, 3, APP_TILE_UNI); /* 4:1 */
    CHECK_MSG(app_tile_layout_compute(&d, &l, err, sizeof err) == APP_OK, "%s", err);
    int turned = 0, straight = 0;
    for (int i = 0; i < l.tile_count; i++) {
        if (!l.tiles[i].whole)
            continue;
        if (l.tiles[i].herring)
            turned++;
        else
            straight++;
        double rd = l.tiles[i].rotation_deg;
        CHECK(fabs(rd - 315) < 1e-9 || fabs(rd - 45) < 1e-9);
    }
    printf("herringbone: %d + %d whole, %d cut\n", straight, turned, l.cut_count);
    CHECK(abs(turned - straight) <= 0.1 * (turned + straight));
    /* 7.2 m2 holds 80 nominal 600 x 150 cells. A tile at 45 degrees is whole when its centre
     * is more than its half diagonal (307 mm) from the walls or so: the inner 2386 x 1786 mm
     * holds about 47 cells' worth; fewer than 80 can be whole. */
    CHECK(l.whole_count >= 40 && l.whole_count < 80);
    check_balance(&l, 3000.0 * 2400, "herringbone");
    app_tile_layout_free(&l);

    /* Vertical stack: 297 x 597 standing: 3000 / 300 = 10 columns, 2400 / 600 = 4 rows. */
    t = tiling(APP_PATTERN_VERTICAL_STACK, APP_ALIGN_CORNER, 3);
    f = spec(597, 297, 3, APP_TILE_UNI);
    CHECK_MSG(app_tile_layout_compute(&d, &l, err, sizeof err) == APP_OK, "%s", err);
    CHECK(l.whole_count == 40 && l.cut_count == 0);
    check_balance(&l, 3000.0 * 2400, "stack");
    app_tile_layout_free(&l);
    app_surface_region_free(&r);
}

/* A wall band with a border row: tiled 0..1500 with a 597 x 97 border at 897; the field is cut
 * 3 mm below and above the border (894 and 1000). */
static void test_band_and_border(void)
{
    char err[256] = "";
    app_surface_region r;
    app_surface_region_init(&r, "wall:2", APP_SURFACE_WALL);
    CHECK(app_region_set_outer_rect(&r, 0, 0, 1200, 2500, err, sizeof err) == APP_OK);
    app_tile_spec f = spec(297, 297, 3, APP_TILE_UNI);
    app_tile_spec b = spec(297, 97, 3, APP_TILE_BOR);
    snprintf(b.product.article, sizeof b.product.article, "BORDER");
    app_tiling t = tiling(APP_PATTERN_STRAIGHT, APP_ALIGN_CORNER, 3);
    t.to_mm = 1500;
    t.border_count = 1;
    t.borders[0].bottom_mm = 900;
    app_tile_layout_desc d = {&r, &t, &f, &b, 0};
    app_tile_layout l;
    CHECK_MSG(app_tile_layout_compute(&d, &l, err, sizeof err) == APP_OK, "%s", err);
    /* Field: rows at 300 j..300 j + 297. Below: rows 0, 1, 2 whole (up to 897 - but the strip
     * starts at 897, so row 2 ending at 897 is whole), 4 tiles each: 12 whole. The strip is
     * 897..1000; row 3 (900..1197) is cut to 1000..1197: 4 cuts; row 4 (1200..1497) whole: 4.
     * Border row: 4 whole border tiles (297 wide, s 0..1197) at 900..997. */
    int border = 0, field_whole = 0, field_cut = 0;
    for (int i = 0; i < l.tile_count; i++) {
        if (l.tiles[i].product == 1) {
            border++;
            CHECK(l.tiles[i].whole && l.tiles[i].row == -1);
            CHECK(fabs(l.tiles[i].cell[0].y - 900) < 1e-9);
        } else if (l.tiles[i].whole)
            field_whole++;
        else
            field_cut++;
    }
    CHECK(border == 4);
    CHECK(field_whole == 16);
    CHECK(field_cut == 4);
    check_balance(&l, 1200.0 * 1500, "band");
    app_tile_layout_free(&l);
    app_surface_region_free(&r);
}

/* Random star-shaped outlines (simple by construction), random holes that overlap each other
 * and stick out, every pattern at a random angle and origin: the tiles and their joints must
 * always cover exactly the outline minus the union of the holes (computed by the region's own
 * winding-rule area), and no tile may be larger than a whole one. */
static unsigned rnd_state = 12345;
static double rnd(void)
{
    rnd_state = rnd_state * 1103515245u + 12345u;
    return ((rnd_state >> 8) & 0xffffff) / (double)0x1000000;
}

static void test_random_regions(void)
{
    char err[256] = "";
    for (int iter = 0; iter < 120; iter++) {
        app_point2 pts[24];
        int n = 3 + (int)(rnd() * 20);
        for (int i = 0; i < n; i++) {
            double a = 2 * 3.14159265358979 * (i + 0.8 * rnd()) / n, rad = 800 + 1500 * rnd();
            pts[i] = (app_point2){2000 + rad * cos(a), 2000 + rad * sin(a)};
        }
        app_surface_region r;
        app_surface_region_init(&r, "floor", APP_SURFACE_FLOOR);
        CHECK(app_region_set_outer(&r, pts, n, err, sizeof err) == APP_OK);
        int holes = (int)(rnd() * 4);
        for (int h = 0; h < holes; h++) {
            double x = 4000 * rnd(), y = 4000 * rnd();
            CHECK(app_region_add_hole_rect(&r, x, y, x + 200 + 1200 * rnd(), y + 200 + 900 * rnd(),
                                           APP_HOLE_COVERED, "", err, sizeof err) == APP_OK);
        }
        double expect = app_surface_region_area(&r);
        app_tile_spec f = spec(50 + 500 * rnd(), 50 + 500 * rnd(), 5 * rnd(), APP_TILE_UNI);
        app_tiling t = tiling((app_tile_pattern)(iter % 6), (app_tile_align)(iter % 3), f.grout_mm);
        t.rotation_deg = 360 * rnd();
        t.origin_mm[0] = 4000 * rnd();
        t.origin_mm[1] = 4000 * rnd();
        app_tile_layout_desc d = {&r, &t, &f, NULL, 0};
        app_tile_layout l;
        CHECK_MSG(app_tile_layout_compute(&d, &l, err, sizeof err) == APP_OK, "%s", err);
        char what[64];
        snprintf(what, sizeof what, "random %d", iter);
        if (expect > 1e5)
            check_balance(&l, expect, what);
        for (int i = 0; i < l.tile_count; i++)
            CHECK(l.tiles[i].area_mm2 <= f.work_w_mm * f.work_h_mm * (1 + 1e-9));
        app_tile_layout_free(&l);
        app_surface_region_free(&r);
    }
}

/* Regions of a plan (the fallback of app_surface_region_from_plan): a 3000 x 2000 room, 2500
 * high, a door 800 x 2000 on wall 0 at 300, a window 1000 x 1200 at sill 900 on wall 1 at 500,
 * a pre-wall 1200 wide, 200 deep, 1100 high on wall 2 at 900, a niche 400 x 300 on wall 3. */
static void test_regions_from_plan(void)
{
    char err[256] = "";
    app_point2 corners[4] = {{0, 0}, {3000, 0}, {3000, 2000}, {0, 2000}};
    app_opening op[2];
    memset(op, 0, sizeof op);
    op[0].type = APP_OPENING_DOOR, op[0].wall = 0, op[0].offset_mm = 300;
    op[0].width_mm = 800, op[0].height_mm = 2000;
    op[1].type = APP_OPENING_WINDOW, op[1].wall = 1, op[1].offset_mm = 500;
    op[1].width_mm = 1000, op[1].height_mm = 1200, op[1].sill_mm = 900;
    app_prewall pw;
    memset(&pw, 0, sizeof pw);
    snprintf(pw.name, sizeof pw.name, "box");
    pw.wall = 2, pw.offset_mm = 900, pw.width_mm = 1200, pw.depth_mm = 200, pw.height_mm = 1100;
    app_niche ni;
    memset(&ni, 0, sizeof ni);
    ni.wall = 3, ni.offset_mm = 500, ni.width_mm = 400, ni.sill_mm = 1000, ni.height_mm = 300;
    ni.depth_mm = 80;
    app_room_plan plan;
    memset(&plan, 0, sizeof plan);
    plan.corners = corners, plan.corner_count = 4, plan.height_mm = 2500;
    plan.openings = op, plan.opening_count = 2;
    plan.prewalls = &pw, plan.prewall_count = 1;
    plan.niches = &ni, plan.niche_count = 1;
    struct {
        const char *surface;
        double area;
    } cases[] = {
        {"floor", 3000.0 * 2000 - 1200.0 * 200}, /* the box stands on the floor */
        {"ceiling", 3000.0 * 2000},
        {"wall:0", 3000.0 * 2500 - 800.0 * 2000},
        {"wall:1", 2000.0 * 2500 - 1000.0 * 1200},
        {"wall:2", 3000.0 * 2500 - 1200.0 * 1100}, /* behind the box */
        {"wall:3", 2000.0 * 2500 - 400.0 * 300},
        {"prewall:box:front", 1200.0 * 1100},
        {"prewall:box:left", 200.0 * 1100},
        {"prewall:box:top", 1200.0 * 200},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        app_surface_region r;
        CHECK_MSG(app_surface_region_from_plan(&plan, cases[i].surface, &r, err, sizeof err) ==
                      APP_OK,
                  "%s", err);
        CHECK_MSG(fabs(app_surface_region_area(&r) - cases[i].area) < 1e-6, "%s", cases[i].surface);
        app_surface_region_free(&r);
    }
    app_surface_region r;
    CHECK(app_surface_region_from_plan(&plan, "wall:4", &r, err, sizeof err) != APP_OK);
    CHECK(app_surface_region_from_plan(&plan, "wall:1x", &r, err, sizeof err) != APP_OK);
    CHECK(app_surface_region_from_plan(&plan, "prewall:nope:front", &r, err, sizeof err) != APP_OK);
    CHECK(app_surface_region_from_plan(&plan, "prewall:box:back", &r, err, sizeof err) != APP_OK);
    CHECK(tu_contains(err, "prewall:box:back"));
}

static void test_errors(void)
{
    char err[256] = "";
    app_surface_region r;
    app_surface_region_init(&r, "wall:0", APP_SURFACE_WALL);
    app_tile_spec f = spec(297, 297, 3, APP_TILE_UNI);
    app_tiling t = tiling(APP_PATTERN_STRAIGHT, APP_ALIGN_CORNER, 3);
    app_tile_layout_desc d = {&r, &t, &f, NULL, 0};
    app_tile_layout l;
    CHECK(app_tile_layout_compute(&d, &l, err, sizeof err) != APP_OK); /* no outline */
    CHECK(tu_contains(err, "tile_layout"));
    app_point2 bad[3] = {{0, 0}, {NAN, 0}, {0, 1}};
    CHECK(app_region_set_outer(&r, bad, 3, err, sizeof err) != APP_OK);
    app_point2 flat[3] = {{0, 0}, {1, 1}, {2, 2}};
    CHECK(app_region_set_outer(&r, flat, 3, err, sizeof err) != APP_OK);
    CHECK(app_region_set_outer_rect(&r, 0, 0, 100000, 100000, err, sizeof err) == APP_OK);
    f.work_w_mm = 0;
    CHECK(app_tile_layout_compute(&d, &l, err, sizeof err) != APP_OK);
    f = spec(1, 1, 0, APP_TILE_UNI);
    d.max_tiles = 1000;
    CHECK(app_tile_layout_compute(&d, &l, err, sizeof err) != APP_OK); /* 1e10 tiles */
    f = spec(297, 297, 3, APP_TILE_UNI);
    t.grout_mm = -1;
    CHECK(app_tile_layout_compute(&d, &l, err, sizeof err) != APP_OK);
    t.grout_mm = 3;
    t.to_mm = 10;
    t.from_mm = 20;
    CHECK(app_tile_layout_compute(&d, &l, err, sizeof err) != APP_OK); /* empty band */
    app_surface_region_free(&r);
    app_surface_region_free(&r); /* twice is fine */
    app_tile_layout_free(NULL);
    app_tile_pattern pat;
    app_tile_align al;
    CHECK(app_tile_pattern_parse("Half-Offset", &pat) && pat == APP_PATTERN_HALF_OFFSET);
    CHECK(app_tile_pattern_parse("vertical_stack", &pat) && pat == APP_PATTERN_VERTICAL_STACK);
    CHECK(!app_tile_pattern_parse("half", &pat) && !app_tile_pattern_parse(NULL, &pat));
    CHECK(!strcmp(app_tile_pattern_name(APP_PATTERN_HERRINGBONE), "herringbone"));
    CHECK(!strcmp(app_tile_pattern_name((app_tile_pattern)99), ""));
    CHECK(app_tile_align_parse("corner", &al) && al == APP_ALIGN_CORNER);
    CHECK(!strcmp(app_tile_align_name(APP_ALIGN_LINE), "line"));
}

int main(void)
{
    test_wall_half_offset_window();
    test_floor_diagonal();
    test_floor_l_shape();
    test_third_offset_and_herringbone();
    test_band_and_border();
    test_random_regions();
    test_regions_from_plan();
    test_errors();
    return check_report("tile_layout");
}
