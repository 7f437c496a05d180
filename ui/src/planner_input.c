/* Mouse and keyboard to navigation: left drag orbits (or looks around when walking), the wheel
 * zooms (the plan and the elevation too, about the pointer and the centre), W A S D walk at 1.2 m/s
 * (shift: 2.5 m/s), Tab switches orbit and walk, 1-4 pick the quality, F1-F9 fly to stored
 * viewpoints, V switches the 3D and the plan view, Ctrl+Z undo, Ctrl+Y (or Ctrl+Shift+Z) redo,
 * Ctrl+O, Ctrl+S, Ctrl+Shift+S,
 * Ctrl+P, Ctrl+E and Esc as planner_actions.h says, Delete removes the selected fixture, Ctrl+R
 * turns it by 90 degrees.
 * Presentation: P shows or hides the UI, T starts or stops the tour, R the turntable, F11
 * fullscreen, F12 a print-quality screenshot. The events come from the frame's share of the input
 * queue (gui.h, input_queue.h): Dear ImGui sees every one of them; the planner acts only on those
 * the widgets do not want (a key while no text field has the keyboard, the wheel and the buttons
 * while the pointer is over no panel).
 */
#include "planner.h"
#include "planner_actions.h"

#include "gui.h"
#include "input_queue.h"
#include "tiles.h"

#include <GLFW/glfw3.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static void on_scroll(planner *p, double dy)
{
    if (dy == 0 || ui_gui_wants_mouse())
        return;
    if (p->view == UI_VIEW_PLAN)
        planner_plan_scroll(p, dy);
    else if (p->view == UI_VIEW_ELEVATION) {
        /* The same steps and limits as the tile panel's + and - buttons. */
        ui_tiles *t = planner_tiles(p);
        if (!t)
            return;
        double z = (t->zoom > 0 ? t->zoom : 1) * pow(1.25, dy);
        t->zoom = z < 0.25 ? 0.25 : z > 20 ? 20 : z;
    } else if (p->mode == UI_MODE_ORBIT)
        ui_orbit_zoom(&p->orbit, dy);
}

static void on_key(planner *p, int key, int mods)
{
    int ctrl = (mods & GLFW_MOD_CONTROL) != 0;
    if (planner_action_key(p, key, mods)) /* files and jobs: Ctrl+O, Ctrl+S, Ctrl+P, ... */
        return;
    if (ctrl && key == GLFW_KEY_Z)
        planner_undo(p, (mods & GLFW_MOD_SHIFT) != 0);
    else if (ctrl && key == GLFW_KEY_Y)
        planner_undo(p, 1);
    else if (ctrl && key == GLFW_KEY_R)
        planner_rotate_selected(p); /* 90 degrees, as Edit > Rotate */
    else if (ctrl)
        return; /* Ctrl+A, Ctrl+C, ... are the widgets' */
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
        planner_action_job_to(p, PLANNER_JOB_RENDER_IMAGE, name); /* off the frame loop */
    }
}

/* TESSERA_FRAME_DELAY_MS=N makes every frame N ms longer: the window as a slow machine runs
 * it, for tests that a hand's short click or fast typing still counts. */
static void frame_delay(void)
{
    static long delay_ms = -1;
    if (delay_ms < 0) {
        const char *v = getenv("TESSERA_FRAME_DELAY_MS");
        delay_ms = v ? strtol(v, NULL, 10) : 0;
        if (delay_ms < 0 || delay_ms > 2000)
            delay_ms = 0;
    }
    if (delay_ms > 0) {
        struct timespec ts = {delay_ms / 1000, (delay_ms % 1000) * 1000000L};
        nanosleep(&ts, NULL);
    }
}

/* While a script runs, what the hand changed in the view, the selection and the catalog
 * search is logged: tests that drive the window with real events read it back. */
static void log_changes(const planner *p)
{
    static const char *const view_names[] = {"3D", "plan", "elevation"}; /* UI_VIEW_* */
    static int last_view = -1, last_selected = -1;
    static char last_search[sizeof p->browser.text];
    if (!p->script.count)
        return;
    if (last_view < 0)
        last_view = p->view;
    if (p->view != last_view && p->view >= 0 && p->view < 3) {
        fprintf(stderr, "tessera: view %s\n", view_names[p->view]);
        last_view = p->view;
    }
    int s = p->plan_o.selected_object;
    if (s != last_selected) {
        if (s >= 0 && s < p->project.object_count)
            fprintf(stderr, "tessera: selected \"%s\"\n", p->project.objects[s].name);
        else
            fprintf(stderr, "tessera: selection cleared\n");
        last_selected = s;
    }
    if (strcmp(p->browser.text, last_search)) {
        fprintf(stderr, "tessera: catalog search \"%s\"\n", p->browser.text);
        memcpy(last_search, p->browser.text, sizeof last_search);
    }
}

static void drag_3d_view(planner *p)
{
    double x, y;
    ui_gui_pointer(&x, &y);
    int down = ui_gui_mouse_down(GLFW_MOUSE_BUTTON_LEFT);
    if (down && !p->dragging && !ui_gui_wants_mouse()) {
        p->dragging = 1;
        /* A press on the selection's handles moves or turns it, on a fixture (orbit mode)
         * drags it; elsewhere it turns the view. */
        if (p->mode == UI_MODE_ORBIT && !p->presenting && !planner_handles_press(p, x, y))
            planner_fixture_drag_press(p, x, y);
    } else if (!down) {
        planner_handles_release(p);
        if (p->fixture_drag.active && p->fixture_drag.by_pointer)
            planner_fixture_drag_end(p, 1);
        p->dragging = 0;
    }
    if (planner_handles_dragging(p))
        planner_handles_pointer(p, x, y);
    else if (p->fixture_drag.active && p->fixture_drag.by_pointer)
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
}

/* Walking reads the keys held now: a held key is a speed, not an event. */
static void walk_keys(planner *p, double dt)
{
    GLFWwindow *w = p->window;
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

int planner_input_live(const planner *p)
{
    return !p->script.count || p->action >= p->script.count ||
           p->script.actions[p->action].kind == UI_ACT_WAIT_FILE;
}

void planner_handle_input(planner *p, double dt)
{
    frame_delay();
    log_changes(p);
    ui_gui_take_input();
    const ui_input_frame *in = ui_gui_input();
    int keyboard_free = !ui_gui_wants_keyboard();
    for (int i = 0; i < in->count; i++) {
        const ui_input_event *e = &in->events[i];
        if (e->kind == UI_INPUT_KEY && e->action == GLFW_PRESS && keyboard_free)
            on_key(p, e->code, e->mods);
        else if (e->kind == UI_INPUT_SCROLL)
            on_scroll(p, e->y);
    }
    if (p->view != UI_VIEW_3D)
        return; /* the plan and the elevation read the pointer themselves */
    drag_3d_view(p);
    if (p->mode == UI_MODE_WALK && keyboard_free && dt > 0 && dt <= 0.5)
        walk_keys(p, dt);
}
