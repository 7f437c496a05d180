/* The planner's panel layout (ui/src/panel_layout.h) and the Selection panel's probe policy
 * lines (ui/src/probe_props.h), without a window.
 * Layout: at 640x360 .. 2560x1440, with both panes or one, the menu bar, toolbar, status bar,
 * the two panel columns, the panes and the splitter do not overlap, stay inside the window and
 * cover it; from 1024 wide plan and 3D fit side by side; the splitter follows a drag within
 * its limits; the catalog's list keeps three rows.
 * Probe lines: each combo choice's line runs through app's script as one undo step and sets
 * exactly that field of the demo's basin material (which the basin shares with nobody else
 * here, and every object sharing it would follow); undo restores the document. */
#include "app/project/commands.h"
#include "check.h"
#include "panel_layout.h"
#include "grain_props.h"
#include "probe_props.h"

#include <stdio.h>
#include <string.h>

static int inside(ui_rect r, int w, int h)
{
    return r.x >= 0 && r.y >= 0 && r.x + r.w <= w + 0.5f && r.y + r.h <= h + 0.5f;
}

/* The area of r, 0 for a hidden pane. */
static float area(ui_rect r)
{
    return r.w > 0 && r.h > 0 ? r.w * r.h : 0.0f;
}

static void test_layout(void)
{
    static const int sizes[][2] = {{640, 360},  {800, 450},   {1024, 600}, {1280, 720},
                                   {1366, 768}, {1920, 1080}, {2560, 1440}};
    static const char *const names[] = {"menu",  "toolbar", "status", "left",
                                        "right", "2d",      "3d",     "splitter"};
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++)
        for (int panes = 0; panes < 2; panes++)
            for (int active_2d = 0; active_2d < 2; active_2d++) {
                int w = sizes[s][0], h = sizes[s][1];
                ui_layout l;
                ui_layout_compute(w, h, panes, 0.5f, active_2d, &l);
                ui_rect r[8] = {l.menu,  l.toolbar, l.status,  l.left,
                                l.right, l.pane_2d, l.pane_3d, l.splitter};
                float total = 0;
                for (int i = 0; i < 8; i++) {
                    total += area(r[i]);
                    if (!area(r[i]))
                        continue;
                    CHECK_MSG(inside(r[i], w, h), "%dx%d: %s at %.0f,%.0f %.0fx%.0f", w, h,
                              names[i], r[i].x, r[i].y, r[i].w, r[i].h);
                    for (int k = i + 1; k < 8; k++)
                        CHECK_MSG(!area(r[k]) || !ui_rect_overlap(r[i], r[k]),
                                  "%dx%d panes %d: %s overlaps %s", w, h, panes, names[i],
                                  names[k]);
                }
                /* Nothing left uncovered: the window is exactly its parts. */
                CHECK_MSG(total == (float)w * (float)h, "%dx%d: the parts cover %.0f of %.0f px", w,
                          h, total, (float)w * (float)h);
                /* From 1024 wide, the plan and the 3D view fit side by side, each at least
                 * UI_LAYOUT_MIN_PANE_W; alone, the active one takes the whole centre. */
                int both = panes == UI_PANES_BOTH && w >= 1024;
                CHECK_MSG(!both || (l.pane_2d.w >= UI_LAYOUT_MIN_PANE_W &&
                                    l.pane_3d.w >= UI_LAYOUT_MIN_PANE_W && l.splitter.w > 0),
                          "%dx%d: side by side %.0f | %.0f", w, h, l.pane_2d.w, l.pane_3d.w);
                if (!both && panes == UI_PANES_ONE) {
                    ui_rect shown = active_2d ? l.pane_2d : l.pane_3d;
                    ui_rect hidden = active_2d ? l.pane_3d : l.pane_2d;
                    CHECK(!memcmp(&shown, &l.centre, sizeof shown) && !area(hidden));
                }
                CHECK_MSG(l.catalog_list_h >= 3 * 44.0f, "%dx%d: list %.0f", w, h,
                          l.catalog_list_h);
                CHECK(l.left.w >= 220 && l.right.w >= 250);
            }
    /* The splitter follows a drag and stops where a pane would get too narrow. */
    ui_layout l;
    ui_layout_compute(1280, 720, UI_PANES_BOTH, 0.5f, 0, &l);
    float s = ui_layout_split_at(&l, l.centre.x + 400);
    ui_layout_compute(1280, 720, UI_PANES_BOTH, s, 0, &l);
    CHECK_MSG(l.splitter.x + l.splitter.w / 2 > l.centre.x + 399 &&
                  l.splitter.x + l.splitter.w / 2 < l.centre.x + 401,
              "splitter at %.1f", l.splitter.x);
    ui_layout_compute(1280, 720, UI_PANES_BOTH, ui_layout_split_at(&l, 0), 0, &l);
    CHECK(l.pane_2d.w == UI_LAYOUT_MIN_PANE_W);
    ui_layout_compute(1280, 720, UI_PANES_BOTH, ui_layout_split_at(&l, 5000), 0, &l);
    CHECK(l.pane_3d.w >= UI_LAYOUT_MIN_PANE_W && l.pane_3d.w < UI_LAYOUT_MIN_PANE_W + 1);
    /* 800 x 450 (the sessions' size) is too narrow for two panes: the active view alone. */
    ui_layout_compute(800, 450, UI_PANES_BOTH, 0.5f, 1, &l);
    CHECK(area(l.pane_2d) > 0 && !area(l.pane_3d) && l.edit_narrow);
    CHECK(ui_rect_overlap((ui_rect){0, 0, 10, 10}, (ui_rect){5, 5, 10, 10}));
    CHECK(!ui_rect_overlap((ui_rect){0, 0, 10, 10}, (ui_rect){10, 0, 10, 10}));
    CHECK(ui_rect_contains((ui_rect){0, 0, 10, 10}, 0, 9.5) &&
          !ui_rect_contains((ui_rect){0, 0, 10, 10}, 10, 5));
}

static void run_line(app_project *p, app_history *h, const char *line)
{
    char err[1024];
    int undo = app_history_undo_count(h);
    app_script_env env = {NULL, NULL, NULL, NULL};
    CHECK_MSG(app_script_run(p, h, line, strlen(line), "panel", &env, NULL, err, sizeof err) ==
                  APP_OK,
              "%s: %s", line, err);
    CHECK_MSG(app_history_undo_count(h) == undo + 1, "%s", line);
}

static void test_probe_lines(void)
{
    app_project p, original;
    char err[1024], diff[512], line[256];
    CHECK_MSG(app_project_read(TESSERA_SOURCE_DIR "/assets/projects/designed-bathroom.json", &p,
                               err, sizeof err) == APP_OK,
              "%s", err);
    CHECK(app_project_copy(&original, &p, err, sizeof err) == APP_OK);
    int m = app_project_find_material(&p, "Cerana CE410401 WH");
    CHECK(m >= 0);
    if (m < 0)
        return;
    app_history *h = app_history_create(0);
    /* The expect-probe script check. */
    char why[512];
    CHECK(ui_probe_expect(&p, "\"Cerana CE410401 WH\" default", why, sizeof why) == 0);
    CHECK(ui_probe_expect(&p, "Cerana CE410401 WH default", why, sizeof why) == 0);
    CHECK(ui_probe_expect(&p, "\"Cerana CE410401 WH\" once", why, sizeof why) == 1 &&
          strstr(why, "updates default, expected once"));
    CHECK(ui_probe_expect(&p, "\"Cerana CE410401 WH\" weekly", why, sizeof why) == 1 &&
          strstr(why, "weekly is not"));
    CHECK(ui_probe_expect(&p, "\"chrome\" once", why, sizeof why) == 1 &&
          strstr(why, "no material named \"chrome\""));
    CHECK(ui_probe_expect(&p, "once", why, sizeof why) == 1);
    /* Every update choice but static (the demo has no prepared map). */
    for (int u = 0; u < 5; u++) {
        CHECK(!ui_probe_line(line, sizeof line, p.materials[m].name, UI_PROBE_UPDATE, u));
        run_line(&p, h, line);
        CHECK_MSG(p.materials[m].probe_update == u, "%s", ui_probe_update_labels[u]);
        static const char *const words[5] = {"default", "every-frame", "once", "on-change",
                                             "time-sliced"};
        char text[128];
        snprintf(text, sizeof text, "\"%s\" %s", p.materials[m].name, words[u]);
        CHECK_MSG(ui_probe_expect(&p, text, why, sizeof why) == 0, "%s", why);
    }
    CHECK(!ui_probe_line(line, sizeof line, p.materials[m].name, UI_PROBE_EVERY, 6));
    run_line(&p, h, line);
    CHECK(p.materials[m].probe_update == APP_PROBE_EVERY_FRAME && p.materials[m].probe_every == 6);
    /* The resolution combo: its items and the texels they stand for. */
    const char *items[6];
    char other[16];
    int current;
    CHECK(ui_probe_resolution_items(0, items, other, &current) == 5 && current == 0 &&
          !strcmp(items[2], "128"));
    CHECK(ui_probe_resolution_items(1024, items, other, &current) == 6 && current == 5 &&
          !strcmp(items[5], "1024") && ui_probe_resolution_of(5, 1024) == 1024);
    for (int k = 4; k >= 0; k--) {
        int res = ui_probe_resolution_of(k, 0);
        CHECK(!ui_probe_line(line, sizeof line, p.materials[m].name, UI_PROBE_RESOLUTION, res));
        run_line(&p, h, line);
        CHECK(p.materials[m].probe_resolution == res);
        ui_probe_resolution_items(p.materials[m].probe_resolution, items, other, &current);
        CHECK(current == k);
    }
    for (int c = 4; c >= 0; c--) {
        CHECK(!ui_probe_line(line, sizeof line, p.materials[m].name, UI_PROBE_CORRECTION, c));
        run_line(&p, h, line);
        CHECK_MSG(p.materials[m].correction == c, "%s", ui_probe_correction_labels[c]);
    }
    /* Static without a map is refused by the command, with the reason. */
    CHECK(!ui_probe_line(line, sizeof line, p.materials[m].name, UI_PROBE_UPDATE, 5));
    app_script_env env = {NULL, NULL, NULL, NULL};
    CHECK(app_script_run(&p, h, line, strlen(line), "panel", &env, NULL, err, sizeof err) !=
              APP_OK &&
          strstr(err, "prepared map"));
    /* A line that does not fit is reported, not cut. */
    char tiny[16];
    CHECK(ui_probe_line(tiny, sizeof tiny, p.materials[m].name, UI_PROBE_UPDATE, 1) == 1);
    /* The wood grain combo: its items, and each line turns the material's grain. */
    const char *grains[4];
    char grain_other[32];
    int shown;
    CHECK(ui_grain_items(APP_PATTERN_NONE, 0.0f, grains, grain_other, &shown) == 3 &&
          shown == UI_GRAIN_NONE);
    CHECK(ui_grain_items(APP_PATTERN_WOOD, 30.0f, grains, grain_other, &shown) == 4 &&
          shown == UI_GRAIN_OTHER && !strcmp(grains[3], "wood, 30 degrees"));
    for (int k = UI_GRAIN_VERTICAL; k >= UI_GRAIN_NONE; k--) {
        CHECK(!ui_grain_line(line, sizeof line, p.materials[m].name, k));
        run_line(&p, h, line);
        ui_grain_items(p.materials[m].pattern, p.materials[m].grain_deg, grains, grain_other,
                       &shown);
        CHECK_MSG(shown == k, "%s shows item %d", line, shown);
    }
    CHECK(ui_grain_line(line, sizeof line, p.materials[m].name, UI_GRAIN_OTHER) == 1);
    /* Undoing every step gives the demo back exactly. */
    while (app_history_undo_count(h) > 0)
        CHECK(app_history_undo(h, &p, err, sizeof err) == APP_OK);
    CHECK_MSG(app_project_equal(&original, &p, diff, sizeof diff), "%s", diff);
    app_history_destroy(h);
    app_project_free_all(&original);
    app_project_free_all(&p);
}

int main(void)
{
    test_layout();
    test_probe_lines();
    return check_report("ui.panel_layout");
}
