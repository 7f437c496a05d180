/* The planner's panels: the view panel (quality, navigation mode, stored viewpoints), the
 * project summary and the selection's properties, docked in the window's columns beside the
 * views (panel_layout.h); each panel is a collapsible section of its column. */
#include "planner.h"
#include "planner_actions.h"

#include "app/project/commands.h"
#include "gui.h"
#include "grain_props.h"
#include "probe_props.h"
#include "render/ui_texture.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* Opens a panel as a section of the column being drawn (ui_gui_begin_column); collapsed 0/1
 * applies when place is 1 (the window's first frame), -1 leaves it to the user. Pair with
 * ui_gui_end. */
static int begin_panel(const char *title, ui_rect r, int place, int collapsed)
{
    return ui_gui_begin_placed(title, r.x, r.y, r.w, r.h, place, collapsed);
}

static void view_panel(planner *p)
{
    if (begin_panel("View", p->layout.left, 0, -1)) {
        int q = p->quality;
        if (ui_gui_combo("quality", &q, ui_quality_names, 4))
            planner_set_quality(p, q);
        static const char *const views[3] = {"3D", "plan", "elevation"}; /* UI_VIEW_* */
        ui_gui_combo("view (V)", &p->view, views, 3);
        static const char *const modes[2] = {"orbit", "walk"};
        ui_gui_combo("navigate", &p->mode, modes, 2);
        ui_gui_text("%s", p->mode == UI_MODE_ORBIT ? "drag: orbit, wheel: zoom"
                                                   : "W A S D: walk, drag: look");
        ui_gui_separator();
        ui_gui_text("Viewpoints");
        for (int i = 0; i < p->project.camera_count; i++)
            if (ui_gui_selectable(p->project.cameras[i].name, i == p->camera))
                planner_fly_to_camera(p, i, 1.0);
        ui_gui_separator();
        if (ui_gui_button("Present (P)"))
            p->presenting = 1;
        ui_gui_same_line();
        if (ui_gui_button(p->touring ? "Stop tour" : "Tour (T)")) {
            p->touring = !p->touring;
            p->tour_clock = 1e9;
        }
        ui_gui_same_line();
        if (ui_gui_button(p->turntable ? "Stop turning" : "Turn (R)"))
            p->turntable = !p->turntable;
        if (ui_gui_button("Share folder..."))
            planner_action_share(p);
        ui_gui_same_line();
        if (ui_gui_button("Panorama..."))
            planner_action_panorama(p);
        ui_gui_same_line();
        if (ui_gui_button("Video..."))
            planner_action_video(p);
    }
    ui_gui_end();
}

/* The project and its file: new, open, save, save as, recent files, print, render, export.
 * Open, save as and the jobs ask for the file in the native dialog (planner_actions.h); new and
 * open ask first when there are unsaved changes. */
void planner_file_request(planner *p, int what)
{
    if (p->dirty) {
        p->file_pending = what; /* prompts() asks, then runs it */
        return;
    }
    if (what == UI_FILE_NEW)
        planner_file_new(p);
    else
        planner_file_open(p, p->file_path);
}

static void project_panel(planner *p)
{
    /* Short windows start with it closed: the selection's fields need the room. */
    int first = !p->columns_placed;
    if (begin_panel("Project", p->layout.left, first, first ? p->layout.left.h < 560 : -1)) {
        ui_gui_text("%s%s", p->project.name, p->dirty ? " *" : "");
        ui_gui_text("%s", p->project.path[0] ? p->project.path : "(not saved yet)");
        ui_gui_text("%.0f x %.0f x %.0f mm", p->project.room.width_mm, p->project.room.depth_mm,
                    p->project.room.height_mm);
        ui_gui_text("%d objects, %d lights", p->project.object_count, p->project.light_count);
        if (ui_gui_button("New"))
            planner_file_request(p, UI_FILE_NEW);
        ui_gui_same_line();
        if (ui_gui_button("Open..."))
            planner_action_open_dialog(p);
        ui_gui_same_line();
        if (ui_gui_button("Save"))
            planner_action_save(p);
        ui_gui_same_line();
        if (ui_gui_button("Save as..."))
            planner_action_save_as(p);
        if (ui_gui_button("Print PDF..."))
            planner_action_print_pdf(p);
        ui_gui_same_line();
        if (ui_gui_button("Render image..."))
            planner_action_render_image(p);
        ui_gui_same_line();
        if (ui_gui_button("Export GLB..."))
            planner_action_export_glb(p);
        const ui_recent *recent = planner_recent_files(p);
        for (int i = 0; recent && i < recent->count && i < 5; i++) {
            const char *base = strrchr(recent->paths[i], '/');
            char label[300];
            snprintf(label, sizeof label, "%d %.200s##recent%d", i + 1,
                     base ? base + 1 : recent->paths[i], i);
            if (ui_gui_selectable(label, 0)) {
                planner_action_open_recent(p, i);
                break; /* the list was reordered */
            }
        }
        if (!strncmp(p->status, "cannot open", 11) || !strncmp(p->status, "open:", 5) ||
            !strncmp(p->status, "save", 4) || strstr(p->status, ": cannot "))
            ui_gui_text_wrapped(p->status);
    }
    ui_gui_end();
}

static void edit_panel(planner *p)
{
    if (begin_panel("Edit", p->layout.left, 0, -1)) {
        int narrow = p->layout.edit_narrow; /* one button a row */
        char label[160];
        const char *u = app_history_undo_label(p->history), *r = app_history_redo_label(p->history);
        snprintf(label, sizeof label, "Undo %s##undo", u && *u ? u : "");
        if (ui_gui_button(label))
            planner_undo(p, 0);
        if (!narrow)
            ui_gui_same_line();
        snprintf(label, sizeof label, "Redo %s##redo", r && *r ? r : "");
        if (ui_gui_button(label))
            planner_undo(p, 1);
        ui_gui_same_line();
        if (ui_gui_button(p->dirty ? "Save *" : "Save"))
            planner_save(p, NULL);
        if (p->browser.selected >= 0) { /* on a row of its own: the undo label is long */
            if (ui_gui_button("Place selected product")) {
                /* At the room's centre; the edit snaps it to the nearest wall. */
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
        }
        ui_gui_text("%s", p->status);
        int errors = app_findings_errors(&p->findings);
        ui_gui_text("%d findings, %d errors", p->findings.count, errors);
        for (int i = 0; i < p->findings.count && i < 3; i++)
            ui_gui_text_wrapped(p->findings.items[i].message);
    }
    ui_gui_end();
}

/* The material's reflection (RENDERING.md sections 3-6) and its probe policy (section 8):
 * intensity, glossiness and blend commit one `reflect` line when the slider is let go or the
 * combo changes; each probe field one `probe` line (probe_props.h). Both edit the material,
 * so every object sharing it follows (docs/editing.md); the scene is rebuilt from the
 * document after each (planner_doc_changed), so the 3D view shows the change at once. */
static void material_fields(planner *p, int mi)
{
    const app_material *m = &p->project.materials[mi];
    char line[256];
    /* The sliders' values while dragging; taken from the material again whenever it changes
     * underneath (another material, an undo). */
    static float kr, g, seen_kr = -1, seen_g = -1;
    static int blend, seen_blend = -1, seen_mat = -1;
    if (seen_mat != mi || seen_kr != m->reflectivity || seen_g != m->glossiness ||
        seen_blend != m->blend) {
        kr = seen_kr = m->reflectivity;
        g = seen_g = m->glossiness;
        blend = seen_blend = m->blend;
        seen_mat = mi;
    }
    static const char *const blends[3] = {"mix", "add", "fresnel"};
    ui_gui_separator();
    ui_gui_text("material %s", m->name);
    int commit = ui_gui_slider_commit("reflection k_r", &kr, 0.0f, 1.0f);
    commit |= ui_gui_slider_commit("glossiness g", &g, 0.0f, 1.0f);
    commit |= ui_gui_combo("blend", &blend, blends, 3);
    if (commit) {
        snprintf(line, sizeof line, "reflect \"%s\" %.3f gloss %.3f blend %s", m->name, kr, g,
                 blends[blend]);
        planner_edit(p, line);
        return; /* m may have moved */
    }
    /* The wood grain (docs/rendering.md "Wood grain"): one `pattern` line (grain_props.h). */
    const char *grain_items[4];
    char grain_other[32];
    int grain_item,
        grain_n = ui_grain_items(m->pattern, m->grain_deg, grain_items, grain_other, &grain_item);
    int grain_shown = grain_item;
    if (ui_gui_combo("wood grain", &grain_item, grain_items, grain_n) &&
        grain_item != grain_shown) {
        if (!ui_grain_line(line, sizeof line, m->name, grain_item))
            planner_edit(p, line);
        return;
    }
    ui_gui_text("reflection probe");
    int update = m->probe_update >= 0 && m->probe_update <= APP_PROBE_STATIC ? m->probe_update : 0;
    if (ui_gui_combo("update", &update, ui_probe_update_labels, 6) && update != m->probe_update) {
        if (!ui_probe_line(line, sizeof line, m->name, UI_PROBE_UPDATE, update))
            planner_edit(p, line);
        return;
    }
    if (update == APP_PROBE_EVERY_FRAME) {
        static double every;
        static int seen_every = -1, seen_every_mat = -1;
        if (seen_every != m->probe_every || seen_every_mat != mi) {
            seen_every = m->probe_every;
            seen_every_mat = mi;
            every = m->probe_every > 1 ? m->probe_every : 1;
        }
        if (ui_gui_input_double_enter("every N frames", &every)) {
            seen_every = -1; /* shows the material's value again, whatever happens */
            if (every >= 1 && every <= 1000000 && every == (int)every) {
                if (!ui_probe_line(line, sizeof line, m->name, UI_PROBE_EVERY, (int)every))
                    planner_edit(p, line);
            } else {
                planner_status(p, "every N frames: a whole number from 1 to 1000000");
            }
            return;
        }
    }
    const char *items[6];
    char other[16];
    int res_item, n = ui_probe_resolution_items(m->probe_resolution, items, other, &res_item);
    if (ui_gui_combo("resolution", &res_item, items, n)) {
        int res = ui_probe_resolution_of(res_item, m->probe_resolution);
        if (res != m->probe_resolution &&
            !ui_probe_line(line, sizeof line, m->name, UI_PROBE_RESOLUTION, res))
            planner_edit(p, line);
        return;
    }
    int corr = m->correction >= 0 && m->correction <= APP_CORRECTION_DEPTH ? m->correction : 0;
    if (ui_gui_combo("correction", &corr, ui_probe_correction_labels, 5) && corr != m->correction &&
        !ui_probe_line(line, sizeof line, m->name, UI_PROBE_CORRECTION, corr))
        planner_edit(p, line);
}

/* The selected fixture's card and properties: what it is, where it stands, its finish, and
 * for power users its material's reflection and probe policy. Each field commits one edit
 * line when the user presses Enter, lets go of a slider or picks from a combo. */

/* The selected product's finish variants from the catalog, one `variant`
 * edit (with its render material, one undo step) when another is picked. The product is read
 * once per selection. Returns 1 when the document changed. */
static int variant_combo(planner *p, const app_object *o)
{
    static cat_product product;
    static char key[256];
    char want[256];
    snprintf(want, sizeof want, "%s\n%s", o->product.manufacturer, o->product.article);
    if (strcmp(key, want)) {
        cat_product_free(&product);
        memset(&product, 0, sizeof product);
        char err[512];
        snprintf(key, sizeof key, "%s", want);
        if (!p->browser.db ||
            cat_product_find(p->browser.db, o->product.manufacturer, o->product.article, &product,
                             err, sizeof err) != CAT_DB_OK)
            product.variant_count = 0;
    }
    if (product.variant_count <= 1)
        return 0;
    enum { MAX_SHOWN = 32 };
    const char *names[MAX_SHOWN];
    char labels[MAX_SHOWN][96];
    int n = product.variant_count < MAX_SHOWN ? product.variant_count : MAX_SHOWN, current = 0;
    for (int v = 0; v < n; v++) {
        snprintf(labels[v], sizeof labels[v], "%s %s", product.variants[v].code,
                 product.variants[v].name);
        names[v] = labels[v];
        if (!strcmp(product.variants[v].code, o->product.variant))
            current = v;
    }
    int chosen = current;
    if (!ui_gui_combo("variant", &chosen, names, n) || chosen == current)
        return 0;
    char line[256];
    snprintf(line, sizeof line, "variant \"%s\" %s", o->name, product.variants[chosen].code);
    planner_edit(p, line);
    return 1;
}

/* What the selection is mounted on and what is mounted on it (app_object.parent), and the
 * Ungroup button that detaches both; 1 when it edited the document. */
static int group_fields(planner *p, const app_object *o)
{
    int children = 0;
    for (int k = 0; k < p->project.object_count; k++)
        children += !strcmp(p->project.objects[k].parent, o->name);
    if (!o->parent[0] && !children)
        return 0;
    if (o->parent[0])
        ui_gui_text("mounted on %s", o->parent);
    if (children)
        ui_gui_text("carries %d object%s (they move with it)", children, children == 1 ? "" : "s");
    if (!ui_gui_button("Ungroup"))
        return 0;
    char line[160];
    snprintf(line, sizeof line, "ungroup \"%s\"", o->name);
    planner_edit(p, line);
    return 1;
}

static void selection_panel(planner *p)
{
    int i = p->plan_o.selected_object;
    if (i < 0 || i >= p->project.object_count)
        return;
    const app_object *o = &p->project.objects[i];
    if (begin_panel("Selection", p->layout.left, 0, -1)) {
        char line[256];
        ui_gui_text("%s", o->name);
        if (o->has_product)
            ui_gui_text("%s %s %s", o->product.manufacturer, o->product.article,
                        o->product.variant);
        /* The fields hold what the user types until the document's own values change
         * (another selection, a drag, an undo): then they show the document again. */
        static double pos[3], rot, seen[4];
        static int shown = -1;
        if (shown != i || seen[0] != o->position_mm[0] || seen[1] != o->position_mm[1] ||
            seen[2] != o->position_mm[2] || seen[3] != o->rotation_deg[2]) {
            for (int k = 0; k < 3; k++)
                pos[k] = seen[k] = o->position_mm[k];
            rot = seen[3] = o->rotation_deg[2];
            shown = i;
        }
        int moved = ui_gui_input_double_enter("x mm", &pos[0]);
        moved |= ui_gui_input_double_enter("y mm", &pos[1]);
        moved |= ui_gui_input_double_enter("elevation mm", &pos[2]);
        if (moved) {
            snprintf(line, sizeof line, "move \"%s\" %.1f %.1f %.1f", o->name, pos[0], pos[1],
                     pos[2]);
            planner_edit(p, line);
            shown = -1;
            ui_gui_end();
            return;
        }
        if (ui_gui_input_double_enter("rotation deg", &rot)) {
            snprintf(line, sizeof line, "rotate \"%s\" %.1f", o->name, rot);
            planner_edit(p, line);
            shown = -1;
            ui_gui_end();
            return;
        }
        if (o->has_product && variant_combo(p, o)) {
            ui_gui_end();
            return;
        }
        if (ui_gui_button("Rotate 90")) {
            snprintf(line, sizeof line, "rotate \"%s\" %.0f", o->name,
                     fmod(o->rotation_deg[2] + 90, 360));
            planner_edit(p, line);
            ui_gui_end();
            return;
        }
        ui_gui_same_line();
        if (ui_gui_button("Remove")) {
            snprintf(line, sizeof line, "remove \"%s\"", o->name);
            p->plan_o.selected_object = -1;
            planner_edit(p, line);
            ui_gui_end();
            return;
        }
        if (group_fields(p, o)) {
            ui_gui_end();
            return;
        }
        if (o->material >= 0 && o->material < p->project.material_count)
            material_fields(p, o->material);
    }
    ui_gui_end();
}

/* Modal questions: recover an autosave, save before closing. */
static void prompts(planner *p, int width, int height)
{
    float x = (float)width / 2 - 170.0f, y = (float)height / 2 - 60.0f;
    if (p->recovery_offered) {
        if (ui_gui_begin("Recover?", x - 60.0f, y, 460.0f, 100.0f)) {
            ui_gui_text("Unsaved changes of this project were autosaved.");
            if (ui_gui_button("Recover them")) {
                planner_recover(p, 1);
                p->recovery_offered = 0;
            }
            ui_gui_same_line();
            if (ui_gui_button("Discard")) {
                planner_recover(p, 0);
                p->recovery_offered = 0;
            }
        }
        ui_gui_end();
    }
    if (p->file_pending) {
        if (ui_gui_begin("Unsaved changes##file", x, y, 340.0f, 100.0f)) {
            ui_gui_text("%s has unsaved changes.", p->project.name);
            int what = p->file_pending;
            if (ui_gui_button("Save first") && planner_save(p, NULL) == 0) {
                p->file_pending = 0;
                planner_file_request(p, what);
            }
            ui_gui_same_line();
            if (ui_gui_button("Discard them")) {
                p->file_pending = 0;
                p->dirty = 0;
                planner_file_request(p, what);
            }
            ui_gui_same_line();
            if (ui_gui_button("Cancel"))
                p->file_pending = 0;
        }
        ui_gui_end();
    }
    if (p->close_requested) {
        if (ui_gui_begin("Unsaved changes", x, y, 340.0f, 100.0f)) {
            ui_gui_text("Save the changes to %s?", p->project.name);
            if (ui_gui_button("Save") && planner_save(p, NULL) == 0)
                p->quit = 1;
            ui_gui_same_line();
            if (ui_gui_button("Discard"))
                p->quit = 1;
            ui_gui_same_line();
            if (ui_gui_button("Cancel"))
                p->close_requested = 0;
        }
        ui_gui_end();
    }
}

void planner_draw_panels(planner *p, int width, int height)
{
    const ui_layout *l = &p->layout;
    if (!p->browser.thumbs && p->ctx) { /* the browser was opened after the document */
        ui_thumbnails_init(&p->thumbs, p->ctx);
        p->browser.thumbs = &p->thumbs;
    }
    ui_gui_begin_column("##left", l->left.x, l->left.y, l->left.w, l->left.h);
    view_panel(p);
    edit_panel(p);
    selection_panel(p);
    planner_wall_panel(p); /* planner_plan.c: in the Selection's place, for a wall */
    project_panel(p);
    ui_gui_end_column();

    ui_gui_begin_column("##right", l->right.x, l->right.y, l->right.w, l->right.h);
    ui_catalog_browser_draw(&p->browser, l->right.x, l->right.y, l->right.w, l->right.h,
                            l->catalog_list_h, 0);
    planner_tile_panel(p, width, height); /* tile_panel.c */
    int first = !p->columns_placed;
    ui_quantities_draw(&p->quantities, &p->project, p->browser.db, l->right.x, l->right.y,
                       l->right.w, l->right.h, first, first ? l->right.h < 560 : -1);
    ui_gui_end_column();
    p->columns_placed = 1;

    planner_splitter(p); /* window_panes.c */
    planner_toolbar(p);  /* toolbar.c */
    planner_menu_bar(p); /* menu_bar.c */
    prompts(p, width, height);
    planner_drag_drop_frame(p);
    /* One thumbnail a frame (each costs a frame's worth of llvmpipe time), rendered off screen,
     * in a frame whose 3D view left room for it (at most the budget: a still's strip, the
     * view's first render); then the window is the target again. */
    int room = p->view_ms_now <= p->budget_ms;
    if (room && ui_thumbnails_update(&p->thumbs, p->browser.db, 1) > 0)
        rd_bind_window(p->ctx, width, height);
}
