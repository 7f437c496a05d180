/* The planner's panel layout (ui/src/panel_layout.h) and the Selection panel's probe policy
 * lines (ui/src/probe_props.h), without a window.
 * Layout: at 640x360 .. 1920x1080, with and without a selection, the panels that show together
 * in the 3D view (View, Selection, Project, Edit, Catalog, Quantities, the frame-time overlay)
 * and the plan view's Tiles panel do not overlap and stay inside the window; small windows
 * start with Project and Quantities collapsed; the catalog's list keeps three rows.
 * Probe lines: each combo choice's line runs through app's script as one undo step and sets
 * exactly that field of the demo's basin material (which the basin shares with nobody else
 * here, and every object sharing it would follow); undo restores the document. */
#include "app/project/commands.h"
#include "check.h"
#include "panel_layout.h"
#include "probe_props.h"

#include <stdio.h>
#include <string.h>

static int inside(ui_rect r, int w, int h)
{
    return r.x >= 0 && r.y >= 0 && r.x + r.w <= w + 0.5f && r.y + r.h <= h + 0.5f && r.w >= 60 &&
           r.h >= UI_LAYOUT_TITLE_H;
}

static void test_layout(void)
{
    static const int sizes[][2] = {{640, 360},  {800, 450},  {1024, 600},
                                   {1280, 720}, {1366, 768}, {1920, 1080}};
    static const char *const names[] = {"view",    "selection",  "project", "edit",
                                        "catalog", "quantities", "overlay", "tiles"};
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++)
        for (int sel = 0; sel < 2; sel++) {
            int w = sizes[s][0], h = sizes[s][1];
            ui_layout l;
            ui_layout_compute(w, h, sel, &l);
            ui_rect r[8] = {l.view,    l.selection,  l.project, l.edit,
                            l.catalog, l.quantities, l.overlay, l.tiles};
            for (int i = 0; i < 8; i++) {
                if (i == 1 && !sel)
                    continue;
                CHECK_MSG(inside(r[i], w, h), "%dx%d sel %d: %s at %.0f,%.0f %.0fx%.0f", w, h, sel,
                          names[i], r[i].x, r[i].y, r[i].w, r[i].h);
                for (int k = i + 1; k < 8; k++) {
                    if (k == 1 && !sel)
                        continue;
                    CHECK_MSG(!ui_rect_overlap(r[i], r[k]), "%dx%d sel %d: %s overlaps %s", w, h,
                              sel, names[i], names[k]);
                }
            }
            CHECK_MSG(l.catalog_list_h >= 3 * 44.0f, "%dx%d: list %.0f", w, h, l.catalog_list_h);
            CHECK(l.quantities_collapsed == (h < UI_LAYOUT_TALL));
            CHECK(l.project_collapsed == (h < UI_LAYOUT_TALL || sel));
            /* The collapsed panels take their title bar only, at the window's bottom. */
            if (l.quantities_collapsed)
                CHECK(l.quantities.h == UI_LAYOUT_TITLE_H);
            if (sel)
                CHECK_MSG(l.selection.h >= (h < UI_LAYOUT_TALL ? 180.0f : 390.0f),
                          "%dx%d: selection %.0f tall", w, h, l.selection.h);
        }
    /* The two sizes the tests run at. */
    ui_layout small, big;
    ui_layout_compute(800, 450, 1, &small);
    ui_layout_compute(1280, 720, 0, &big);
    CHECK(small.edit_narrow && !big.edit_narrow);
    CHECK(!big.project_collapsed && !big.quantities_collapsed && big.view.h == 250.0f);
    CHECK(ui_rect_overlap((ui_rect){0, 0, 10, 10}, (ui_rect){5, 5, 10, 10}));
    CHECK(!ui_rect_overlap((ui_rect){0, 0, 10, 10}, (ui_rect){10, 0, 10, 10}));
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
