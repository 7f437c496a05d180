/* A dropped product and door swings (docs/editing.md "Mounting heights"): `place ... snap
 * wall`, the window's drop, slides the product along the wall it snapped to out of an
 * inward-opening door's swing; when the whole wall lies in the swing it stays and the
 * `opening` check reports it. */
#include "test_util.h"

#include "app/project/commands.h"
#include "placement_test_catalog.h"

#include <math.h>

static const char *csv = TESSERA_SOURCE_DIR "/assets/catalog/fixtures.csv";

/* A room of n corners (counter-clockwise, mm). */
static void make_room(app_project *p, const double (*corners)[2], int n)
{
    memset(p, 0, sizeof *p);
    p->version = p->file_version = 2;
    p->plan.corner_count = n;
    p->plan.corners = calloc((size_t)n, sizeof *p->plan.corners);
    for (int i = 0; i < n; i++) {
        p->plan.corners[i].x = corners[i][0];
        p->plan.corners[i].y = corners[i][1];
    }
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

/* The number of `tessera check` findings (of kind opening) saying `what`. */
static int door_findings(const app_project *p, const char *what)
{
    app_fixture *fx = NULL;
    int n = 0, count = 0;
    char err[512] = "";
    app_findings f = {0};
    CHECK_MSG(app_placement_fixtures(p, ptc_lookup, (void *)csv, &fx, &n, err, sizeof err) ==
                  APP_OK,
              "%s", err);
    CHECK_MSG(app_placement_check(p, fx, n, NULL, &f, err, sizeof err) == APP_OK, "%s", err);
    for (int i = 0; i < f.count; i++) {
        printf("  %s %s: %s\n", app_severity_name(f.items[i].severity),
               app_finding_kind_name(f.items[i].kind), f.items[i].message);
        if (f.items[i].kind == APP_FINDING_OPENING && tu_contains(f.items[i].message, what))
            count++;
    }
    app_findings_free(&f);
    free(fx);
    return count;
}

static const double box[4][2] = {{0, 0}, {3000, 0}, {3000, 2500}, {0, 2500}};
/* The door in wall 0 (y = 0) from x 2100 to 2900 opens into the room: its leaf sweeps the
 * square x 2100..2900, y 0..800. */
static const char *door = "door d wall 0 at 2100 width 800 height 2000 swing in-left\n";

static void test_slid_along_the_side_wall(void)
{
    /* The WC (360 wide, 560 deep) dropped at (2900, 400) snaps to wall 1 (x = 3000) at
     * y = 400, in the swing; the nearest clear place on wall 1 has its side at the swing's
     * edge: y = 800 + 180. */
    app_project p;
    make_room(&p, box, 4);
    app_history *h = app_history_create(0);
    run(&p, h, door);
    run(&p, h, "place Cerana CE413701 WH at 2900 400 snap wall as wc\n");
    const app_object *wc = named(&p, "wc");
    CHECK(wc != NULL);
    if (wc) {
        CHECK_NEAR(wc->position_mm[0], 3000, 1e-6); /* against the same wall */
        CHECK_NEAR(wc->position_mm[1], 980, 1e-6);
        CHECK_NEAR(fmod(wc->rotation_deg[2] + 360, 360), 90, 1e-6);
        /* A floor-standing back-to-wall WC: its catalog row mounts its bottom at 0. */
        CHECK_NEAR(wc->position_mm[2], 0, 1e-6);
    }
    CHECK_MSG(door_findings(&p, "door") == 0, "the dropped WC is still in the door swing");
    app_history_destroy(h);
    app_project_free_all(&p);
}

static void test_slid_along_the_door_wall(void)
{
    /* Dropped beside the door on its own wall: slid to the nearer side, x = 2100 - 180, rather
     * than past the door (no room for it between the door and the corner). */
    app_project p;
    make_room(&p, box, 4);
    app_history *h = app_history_create(0);
    run(&p, h, door);
    run(&p, h, "place Cerana CE413701 WH at 2700 100 snap wall as wc\n");
    const app_object *wc = named(&p, "wc");
    CHECK(wc != NULL);
    if (wc) {
        CHECK_NEAR(wc->position_mm[0], 1920, 1e-6);
        CHECK_NEAR(wc->position_mm[1], 0, 1e-6);
    }
    CHECK(door_findings(&p, "door") == 0);

    /* A vanity (800 wide, x 1100..1900) already stands where that would be: the WC goes to
     * the left of it, clear of its footprint and 200 mm from it (VDI 6000 sheet 1). */
    app_history_destroy(h);
    app_project_free_all(&p);
    make_room(&p, box, 4);
    h = app_history_create(0);
    run(&p, h, door);
    run(&p, h, "place Cerana CE419501 OK at 1500 0 snap wall as vanity\n");
    run(&p, h, "place Cerana CE413701 WH at 2700 100 snap wall as wc\n");
    wc = named(&p, "wc");
    const app_object *v = named(&p, "vanity");
    CHECK(wc && v);
    if (wc && v) {
        CHECK_NEAR(v->position_mm[0], 1500, 1e-6);
        CHECK_NEAR(wc->position_mm[0], 1100 - 200 - 180, 1e-6);
        CHECK_NEAR(wc->position_mm[1], 0, 1e-6);
    }
    CHECK(door_findings(&p, "door") == 0);
    app_history_destroy(h);
    app_project_free_all(&p);
}

static void test_wall_inside_the_swing(void)
{
    /* An L-shaped room: wall 1 runs from (1000, 0) to (1000, 700), wholly within the swing of
     * the door in wall 0 (x 100..900, y 0..800). A WC dropped on it has nowhere to go there: it
     * stays and the check reports it. */
    static const double ell[6][2] = {{0, 0},      {1000, 0},    {1000, 700},
                                     {3000, 700}, {3000, 2500}, {0, 2500}};
    app_project p;
    make_room(&p, ell, 6);
    app_history *h = app_history_create(0);
    run(&p, h, "door d wall 0 at 100 width 800 height 2000 swing in-left\n");
    run(&p, h, "place Cerana CE413701 WH at 950 350 snap wall as wc\n");
    const app_object *wc = named(&p, "wc");
    CHECK(wc != NULL);
    if (wc) {
        CHECK_NEAR(wc->position_mm[0], 1000, 1e-6);
        CHECK_NEAR(wc->position_mm[1], 350, 1e-6);
    }
    CHECK_MSG(door_findings(&p, "in the swing of the door") == 1,
              "the WC left in the swing is not reported");
    app_history_destroy(h);
    app_project_free_all(&p);
}

static void test_explicit_rule_kept(void)
{
    /* `snap wall corner` is the script's own rule, not a drop: kept as written. */
    app_project p;
    make_room(&p, box, 4);
    app_history *h = app_history_create(0);
    run(&p, h, door);
    run(&p, h, "place Cerana CE413701 WH at 2900 400 snap wall corner as wc\n");
    const app_object *wc = named(&p, "wc");
    CHECK(wc && fabs(wc->position_mm[1] - 180) < 1e-6);
    CHECK(door_findings(&p, "door") == 1);
    app_history_destroy(h);
    app_project_free_all(&p);
}

static void test_clear_of_free_areas(void)
{
    /* app_slide_out_of_swing alone: a WC on wall 0 at x = 1500 (footprint x 1320..1680, y
     * 0..560) keeps its 800 x 550 free area in front (x 1100..1900, y 560..1110). A cabinet
     * 400 wide and 600 deep (a category without a side distance) dropped at x = 2500 in the
     * swing would fit at x = 1900 beside the WC's footprint, but its front would stand in the
     * WC's free area: it goes to x = 1100 - 200 = 900. */
    app_project p;
    make_room(&p, box, 4);
    app_history *h = app_history_create(0);
    run(&p, h, door);
    app_fixture wc;
    memset(&wc, 0, sizeof wc);
    wc.object = 0;
    wc.category = CAT_CATEGORY_WCS_BIDETS;
    wc.has_product = 1;
    wc.role = APP_ROLE_FIXTURE;
    wc.centre[0] = 1500;
    wc.centre[1] = 280;
    wc.half[0] = 180;
    wc.half[1] = 280;
    wc.z1 = 420;
    wc.width_mm = 360;
    wc.depth_mm = 560;
    app_pose in = {2500, 0, 0, 0}, out;
    CHECK(app_slide_out_of_swing(&p.plan, &wc, 1, CAT_CATEGORY_ACCESSORIES, 400, 600, 0, 900, in,
                                 &out) == 1);
    CHECK_NEAR(out.x, 900, 1e-6);
    CHECK_NEAR(out.y, 0, 1e-6);
    /* 500 deep, it stays out of the free area anyway: beside the WC's footprint at 1900. */
    CHECK(app_slide_out_of_swing(&p.plan, &wc, 1, CAT_CATEGORY_ACCESSORIES, 400, 500, 0, 900, in,
                                 &out) == 1);
    CHECK_NEAR(out.x, 1900, 1e-6);
    /* Out of every swing already: not moved. */
    in.x = 1000;
    CHECK(app_slide_out_of_swing(&p.plan, &wc, 1, CAT_CATEGORY_ACCESSORIES, 400, 500, 0, 900, in,
                                 &out) == 0);
    CHECK_NEAR(out.x, 1000, 1e-6);
    app_history_destroy(h);
    app_project_free_all(&p);
}

int main(void)
{
    test_clear_of_free_areas();
    test_slid_along_the_side_wall();
    test_slid_along_the_door_wall();
    test_wall_inside_the_swing();
    test_explicit_rule_kept();
    return check_report("drop_swing");
}
