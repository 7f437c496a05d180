/* The tile panel's edits and script actions without a window (ui/src/tiles.h): on the shipped
 * demo (its tilings read from the real catalog), each edit is one undo step that changes just
 * what it says; a click on the elevation snaps the start point; a second tiling on a surface
 * is addressed by its name, not the first's; refused edits change nothing; the layouts the
 * elevation draws follow the document; the script actions run and fail as documented; undoing
 * everything gives the document back exactly. */
#include "check.h"
#include "tiles.h"

#include "app/project/commands.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static ui_action action(ui_action_kind kind, const char *text, double a)
{
    ui_action x;
    memset(&x, 0, sizeof x);
    x.kind = kind;
    x.a = a;
    x.frames = 1;
    snprintf(x.text, sizeof x.text, "%s", text);
    return x;
}

int main(void)
{
    /* A catalog of its own, built from the shipped data on first use. */
    char dir[] = "/tmp/tessera-tile-actions-XXXXXX", db[128];
    CHECK(mkdtemp(dir) != NULL);
    snprintf(db, sizeof db, "%s/catalog.sqlite", dir);
    setenv("TESSERA_CATALOG", db, 1);

    static planner p; /* large: not on the stack */
    memset(&p, 0, sizeof p);
    p.plan_o.selected_object = p.plan_o.selected_wall = -1;
    char err[1024], diff[512];
    CHECK_MSG(app_project_read(TESSERA_SOURCE_DIR "/assets/projects/designed-bathroom.json",
                               &p.project, err, sizeof err) == APP_OK,
              "%s", err);
    CHECK(planner_doc_open(&p) == 0);
    app_project original;
    CHECK(app_project_copy(&original, &p.project, err, sizeof err) == APP_OK);

    int w1 = ui_tiles_find(&p.project, "wall:1");
    CHECK(w1 >= 0 && ui_tiles_find(&p.project, "wall-1") == w1);
    CHECK(ui_tiles_find(&p.project, "wall:9") == -1);
    if (w1 < 0)
        return check_report("ui_tile_actions");
    const app_tiling *g = &p.project.tilings[w1];

    /* Each edit: one undo step, the field changed. */
    int steps = app_history_undo_count(p.history);
    CHECK(planner_tile_pattern(&p, w1, APP_PATTERN_HERRINGBONE) == 0);
    g = &p.project.tilings[w1];
    CHECK(g->pattern == APP_PATTERN_HERRINGBONE);
    CHECK(app_history_undo_count(p.history) == ++steps);
    float rgb[3] = {0.2f, 0.3f, 0.4f};
    CHECK(planner_tile_grout(&p, w1, 4.5, rgb) == 0);
    g = &p.project.tilings[w1];
    CHECK(g->grout_mm == 4.5 && fabsf(g->grout_color[0] - 0.2f) < 1e-6f &&
          fabsf(g->grout_color[2] - 0.4f) < 1e-6f);
    CHECK(planner_tile_start(&p, w1, APP_ALIGN_LINE, 123.4, 56.7) == 0);
    g = &p.project.tilings[w1];
    CHECK(g->align == APP_ALIGN_LINE && fabs(g->origin_mm[0] - 123.4) < 1e-9 &&
          fabs(g->origin_mm[1] - 56.7) < 1e-9);
    CHECK(planner_tile_rotation(&p, w1, 30) == 0 && p.project.tilings[w1].rotation_deg == 30);
    CHECK(planner_tile_band(&p, w1, 100, 2000) == 0);
    g = &p.project.tilings[w1];
    CHECK(g->from_mm == 100 && g->to_mm == 2000);
    CHECK(app_history_undo_count(p.history) == steps + 4);
    steps += 4;

    /* Border rows: the demo's row at 1200, one added, moved, the first removed. */
    int rows = g->border_count;
    app_product_ref border = {"Fliesenwerk Altena", "FA-10131", "GL"};
    CHECK(planner_tile_border_add(&p, w1, &border, 600) == 0);
    g = &p.project.tilings[w1];
    CHECK(g->border_count == rows + 1 && !strcmp(g->borders[rows].product.article, "FA-10131"));
    CHECK(planner_tile_border_move(&p, w1, rows, 700) == 0);
    CHECK(p.project.tilings[w1].borders[rows].bottom_mm == 700);
    CHECK(planner_tile_border_remove(&p, w1, 0) == 0);
    g = &p.project.tilings[w1];
    CHECK(g->border_count == rows && g->borders[rows - 1].bottom_mm == 700);
    CHECK(app_history_undo_count(p.history) == steps + 3);
    steps += 3;

    /* Refused: nothing changes, no step. */
    app_project before;
    CHECK(app_project_copy(&before, &p.project, err, sizeof err) == APP_OK);
    CHECK(planner_tile_band(&p, w1, 2000, 100) == 1);
    CHECK(strstr(p.status, "band") != NULL);
    CHECK(planner_tile_grout(&p, w1, 500, rgb) == 1);
    CHECK(planner_tile_border_remove(&p, w1, 7) == 1);
    CHECK(planner_tile_pattern(&p, p.project.tiling_count + 3, APP_PATTERN_DIAGONAL) == 1);
    CHECK_MSG(app_project_equal(&before, &p.project, diff, sizeof diff), "%s", diff);
    CHECK(app_history_undo_count(p.history) == steps);
    app_project_free_all(&before);

    /* A click on the elevation: the shown surface's tiling starts at the point, 10 mm grid. */
    ui_tiles_show(&p, "wall:1");
    CHECK(planner_elevation_click(&p, 1004.2, 796.9) == 0);
    g = &p.project.tilings[w1];
    CHECK(g->align == APP_ALIGN_LINE && g->origin_mm[0] == 1000 && g->origin_mm[1] == 800);
    steps++;

    /* The layouts the elevation draws: one per tiling, recomputed after an edit (a diagonal
     * lattice is turned 45 degrees), the shown surface's region and frame. */
    ui_tiles *t = planner_tiles(&p);
    CHECK(t && ui_tiles_refresh(&p, t) == 0);
    if (t) {
        CHECK_MSG(t->layout_count == p.project.tiling_count && t->region_ok, "%s", t->error);
        CHECK(t->layout_count > w1 && t->layouts[w1].tile_count > 20);
        CHECK(t->surface_count >= 6 && t->frame.kind == APP_SURFACE_WALL);
        unsigned long long h = t->hash;
        CHECK(planner_tile_pattern(&p, w1, APP_PATTERN_DIAGONAL) == 0);
        steps++;
        CHECK(ui_tiles_refresh(&p, t) == 0 && t->hash != h);
        CHECK(t->layout_count > w1 && fabs(fmod(t->layouts[w1].angle_deg - 30, 90) - 45) < 1e-6);
        printf("layouts of %d tilings: %.1f ms\n", t->layout_count, t->refresh_ms);
    }

    /* A second tiling on wall 1 (above the first's band): edits reach it by its name. */
    app_command_desc d;
    memset(&d, 0, sizeof d);
    d.type = APP_CMD_SET_TILING;
    d.index = -1;
    d.tiling = p.project.tilings[w1];
    snprintf(d.tiling.name, sizeof d.tiling.name, "wall-1-top");
    d.tiling.from_mm = 2000;
    d.tiling.to_mm = 0;
    d.tiling.border_count = 0;
    CHECK_MSG(app_history_do(p.history, &p.project, &d, err, sizeof err) == APP_OK, "%s", err);
    steps++;
    int top = ui_tiles_on_surface(&p.project, "wall:1", 1);
    CHECK(top == p.project.tiling_count - 1 && ui_tiles_on_surface(&p.project, "wall:1", 0) == w1);
    CHECK(planner_tile_pattern(&p, top, APP_PATTERN_THIRD_OFFSET) == 0);
    steps++;
    CHECK(p.project.tilings[top].pattern == APP_PATTERN_THIRD_OFFSET);
    CHECK(p.project.tilings[w1].pattern == APP_PATTERN_DIAGONAL);

    /* Script actions. */
    ui_action a = action(UI_ACT_TILE_GROUT, "wall:1 6 0.5 0.5 0.5", 0);
    CHECK(planner_tile_action(&p, &a) == 0 && p.project.tilings[w1].grout_mm == 6 &&
          p.project.tilings[w1].grout_color[1] == 0.5f);
    a = action(UI_ACT_TILE_GROUT, "floor 2", 0); /* the colour kept */
    int fl = ui_tiles_find(&p.project, "floor");
    float floor_rgb = fl >= 0 ? p.project.tilings[fl].grout_color[0] : -1;
    CHECK(planner_tile_action(&p, &a) == 0 && fl >= 0 && p.project.tilings[fl].grout_mm == 2 &&
          p.project.tilings[fl].grout_color[0] == floor_rgb);
    a = action(UI_ACT_TILE_START, "floor corner", 0);
    CHECK(planner_tile_action(&p, &a) == 0 && p.project.tilings[fl].align == APP_ALIGN_CORNER);
    a = action(UI_ACT_TILE_START, "floor 250 -40", 0);
    CHECK(planner_tile_action(&p, &a) == 0 && p.project.tilings[fl].origin_mm[1] == -40);
    a = action(UI_ACT_EXPECT_PATTERN, "wall:1 diagonal", 0);
    CHECK(planner_tile_action(&p, &a) == 0);
    a = action(UI_ACT_EXPECT_PATTERN, "wall-1-top third-offset", 0);
    CHECK(planner_tile_action(&p, &a) == 0);
    a = action(UI_ACT_EXPECT_PATTERN, "wall:1 straight", 0);
    CHECK(planner_tile_action(&p, &a) == 1 && strstr(p.status, "expected straight"));
    a = action(UI_ACT_TILE_PATTERN, "wall:9 straight", 0);
    CHECK(planner_tile_action(&p, &a) == 1 && strstr(p.status, "no tiling"));
    a = action(UI_ACT_EXPECT_TILES, "wall:1 20", 0);
    CHECK(planner_tile_action(&p, &a) == 0);
    a = action(UI_ACT_EXPECT_TILES, "wall:1 100000", 0);
    CHECK(planner_tile_action(&p, &a) == 1);
    a = action(UI_ACT_ELEVATION_WALL, "", 9);
    CHECK(planner_tile_action(&p, &a) == 1 && strstr(p.status, "no wall 9"));
    a = action(UI_ACT_ELEVATION_WALL, "", 2);
    CHECK(planner_tile_action(&p, &a) == 0 && p.view == UI_VIEW_ELEVATION && t &&
          !strcmp(t->surface, "wall:2"));
    a = action(UI_ACT_TILE_SURFACE, "prewall:wc-wall:front", 0);
    CHECK(planner_tile_action(&p, &a) == 0 && t && t->region_ok &&
          t->frame.kind == APP_SURFACE_PREWALL_SIDE);
    a = action(UI_ACT_TILE_SURFACE, "wall:77", 0);
    CHECK(planner_tile_action(&p, &a) == 1 && strstr(p.status, "no surface") && t &&
          !strcmp(t->surface, "prewall:wc-wall:front"));
    a = action(UI_ACT_TILE_PANEL, "on", 0);
    CHECK(planner_tile_action(&p, &a) == 0 && t && t->in_3d);
    a = action(UI_ACT_TILE_BORDER, "wall:1 900", 0); /* no tile selected in the browser */
    CHECK(planner_tile_action(&p, &a) == 1 && strstr(p.status, "select a tile"));
    steps += 4;

    /* In the plan, a wall picked shows it in the panel once; picking another surface in the
     * panel then sticks until another wall is picked (no widgets without Dear ImGui: the
     * panel's state alone). */
    p.view = UI_VIEW_PLAN;
    p.plan_o.selected_wall = 3;
    planner_tile_panel(&p, 1280, 720);
    CHECK(t && !strcmp(t->surface, "wall:3") && t->plan_wall == 3);
    ui_tiles_show(&p, "floor");
    planner_tile_panel(&p, 1280, 720);
    CHECK(t && !strcmp(t->surface, "floor"));
    p.plan_o.selected_wall = 0;
    planner_tile_panel(&p, 1280, 720);
    CHECK(t && !strcmp(t->surface, "wall:0"));
    ui_tiles_show(&p, "prewall:wc-wall:front");

    /* The surface shown goes away (its pre-wall removed): the panel shows the first wall. */
    CHECK(planner_edit(&p, "remove-prewall wc-wall") == 0);
    steps++;
    CHECK(t && ui_tiles_refresh(&p, t) == 0 && !strcmp(t->surface, "wall:0") && t->region_ok);

    /* Undo everything: the document as read. */
    CHECK(app_history_undo_count(p.history) == steps);
    while (app_history_undo_count(p.history) > 0)
        CHECK(planner_undo(&p, 0) == 0);
    CHECK_MSG(app_project_equal(&original, &p.project, diff, sizeof diff), "%s", diff);

    planner_tiles_free(&p);
    planner_doc_close(&p);
    app_project_free_all(&original);
    app_project_free_all(&p.project);
    unlink(db);
    rmdir(dir);
    return check_report("ui_tile_actions");
}
