/* Project file version 2: the floor plan, openings, pre-walls, niches, slope,
 * tilings and product references read, written and read back exactly; version 1 files
 * migrate to a 4-corner plan; malformed plans give an error with the JSON path; saving keeps
 * the previous file as PATH.bak. */
#include "app/project/project.h"
#include "test_util.h"

#include <math.h>

#define DATA TESSERA_PROJECT_TEST_DATA

static void check_same_plan(const app_room_plan *a, const app_room_plan *b)
{
    CHECK(a->corner_count == b->corner_count);
    for (int i = 0; i < a->corner_count && i < b->corner_count; i++)
        CHECK(a->corners[i].x == b->corners[i].x && a->corners[i].y == b->corners[i].y);
    CHECK(a->height_mm == b->height_mm && a->wall_thickness_mm == b->wall_thickness_mm);
    CHECK(a->opening_count == b->opening_count);
    for (int i = 0; i < a->opening_count && i < b->opening_count; i++)
        CHECK(!memcmp(&a->openings[i], &b->openings[i], sizeof a->openings[i]));
    CHECK(a->prewall_count == b->prewall_count);
    for (int i = 0; i < a->prewall_count && i < b->prewall_count; i++)
        CHECK(!memcmp(&a->prewalls[i], &b->prewalls[i], sizeof a->prewalls[i]));
    CHECK(a->niche_count == b->niche_count);
    for (int i = 0; i < a->niche_count && i < b->niche_count; i++)
        CHECK(!memcmp(&a->niches[i], &b->niches[i], sizeof a->niches[i]));
    CHECK(!memcmp(&a->slope, &b->slope, sizeof a->slope));
}

static void check_same(const app_project *a, const app_project *b)
{
    check_same_plan(&a->plan, &b->plan);
    CHECK(a->tiling_count == b->tiling_count);
    for (int i = 0; i < a->tiling_count && i < b->tiling_count; i++)
        CHECK(!memcmp(&a->tilings[i], &b->tilings[i], sizeof a->tilings[i]));
    CHECK(a->object_count == b->object_count);
    for (int i = 0; i < a->object_count && i < b->object_count; i++) {
        CHECK(a->objects[i].has_product == b->objects[i].has_product);
        CHECK(
            !memcmp(&a->objects[i].product, &b->objects[i].product, sizeof a->objects[i].product));
    }
    CHECK(a->room.width_mm == b->room.width_mm && a->room.depth_mm == b->room.depth_mm &&
          a->room.height_mm == b->room.height_mm);
}

static void test_read_fixture(void)
{
    app_project p;
    char err[1024];
    app_result r = app_project_read(DATA "/v2_l_room.json", &p, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    if (r != APP_OK)
        return;
    CHECK(p.version == 2 && p.file_version == 2);
    CHECK(p.plan.corner_count == 6);
    CHECK(p.plan.corners[3].x == 1800 && p.plan.corners[3].y == 1800);
    CHECK(p.plan.height_mm == 2600 && p.plan.wall_thickness_mm == 150);
    CHECK(p.room.width_mm == 3000 && p.room.depth_mm == 3000 && p.room.height_mm == 2600);
    CHECK(p.plan.opening_count == 2);
    CHECK(p.plan.openings[0].type == APP_OPENING_WINDOW && p.plan.openings[0].wall == 1);
    CHECK(p.plan.openings[0].sill_mm == 900 && fabsf(p.plan.openings[0].light[2] - 0.9f) < 1e-6f);
    CHECK(p.plan.openings[1].type == APP_OPENING_DOOR &&
          p.plan.openings[1].swing == APP_SWING_IN_RIGHT);
    CHECK(p.plan.openings[1].light[0] == 0); /* doors let no light in by default */
    CHECK(p.plan.prewall_count == 1 && !strcmp(p.plan.prewalls[0].name, "wc-box"));
    CHECK(p.plan.prewalls[0].depth_mm == 200 && p.plan.prewalls[0].wall == 5);
    CHECK(p.plan.niche_count == 1 && p.plan.niches[0].depth_mm == 80);
    CHECK(p.plan.slope.present && p.plan.slope.wall == 0 && p.plan.slope.knee_mm == 1600 &&
          p.plan.slope.run_mm == 700);
    CHECK(p.tiling_count == 3);
    CHECK(!strcmp(p.tilings[0].surface, "floor") &&
          p.tilings[0].pattern == APP_PATTERN_HALF_OFFSET);
    CHECK(p.tilings[0].align == APP_ALIGN_CORNER && p.tilings[0].grout_mm == 3);
    CHECK(!strcmp(p.tilings[0].product.article, "TZ61002"));
    CHECK(p.tilings[1].align == APP_ALIGN_LINE && p.tilings[1].origin_mm[0] == 100);
    CHECK(p.tilings[1].to_mm == 1200 && p.tilings[1].border_count == 1);
    CHECK(p.tilings[1].borders[0].bottom_mm == 1200);
    CHECK(p.tilings[2].pattern == APP_PATTERN_VERTICAL_STACK);
    CHECK(fabsf(p.tilings[2].grout_color[0] - 0.6f) < 1e-6f); /* the default grout colour */
    CHECK(p.object_count == 2 && !p.objects[0].has_product && p.objects[1].has_product);
    CHECK(!strcmp(p.objects[1].product.manufacturer, "Cerana") &&
          !strcmp(p.objects[1].product.article, "CE412901") &&
          !strcmp(p.objects[1].product.variant, "WH"));
    app_project_free(&p);
}

static void test_round_trip(const char *dir)
{
    app_project a, b;
    char err[1024];
    app_result r = app_project_read(DATA "/v2_l_room.json", &a, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    if (r != APP_OK)
        return;
    char out1[1024], out2[1024];
    snprintf(out1, sizeof out1, "%s/rt1.json", dir);
    snprintf(out2, sizeof out2, "%s/rt2.json", dir);
    r = app_project_write(out1, &a, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    r = app_project_read(out1, &b, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    if (r == APP_OK) {
        check_same(&a, &b);
        CHECK(app_project_write(out2, &b, err, sizeof err) == APP_OK);
        char *t1 = tu_read_file(out1, NULL), *t2 = tu_read_file(out2, NULL);
        CHECK(t1 && t2 && !strcmp(t1, t2)); /* writing is a fixed point */
        CHECK(t1 && tu_contains(t1, "\"version\":\t2,"));
        free(t1);
        free(t2);
        app_project_free(&b);
    }
    app_project_free(&a);
}

static void test_migration(const char *dir)
{
    app_project p, q;
    char err[1024];
    app_result r = app_project_read(DATA "/valid.json", &p, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    if (r != APP_OK)
        return;
    CHECK(p.file_version == 1 && p.version == 2);
    CHECK(p.plan.corner_count == 4);
    double w = p.room.width_mm, d = p.room.depth_mm;
    CHECK(w == 2400 && d == 3000 && p.plan.height_mm == 2500 && p.room.height_mm == 2500);
    const double want[4][2] = {{0, 0}, {w, 0}, {w, d}, {0, d}};
    for (int i = 0; i < 4 && i < p.plan.corner_count; i++)
        CHECK(p.plan.corners[i].x == want[i][0] && p.plan.corners[i].y == want[i][1]);
    CHECK(p.plan.wall_thickness_mm == APP_ROOM_DEFAULT_WALL_THICKNESS_MM);
    CHECK(p.plan.opening_count == 0 && p.plan.prewall_count == 0 && p.plan.niche_count == 0);
    CHECK(!p.plan.slope.present && p.tiling_count == 0);
    char out[1024];
    snprintf(out, sizeof out, "%s/migrated.json", dir);
    CHECK(app_project_write(out, &p, err, sizeof err) == APP_OK);
    r = app_project_read(out, &q, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    if (r == APP_OK) {
        CHECK(q.file_version == 2);
        check_same(&p, &q);
        CHECK(q.room.floor_material == p.room.floor_material &&
              q.room.wall_material == p.room.wall_material);
        app_project_free(&q);
    }
    /* A project built by version 1 code (room box only, no plan) is written as a plan. */
    app_room_plan plan = p.plan;
    memset(&p.plan, 0, sizeof p.plan);
    p.room.width_mm = 1234.5;
    r = app_project_write(out, &p, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    if (app_project_read(out, &q, err, sizeof err) == APP_OK) {
        CHECK(q.plan.corner_count == 4 && q.plan.corners[2].x == 1234.5 &&
              q.plan.corners[2].y == 3000 && q.room.width_mm == 1234.5);
        app_project_free(&q);
    }
    p.plan = plan;
    app_project_free(&p);
}

typedef struct bad_case {
    const char *name, *find, *replace;
    const char *path, *detail;
} bad_case;

static const bad_case bad_cases[] = {
    {"plan_missing", "\"plan\": {", "\"plan_x\": {", "$.plan: ", "missing (required)"},
    {"corners_two", "[[0, 0], [3000, 0], [3000, 1800], [1800, 1800], [1800, 3000], [0, 3000]]",
     "[[0, 0], [3000, 0]]", "$.plan.corners: ", "3 to 256 corners, got 2"},
    {"corner_not_pair", "[1800, 1800]", "[1800]", "$.plan.corners[3]: ", "expected [x, y]"},
    {"corner_string", "[1800, 1800]", "[1800, \"a\"]",
     "$.plan.corners[3][1]: ", "expected a finite number, got string"},
    {"corner_overflow", "[1800, 1800]", "[1e999, 1800]",
     "$.plan.corners[3][0]: ", "must be a finite number"},
    {"clockwise", "[[0, 0], [3000, 0], [3000, 1800], [1800, 1800], [1800, 3000], [0, 3000]]",
     "[[0, 3000], [1800, 3000], [1800, 1800], [3000, 1800], [3000, 0], [0, 0]]",
     "$.plan.corners: ", "clockwise"},
    {"self_intersecting",
     "[[0, 0], [3000, 0], [3000, 1800], [1800, 1800], [1800, 3000], [0, 3000]]",
     "[[0, 0], [3000, 0], [3000, 1800], [3500, -500], [1800, 3000], [0, 3000]]",
     "$.plan.corners: ", "crosses or touches wall"},
    {"repeated_corner", "[1800, 1800], [1800, 3000]", "[1800, 1800], [1800, 1800]",
     "$.plan.corners[4]: ", "wall 3 is shorter than 1 mm"},
    {"fold_back", "[[0, 0], [3000, 0], [3000, 1800]", "[[0, 0], [3000, 0], [2000, 0]",
     "$.plan.corners[1]: ", "fold back"},
    {"height_zero", "\"height\": 2600", "\"height\": 0", "$.plan.height: ", "must be > 0"},
    {"thickness_negative", "\"wall_thickness\": 150", "\"wall_thickness\": -1",
     "$.plan.wall_thickness: ", "must be > 0"},
    {"opening_wall_out_of_range", "\"type\": \"window\", \"wall\": 1",
     "\"type\": \"window\", \"wall\": 6",
     "$.plan.openings[0].wall: ", "wall 6 does not exist (the plan has 6 walls, 0..5)"},
    {"opening_wall_negative", "\"type\": \"window\", \"wall\": 1",
     "\"type\": \"window\", \"wall\": -1", "$.plan.openings[0].wall: ", "must be in [0, 255]"},
    {"opening_too_long", "\"offset\": 500, \"width\": 800", "\"offset\": 1100, \"width\": 800",
     "$.plan.openings[0]: ",
     "reaches 1900 mm along wall 1 (offset + width), beyond its length of 1800"},
    {"opening_too_high", "\"sill\": 900, \"height\": 1200", "\"sill\": 1500, \"height\": 1200",
     "$.plan.openings[0]: ", "top is at 2700 mm, above the wall height of 2600"},
    {"opening_type_unknown", "\"type\": \"window\"", "\"type\": \"hatch\"",
     "$.plan.openings[0].type: ", "unknown value \"hatch\" (expected door or window)"},
    {"opening_type_missing", "\"type\": \"window\", ", "",
     "$.plan.openings[0].type: ", "missing (required)"},
    {"swing_unknown", "\"swing\": \"in-right\"", "\"swing\": \"up\"",
     "$.plan.openings[1].swing: ", "expected in-left, in-right, out-left, out-right or sliding"},
    {"openings_overlap", "\"wall\": 4, \"offset\": 900", "\"wall\": 1, \"offset\": 900",
     "$.plan.openings[1]: ", "overlaps opening 0 (\"window\") on wall 1"},
    {"light_negative", "\"light\": [1.0, 0.97, 0.9]", "\"light\": [1.0, -1, 0.9]",
     "$.plan.openings[0].light[1]: ", "must be >= 0"},
    {"prewall_too_long", "\"offset\": 1000, \"width\": 1200", "\"offset\": 2000, \"width\": 1200",
     "$.plan.prewalls[0]: ", "beyond its length of 3000"},
    {"prewall_too_high", "\"depth\": 200, \"height\": 1200", "\"depth\": 200, \"height\": 2700",
     "$.plan.prewalls[0]: ", "above the wall height"},
    {"prewall_colon", "\"name\": \"wc-box\"", "\"name\": \"wc:box\"",
     "$.plan.prewalls[0].name: ", "must not contain ':'"},
    {"niche_too_deep", "\"depth\": 80}", "\"depth\": 150}",
     "$.plan.niches[0].depth: ", "must be less than the wall thickness (150 mm), got 150"},
    {"niche_sill_missing", "\"sill\": 1000,", "", "$.plan.niches[0].sill: ", "missing"},
    {"slope_knee_too_high", "\"knee\": 1600", "\"knee\": 2600",
     "$.plan.slope.knee: ", "must be below the wall height (2600 mm), got 2600"},
    {"slope_wall", "\"slope\": {\"wall\": 0", "\"slope\": {\"wall\": 9",
     "$.plan.slope.wall: ", "wall 9 does not exist"},
    {"slope_not_object", "\"slope\": {\"wall\": 0, \"knee\": 1600, \"run\": 700}", "\"slope\": 3",
     "$.plan.slope: ", "expected an object, got number"},
    {"tiling_surface_unknown", "\"surface\": \"floor\"", "\"surface\": \"roof\"",
     "$.tilings[0].surface: ", "unknown surface \"roof\""},
    {"tiling_wall_out_of_range", "\"surface\": \"wall:0\"", "\"surface\": \"wall:6\"",
     "$.tilings[1].surface: ", "wall 6 does not exist (the plan has 6 walls)"},
    {"tiling_prewall_unknown", "\"prewall:wc-box:front\"", "\"prewall:duct:front\"",
     "$.tilings[2].surface: ", "no pre-wall named \"duct\""},
    {"tiling_prewall_face", "\"prewall:wc-box:front\"", "\"prewall:wc-box:back\"",
     "$.tilings[2].surface: ", "unknown pre-wall face \"back\""},
    {"tiling_product_missing_article", "\"article\": \"TZ61002\"", "\"art\": \"TZ61002\"",
     "$.tilings[0].product.article: ", "missing (required)"},
    {"tiling_pattern_unknown", "\"pattern\": \"half-offset\"", "\"pattern\": \"zigzag\"",
     "$.tilings[0].pattern: ", "unknown value \"zigzag\""},
    {"tiling_grout_too_wide", "\"grout\": 3", "\"grout\": 300",
     "$.tilings[0].grout: ", "must be in [0, 100], got 300"},
    {"tiling_align_unknown", "\"align\": \"corner\"", "\"align\": \"left\"",
     "$.tilings[0].align: ", "expected centred, corner, line or auto"},
    {"tiling_to_below_from", "\"to\": 1200", "\"to\": -5", "$.tilings[1].to: ", "must be >= 0"},
    {"tiling_band_empty", "\"from\": 0, \"to\": 1200", "\"from\": 1300, \"to\": 1200",
     "$.tilings[1].to: ", "must be above \"from\" (1300 mm)"},
    {"tiling_border_no_bottom", "\"bottom\": 1200", "\"top\": 1200",
     "$.tilings[1].borders[0].bottom: ", "missing"},
    {"tilings_not_array", "\"tilings\": [", "\"tilings\": {}, \"x\": [",
     "$.tilings: ", "expected an array, got object"},
    {"object_product_no_manufacturer", "\"manufacturer\": \"Cerana\", ", "",
     "$.objects[1].product.manufacturer: ", "missing (required)"},
    {"object_product_and_shape", "\"name\": \"wc\", \"product\"",
     "\"name\": \"wc\", \"shape\": \"box\", \"product\"",
     "$.objects[1]: ", "has more than one of \"shape\", \"model\" and \"product\""},
    {"object_product_variant_long", "\"variant\": \"WH\"", "\"variant\": \"WHWHWHWHWHWHWHWHWH\"",
     "$.objects[1].product.variant: ", "too long"},
};

static void test_errors(void)
{
    char *text = tu_read_file(DATA "/v2_l_room.json", NULL);
    CHECK(text != NULL);
    if (!text)
        return;
    int failed = 0;
    for (size_t k = 0; k < sizeof bad_cases / sizeof bad_cases[0]; k++) {
        const bad_case *c = &bad_cases[k];
        char *bad = tu_replace(text, c->find, c->replace);
        CHECK_MSG(bad != NULL, "%s", c->name);
        if (!bad)
            continue;
        app_project p;
        char err[1024];
        int before = check_failures;
        app_result r = app_project_parse(bad, strlen(bad), DATA "/case.json", &p, err, sizeof err);
        CHECK_MSG(r == APP_ERR_SCHEMA, "%s", err);
        CHECK_MSG(tu_contains(err, c->path), "%s", err);
        CHECK_MSG(tu_contains(err, c->detail), "%s", err);
        if (check_failures != before) {
            fprintf(stderr, "FAIL %s\n", c->name);
            failed++;
        }
        if (r == APP_OK)
            app_project_free(&p);
        free(bad);
    }
    printf("project_v2: %zu malformed cases, %d failed\n", sizeof bad_cases / sizeof bad_cases[0],
           failed);
    free(text);
}

/* Saving keeps the previous file as PATH.bak and leaves no temporary files. */
static void test_backup(const char *dir)
{
    app_project p;
    char err[1024];
    if (app_project_read(DATA "/v2_l_room.json", &p, err, sizeof err) != APP_OK) {
        CHECK_MSG(0, "%s", err);
        return;
    }
    char path[1024], bak[1100];
    snprintf(path, sizeof path, "%s/backup.json", dir);
    snprintf(bak, sizeof bak, "%s.bak", path);
    snprintf(p.name, sizeof p.name, "first");
    CHECK(app_project_write(path, &p, err, sizeof err) == APP_OK);
    CHECK(access(bak, F_OK) != 0); /* nothing to keep the first time */
    snprintf(p.name, sizeof p.name, "second");
    CHECK(app_project_write(path, &p, err, sizeof err) == APP_OK);
    snprintf(p.name, sizeof p.name, "third");
    CHECK(app_project_write(path, &p, err, sizeof err) == APP_OK);
    app_project q;
    if (app_project_read(bak, &q, err, sizeof err) == APP_OK) {
        CHECK(!strcmp(q.name, "second"));
        app_project_free(&q);
    } else {
        CHECK_MSG(0, "%s", err);
    }
    if (app_project_read(path, &q, err, sizeof err) == APP_OK) {
        CHECK(!strcmp(q.name, "third"));
        app_project_free(&q);
    }
    CHECK(tu_count_entries(dir, "backup.json.tmp") == 0);
    /* A failed save leaves both the file and its backup as they were. */
    app_project_test_fail_write_after(10);
    snprintf(p.name, sizeof p.name, "fourth");
    CHECK(app_project_write(path, &p, err, sizeof err) == APP_ERR_IO);
    app_project_test_fail_write_after(-1);
    if (app_project_read(path, &q, err, sizeof err) == APP_OK) {
        CHECK(!strcmp(q.name, "third"));
        app_project_free(&q);
    }
    if (app_project_read(bak, &q, err, sizeof err) == APP_OK) {
        CHECK(!strcmp(q.name, "second"));
        app_project_free(&q);
    }
    app_project_free(&p);
}

int main(void)
{
    char *dir = tu_make_temp_dir();
    CHECK(dir != NULL);
    if (!dir)
        return check_report("project_v2");
    test_read_fixture();
    test_round_trip(dir);
    test_migration(dir);
    test_errors();
    test_backup(dir);
    tu_remove_tree(dir);
    free(dir);
    return check_report("project_v2");
}
