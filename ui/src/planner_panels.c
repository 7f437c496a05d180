/* The planner's panels: the frame-time overlay (issue 8 item 6: speed for accuracy, live), the
 * view panel (quality, navigation mode, stored viewpoints) and the project summary. */
#include "planner.h"

#include "app/commands.h"
#include "gui.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static float mean(const float *v, long count)
{
    int n = count < UI_FRAME_HISTORY ? (int)count : UI_FRAME_HISTORY;
    double s = 0;
    for (int i = 0; i < n; i++)
        s += v[i];
    return n ? (float)(s / n) : 0.0f;
}

static void frame_overlay(planner *p, int width)
{
    if (ui_gui_begin_overlay("##frame-time", (float)width - 230.0f, 10.0f, 0.55f)) {
        float ms = mean(p->frame_ms, p->frame_count), rms = mean(p->render_ms, p->frame_count);
        ui_gui_text("%.1f ms  %.0f fps", ms, ms > 0 ? 1000.0f / ms : 0.0f);
        ui_gui_text("3D view %.1f ms at %.0f %%", rms, p->render_scale * 100.0f);
        ui_gui_text("quality: %s, catalog search %.1f ms", ui_quality_names[p->quality],
                    p->browser.search_ms);
        ui_gui_plot_lines("##ms", p->frame_ms, UI_FRAME_HISTORY, 0.0f, 100.0f, 200.0f, 30.0f);
    }
    ui_gui_end();
}

static void view_panel(planner *p)
{
    if (ui_gui_begin("View", 10.0f, 10.0f, 260.0f, 250.0f)) {
        int q = p->quality;
        if (ui_gui_combo("quality", &q, ui_quality_names, 4))
            planner_set_quality(p, q);
        static const char *const views[2] = {"3D", "plan"};
        ui_gui_combo("view (V)", &p->view, views, 2);
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
        if (ui_gui_button("Share folder")) {
            char dir[1100];
            snprintf(dir, sizeof dir, "%s-share", p->project.path[0] ? p->project.path : "tessera");
            char *dot = strrchr(dir, '.');
            if (dot && !strcmp(dot, ".json-share"))
                memmove(dot, "-share", 7);
            planner_share(p, dir);
        }
    }
    ui_gui_end();
}

static void project_panel(planner *p, int height)
{
    if (ui_gui_begin("Project", 10.0f, (float)height - 130.0f, 260.0f, 120.0f)) {
        ui_gui_text("%s", p->project.name);
        ui_gui_text("%.0f x %.0f x %.0f mm", p->project.room.width_mm, p->project.room.depth_mm,
                    p->project.room.height_mm);
        ui_gui_text("%d objects, %d lights", p->project.object_count, p->project.light_count);
    }
    ui_gui_end();
}

static void edit_panel(planner *p, int width, int height)
{
    if (ui_gui_begin("Edit", (float)width / 2 - 200.0f, (float)height - 150.0f, 400.0f, 140.0f)) {
        char label[160];
        const char *u = app_history_undo_label(p->history), *r = app_history_redo_label(p->history);
        snprintf(label, sizeof label, "Undo %s##undo", u && *u ? u : "");
        if (ui_gui_button(label))
            planner_undo(p, 0);
        ui_gui_same_line();
        snprintf(label, sizeof label, "Redo %s##redo", r && *r ? r : "");
        if (ui_gui_button(label))
            planner_undo(p, 1);
        ui_gui_same_line();
        if (ui_gui_button(p->dirty ? "Save *" : "Save"))
            planner_save(p, NULL);
        if (p->browser.selected >= 0) {
            ui_gui_same_line();
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

/* The selected fixture's card and properties: what it is, where it stands, its finish, and
 * for power users its material's reflection (RENDERING.md sections 3-6). Each field commits
 * one edit line when the user presses Enter or lets go of a slider. */
static void selection_panel(planner *p, int width)
{
    int i = p->plan_o.selected_object;
    if (i < 0 || i >= p->project.object_count)
        return;
    const app_object *o = &p->project.objects[i];
    (void)width;
    if (ui_gui_begin("Selection", 10.0f, 270.0f, 260.0f, 230.0f)) {
        char line[256];
        ui_gui_text("%s", o->name);
        if (o->has_product)
            ui_gui_text("%s %s %s", o->product.manufacturer, o->product.article,
                        o->product.variant);
        static double pos[3], rot;
        static int shown = -1;
        if (shown != i || !p->dirty) {
            for (int k = 0; k < 3; k++)
                pos[k] = o->position_mm[k];
            rot = o->rotation_deg[2];
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
        }
        if (ui_gui_input_double_enter("rotation deg", &rot)) {
            snprintf(line, sizeof line, "rotate \"%s\" %.1f", o->name, rot);
            planner_edit(p, line);
            shown = -1;
        }
        if (ui_gui_button("Rotate 90")) {
            snprintf(line, sizeof line, "rotate \"%s\" %.0f", o->name,
                     fmod(o->rotation_deg[2] + 90, 360));
            planner_edit(p, line);
        }
        ui_gui_same_line();
        if (ui_gui_button("Remove")) {
            snprintf(line, sizeof line, "remove \"%s\"", o->name);
            p->plan_o.selected_object = -1;
            planner_edit(p, line);
            ui_gui_end();
            return;
        }
        if (o->material >= 0 && o->material < p->project.material_count) {
            const app_material *m = &p->project.materials[o->material];
            static float kr, g;
            static int blend, shown_mat = -1;
            if (shown_mat != o->material) {
                kr = m->reflectivity;
                g = m->glossiness;
                blend = m->blend;
                shown_mat = o->material;
            }
            static const char *const blends[3] = {"mix", "add", "fresnel"};
            ui_gui_text("material %s", m->name);
            int commit = ui_gui_slider_commit("reflection k_r", &kr, 0.0f, 1.0f);
            commit |= ui_gui_slider_commit("glossiness g", &g, 0.0f, 1.0f);
            commit |= ui_gui_combo("blend", &blend, blends, 3);
            if (commit) {
                snprintf(line, sizeof line, "reflect \"%s\" %.3f gloss %.3f blend %s", m->name, kr,
                         g, blends[blend]);
                planner_edit(p, line);
                shown_mat = -1;
            }
        }
    }
    ui_gui_end();
}

/* Modal questions: recover an autosave, save before closing. */
static void prompts(planner *p, int width, int height)
{
    float x = (float)width / 2 - 170.0f, y = (float)height / 2 - 60.0f;
    if (p->recovery_offered) {
        if (ui_gui_begin("Recover?", x, y, 340.0f, 100.0f)) {
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
    view_panel(p);
    edit_panel(p, width, height);
    selection_panel(p, width);
    prompts(p, width, height);
    project_panel(p, height);
    ui_catalog_browser_draw(&p->browser, (float)width - 350.0f, 130.0f);
    frame_overlay(p, width);
}
