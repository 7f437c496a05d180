/* The drag's snap preview (app/design/snap_guides.h) on the designed demo: it lands where the
 * drag's `move ... snap wall corner neighbour` edit lands, draws the wall and corner guides,
 * and measures the box's clear distances to the walls; away from every wall it moves freely
 * with no guides; beside a neighbour it keeps the 200 mm gap, its guide on the neighbour's
 * side. */
#include "test_util.h"

#include "app/design/snap_guides.h"
#include "app/project/commands.h"
#include "placement_test_catalog.h"

#include <math.h>

static const char *csv = TESSERA_SOURCE_DIR "/assets/catalog/fixtures.csv";
static const char *demo = TESSERA_SOURCE_DIR "/assets/projects/designed-bathroom.json";

static int object_named(const app_project *p, const char *name)
{
    for (int i = 0; i < p->object_count; i++)
        if (!strcmp(p->objects[i].name, name))
            return i;
    return -1;
}

static int fixture_of(const app_fixture *fx, int n, int object)
{
    for (int i = 0; i < n; i++)
        if (fx[i].object == object)
            return i;
    return -1;
}

/* The preview for `name` asked to go to (x, y), and the same move run as the drag's edit. */
static void preview_and_edit(const char *name, double x, double y, app_snap_preview *s,
                             double edited[3], double *edited_rot)
{
    app_project p;
    char err[1024] = "";
    CHECK_MSG(app_project_read(demo, &p, err, sizeof err) == APP_OK, "%s", err);
    app_fixture *fx = NULL;
    int n = 0;
    CHECK_MSG(app_placement_fixtures(&p, ptc_lookup, (void *)csv, &fx, &n, err, sizeof err) ==
                  APP_OK,
              "%s", err);
    int o = object_named(&p, name), k = fixture_of(fx, n, o);
    CHECK(o >= 0 && k >= 0);
    if (o < 0 || k < 0)
        return;
    app_pose in = {x, y, p.objects[o].position_mm[2], p.objects[o].rotation_deg[2]};
    app_snap_preview_of(&p, fx, n, k, in, s);
    free(fx);

    char line[256];
    snprintf(line, sizeof line, "move \"%s\" %.0f %.0f %.0f snap wall corner neighbour\n", name, x,
             y, in.z);
    app_history *h = app_history_create(0);
    app_script_env env = {ptc_lookup, (void *)csv, NULL, NULL};
    if (app_script_run(&p, h, line, strlen(line), "test.edit", &env, NULL, err, sizeof err) ==
        APP_OK) {
        memcpy(edited, p.objects[o].position_mm, 3 * sizeof *edited);
        *edited_rot = p.objects[o].rotation_deg[2];
    } else { /* no wall near: the drag moves it without snapping */
        edited[0] = x;
        edited[1] = y;
        edited[2] = in.z;
        *edited_rot = in.rotation_deg;
    }
    app_history_destroy(h);
    app_project_free_all(&p);
}

static int guides_of(const app_snap_preview *s, app_snap_guide_kind kind)
{
    int n = 0;
    for (int g = 0; g < s->guide_count; g++)
        n += s->guides[g].kind == kind;
    return n;
}

/* A neighbour: in a 3000 x 2500 room, a basin dragged 300 mm beside a WC on the same wall
 * slides to the 200 mm gap; its left distance is that gap and the neighbour guide runs along
 * the WC's side. */
static void neighbour_case(void)
{
    app_project p;
    memset(&p, 0, sizeof p);
    p.version = p.file_version = 2;
    p.plan.corner_count = 4;
    p.plan.corners = calloc(4, sizeof *p.plan.corners);
    p.plan.corners[1].x = p.plan.corners[2].x = 3000;
    p.plan.corners[2].y = p.plan.corners[3].y = 2500;
    p.plan.height_mm = p.room.height_mm = 2500;
    p.plan.wall_thickness_mm = 120;
    p.room.width_mm = 3000;
    p.room.depth_mm = 2500;
    p.material_count = 1;
    p.materials = calloc(1, sizeof *p.materials);
    snprintf(p.materials[0].name, sizeof p.materials[0].name, "default");
    const char *text = "place Cerana CE413701 WH at 1000 0 0 snap wall as wc\n"
                       "place Cerana CE410401 WH at 2200 0 680 snap wall as basin\n";
    app_history *h = app_history_create(0);
    app_script_env env = {ptc_lookup, (void *)csv, NULL, NULL};
    char err[1024] = "";
    CHECK_MSG(app_script_run(&p, h, text, strlen(text), "test.edit", &env, NULL, err, sizeof err) ==
                  APP_OK,
              "%s", err);
    app_fixture *fx = NULL;
    int n = 0;
    CHECK_MSG(app_placement_fixtures(&p, ptc_lookup, (void *)csv, &fx, &n, err, sizeof err) ==
                  APP_OK,
              "%s", err);
    int wc = object_named(&p, "wc"), basin = object_named(&p, "basin");
    int kw = fixture_of(fx, n, wc), kb = fixture_of(fx, n, basin);
    CHECK(kw >= 0 && kb >= 0);
    if (kw >= 0 && kb >= 0) {
        double wc_right = fx[kw].centre[0] + fx[kw].half[0];
        app_pose in = {wc_right + 300 + fx[kb].half[0], 0, 680, 0};
        app_snap_preview s;
        app_snap_preview_of(&p, fx, n, kb, in, &s);
        CHECK_MSG(s.wall == 0 && s.neighbour == wc, "wall %d neighbour %d", s.wall, s.neighbour);
        CHECK_NEAR(s.pose.x, wc_right + 200 + fx[kb].half[0], 1e-6);
        CHECK(s.sides[APP_SNAP_LEFT].found);
        CHECK_NEAR(s.sides[APP_SNAP_LEFT].mm, 200, 1e-6);
        CHECK(guides_of(&s, APP_SNAP_GUIDE_NEIGHBOUR) == 1);
        for (int g = 0; g < s.guide_count; g++)
            if (s.guides[g].kind == APP_SNAP_GUIDE_NEIGHBOUR) {
                CHECK_NEAR(s.guides[g].a[0], wc_right, 1e-6);
                CHECK_NEAR(s.guides[g].b[0], wc_right, 1e-6);
            }
    }
    free(fx);
    app_history_destroy(h);
    app_project_free_all(&p);
}

int main(void)
{
    neighbour_case();
    app_snap_preview s;
    double at[3], rot;

    /* The vanity (on wall 1, x = 2600, facing -x) dragged 50 mm off its wall and 170 mm short
     * of the corner with wall 2 (y = 3200): back onto the wall, slid into the corner. */
    preview_and_edit("vanity", 2550, 2850, &s, at, &rot);
    CHECK_MSG(s.wall == 1, "wall %d", s.wall);
    CHECK(s.corner == 1);
    CHECK_NEAR(s.pose.x, at[0], 1e-6);
    CHECK_NEAR(s.pose.y, at[1], 1e-6);
    CHECK_NEAR(s.pose.rotation_deg, rot, 1e-6);
    CHECK_NEAR(s.pose.x, 2600, 1e-6);
    double width = 2 * s.half[0], depth = 2 * s.half[1];
    CHECK(width > 300 && depth > 300);
    CHECK_NEAR(s.pose.y, 3200 - width / 2, 1e-6);
    /* Its right side (local +x = +y) touches wall 2, its left faces wall 0 across the room. */
    CHECK(s.sides[APP_SNAP_RIGHT].found && s.sides[APP_SNAP_LEFT].found);
    CHECK_NEAR(s.sides[APP_SNAP_RIGHT].mm, 0, 1e-6);
    CHECK_NEAR(s.sides[APP_SNAP_LEFT].mm, 3200 - width, 1e-6);
    CHECK_NEAR(s.sides[APP_SNAP_LEFT].b[1], 0, 1e-6);
    /* The front looks across the room (-x) to the towel radiator on wall 3: less than the
     * room's width minus its own depth, ending left of the vanity's front. */
    CHECK(s.sides[APP_SNAP_FRONT].found);
    CHECK(s.sides[APP_SNAP_FRONT].mm > 0 && s.sides[APP_SNAP_FRONT].mm <= 2600 - depth + 1e-6);
    CHECK_NEAR(s.sides[APP_SNAP_FRONT].a[0], 2600 - depth, 1e-6);
    /* Guides: wall 1's face from corner to corner, and the side on wall 2. */
    CHECK(guides_of(&s, APP_SNAP_GUIDE_WALL) == 1 && guides_of(&s, APP_SNAP_GUIDE_CORNER) == 1);
    CHECK_NEAR(s.guides[0].a[0], 2600, 1e-6);
    CHECK_NEAR(fabs(s.guides[0].b[1] - s.guides[0].a[1]), 3200, 1e-6);
    CHECK_NEAR(s.guides[1].a[1], 3200, 1e-6);
    CHECK_NEAR(s.guides[1].b[1], 3200, 1e-6);

    /* Along its wall in the middle: on the wall, no corner, the sides sum to the wall. */
    preview_and_edit("vanity", 2590, 1500, &s, at, &rot);
    CHECK(s.wall == 1 && !s.corner && s.neighbour < 0);
    CHECK_NEAR(s.pose.x, at[0], 1e-6);
    CHECK_NEAR(s.pose.y, at[1], 1e-6);
    CHECK_NEAR(s.sides[APP_SNAP_LEFT].mm + s.sides[APP_SNAP_RIGHT].mm + width, 3200, 1e-6);
    CHECK_NEAR(s.sides[APP_SNAP_LEFT].mm, 1500 - width / 2, 1e-6);
    CHECK(guides_of(&s, APP_SNAP_GUIDE_WALL) == 1 && s.guide_count == 1);

    /* In the middle of the room: no wall within 500 mm, it goes where it is dropped. */
    preview_and_edit("vanity", 1300, 1700, &s, at, &rot);
    CHECK(s.wall == -1 && s.guide_count == 0);
    CHECK_NEAR(s.pose.x, 1300, 1e-9);
    CHECK_NEAR(s.pose.y, 1700, 1e-9);
    CHECK_NEAR(s.pose.rotation_deg, rot, 1e-9);
    return check_report("snap_guides");
}
