/* The window's menu bar: File, Edit, View, Insert, Render, Help. Every keyboard shortcut of
 * the window (planner_input.c) is also an entry here that shows its key, so nothing hides
 * behind a key; Help lists them all (docs/ui.md has the same table). */
#include "planner.h"
#include "planner_actions.h"

#include "app/project/commands.h"
#include "gui.h"

#include <GLFW/glfw3.h>
#include <stdio.h>

/* The shortcuts, as Help > Keyboard shortcuts lists them. */
static const char *const shortcuts[][2] = {
    {"Ctrl+S", "File > Save"},
    {"F12", "File / Render > Print-quality screenshot"},
    {"Ctrl+Z", "Edit > Undo"},
    {"Ctrl+Y, Ctrl+Shift+Z", "Edit > Redo"},
    {"Delete", "Edit > Delete the selected fixture"},
    {"Ctrl+R", "Edit > Rotate the selected fixture by 90 degrees"},
    {"V", "View > Switch plan / 3D"},
    {"Tab", "View > Walk (else orbit)"},
    {"F1 .. F9", "View > Viewpoints: fly to viewpoint 1 .. 9"},
    {"P", "View > Presentation (the panels hidden)"},
    {"T", "View > Tour through the viewpoints"},
    {"R", "View > Turntable"},
    {"F11", "View > Fullscreen"},
    {"1 2 3 4", "Render > Quality: draft, interactive, final, print"},
    {"W A S D", "walk forward, left, back, right (Shift: faster)"},
    {"left drag", "3D: orbit or look; on a fixture: move it; plan: corners, walls, fixtures"},
    {"right drag", "plan and elevation: pan"},
    {"wheel", "zoom the view under the pointer; scroll a panel"},
};

static int has_selection(const planner *p)
{
    return p->plan_o.selected_object >= 0 && p->plan_o.selected_object < p->project.object_count;
}

static int selected_wall(const planner *p)
{
    int w = p->plan_o.selected_wall;
    return w >= 0 && w < p->project.plan.corner_count ? w : -1;
}

static void recent_menu(planner *p)
{
    const ui_recent *recent = planner_recent_files(p);
    if (!ui_gui_begin_menu("Open recent", recent && recent->count > 0))
        return;
    for (int i = 0; recent && i < recent->count; i++) {
        char label[1100];
        snprintf(label, sizeof label, "%d %s##recent-menu%d", i + 1, recent->paths[i], i);
        if (ui_gui_menu_item(label, NULL, -1, 1))
            planner_action_open_recent(p, i + 1);
    }
    ui_gui_end_menu();
}

static void file_menu(planner *p)
{
    if (!ui_gui_begin_menu("File", 1))
        return;
    if (ui_gui_menu_item("New", NULL, -1, 1))
        planner_file_request(p, UI_FILE_NEW);
    if (ui_gui_menu_item("Open...", planner_action_shortcut("open"), -1, 1))
        planner_action_open_dialog(p);
    recent_menu(p);
    if (ui_gui_menu_item("Save", planner_action_shortcut("save"), -1, !p->read_only))
        planner_action_save(p);
    if (ui_gui_menu_item("Save as...", planner_action_shortcut("save-as"), -1, 1))
        planner_action_save_as(p);
    ui_gui_separator();
    if (ui_gui_menu_item("Print to PDF...", planner_action_shortcut("print-pdf"), -1, 1))
        planner_action_print_pdf(p);
    if (ui_gui_menu_item("Export GLB...", planner_action_shortcut("export-glb"), -1, 1))
        planner_action_export_glb(p);
    if (ui_gui_menu_item("Share folder...", NULL, -1, 1))
        planner_action_share(p);
    if (ui_gui_menu_item("Print-quality screenshot", "F12", -1, 1))
        planner_print_shot_now(p);
    ui_gui_separator();
    if (ui_gui_menu_item("Quit", NULL, -1, 1)) {
        if (p->dirty)
            p->close_requested = 1; /* the unsaved-changes question first */
        else
            p->quit = 1;
    }
    ui_gui_end_menu();
}

static void edit_menu(planner *p)
{
    if (!ui_gui_begin_menu("Edit", 1))
        return;
    const char *u = app_history_undo_label(p->history), *r = app_history_redo_label(p->history);
    char label[160];
    snprintf(label, sizeof label, "Undo %s##undo", u && *u ? u : "");
    if (ui_gui_menu_item(label, "Ctrl+Z", -1, u && *u))
        planner_undo(p, 0);
    snprintf(label, sizeof label, "Redo %s##redo", r && *r ? r : "");
    if (ui_gui_menu_item(label, "Ctrl+Y", -1, r && *r))
        planner_undo(p, 1);
    ui_gui_separator();
    if (ui_gui_menu_item("Delete the selected fixture", "Delete", -1, has_selection(p)))
        planner_delete_selected(p);
    if (ui_gui_menu_item("Rotate the selected fixture by 90 degrees", "Ctrl+R", -1,
                         has_selection(p)))
        planner_rotate_selected(p);
    ui_gui_end_menu();
}

static void viewpoints_menu(planner *p)
{
    if (!ui_gui_begin_menu("Viewpoints", p->project.camera_count > 0))
        return;
    for (int i = 0; i < p->project.camera_count; i++) {
        char key[16];
        snprintf(key, sizeof key, "F%d", i + 1);
        if (ui_gui_menu_item(p->project.cameras[i].name, i < 9 ? key : NULL, i == p->camera, 1))
            planner_fly_to_camera(p, i, 1.0);
    }
    ui_gui_end_menu();
}

static void view_menu(planner *p)
{
    if (!ui_gui_begin_menu("View", 1))
        return;
    int both = p->panes == UI_PANES_BOTH;
    if (ui_gui_menu_item("Plan and 3D side by side", NULL, both, 1))
        planner_show_panes(p, 1);
    if (ui_gui_menu_item("Plan only", NULL, !both && p->view == UI_VIEW_PLAN, 1)) {
        planner_show_panes(p, 0);
        p->view = UI_VIEW_PLAN;
    }
    if (ui_gui_menu_item("3D only", NULL, !both && p->view == UI_VIEW_3D, 1)) {
        planner_show_panes(p, 0);
        p->view = UI_VIEW_3D;
    }
    if (ui_gui_menu_item("Elevation of the tile panel's wall", NULL,
                         p->view_2d == UI_VIEW_ELEVATION, 1))
        p->view = UI_VIEW_ELEVATION;
    if (ui_gui_menu_item("Switch plan / 3D", "V", -1, 1))
        p->view = p->view == UI_VIEW_3D ? UI_VIEW_PLAN : UI_VIEW_3D;
    ui_gui_separator();
    if (ui_gui_menu_item("Walk (else orbit)", "Tab", p->mode == UI_MODE_WALK, 1))
        p->mode = p->mode == UI_MODE_ORBIT ? UI_MODE_WALK : UI_MODE_ORBIT;
    viewpoints_menu(p);
    ui_gui_separator();
    if (ui_gui_menu_item("Presentation", "P", p->presenting, 1))
        p->presenting = !p->presenting;
    if (ui_gui_menu_item("Tour", "T", p->touring, 1))
        planner_toggle_tour(p);
    if (ui_gui_menu_item("Turntable", "R", p->turntable, 1))
        p->turntable = !p->turntable;
    if (ui_gui_menu_item("Fullscreen", "F11", glfwGetWindowMonitor(p->window) != NULL, 1))
        planner_toggle_fullscreen(p);
    ui_gui_end_menu();
}

static void insert_menu(planner *p)
{
    if (!ui_gui_begin_menu("Insert", 1))
        return;
    int wall = selected_wall(p);
    static const char *const items[4] = {"Door in the selected wall", "Window in the selected wall",
                                         "Pre-wall at the selected wall",
                                         "Niche in the selected wall"};
    for (int k = 0; k < 4; k++) {
        char line[256];
        if (ui_gui_menu_item(items[k], NULL, -1, wall >= 0) &&
            planner_wall_item_line(p, k, wall, line, sizeof line))
            planner_edit(p, line);
    }
    ui_gui_separator();
    if (ui_gui_menu_item("The catalog's product at the room's first wall", NULL, -1,
                         p->browser.selected >= 0)) {
        /* As the Edit panel places it: the room's middle, 300 mm from its first wall; the
         * edit snaps it to the nearest wall. */
        double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
        for (int i = 0; i < p->project.plan.corner_count; i++) {
            const app_point2 *c = &p->project.plan.corners[i];
            lo[0] = c->x < lo[0] ? c->x : lo[0];
            lo[1] = c->y < lo[1] ? c->y : lo[1];
            hi[0] = c->x > hi[0] ? c->x : hi[0];
            hi[1] = c->y > hi[1] ? c->y : hi[1];
        }
        planner_place_selected(p, (lo[0] + hi[0]) / 2, lo[1] + 300);
    }
    if (ui_gui_menu_item("The catalog's tile on the selected wall", NULL, -1,
                         wall >= 0 && p->browser.selected >= 0)) {
        char surface[32];
        snprintf(surface, sizeof surface, "wall:%d", wall);
        planner_tile_selected(p, surface);
    }
    ui_gui_end_menu();
}

static void render_menu(planner *p)
{
    if (!ui_gui_begin_menu("Render", 1))
        return;
    static const char *const labels[4] = {"Draft quality", "Interactive quality", "Final quality",
                                          "Print quality"};
    static const char *const keys[4] = {"1", "2", "3", "4"};
    for (int i = 0; i < 4; i++)
        if (ui_gui_menu_item(labels[i], keys[i], p->quality == i, 1))
            planner_set_quality(p, i);
    ui_gui_separator();
    if (ui_gui_menu_item("Print-quality screenshot", "F12", -1, 1))
        planner_print_shot_now(p);
    if (ui_gui_menu_item("Render image at print quality...", NULL, -1, 1))
        planner_action_render_image(p);
    if (ui_gui_menu_item("Panorama...", NULL, -1, 1))
        planner_action_panorama(p);
    if (ui_gui_menu_item("Video of the viewpoints...", NULL, -1, 1))
        planner_action_video(p);
    if (ui_gui_menu_item("Share folder (renders, panorama, plan)...", NULL, -1, 1))
        planner_action_share(p);
    if (planner_job_running(p) && ui_gui_menu_item("Cancel the running job", "Esc", -1, 1))
        planner_action_cancel_job(p);
    ui_gui_end_menu();
}

static void help_menu(planner *p)
{
    if (!ui_gui_begin_menu("Help", 1))
        return;
    if (ui_gui_menu_item("Keyboard shortcuts", NULL, p->show_shortcuts, 1))
        p->show_shortcuts = !p->show_shortcuts;
    ui_gui_menu_item("The manual: docs/ui.md", NULL, -1, 0);
    ui_gui_end_menu();
}

static void shortcuts_window(planner *p)
{
    if (!p->show_shortcuts)
        return;
    const ui_rect *c = &p->layout.centre;
    if (ui_gui_begin_closable("Keyboard shortcuts", c->x + 20, c->y + 20, 640, 400,
                              &p->show_shortcuts)) {
        for (size_t i = 0; i < sizeof shortcuts / sizeof shortcuts[0]; i++) {
            ui_gui_text("%s", shortcuts[i][0]);
            ui_gui_same_line_at(180);
            ui_gui_text("%s", shortcuts[i][1]);
        }
    }
    ui_gui_end();
}

void planner_menu_bar(planner *p)
{
    if (ui_gui_begin_menu_bar()) {
        file_menu(p);
        edit_menu(p);
        view_menu(p);
        insert_menu(p);
        render_menu(p);
        help_menu(p);
        ui_gui_end_menu_bar();
    }
    shortcuts_window(p);
}
