/* The print set (app/output/print.h) on a project made in memory: a 3000 x 2400 room with a door, a
 * window, a WC pre-wall, a niche, catalog fixtures and tiled walls. Checks the real PDF
 * (pdfinfo: the pages; pdftotext: the article numbers and the quotation's total as the bill of
 * materials computes it), the true scale (a 3000 mm wall is 150 mm at 1:20, measured in the
 * SVG's own coordinates), the elevations' tile counts against the quantities, the scale rules
 * and bad input. Needs poppler-utils (pdfinfo, pdftotext). */
#define _POSIX_C_SOURCE 200809L
#include "app/output/print.h"
#include "app/design/quantities.h"
#include "app/design/room_surfaces.h"
#include "test_util.h"

#include "../../app/src/output/print_internal.h" /* pr_convex_hull, pr_format_money */

#include <math.h>

static app_point2 corners[4] = {{0, 0}, {3000, 0}, {3000, 2400}, {0, 2400}};

static app_object product_object(const char *name, const char *maker, const char *article, double x,
                                 double y, double z, double rot_z)
{
    app_object o;
    memset(&o, 0, sizeof o);
    snprintf(o.name, sizeof o.name, "%s", name);
    o.shape = APP_SHAPE_BOX;
    o.position_mm[0] = x;
    o.position_mm[1] = y;
    o.position_mm[2] = z;
    o.rotation_deg[2] = rot_z;
    o.scale[0] = o.scale[1] = o.scale[2] = 1;
    o.has_product = 1;
    snprintf(o.product.manufacturer, sizeof o.product.manufacturer, "%s", maker);
    snprintf(o.product.article, sizeof o.product.article, "%s", article);
    return o;
}

static app_tiling tiling(const char *surface, const char *maker, const char *article, double to)
{
    app_tiling t;
    memset(&t, 0, sizeof t);
    snprintf(t.name, sizeof t.name, "%s", surface);
    snprintf(t.surface, sizeof t.surface, "%s", surface);
    snprintf(t.product.manufacturer, sizeof t.product.manufacturer, "%s", maker);
    snprintf(t.product.article, sizeof t.product.article, "%s", article);
    t.pattern = APP_PATTERN_STRAIGHT;
    t.align = APP_ALIGN_CENTRED;
    t.grout_color[0] = t.grout_color[1] = t.grout_color[2] = 0.6f;
    t.to_mm = to;
    return t;
}

static app_opening openings[2];
static app_prewall prewalls[1];
static app_niche niches[1];
static app_object objects[4];
static app_tiling tilings[5];
static app_material materials[1];

static void make_project(app_project *p)
{
    memset(p, 0, sizeof *p);
    p->version = p->file_version = APP_PROJECT_VERSION;
    snprintf(p->name, sizeof p->name, "Print test bathroom");
    p->room = (app_room){3000, 2400, 2500, 0, 0, 0};
    p->plan.corners = corners;
    p->plan.corner_count = 4;
    p->plan.height_mm = 2500;
    p->plan.wall_thickness_mm = 120;
    openings[0] = (app_opening){.name = "door",
                                .type = APP_OPENING_DOOR,
                                .wall = 2,
                                .offset_mm = 300,
                                .width_mm = 800,
                                .height_mm = 2010,
                                .swing = APP_SWING_IN_LEFT};
    openings[1] = (app_opening){.name = "window",
                                .type = APP_OPENING_WINDOW,
                                .wall = 1,
                                .offset_mm = 800,
                                .width_mm = 900,
                                .height_mm = 1200,
                                .sill_mm = 900};
    p->plan.openings = openings;
    p->plan.opening_count = 2;
    prewalls[0] = (app_prewall){.name = "wc-box",
                                .wall = 3,
                                .offset_mm = 1000,
                                .width_mm = 1200,
                                .depth_mm = 200,
                                .height_mm = 1200};
    p->plan.prewalls = prewalls;
    p->plan.prewall_count = 1;
    niches[0] = (app_niche){.name = "niche",
                            .wall = 0,
                            .offset_mm = 2300,
                            .width_mm = 400,
                            .sill_mm = 1200,
                            .height_mm = 300,
                            .depth_mm = 80};
    p->plan.niches = niches;
    p->plan.niche_count = 1;
    /* A wall-hung WC before the pre-wall (wall 3 runs down the left side; facing +x), a basin
     * on wall 0 with its rim at 850, its mixer, and a primitive without a product. */
    objects[0] = product_object("wc", "Cerana", "CE413001", 200, 800, 80, -90);
    objects[1] = product_object("basin", "Cerana", "CE410001", 1500, 0, 685, 0);
    objects[2] = product_object("mixer", "Aquavera", "31000000", 1500, 60, 850, 0);
    memset(&objects[3], 0, sizeof objects[3]);
    snprintf(objects[3].name, sizeof objects[3].name, "towel-rail");
    objects[3].shape = APP_SHAPE_CYLINDER;
    objects[3].position_mm[0] = 2975;
    objects[3].position_mm[1] = 1800;
    objects[3].position_mm[2] = 1100;
    objects[3].rotation_deg[0] = 90;
    objects[3].size_mm[0] = objects[3].size_mm[1] = 25;
    objects[3].size_mm[2] = 500;
    objects[3].scale[0] = objects[3].scale[1] = objects[3].scale[2] = 1;
    p->objects = objects;
    p->object_count = 4;
    tilings[0] = tiling("wall:0", "Terrazza Ceramiche", "TZ61000", 0);
    tilings[1] = tiling("wall:1", "Fliesenwerk Altena", "FA-10104", 2000);
    tilings[2] = tiling("prewall:wc-box:front", "Fliesenwerk Altena", "FA-10103", 0);
    tilings[3] = tiling("floor", "Terrazza Ceramiche", "TZ61006", 0);
    tilings[4] = tiling("prewall:wc-box:top", "Fliesenwerk Altena", "FA-10107", 0);
    p->tilings = tilings;
    p->tiling_count = 5;
    snprintf(materials[0].name, sizeof materials[0].name, "default");
    p->materials = materials;
    p->material_count = 1;
}

static char *run_capture(const char *cmd)
{
    FILE *f = popen(cmd, "r");
    if (!f)
        return NULL;
    size_t cap = 1 << 16, n = 0;
    char *buf = malloc(cap);
    size_t got;
    while (buf && (got = fread(buf + n, 1, cap - n - 1, f)) > 0) {
        n += got;
        if (n + 1 >= cap) {
            char *nb = realloc(buf, cap * 2);
            if (!nb) {
                free(buf);
                buf = NULL;
                break;
            }
            buf = nb;
            cap *= 2;
        }
    }
    if (buf)
        buf[n] = 0;
    pclose(f);
    return buf;
}

static void money(long long cents, char *out, size_t size)
{
    /* 1234567 -> "12,345.67": what a quotation prints. */
    char digits[32], grouped[64];
    snprintf(digits, sizeof digits, "%lld", cents / 100);
    size_t n = strlen(digits), j = 0;
    for (size_t i = 0; i < n; i++) {
        if (i > 0 && (n - i) % 3 == 0)
            grouped[j++] = ',';
        grouped[j++] = digits[i];
    }
    grouped[j] = 0;
    snprintf(out, size, "%s.%02lld", grouped, cents % 100);
}

/* The inner ring of the plan's wall (the only even-odd filled path): its extent in mm. */
static int wall_inner_extent(const char *svg_path, double *w_mm, double *h_mm)
{
    FILE *f = fopen(svg_path, "rb");
    if (!f)
        return 0;
    static char text[1 << 22];
    size_t n = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[n] = 0;
    const char *p = strstr(text, "fill-rule:evenodd");
    if (!p)
        return 0;
    const char *d = strstr(p, " d=\"");
    if (!d)
        return 0;
    d += 4;
    /* Second sub-path: after the first "Z M". */
    const char *second = strstr(d, "Z M");
    if (!second)
        return 0;
    second += 2;
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    const char *s = second;
    while (*s && *s != '"' && *s != 'Z') {
        if (*s == 'M' || *s == 'L') {
            double x, y;
            if (sscanf(s + 1, "%lf %lf", &x, &y) != 2)
                return 0;
            x0 = fmin(x0, x);
            x1 = fmax(x1, x);
            y0 = fmin(y0, y);
            y1 = fmax(y1, y);
        }
        s++;
    }
    *w_mm = (x1 - x0) * 25.4 / 72.0;
    *h_mm = (y1 - y0) * 25.4 / 72.0;
    return 1;
}

/* The outline of a part: the convex hull of its projected points (interior and collinear
 * points dropped, counter-clockwise). */
static void test_hull(void)
{
    const app_point2 pts[] = {{0, 0}, {10, 0}, {5, 5}, {10, 10}, {0, 10}, {5, 0}, {2, 8}, {10, 5}};
    app_point2 hull[16];
    int n = pr_convex_hull(pts, 8, hull);
    CHECK(n == 4);
    CHECK(n == 4 && app_polygon_signed_area(hull, n) == 100.0);
    CHECK(pr_convex_hull(pts, 1, hull) == 1);
    CHECK(pr_convex_hull(pts, 0, hull) == 0);
    char text[48];
    pr_format_money(123456789, text, sizeof text);
    CHECK(!strcmp(text, "1,234,567.89"));
    pr_format_money(5, text, sizeof text);
    CHECK(!strcmp(text, "0.05"));
    pr_format_money(-100000, text, sizeof text);
    CHECK(!strcmp(text, "-1,000.00"));
}

static void test_scales(void)
{
    double w, h;
    app_paper_size_mm(APP_PAPER_A3, 1, &w, &h);
    CHECK(w == 420 && h == 297);
    app_paper_size_mm(APP_PAPER_A4, 0, &w, &h);
    CHECK(w == 210 && h == 297);
    /* 3000 mm + 2 x 20 mm border: at 1:20 needs 190 mm. */
    CHECK(app_print_fit_scale(3000, 2000, 20, 190, 200) == 20);
    CHECK(app_print_fit_scale(3000, 2000, 20, 189.9, 200) == 25);
    CHECK(app_print_fit_scale(7000, 6000, 20, 190, 200) == 50);
    CHECK(app_print_fit_scale(8000, 6000, 20, 190, 200) == 100);
    CHECK(app_print_fit_scale(1e6, 1e6, 20, 190, 200) == 200);
    /* 1:10 when the drawing fits at it (a pre-wall, a small room on A3). */
    CHECK(app_print_fit_scale(1500, 1000, 20, 190, 200) == 10);
    int n = -1;
    CHECK(app_print_scale_parse("1:25", &n) && n == 25);
    CHECK(app_print_scale_parse("50", &n) && n == 50);
    CHECK(app_print_scale_parse("fit", &n) && n == 0);
    CHECK(!app_print_scale_parse("1:", &n));
    CHECK(!app_print_scale_parse("1:0", &n));
    CHECK(!app_print_scale_parse("1:2x", &n));
    CHECK(!app_print_scale_parse("", &n));
    app_paper paper;
    CHECK(app_paper_parse("a3", &paper) && paper == APP_PAPER_A3);
    CHECK(!app_paper_parse("A5", &paper));
}

int main(void)
{
    test_scales();
    test_hull();
    char dir[] = "/tmp/tessera-print-test-XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    char db_path[512], pdf[512], svg_dir[512], err[2048] = "";
    snprintf(db_path, sizeof db_path, "%s/catalog.sqlite", dir);
    snprintf(pdf, sizeof pdf, "%s/plan.pdf", dir);
    snprintf(svg_dir, sizeof svg_dir, "%s/svg", dir);
    CHECK(mkdir(svg_dir, 0777) == 0);

    app_project p;
    make_project(&p);
    app_print_options o = {.paper = APP_PAPER_A4,
                           .landscape = 1,
                           .scale = 20,
                           .customer = "Jane Customer",
                           .date = "2026-11-22",
                           .catalog_db = db_path,
                           .catalog_source = TESSERA_SOURCE_DIR "/assets/catalog",
                           .assets_dir = TESSERA_SOURCE_DIR "/assets",
                           .verbose = 1};
    app_print_report rep;
    app_result r = app_print_pdf(&p, &o, pdf, &rep, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    /* Plan, 4 walls, 1 pre-wall front, no renders, the part list. */
    CHECK(rep.elevation_pages == 5);
    CHECK(rep.partlist_pages >= 1);
    CHECK(rep.pages == 1 + 5 + rep.partlist_pages);
    CHECK(rep.plan_scale == 20 && rep.elevation_scale == 20);
    CHECK(rep.fixtures == 4);

    char cmd[1200];
    snprintf(cmd, sizeof cmd, "pdfinfo '%s'", pdf);
    char *info = run_capture(cmd);
    CHECK_MSG(info != NULL && strstr(info, "Pages:"), "pdfinfo missing (poppler-utils)");
    if (info && strstr(info, "Pages:")) {
        int pages = atoi(strstr(info, "Pages:") + 6);
        CHECK(pages == rep.pages);
        CHECK(strstr(info, "Print test bathroom") != NULL); /* the PDF title */
    }
    free(info);

    /* The quotation's figures, computed independently from the same catalog. */
    cat_db *db = NULL;
    CHECK(cat_catalog_open(db_path, NULL, &db, err, sizeof err) == CAT_DB_OK);
    app_tile_layout *layouts = NULL;
    int layout_count = 0;
    app_quantities q = {0};
    app_bom bom = {0};
    r = app_project_tile_layouts(&p, db, app_room_region_provider, NULL, &layouts, &layout_count,
                                 err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    if (r == APP_OK) {
        CHECK_MSG(app_quantities_compute(layouts, layout_count, NULL, &q, err, sizeof err) ==
                      APP_OK,
                  "%s", err);
        CHECK_MSG(app_bom_build(db, &p, &q, &bom, err, sizeof err) == APP_OK, "%s", err);
        /* The quotation's consumables and labour lines (docs/tiling.md). */
        app_consumables cons;
        CHECK_MSG(app_consumables_compute(&p, db, layouts, layout_count, NULL, &cons, err,
                                          sizeof err) == APP_OK,
                  "%s", err);
        CHECK_MSG(app_bom_add_consumables(db, &cons, NULL, &bom, err, sizeof err) == APP_OK, "%s",
                  err);
    }
    snprintf(cmd, sizeof cmd, "pdftotext '%s' -", pdf);
    char *text = run_capture(cmd);
    CHECK(text != NULL);
    if (text) {
        const char *articles[] = {"CE413001", "CE410001",       "31000000",      "TZ61000",
                                  "FA-10104", "FA-10103",       "TZ61006",       "FA-10107",
                                  "FW-C2-25", "LAB-TILE-FLOOR", "LAB-TILE-WALL", "LAB-FIXTURE"};
        for (size_t i = 0; i < sizeof articles / sizeof articles[0]; i++)
            CHECK_MSG(strstr(text, articles[i]) != NULL, "%s", articles[i]);
        CHECK(strstr(text, "Jane Customer") != NULL);
        /* The quotation's header: a number from the date, valid 30 days (app/output/quote.h). */
        CHECK(strstr(text, "Quote no. Q-20261122-") != NULL);
        CHECK(strstr(text, "Valid until 2026-12-22 (30 days)") != NULL);
        CHECK(strstr(text, "1:20") != NULL);
        char page_text[32];
        snprintf(page_text, sizeof page_text, "%d of %d", rep.pages, rep.pages);
        CHECK_MSG(strstr(text, page_text) != NULL, "%s", page_text);
        char total[96], net[96];
        money(bom.gross_cents, total, sizeof total);
        money(bom.net_cents, net, sizeof net);
        CHECK(bom.gross_cents > 0);
        CHECK_MSG(strstr(text, total) != NULL, "%s", total);
        CHECK_MSG(strstr(text, net) != NULL, "%s", net);
    }
    free(text);

    /* Elevation counts equal the quantities' counts of the products laid on that sheet's faces
     * (one product per face here: wall 0 TZ61000, wall 1 FA-10104; the pre-wall's sheet shows
     * its front FA-10103 and, unfolded, its top FA-10107). */
    const char *by_elevation[5][2] = {{"TZ61000", NULL},
                                      {"FA-10104", NULL},
                                      {NULL, NULL},
                                      {NULL, NULL},
                                      {"FA-10103", "FA-10107"}};
    for (int e = 0; e < 5; e++) {
        int whole = 0, cut = 0;
        for (int a = 0; a < 2 && by_elevation[e][a]; a++) {
            int found = 0;
            for (int i = 0; i < q.line_count; i++)
                if (!strcmp(q.lines[i].spec.product.article, by_elevation[e][a])) {
                    whole += q.lines[i].whole;
                    cut += q.lines[i].cut;
                    found = 1;
                }
            CHECK_MSG(found, "%s", by_elevation[e][a]);
        }
        CHECK(rep.elevation_whole[e] == whole);
        CHECK(rep.elevation_cut[e] == cut);
        if (by_elevation[e][0])
            CHECK(whole + cut > 0);
    }

    /* True scale, from the SVG's own coordinates: the room's inside is 3000 x 2400 mm. */
    r = app_print_svg(&p, &o, svg_dir, &rep, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    char svg[600];
    snprintf(svg, sizeof svg, "%s/page-01.svg", svg_dir);
    double w_mm = 0, h_mm = 0;
    CHECK(wall_inner_extent(svg, &w_mm, &h_mm));
    CHECK_MSG(fabs(w_mm - 150.0) <= 0.1, "3000 mm wall at 1:20");
    CHECK_MSG(fabs(h_mm - 120.0) <= 0.1, "2400 mm wall at 1:20");
    fprintf(stderr, "plan at 1:20: %.3f x %.3f mm on paper\n", w_mm, h_mm);
    snprintf(svg, sizeof svg, "%s/page-%02d.svg", svg_dir, rep.pages);
    CHECK(access(svg, R_OK) == 0);

    /* Fit: A3 landscape takes the room at 1:20 too; A4 portrait needs 1:25. */
    o.scale = 0;
    o.paper = APP_PAPER_A4;
    o.landscape = 0;
    r = app_print_pdf(&p, &o, pdf, &rep, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    CHECK(rep.plan_scale == 20 || rep.plan_scale == 25);

    /* Bad input gives an error, not a crash. */
    CHECK(app_print_pdf(&p, &o, "/no/such/folder/x.pdf", &rep, err, sizeof err) == APP_ERR_IO);
    CHECK(strstr(err, "/no/such/folder/x.pdf") != NULL);
    const char *missing[] = {"/no/such/image.png"};
    o.images = missing;
    o.image_count = 1;
    CHECK(app_print_pdf(&p, &o, pdf, &rep, err, sizeof err) == APP_ERR_IO);
    CHECK(strstr(err, "/no/such/image.png") != NULL);
    o.image_count = -1;
    CHECK(app_print_pdf(&p, &o, pdf, &rep, err, sizeof err) == APP_ERR_SCHEMA);
    /* The failed runs left the previous PDF whole and no temporary file behind. */
    snprintf(cmd, sizeof cmd, "pdfinfo '%s' >/dev/null 2>&1 && ls '%s' | grep -c part", pdf, dir);
    char *left = run_capture(cmd);
    CHECK_MSG(left && atoi(left) == 0 && left[0] == '0', "%s", left ? left : "(none)");
    free(left);

    app_bom_free(&bom);
    app_quantities_free(&q);
    app_tile_layouts_free(layouts, layout_count);
    cat_db_close(db);
    /* TESSERA_TEST_KEEP=1 keeps the PDF and SVGs to look at. */
    if (!getenv("TESSERA_TEST_KEEP")) {
        snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
        CHECK(system(cmd) == 0);
    } else {
        fprintf(stderr, "kept %s\n", dir);
    }
    return check_report("print");
}
