/* Mouse and keyboard to navigation: left drag orbits (or looks around when walking), the wheel
 * zooms, W A S D walk at 1.2 m/s (shift: 2.5 m/s), Tab switches orbit and walk, 1-4 pick the
 * quality, F1-F9 fly to stored viewpoints, V switches the 3D and the plan view, Ctrl+Z undo,
 * Ctrl+Y (or Ctrl+Shift+Z) redo, Ctrl+S save, Delete removes the selected fixture. Presentation: P
 * shows or hides the UI, T starts or stops the tour, R the turntable, F11 fullscreen, F12 a
 * print-quality screenshot. Widgets get the input first. */
#include "planner.h"

#include "gui.h"

#include <GLFW/glfw3.h>
#include <stdio.h>
#include <time.h>

static void on_scroll(GLFWwindow *w, double dx, double dy)
{
    (void)dx;
    planner *p = glfwGetWindowUserPointer(w);
    if (!p || ui_gui_wants_mouse())
        return;
    if (p->view == UI_VIEW_PLAN)
        planner_plan_scroll(p, dy);
    else if (p->mode == UI_MODE_ORBIT)
        ui_orbit_zoom(&p->orbit, dy);
}

static void on_key(GLFWwindow *w, int key, int scancode, int action, int mods)
{
    (void)scancode;
    planner *p = glfwGetWindowUserPointer(w);
    if (!p || action != GLFW_PRESS || ui_gui_wants_keyboard())
        return;
    int ctrl = (mods & GLFW_MOD_CONTROL) != 0;
    if (ctrl && key == GLFW_KEY_Z)
        planner_undo(p, (mods & GLFW_MOD_SHIFT) != 0);
    else if (ctrl && key == GLFW_KEY_Y)
        planner_undo(p, 1);
    else if (ctrl && key == GLFW_KEY_S)
        planner_save(p, NULL);
    else if (key == GLFW_KEY_V)
        p->view = p->view == UI_VIEW_3D ? UI_VIEW_PLAN : UI_VIEW_3D;
    else if (key == GLFW_KEY_DELETE && p->plan_o.selected_object >= 0 &&
             p->plan_o.selected_object < p->project.object_count) {
        char line[128];
        snprintf(line, sizeof line, "remove \"%s\"",
                 p->project.objects[p->plan_o.selected_object].name);
        p->plan_o.selected_object = -1;
        planner_edit(p, line);
    } else if (key == GLFW_KEY_TAB)
        p->mode = p->mode == UI_MODE_ORBIT ? UI_MODE_WALK : UI_MODE_ORBIT;
    else if (key >= GLFW_KEY_1 && key <= GLFW_KEY_4)
        planner_set_quality(p, key - GLFW_KEY_1);
    else if (key >= GLFW_KEY_F1 && key <= GLFW_KEY_F9)
        planner_fly_to_camera(p, key - GLFW_KEY_F1, 1.0);
    else if (key == GLFW_KEY_P)
        p->presenting = !p->presenting;
    else if (key == GLFW_KEY_T) {
        p->touring = !p->touring;
        p->tour_clock = 1e9; /* leave for the next viewpoint at once */
    } else if (key == GLFW_KEY_R)
        p->turntable = !p->turntable;
    else if (key == GLFW_KEY_F11)
        planner_toggle_fullscreen(p);
    else if (key == GLFW_KEY_F12) {
        char name[256];
        time_t t = time(NULL);
        struct tm tm;
        localtime_r(&t, &tm);
        strftime(name, sizeof name, "tessera-%Y%m%d-%H%M%S.png", &tm);
        planner_print_shot(p, name);
    }
}

void planner_handle_input(planner *p, double dt)
{
    GLFWwindow *w = p->window;
    /* Callbacks are chained after ImGui's (installed first by ui_gui_init). */
    static GLFWwindow *hooked;
    if (hooked != w) {
        glfwSetScrollCallback(w, on_scroll);
        glfwSetKeyCallback(w, on_key);
        hooked = w;
    }
    double x, y;
    glfwGetCursorPos(w, &x, &y);
    int down = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    if (p->view != UI_VIEW_3D)
        return; /* the plan and the elevation read the pointer themselves */
    if (down && !p->dragging && !ui_gui_wants_mouse()) {
        p->dragging = 1;
        /* A press on a fixture (orbit mode) drags it; elsewhere it turns the view. */
        if (p->mode == UI_MODE_ORBIT && !p->presenting)
            planner_fixture_drag_press(p, x, y);
    } else if (!down) {
        if (p->fixture_drag.active && p->fixture_drag.by_pointer)
            planner_fixture_drag_end(p, 1);
        p->dragging = 0;
    }
    if (p->fixture_drag.active && p->fixture_drag.by_pointer)
        planner_fixture_drag_pointer(p, x, y);
    else if (p->dragging) {
        double dx = x - p->mouse_x, dy = y - p->mouse_y;
        if (p->mode == UI_MODE_ORBIT)
            ui_orbit_drag(&p->orbit, dx, dy);
        else
            ui_walk_look(&p->walk, dx, dy);
    }
    p->mouse_x = x;
    p->mouse_y = y;
    if (p->view != UI_VIEW_3D || p->mode != UI_MODE_WALK || ui_gui_wants_keyboard() || dt <= 0 ||
        dt > 0.5)
        return;
    double speed = glfwGetKey(w, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ? 2500 : 1200;
    double f = 0, r = 0;
    if (glfwGetKey(w, GLFW_KEY_W) == GLFW_PRESS)
        f += speed * dt;
    if (glfwGetKey(w, GLFW_KEY_S) == GLFW_PRESS)
        f -= speed * dt;
    if (glfwGetKey(w, GLFW_KEY_D) == GLFW_PRESS)
        r += speed * dt;
    if (glfwGetKey(w, GLFW_KEY_A) == GLFW_PRESS)
        r -= speed * dt;
    if (f != 0 || r != 0)
        planner_walk_move(p, f, r);
}
