/* The toolbar under the menu bar: the common commands as icon buttons, each with a tooltip
 * naming it and its key. The icons are line drawings in a unit square (y down), drawn by Dear
 * ImGui, so they follow the style's text colour and need no image files. */
#include "planner.h"
#include "planner_actions.h"

#include "gui.h"

#include <math.h>

#define ICON 26.0f

/* A closed polygon's edges as segments (x0 y0 x1 y1) into out; returns the count. */
static int polygon(const float *xy, int n, float *out)
{
    for (int i = 0; i < n; i++) {
        out[4 * i] = xy[2 * i];
        out[4 * i + 1] = xy[2 * i + 1];
        out[4 * i + 2] = xy[2 * ((i + 1) % n)];
        out[4 * i + 3] = xy[2 * ((i + 1) % n) + 1];
    }
    return n;
}

/* An arc of a circle about (cx, cy) from a0 to a1 (radians) in n segments. */
static int arc(float cx, float cy, float r, float a0, float a1, int n, float *out)
{
    for (int i = 0; i < n; i++) {
        float u = a0 + (a1 - a0) * (float)i / (float)n,
              v = a0 + (a1 - a0) * (float)(i + 1) / (float)n;
        out[4 * i] = cx + r * cosf(u);
        out[4 * i + 1] = cy + r * sinf(u);
        out[4 * i + 2] = cx + r * cosf(v);
        out[4 * i + 3] = cy + r * sinf(v);
    }
    return n;
}

static int tool(const char *id, const float *segments, int count, int active, const char *tip)
{
    int clicked = ui_gui_icon_button(id, segments, count, ICON, active, tip);
    ui_gui_same_line();
    return clicked;
}

static void gap(void)
{
    ui_gui_text(" ");
    ui_gui_same_line();
}

static const float page[] = {0.2f,  0, 0.65f, 0,    0.65f, 0,    0.85f, 0.2f, 0.85f, 0.2f,
                             0.85f, 1, 0.85f, 1,    0.2f,  1,    0.2f,  1,    0.2f,  0,
                             0.65f, 0, 0.65f, 0.2f, 0.65f, 0.2f, 0.85f, 0.2f};
static const float folder[] = {0,     0.15f, 0.35f, 0.15f, 0.35f, 0.15f, 0.45f, 0.3f,
                               0.45f, 0.3f,  1,     0.3f,  1,     0.3f,  1,     0.9f,
                               1,     0.9f,  0,     0.9f,  0,     0.9f,  0,     0.15f};
static const float disk[] = {0,     0,    1,     0,    1,     0,     1,    1,     1,    1,     0,
                             1,     0,    1,     0,    0,     0.25f, 0,    0.25f, 0.3f, 0.25f, 0.3f,
                             0.75f, 0.3f, 0.75f, 0.3f, 0.75f, 0,     0.2f, 0.6f,  0.8f, 0.6f};
static const float undo_arrow[] = {0.1f, 0.4f, 0.4f, 0.15f, 0.1f, 0.4f, 0.4f, 0.65f, 0.1f, 0.4f,
                                   0.7f, 0.4f, 0.7f, 0.4f,  0.9f, 0.6f, 0.9f, 0.6f,  0.9f, 0.85f};
static const float redo_arrow[] = {0.9f, 0.4f, 0.6f, 0.15f, 0.9f, 0.4f, 0.6f, 0.65f, 0.9f, 0.4f,
                                   0.3f, 0.4f, 0.3f, 0.4f,  0.1f, 0.6f, 0.1f, 0.6f,  0.1f, 0.85f};
static const float plan_icon[] = {0, 0, 1, 0, 1, 0,    1,    1,    1,    1,    0,    1,
                                  0, 1, 0, 0, 0, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 1};
static const float cube[] = {0,    0.3f, 0.7f, 0.3f, 0.7f, 0.3f, 0.7f, 1,    0.7f, 1,    0,    1,
                             0,    1,    0,    0.3f, 0,    0.3f, 0.3f, 0,    0.7f, 0.3f, 1,    0,
                             0.3f, 0,    1,    0,    1,    0,    1,    0.7f, 1,    0.7f, 0.7f, 1};
static const float elevation_icon[] = {
    0, 0,     1, 0,     1, 0,     1, 1,     1,    1, 0,    1,     0,    1,     0,    0,
    0, 0.33f, 1, 0.33f, 0, 0.66f, 1, 0.66f, 0.5f, 0, 0.5f, 0.33f, 0.5f, 0.66f, 0.5f, 1};
static const float walker[] = {0.5f, 0.05f, 0.6f, 0.15f, 0.6f,  0.15f, 0.5f,  0.25f,
                               0.5f, 0.25f, 0.4f, 0.15f, 0.4f,  0.15f, 0.5f,  0.05f,
                               0.5f, 0.3f,  0.5f, 0.65f, 0.5f,  0.65f, 0.3f,  1,
                               0.5f, 0.65f, 0.7f, 1,     0.25f, 0.45f, 0.75f, 0.45f};
static const float play[] = {0.2f, 0, 0.9f, 0.5f, 0.9f, 0.5f, 0.2f, 1, 0.2f, 1, 0.2f, 0};

void planner_toolbar(planner *p)
{
    const ui_rect *r = &p->layout.toolbar;
    if (ui_gui_begin_bar("##toolbar", r->x, r->y, r->w, r->h, 4.0f)) {
        if (tool("##new", page, 7, 0, "New project (the empty room)"))
            planner_file_request(p, UI_FILE_NEW);
        if (tool("##open", folder, 6, 0, "Open a project (Ctrl+O)"))
            planner_action_open_dialog(p);
        if (tool("##save", disk, 8, 0, "Save (Ctrl+S)"))
            planner_action_save(p);
        gap();
        if (tool("##undo", undo_arrow, 5, 0, "Undo (Ctrl+Z)"))
            planner_undo(p, 0);
        if (tool("##redo", redo_arrow, 5, 0, "Redo (Ctrl+Y)"))
            planner_undo(p, 1);
        gap();
        float both[8 * 4], xy[8] = {0, 0.1f, 0.45f, 0.1f, 0.45f, 0.9f, 0, 0.9f};
        int n = polygon(xy, 4, both);
        for (int i = 0; i < 4; i++)
            xy[2 * i] += 0.55f;
        n += polygon(xy, 4, both + 4 * n);
        int side_by_side = p->panes == UI_PANES_BOTH;
        if (tool("##both", both, n, side_by_side, "Plan and 3D side by side (View menu)"))
            planner_show_panes(p, 1);
        if (tool("##plan", plan_icon, 6, !side_by_side && p->view == UI_VIEW_PLAN,
                 "Plan only (V switches plan and 3D)")) {
            planner_show_panes(p, 0);
            p->view = UI_VIEW_PLAN;
        }
        if (tool("##3d", cube, 9, !side_by_side && p->view == UI_VIEW_3D,
                 "3D only (V switches plan and 3D)")) {
            planner_show_panes(p, 0);
            p->view = UI_VIEW_3D;
        }
        if (tool("##elevation", elevation_icon, 8, p->view_2d == UI_VIEW_ELEVATION,
                 "Elevation of the tile panel's wall"))
            p->view = UI_VIEW_ELEVATION;
        gap();
        float orbit[12 * 4];
        n = arc(0.5f, 0.5f, 0.42f, 0.3f, 5.8f, 10, orbit);
        float tip_x = 0.5f + 0.42f * cosf(5.8f), tip_y = 0.5f + 0.42f * sinf(5.8f);
        float head[8] = {tip_x, tip_y, tip_x - 0.25f, tip_y - 0.02f,
                         tip_x, tip_y, tip_x + 0.02f, tip_y + 0.25f};
        for (int i = 0; i < 8; i++)
            orbit[4 * n + i] = head[i];
        n += 2;
        if (tool("##orbit", orbit, n, p->mode == UI_MODE_ORBIT,
                 "Orbit: drag to turn, wheel to zoom (Tab switches)"))
            p->mode = UI_MODE_ORBIT;
        if (tool("##walk", walker, 8, p->mode == UI_MODE_WALK,
                 "Walk: W A S D to move, drag to look (Tab switches)"))
            p->mode = UI_MODE_WALK;
        gap();
        if (tool("##present", play, 3, p->presenting, "Presentation: the panels hidden (P)"))
            p->presenting = 1;
        float camera[16 * 4], body[8] = {0, 0.25f, 1, 0.25f, 1, 0.95f, 0, 0.95f};
        n = polygon(body, 4, camera);
        n += arc(0.5f, 0.6f, 0.22f, 0, 6.2832f, 10, camera + 4 * n);
        if (tool("##shot", camera, n, 0, "Print-quality screenshot (F12)"))
            planner_print_shot_now(p);
    }
    ui_gui_end();
}
