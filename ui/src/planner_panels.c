/* The planner's panels: the frame-time overlay (issue 8 item 6: speed for accuracy, live), the
 * view panel (quality, navigation mode, stored viewpoints) and the project summary. */
#include "planner.h"

#include "gui.h"

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
        ui_gui_text("quality: %s", ui_quality_names[p->quality]);
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

void planner_draw_panels(planner *p, int width, int height)
{
    view_panel(p);
    project_panel(p, height);
    ui_catalog_browser_draw(&p->browser, (float)width - 350.0f, 130.0f);
    frame_overlay(p, width);
}
