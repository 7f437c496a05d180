/* Mounting heights and groups (docs/editing.md "Mounting heights", "Groups"): a product
 * placed without a height lands at its mounting height or on its carrier, a vanity's basin,
 * tap and mirror move, turn and go with it in one undo step, `ungroup` parts them, and a
 * basin carried by nothing is a floating error. */
#include "test_util.h"

#include "app/project/commands.h"
#include "placement_test_catalog.h"

#include <math.h>

static const char *csv = TESSERA_SOURCE_DIR "/assets/catalog/fixtures.csv";

static void make_room(app_project *p)
{
    memset(p, 0, sizeof *p);
    p->version = p->file_version = 2;
    p->plan.corner_count = 4;
    p->plan.corners = calloc(4, sizeof *p->plan.corners);
    p->plan.corners[1].x = p->plan.corners[2].x = 3000;
    p->plan.corners[2].y = p->plan.corners[3].y = 2500;
    p->plan.height_mm = 2500;
    p->plan.wall_thickness_mm = 120;
    p->room.width_mm = 3000;
    p->room.depth_mm = 2500;
    p->room.height_mm = 2500;
    p->material_count = 1;
    p->materials = calloc(1, sizeof *p->materials);
    snprintf(p->materials[0].name, sizeof p->materials[0].name, "default");
}

static const app_object *named(const app_project *p, const char *name)
{
    for (int i = 0; i < p->object_count; i++)
        if (!strcmp(p->objects[i].name, name))
            return &p->objects[i];
    return NULL;
}

static int run(app_project *p, app_history *h, const char *text)
{
    app_script_env env = {ptc_lookup, (void *)csv, NULL, stdout};
    char err[1024] = "";
    app_result r =
        app_script_run(p, h, text, strlen(text), "test.edit", &env, NULL, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s: %s", text, err);
    return r == APP_OK;
}

static int floating_errors(const app_project *p)
{
    app_fixture *fx = NULL;
    int n = 0, count = 0;
    char err[512] = "";
    app_findings f = {0};
    CHECK_MSG(app_placement_fixtures(p, ptc_lookup, (void *)csv, &fx, &n, err, sizeof err) ==
                  APP_OK,
              "%s", err);
    CHECK_MSG(app_placement_check(p, fx, n, NULL, &f, err, sizeof err) == APP_OK, "%s", err);
    for (int i = 0; i < f.count; i++)
        if (f.items[i].kind == APP_FINDING_FLOATING) {
            CHECK(f.items[i].severity == APP_SEVERITY_ERROR);
            CHECK(tu_contains(f.items[i].message, "floats"));
            count++;
        }
    app_findings_free(&f);
    free(fx);
    return count;
}

/* The washstand on wall 0 (y = 0): a vanity 800 x 460 x 520, the furniture basin 800 x 480 x
 * 170 dropped beside it, a mixer and a mirror dropped near the basin, none with a height. */
static const char *washstand = "place Cerana CE419501 OK at 1500 0 snap wall as vanity\n"
                               "place Cerana CE410401 WH at 1650 250 as basin\n"
                               "place Aquavera 31003000 CP at 1450 100 as tap\n"
                               "place Vitrelux VX20051 MI at 1500 20 as mirror\n";

static void test_mounting_heights(void)
{
    /* DOMAIN.md: basin rim 850, WC seat 420 (a 340 mm wall-hung WC hangs at 80). */
    CHECK_NEAR(app_mounting_z(CAT_CATEGORY_BASINS, 170), 680, 1e-9);
    CHECK_NEAR(app_mounting_z(CAT_CATEGORY_WCS_BIDETS, 340), 80, 1e-9);
    CHECK_NEAR(app_mounting_z(CAT_CATEGORY_WCS_BIDETS, 800), 0, 1e-9); /* floor-standing */
    CHECK_NEAR(app_mounting_z(CAT_CATEGORY_MIRRORS, 700), 1150, 1e-9);
    CHECK_NEAR(app_mounting_z(CAT_CATEGORY_BATHS, 600), 0, 1e-9);

    app_project p;
    make_room(&p);
    app_history *h = app_history_create(0);
    run(&p, h, washstand);
    const app_object *v = named(&p, "vanity"), *b = named(&p, "basin"), *t = named(&p, "tap"),
                     *m = named(&p, "mirror");
    CHECK(v && b && t && m);
    if (v && b && t && m) {
        /* The vanity's top at 680 (850 - the basin's 170). */
        CHECK_NEAR(v->position_mm[2], 160, 1e-9);
        CHECK(!v->parent[0]);
        /* The basin on the vanity's top, square on it, mounted on it. */
        CHECK_NEAR(b->position_mm[0], v->position_mm[0], 1e-9);
        CHECK_NEAR(b->position_mm[1], v->position_mm[1], 1e-9);
        CHECK_NEAR(b->position_mm[2], 680, 1e-9);
        CHECK_MSG(!strcmp(b->parent, "vanity"), "basin parent \"%s\"", b->parent);
        /* The tap on the basin's tap hole, 50 mm in front of its back, on the rim (850). */
        CHECK_NEAR(t->position_mm[0], 1500, 1e-9);
        CHECK_NEAR(t->position_mm[1], 50, 1e-9);
        CHECK_NEAR(t->position_mm[2], 850, 1e-9);
        CHECK(!strcmp(t->parent, "basin"));
        /* The mirror 300 above the rim. */
        CHECK_NEAR(m->position_mm[2], 1150, 1e-9);
        CHECK(!strcmp(m->parent, "basin"));
    }
    CHECK_MSG(floating_errors(&p) == 0, "the basin on its vanity floats");
    app_history_destroy(h);
    app_project_free_all(&p);

    /* A basin dropped far from any vanity, against the wall: wall-hung at rim height. */
    make_room(&p);
    h = app_history_create(0);
    run(&p, h, "place Cerana CE410401 WH at 700 100 snap wall as basin\n");
    b = named(&p, "basin");
    CHECK(b && fabs(b->position_mm[2] - 680) < 1e-9 && !b->parent[0]);
    CHECK(floating_errors(&p) == 0);
    app_history_destroy(h);
    app_project_free_all(&p);
}

/* The catalog's own mounting heights win over the category's (docs/catalog.md "Mounting
 * heights and companions"): the accessible WC CE413301 (400 high) has its seat at 470, not
 * 420; the close-coupled WC stands on the floor. A vanity placed `with-companions` brings the
 * basin, mixer and mirror its row names, each on its carrier, in one undo step; a product
 * whose mounting height is above the room's ceiling is refused. */
static void test_catalog_mounting(void)
{
    app_product_info info = {.height_mm = 400, .category = CAT_CATEGORY_WCS_BIDETS};
    CHECK_NEAR(app_product_mounting_z(&info), 20, 1e-9); /* the category's 420 */
    info.has_mounting = 1;
    info.mounting_height_mm = 470;
    info.mounting_of = APP_MOUNT_TOP;
    CHECK_NEAR(app_product_mounting_z(&info), 70, 1e-9);
    info.mounting_of = APP_MOUNT_BOTTOM;
    CHECK_NEAR(app_product_mounting_z(&info), 470, 1e-9);

    app_project p;
    make_room(&p);
    app_history *h = app_history_create(0);
    run(&p, h,
        "place Cerana CE413301 WH at 2500 0 snap wall as wc\n"
        "place Cerana CE413501 WH at 700 2500 snap wall as wc2\n");
    CHECK(named(&p, "wc") && fabs(named(&p, "wc")->position_mm[2] - 70) < 1e-9);
    CHECK(named(&p, "wc2") && fabs(named(&p, "wc2")->position_mm[2]) < 1e-9);

    int undo = app_history_undo_count(h);
    run(&p, h, "place Cerana CE419501 OK at 1200 0 snap wall as vanity with-companions\n");
    CHECK(app_history_undo_count(h) == undo + 1);
    CHECK(p.object_count == 6);
    const app_object *v = named(&p, "vanity"), *b = named(&p, "CE410401"),
                     *t = named(&p, "31000000"), *m = named(&p, "VX20051");
    CHECK(v && b && t && m);
    if (v && b && t && m) {
        CHECK_NEAR(v->position_mm[2] + 520, 680, 1e-9); /* the catalog's top 680 */
        CHECK_NEAR(b->position_mm[2], 680, 1e-9);       /* its rim at 850 */
        CHECK(!strcmp(b->parent, "vanity"));
        CHECK_NEAR(t->position_mm[2], 850, 1e-9);
        CHECK(!strcmp(t->parent, "CE410401"));
        CHECK_NEAR(m->position_mm[2], 1150, 1e-9);
        CHECK(!strcmp(m->parent, "CE410401"));
    }
    CHECK(floating_errors(&p) == 0);
    char err[512];
    CHECK(app_history_undo(h, &p, err, sizeof err) == APP_OK && p.object_count == 2);
    app_history_destroy(h);
    app_project_free_all(&p);

    /* A room 1000 mm high: the mirror's 1150 is above its ceiling. */
    make_room(&p);
    p.plan.height_mm = p.room.height_mm = 1000;
    h = app_history_create(0);
    app_script_env env = {ptc_lookup, (void *)csv, NULL, NULL};
    const char *line = "place Vitrelux VX20051 MI at 1500 0 as mirror\n";
    err[0] = 0;
    CHECK(app_script_run(&p, h, line, strlen(line), "t.edit", &env, NULL, err, sizeof err) !=
          APP_OK);
    CHECK_MSG(tu_contains(err, "above the room's ceiling at 1000 mm"), "%s", err);
    /* A product without companions is told so. */
    line = "place Cerana CE413301 WH at 2500 0 with-companions\n";
    CHECK(app_script_run(&p, h, line, strlen(line), "t.edit", &env, NULL, err, sizeof err) !=
          APP_OK);
    CHECK_MSG(tu_contains(err, "has no companions"), "%s", err);
    app_history_destroy(h);
    app_project_free_all(&p);
}

static void test_group_move_rotate_remove(void)
{
    app_project p, before;
    make_room(&p);
    app_history *h = app_history_create(0);
    run(&p, h, washstand);
    char err[512];
    CHECK(app_project_copy(&before, &p, err, sizeof err) == APP_OK);

    /* Move: everything on the vanity by the same offset, one undo step. */
    int undo = app_history_undo_count(h);
    run(&p, h, "move vanity 1000 0 200\n");
    CHECK(app_history_undo_count(h) == undo + 1);
    CHECK_NEAR(named(&p, "basin")->position_mm[0], 1000, 1e-9);
    CHECK_NEAR(named(&p, "basin")->position_mm[2], 720, 1e-9);
    CHECK_NEAR(named(&p, "tap")->position_mm[0], 1000, 1e-9);
    CHECK_NEAR(named(&p, "tap")->position_mm[1], 50, 1e-9);
    CHECK_NEAR(named(&p, "tap")->position_mm[2], 890, 1e-9);
    CHECK_NEAR(named(&p, "mirror")->position_mm[0], 1000, 1e-9);
    CHECK(floating_errors(&p) == 0);
    run(&p, h, "undo\n");
    char diff[512];
    CHECK_MSG(app_project_equal(&p, &before, diff, sizeof diff), "undo of the move: %s", diff);

    /* Rotate about the vanity's origin: the tap 50 mm ahead of it turns with it. */
    run(&p, h, "rotate vanity 90\n");
    const app_object *t = named(&p, "tap");
    CHECK_NEAR(t->position_mm[0], 1500 - 50, 1e-9);
    CHECK_NEAR(t->position_mm[1], 0, 1e-9);
    CHECK_NEAR(t->rotation_deg[2], 90, 1e-9);
    CHECK_NEAR(named(&p, "basin")->rotation_deg[2], 90, 1e-9);
    run(&p, h, "undo\n");
    CHECK_MSG(app_project_equal(&p, &before, diff, sizeof diff), "undo of the turn: %s", diff);

    /* Remove: the vanity and all it carries; undo brings them back in their places. */
    run(&p, h, "remove vanity\n");
    CHECK(p.object_count == 0);
    run(&p, h, "undo\n");
    CHECK_MSG(app_project_equal(&p, &before, diff, sizeof diff), "undo of the removal: %s", diff);

    /* Ungroup: the basin stays where it is when the vanity moves. */
    run(&p, h, "ungroup vanity\n");
    CHECK(!named(&p, "basin")->parent[0]);
    CHECK(!strcmp(named(&p, "tap")->parent, "basin")); /* the tap stays on the basin */
    run(&p, h, "move vanity 1000 0 160\n");
    CHECK_NEAR(named(&p, "basin")->position_mm[0], 1500, 1e-9);
    /* ... which now floats: not on the vanity, and with its rim at 850 on the wall it is
     * wall-hung; lifted off the wall into the room it floats. */
    CHECK(floating_errors(&p) == 0);
    run(&p, h, "move basin 1500 1200 680\n");
    CHECK(floating_errors(&p) == 1);
    CHECK_NEAR(named(&p, "tap")->position_mm[1], 1250, 1e-9); /* the tap came along */

    /* mount: a cycle is refused. */
    app_script_env env = {ptc_lookup, (void *)csv, NULL, stdout};
    const char *cycle = "mount basin on tap\n";
    CHECK(app_script_run(&p, h, cycle, strlen(cycle), "test.edit", &env, NULL, err, sizeof err) !=
          APP_OK);
    CHECK_MSG(tu_contains(err, "hangs on"), "%s", err);
    app_history_destroy(h);
    app_project_free_all(&before);
    app_project_free_all(&p);
}

int main(void)
{
    test_mounting_heights();
    test_group_move_rotate_remove();
    test_catalog_mounting();
    return check_report("placement_groups");
}
