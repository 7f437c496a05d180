/* Edge joint and set-out solver (app/design/tile_layout.h, docs/tiling.md "Edge joint",
 * "Set-out"): the cases a tiler checked by hand. The expected counts are derived in the
 * comments, not taken from the code. */
#include "test_util.h"

#include "app/design/tile_layout.h"

#include <math.h>

static app_tile_spec spec(double w, double h, double grout)
{
    app_tile_spec s;
    memset(&s, 0, sizeof s);
    snprintf(s.product.manufacturer, sizeof s.product.manufacturer, "Test");
    snprintf(s.product.article, sizeof s.product.article, "T-%gx%g", w, h);
    s.work_w_mm = w;
    s.work_h_mm = h;
    s.grout_mm = grout;
    s.reusable_offcuts = s.rotatable = 1;
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
    t.edge_joint_mm = -1; /* the joint width, as a project file's default */
    return t;
}

static void lay(const char *surface, app_surface_kind kind, double w, double h, const app_tiling *t,
                const app_tile_spec *f, app_tile_layout *l)
{
    app_surface_region r;
    char err[256];
    app_surface_region_init(&r, surface, kind);
    CHECK(app_region_set_outer_rect(&r, 0, 0, w, h, err, sizeof err) == APP_OK);
    app_tile_layout_desc d = {&r, t, f, NULL, 0};
    CHECK_MSG(app_tile_layout_compute(&d, l, err, sizeof err) == APP_OK, "%s", err);
    app_surface_region_free(&r);
}

/* 1800 x 2400 floor, 597 x 597 tiles (600 nominal), 2 mm joints. Three tiles and two joints
 * take 3 x 597 + 2 x 2 = 1795 mm, four take 2394 mm: with a 2 mm edge joint the tiled region
 * is 1796 x 2396, so a tile-centred column and a joint-centred row hold 3 x 4 whole tiles and
 * leave 2.5 and 3 mm at the walls for silicone. */
static void test_floor_whole_tiles(void)
{
    app_tile_spec f = spec(597, 597, 2);
    app_tiling t = tiling(APP_PATTERN_STRAIGHT, APP_ALIGN_AUTO, 2);
    app_tile_layout l;
    lay("floor", APP_SURFACE_FLOOR, 1800, 2400, &t, &f, &l);
    CHECK(l.whole_count == 12);
    CHECK(l.cut_count == 0);
    CHECK_NEAR(l.region_area_mm2, 1796.0 * 2396.0, 1e-3);
    app_tile_layout_free(&l);

    /* A corner start also fits 12 once the edge joint is left open ... */
    t.align = APP_ALIGN_CORNER;
    lay("floor", APP_SURFACE_FLOOR, 1800, 2400, &t, &f, &l);
    CHECK(l.whole_count == 12 && l.cut_count == 0);
    app_tile_layout_free(&l);
    /* ... without one it cuts a 3 mm strip (1800 - 1797) and a 4 mm strip (2400 - 2396):
     * 4 + 3 + 1 slivers, far under the 199 mm rule. */
    t.edge_joint_mm = 0;
    lay("floor", APP_SURFACE_FLOOR, 1800, 2400, &t, &f, &l);
    CHECK(l.whole_count == 12 && l.cut_count == 8);
    double width = 0, rule = 0;
    CHECK(app_tile_layout_worst_cut(&l, &t, NULL, &width, &rule) < 1.0);
    CHECK_NEAR(width, 3.0, 1e-6);
    CHECK_NEAR(rule, 199.0, 1e-9); /* a third of 597 */
    app_tile_layout_free(&l);
}

/* A 2000 x 2500 wall in 597 x 297 tiles, half offset, 3 mm joints. Joint-centred, the rows
 * whose tile straddles the centre end in 98.5 mm pieces; the solver shifts the grid so every
 * cut keeps the rule (199 mm across the long side, 99 across the short one). */
static void test_half_offset_wall(void)
{
    app_tile_spec f = spec(597, 297, 3);
    app_tiling t = tiling(APP_PATTERN_HALF_OFFSET, APP_ALIGN_CENTRED, 3);
    app_tile_layout l;
    lay("wall:0", APP_SURFACE_WALL, 2000, 2500, &t, &f, &l);
    double width = 0;
    CHECK(app_tile_layout_worst_cut(&l, &t, NULL, &width, NULL) < 1.0);
    printf("half offset wall, centred: smallest cut %.1f mm\n", width);
    app_tile_layout_free(&l);

    t.align = APP_ALIGN_AUTO;
    lay("wall:0", APP_SURFACE_WALL, 2000, 2500, &t, &f, &l);
    double worst = app_tile_layout_worst_cut(&l, &t, NULL, &width, NULL);
    printf("half offset wall, solved: smallest cut %.1f mm (ratio %.2f)\n", width, worst);
    CHECK(worst >= 1.0);
    CHECK(l.whole_count + l.cut_count > 0);
    app_tile_layout_free(&l);

    /* A stricter rule than the wall allows: 250 mm on every side. The 2494 mm band (2500
     * less two edge joints) holds 8 rows of 300 and 94 mm over; the best split of 94 + 300 puts
     * 197 mm pieces at the floor and the ceiling, 195.5 mm of tile after the 1.5 mm half joint.
     * The solver gets that best achievable, not a worse one. */
    t.min_cut_mm = 250;
    CHECK_NEAR(app_tile_min_cut_mm(&t, 597), 250.0, 1e-9);
    CHECK_NEAR(app_tile_min_cut_mm(&t, 97), 97.0, 1e-9); /* never more than the side */
    lay("wall:0", APP_SURFACE_WALL, 2000, 2500, &t, &f, &l);
    worst = app_tile_layout_worst_cut(&l, &t, NULL, &width, NULL);
    printf("half offset wall, 250 mm rule: smallest cut %.1f mm (ratio %.2f)\n", width, worst);
    CHECK(width >= 195.5 - 1e-6);
    app_tile_layout_free(&l);
}

/* The rule itself: a third of the side, never under 50 mm. */
static void test_min_cut_rule(void)
{
    app_tiling t = tiling(APP_PATTERN_STRAIGHT, APP_ALIGN_AUTO, 2);
    CHECK_NEAR(app_tile_min_cut_mm(&t, 600), 200.0, 1e-9);
    CHECK_NEAR(app_tile_min_cut_mm(&t, 100), 50.0, 1e-9);
    CHECK_NEAR(app_tile_min_cut_mm(&t, 30), 30.0, 1e-9);
    CHECK_NEAR(app_tile_edge_joint_mm(&t, 2.5), 2.5, 1e-12);
    t.edge_joint_mm = 4;
    CHECK_NEAR(app_tile_edge_joint_mm(&t, 2.5), 4.0, 1e-12);
}

/* A fixed origin wins: the grid passes through it even where the solver would move it. */
static void test_fixed_origin(void)
{
    app_tile_spec f = spec(597, 597, 2);
    app_tiling t = tiling(APP_PATTERN_STRAIGHT, APP_ALIGN_LINE, 2);
    t.origin_mm[0] = 123;
    t.origin_mm[1] = 45;
    app_tile_layout l;
    lay("floor", APP_SURFACE_FLOOR, 1800, 2400, &t, &f, &l);
    CHECK_NEAR(l.origin.x, 123.0, 1e-12);
    CHECK_NEAR(l.origin.y, 45.0, 1e-12);
    /* the first column ends at 123 - 1 mm, a 121 mm piece from the 2 mm edge joint */
    CHECK(l.cut_count > 0);
    app_tile_layout_free(&l);
}

/* Openings grow by the edge joint too: a 600 x 600 hole in the middle leaves a 602 mm square
 * ring... the region loses (600 + 2e)^2 instead of 600^2. */
static void test_hole_grows(void)
{
    app_tile_spec f = spec(97, 97, 3);
    app_tiling t = tiling(APP_PATTERN_STRAIGHT, APP_ALIGN_CORNER, 3);
    app_surface_region r;
    char err[256];
    app_surface_region_init(&r, "wall:0", APP_SURFACE_WALL);
    CHECK(app_region_set_outer_rect(&r, 0, 0, 2000, 2000, err, sizeof err) == APP_OK);
    CHECK(app_region_add_hole_rect(&r, 700, 700, 1300, 1300, APP_HOLE_OPENING, "w", err,
                                   sizeof err) == APP_OK);
    app_tile_layout_desc d = {&r, &t, &f, NULL, 0};
    app_tile_layout l;
    CHECK(app_tile_layout_compute(&d, &l, err, sizeof err) == APP_OK);
    CHECK_NEAR(l.region_area_mm2, 1994.0 * 1994.0 - 606.0 * 606.0, 1e-3);
    app_tile_layout_free(&l);
    app_surface_region_free(&r);
}

int main(void)
{
    test_floor_whole_tiles();
    test_half_offset_wall();
    test_min_cut_rule();
    test_fixed_origin();
    test_hole_grows();
    return check_report("tile_setout");
}
