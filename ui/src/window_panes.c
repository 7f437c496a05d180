/* The views' panes: the frame's rectangles from the window's size (panel_layout.h), the active
 * pane following the pointer (the wheel and the keys act on the view under it, as in desktop
 * planners), the splitter between the panes, and a log line of the rectangles whenever they
 * change, so a test can check what the window laid out. */
#include "planner.h"

#include "gui.h"

#include <GLFW/glfw3.h>
#include <stdio.h>

static void log_rect(const char *name, ui_rect r)
{
    fprintf(stderr, " %s %.0f,%.0f,%.0f,%.0f", name, r.x, r.y, r.w, r.h);
}

static void log_layout(planner *p, int width, int height)
{
    const ui_layout *l = &p->layout;
    int now[5] = {width, height, p->panes, (int)l->pane_2d.w, p->presenting};
    int same = 1;
    for (int i = 0; i < 5; i++)
        same &= now[i] == p->layout_logged[i];
    if (same || p->splitter_held) /* a drag logs where it ends, not every frame of it */
        return;
    for (int i = 0; i < 5; i++)
        p->layout_logged[i] = now[i];
    fprintf(stderr, "tessera: layout %dx%d", width, height);
    if (p->presenting) {
        log_rect("3d", l->pane_3d);
    } else {
        log_rect("menu", l->menu);
        log_rect("toolbar", l->toolbar);
        log_rect("left", l->left);
        log_rect("2d", l->pane_2d);
        log_rect("splitter", l->splitter);
        log_rect("3d", l->pane_3d);
        log_rect("right", l->right);
        log_rect("status", l->status);
    }
    fputc('\n', stderr);
}

/* The pane under a pointer that moved (no button held, no panel or menu under it) becomes the
 * active one. A script leaves the pointer alone: its `view` actions choose; while it waits for
 * outside input (wait-file), the pointer chooses as it does for a hand. */
static void follow_pointer(planner *p)
{
    double x, y;
    glfwGetCursorPos(p->window, &x, &y);
    int moved = x != p->pointer_seen[0] || y != p->pointer_seen[1];
    p->pointer_seen[0] = x;
    p->pointer_seen[1] = y;
    int scripted = !planner_input_live(p);
    if (!moved || scripted || p->dragging || p->drop.active || ui_gui_wants_mouse())
        return;
    for (int b = GLFW_MOUSE_BUTTON_1; b <= GLFW_MOUSE_BUTTON_LAST; b++)
        if (glfwGetMouseButton(p->window, b) == GLFW_PRESS)
            return;
    if (ui_rect_contains(p->layout.pane_2d, x, y))
        p->view = p->view_2d;
    else if (ui_rect_contains(p->layout.pane_3d, x, y))
        p->view = UI_VIEW_3D;
}

void planner_layout_frame(planner *p, int width, int height)
{
    if (p->view == UI_VIEW_PLAN || p->view == UI_VIEW_ELEVATION)
        p->view_2d = p->view;
    if (p->view_2d != UI_VIEW_ELEVATION)
        p->view_2d = UI_VIEW_PLAN;
    if (!(p->split > 0 && p->split < 1))
        p->split = 0.5f;
    ui_layout_compute(width, height, p->panes, p->split, p->view != UI_VIEW_3D, &p->layout);
    if (p->presenting) { /* the 3D view fills the window, nothing else shows */
        p->layout.pane_2d = p->layout.splitter = (ui_rect){0, 0, 0, 0};
        p->layout.pane_3d = (ui_rect){0, 0, (float)width, (float)height};
    }
    log_layout(p, width, height);
    if (!p->presenting)
        follow_pointer(p);
}

ui_rect planner_view_rect(const planner *p)
{
    return p->layout.pane_3d;
}

void planner_show_panes(planner *p, int both)
{
    p->panes = both ? UI_PANES_BOTH : UI_PANES_ONE;
}

void planner_splitter(planner *p)
{
    ui_rect s = p->layout.splitter;
    if (s.w <= 0)
        return;
    if (ui_gui_begin_bar("##splitter", s.x, s.y, s.w, s.h, 0.0f)) {
        float x;
        p->splitter_held = ui_gui_drag_handle("##split", s.w, s.h, &x);
        if (p->splitter_held)
            p->split = ui_layout_split_at(&p->layout, x);
    }
    ui_gui_end();
}
