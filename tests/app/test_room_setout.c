/* The set-out of a room (app_room_setout_tilings, docs/tiling.md "Set-out of a room") on
 * tests/data/tiles/setout_room.json: a 2450 x 1750 room, walls in 300 x 600 stack bond (a 600 x
 * 300 grid cell with the 3 mm joint), the floor in 600 x 600, all "setout": "room". The corners
 * lie at 2450, 4200, 6650 and 8400 mm along the unfolded walls, 50, 0, 50 and 0 mm past a
 * multiple of 600: a joint phase phi in [249, 401] keeps both pieces at every corner over 199 mm
 * (a third of 597), and the floor's rows along y (phi - 50 past its own) narrow it to about
 * [254, 398]. Checked from
 * the layouts the quantities count: every wall's grid has the same phase along the unfolded
 * walls (a vertical joint turns each corner: the piece ending one wall and the piece starting the
 * next make one cell) and the same row height; the floor's joints lie on the walls' vertical
 * joints; no cut under the minimum. The same room set out wall by wall breaks the first rule. */
#include "app/design/quantities.h"
#include "app/design/room_surfaces.h"
#include "test_util.h"

#include <math.h>
#include <stdlib.h>

#define DATA TESSERA_SOURCE_DIR "/tests/data/tiles"

/* a mod m in [0, m) */
static double wrap(double a, double m)
{
    double r = fmod(a, m);
    return r < 0 ? r + m : r;
}

/* Distance of two phases on a circle of length m. */
static double phase_gap(double a, double b, double m)
{
    double d = wrap(a - b, m);
    return fmin(d, m - d);
}

static int layouts_of(app_project *p, cat_db *db, app_tile_layout **l, int *n)
{
    char err[1024];
    app_result r = app_room_tile_layouts(p, db, l, n, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    return r == APP_OK && *n == 5;
}

int main(void)
{
    char err[1024] = "", dir[] = "/tmp/tessera-room-setout-XXXXXX", path[512];
    CHECK(mkdtemp(dir) != NULL);
    snprintf(path, sizeof path, "%s/catalog.sqlite", dir);
    cat_db *db = NULL;
    CHECK_MSG(cat_catalog_open(path, TESSERA_SOURCE_DIR "/assets/catalog", &db, err, sizeof err) ==
                  CAT_DB_OK,
              "%s", err);
    app_project p;
    if (!db || app_project_read(DATA "/setout_room.json", &p, err, sizeof err) != APP_OK) {
        CHECK_MSG(0, "%s", err);
        return check_report("room_setout");
    }
    /* the walls unfolded: wall I starts at P_I along the strip */
    const double P[4] = {0, 2450, 4200, 6650}, W = 600, ROWS = 300;
    app_tile_layout *l = NULL;
    int n = 0;
    if (layouts_of(&p, db, &l, &n)) {
        for (int i = 0; i < 4; i++) {
            CHECK_MSG(phase_gap(l[i].origin.x + P[i], l[0].origin.x, W) < 1e-6,
                      "wall %d: joint phase %.3f against %.3f", i, wrap(l[i].origin.x + P[i], W),
                      wrap(l[0].origin.x, W));
            CHECK_MSG(phase_gap(l[i].origin.y, l[0].origin.y, ROWS) < 1e-6, "wall %d rows", i);
            CHECK_MSG(app_tile_layout_worst_cut(&l[i], &p.tilings[i], NULL, NULL, NULL) >= 1.0,
                      "wall %d keeps the minimum cut", i);
        }
        /* the floor's x joints on wall 0's (along +x from (0, 0)), its y joints on wall 1's
         * (along +y from (2450, 0)) */
        CHECK(phase_gap(l[4].origin.x, l[0].origin.x, W) < 1e-6);
        CHECK(phase_gap(l[4].origin.y, l[1].origin.x, W) < 1e-6);
        CHECK(app_tile_layout_worst_cut(&l[4], &p.tilings[4], NULL, NULL, NULL) >= 1.0);
        double phi = wrap(l[0].origin.x, W);
        CHECK_MSG(phi >= 249 && phi <= 401, "phi %.1f", phi);
        app_tile_layouts_free(l, n);
    }
    /* set out wall by wall, the walls' phases differ: the test above can fail */
    for (int i = 0; i < p.tiling_count; i++)
        p.tilings[i].setout_room = 0;
    if (layouts_of(&p, db, &l, &n)) {
        int differ = 0;
        for (int i = 1; i < 4; i++)
            differ |= phase_gap(l[i].origin.x + P[i], l[0].origin.x, W) > 1;
        CHECK_MSG(differ, "the walls set out alone happen to line up");
        app_tile_layouts_free(l, n);
    }
    app_project_free(&p);
    cat_db_close(db);
    return check_report("room_setout");
}
