/* Script actions for tests that work the window with real X events (xdotool) instead of
 * scripted ones: wait-file holds the script while the outside driver works, locate tells it
 * where to click, expect-search reads a text field back (script.h). */
#include "planner.h"

#include "gui.h"
#include "input_queue.h"

#include <GLFW/glfw3.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

enum { WAIT_FILE_SECONDS = 60 };

/* Done once PATH exists and every event sent before it was handled: the driver creates PATH
 * after its last event reached the X server, so one more frame's poll has them all queued, and
 * the script goes on when the queue is empty (a slow frame can leave clicks waiting). It fails
 * after WAIT_FILE_SECONDS without the file and without any input. */
int planner_wait_file(planner *p, const ui_action *a)
{
    static int waiting_action = -1, file_seen;
    static double since;
    double now = glfwGetTime();
    if (waiting_action != p->action) {
        waiting_action = p->action;
        file_seen = 0;
        since = now;
        fprintf(stderr, "tessera: script line %d: waiting for %s\n", a->line, a->text);
    }
    if (file_seen && ui_gui_input_pending() == 0) {
        waiting_action = -1;
        p->action++;
        p->action_frame = 0;
        return 0;
    }
    file_seen = file_seen || access(a->text, F_OK) == 0;
    if (ui_gui_input()->count > 0 || ui_gui_input_pending() > 0)
        since = now; /* the driver is at work: a long one (the soak) may take minutes */
    if (now - since > WAIT_FILE_SECONDS) {
        fprintf(stderr, "tessera: script line %d: %s within %d s\n", a->line,
                file_seen ? "the input was not handled" : "the file did not appear",
                WAIT_FILE_SECONDS);
        waiting_action = -1;
        p->exit_code = 1;
        return 1;
    }
    return 0;
}

static int locate_fixture(planner *p, const char *name)
{
    if (p->view != UI_VIEW_PLAN) {
        snprintf(p->status, sizeof p->status, "locate fixture needs the plan view (view plan)");
        return 1;
    }
    for (int i = 0; i < p->fixture_count; i++) {
        const app_fixture *f = &p->fixtures[i];
        if (f->object < 0 || f->object >= p->project.object_count ||
            strcmp(p->project.objects[f->object].name, name))
            continue;
        float sx, sy;
        ui_plan_to_screen(&p->plan_t, f->centre[0], f->centre[1], &sx, &sy);
        fprintf(stderr, "tessera: locate fixture \"%s\" at %.0f %.0f\n", name, sx, sy);
        return 0;
    }
    snprintf(p->status, sizeof p->status, "the plan has no fixture \"%s\"", name);
    return 1;
}

/* A fixture's footprint in plan mm (what the walker and the checks see): centre, half sides,
 * turn and heights, so a session can tell whether an eye entered it. */
static int locate_box(planner *p, const char *name)
{
    for (int i = 0; i < p->fixture_count; i++) {
        const app_fixture *f = &p->fixtures[i];
        if (f->object < 0 || f->object >= p->project.object_count ||
            strcmp(p->project.objects[f->object].name, name))
            continue;
        fprintf(stderr,
                "tessera: locate box \"%s\" centre %.1f %.1f half %.1f %.1f angle %.1f z %.0f "
                "%.0f\n",
                name, f->centre[0], f->centre[1], f->half[0], f->half[1], f->angle_deg, f->z0,
                f->z1);
        return 0;
    }
    snprintf(p->status, sizeof p->status, "the project has no fixture \"%s\"", name);
    return 1;
}

/* The eye of the view on screen, in plan mm, and the camera mode. */
static int locate_eye(planner *p)
{
    double eye[3], target[3];
    planner_view_points(p, eye, target);
    fprintf(stderr, "tessera: locate eye at %.1f %.1f %.1f %s\n", eye[0], eye[1], eye[2],
            p->mode == UI_MODE_WALK ? "walk" : "orbit");
    return 0;
}

/* Where plan point "X Y" (mm) shows in the plan view. */
static int locate_plan_point(planner *p, const char *xy)
{
    double x, y;
    if (p->view != UI_VIEW_PLAN || sscanf(xy, "%lf %lf", &x, &y) != 2) {
        snprintf(p->status, sizeof p->status,
                 "locate plan X Y needs the plan view and two numbers");
        return 1;
    }
    float sx, sy;
    ui_plan_to_screen(&p->plan_t, x, y, &sx, &sy);
    fprintf(stderr, "tessera: locate plan %.0f %.0f at %.0f %.0f\n", x, y, sx, sy);
    return 0;
}

/* The box around the selection's outline in the 3D view (selection_3d.c). */
static int locate_selection(planner *p)
{
    float b[4];
    if (planner_selection_3d_bounds(p, b))
        fprintf(stderr, "tessera: locate selection at %.0f %.0f %.0f %.0f\n", b[0], b[1], b[2],
                b[3]);
    else
        fprintf(stderr, "tessera: locate selection: none shows\n");
    return 0;
}

/* required = 0 (locate widget-if-drawn): a widget not drawn is logged, not a failure (the soak
 * asks between segments, when the monkey may have hidden the panels). */
static int locate_widget(planner *p, const char *label, int required)
{
    float r[4];
    int visible;
    if (!ui_gui_locate(label, r, &visible)) {
        if (!required) {
            fprintf(stderr, "tessera: locate widget \"%s\" not drawn\n", label);
            return 0;
        }
        snprintf(p->status, sizeof p->status, "no button or text field \"%s\" is drawn", label);
        return 1;
    }
    fprintf(stderr, "tessera: locate widget \"%s\" at %.0f %.0f %s (%.0f %.0f %.0f %.0f)\n", label,
            (r[0] + r[2]) / 2, (r[1] + r[3]) / 2, visible ? "visible" : "hidden", r[0], r[1], r[2],
            r[3]);
    return 0;
}

int planner_input_action(planner *p, const ui_action *a)
{
    if (a->kind == UI_ACT_EXPECT_SEARCH) {
        if (strcmp(p->browser.text, a->text)) {
            snprintf(p->status, sizeof p->status,
                     "the catalog search holds \"%.120s\", expected \"%.120s\"", p->browser.text,
                     a->text);
            return 1;
        }
        return 0;
    }
    if (a->kind == UI_ACT_LOCATE) {
        if (!strncmp(a->text, "fixture ", 8))
            return locate_fixture(p, a->text + 8);
        if (!strncmp(a->text, "widget-if-drawn ", 16))
            return locate_widget(p, a->text + 16, 0);
        if (!strncmp(a->text, "widget ", 7))
            return locate_widget(p, a->text + 7, 1);
        if (!strcmp(a->text, "selection"))
            return locate_selection(p);
        if (!strncmp(a->text, "box ", 4))
            return locate_box(p, a->text + 4);
        if (!strcmp(a->text, "eye"))
            return locate_eye(p);
        if (!strncmp(a->text, "handle ", 7))
            return planner_handles_locate(p, a->text + 7);
        if (!strncmp(a->text, "plan ", 5))
            return locate_plan_point(p, a->text + 5);
        snprintf(p->status, sizeof p->status,
                 "locate widget LABEL, fixture NAME, box NAME, eye, selection, handle NAME or "
                 "plan X Y");
        return 1;
    }
    return 0; /* wait-file runs in planner_wait_file */
}
