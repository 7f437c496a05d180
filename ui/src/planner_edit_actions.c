/* Actions a menu entry, a toolbar button and a key share (menu_bar.c, toolbar.c): each is one
 * edit line or one state change, as the key does it (planner_input.c). */
#include "planner.h"

#include <math.h>
#include <stdio.h>
#include <time.h>

static const app_object *selected_object(const planner *p)
{
    int i = p->plan_o.selected_object;
    return i >= 0 && i < p->project.object_count ? &p->project.objects[i] : NULL;
}

int planner_delete_selected(planner *p)
{
    const app_object *o = selected_object(p);
    if (!o) {
        planner_status(p, "select a fixture first");
        return 1;
    }
    char line[256];
    snprintf(line, sizeof line, "remove \"%s\"", o->name);
    p->plan_o.selected_object = -1;
    return planner_edit(p, line);
}

int planner_rotate_selected(planner *p)
{
    const app_object *o = selected_object(p);
    if (!o) {
        planner_status(p, "select a fixture first");
        return 1;
    }
    char line[256];
    snprintf(line, sizeof line, "rotate \"%s\" %.0f", o->name, fmod(o->rotation_deg[2] + 90, 360));
    return planner_edit(p, line);
}

void planner_toggle_tour(planner *p)
{
    p->touring = !p->touring;
    p->tour_clock = 1e9; /* leave for the next viewpoint at once */
}

int planner_print_shot_now(planner *p)
{
    char name[256];
    time_t t = time(NULL);
    struct tm tm;
    localtime_r(&t, &tm);
    strftime(name, sizeof name, "tessera-%Y%m%d-%H%M%S.png", &tm);
    return planner_print_shot(p, name);
}
