/* Dragging a placed fixture in the 3D view (fixture_drag.h). */
#include "fixture_drag.h"

#include "planner.h"
#include "view_ray.h"

#include "app/project/commands.h"

#include <GLFW/glfw3.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The ray from the eye through window pixel (sx, sy) of the 3D view's pane, mm. */
static int pixel_ray(planner *p, double sx, double sy, double eye[3], double dir[3])
{
    ui_rect r = planner_view_rect(p);
    int w = (int)r.w, h = (int)r.h;
    sx -= r.x;
    sy -= r.y;
    rd_view v;
    planner_view(p, w, h, &v);
    double target[3];
    for (int k = 0; k < 3; k++) {
        eye[k] = v.eye[k] * 1e3;
        target[k] = v.target[k] * 1e3;
    }
    return ui_view_ray(eye, target, v.fov_y_deg, w, h, sx, sy, dir);
}

static const app_fixture *fixture_of_object(const planner *p, int object)
{
    for (int i = 0; i < p->fixture_count; i++)
        if (p->fixtures[i].object == object)
            return &p->fixtures[i];
    return NULL;
}

/* Project object `object`, every object in its group and every object mounted on it (a
 * vanity's basin, tap and mirror), where the document has them. */
static int collect_objects(planner *p, ui_fixture_drag *d)
{
    const app_project *pr = &p->project;
    const char *group = pr->objects[d->object].group;
    d->objects = malloc((size_t)pr->object_count * sizeof *d->objects);
    d->start = malloc((size_t)pr->object_count * sizeof *d->start);
    int *mounted = malloc((size_t)pr->object_count * sizeof *mounted);
    if (!d->objects || !d->start || !mounted) {
        free(mounted);
        return 0;
    }
    int n_mounted = app_group_members(pr, d->object, mounted), m = 0;
    d->object_count = 0;
    for (int i = 0; i < pr->object_count; i++) {
        while (m < n_mounted && mounted[m] < i)
            m++;
        int on_it = m < n_mounted && mounted[m] == i;
        if (i != d->object && !on_it && !(group[0] && !strcmp(pr->objects[i].group, group)))
            continue;
        d->objects[d->object_count] = i;
        memcpy(d->start[d->object_count++], pr->objects[i].position_mm, sizeof d->start[0]);
    }
    free(mounted);
    return 1;
}

static void drag_free(ui_fixture_drag *d)
{
    free(d->objects);
    free(d->start);
    memset(d, 0, sizeof *d);
}

void planner_fixture_drag_forget(planner *p)
{
    drag_free(&p->fixture_drag);
}

int planner_fixture_drag_begin(planner *p, int object, const double grab[3])
{
    ui_fixture_drag *d = &p->fixture_drag;
    const app_fixture *f = fixture_of_object(p, object);
    if (d->active || !f || !p->scene_ready)
        return 1;
    memset(d, 0, sizeof *d);
    d->object = object;
    d->plane_z = grab[2];
    d->grab[0] = grab[0];
    d->grab[1] = grab[1];
    d->start_centre[0] = d->centre[0] = f->centre[0];
    d->start_centre[1] = d->centre[1] = f->centre[1];
    if (!collect_objects(p, d)) {
        drag_free(d);
        planner_status(p, "drag: out of memory");
        return 1;
    }
    d->active = 1;
    p->plan_o.selected_object = object; /* the dragged fixture is the selection */
    return 0;
}

void planner_fixture_drag_to(planner *p, double x_mm, double y_mm)
{
    ui_fixture_drag *d = &p->fixture_drag;
    if (!d->active)
        return;
    d->centre[0] = x_mm;
    d->centre[1] = y_mm;
    /* A translation in the plan of every object of the fixture. */
    double dx = x_mm - d->start_centre[0], dy = y_mm - d->start_centre[1];
    for (int i = 0; i < d->object_count; i++) {
        double at[3] = {d->start[i][0] + dx, d->start[i][1] + dy, d->start[i][2]};
        app_scene_move_object(&p->scene, &p->project, d->objects[i], at);
    }
}

int planner_fixture_drag_end(planner *p, int commit)
{
    ui_fixture_drag *d = &p->fixture_drag;
    if (!d->active)
        return 0;
    int moved = hypot(d->centre[0] - d->start_centre[0], d->centre[1] - d->start_centre[1]) > 1;
    char name[sizeof p->project.objects[0].name];
    memcpy(name, p->project.objects[d->object].name, sizeof name);
    double x = d->centre[0], y = d->centre[1];
    /* Back where the drag began, in the document and the scene, so that the edit below moves
     * the fixture from there (and a refused edit leaves it there). */
    planner_fixture_drag_to(p, d->start_centre[0], d->start_centre[1]);
    drag_free(d);
    /* One move edit (snapped to the nearest wall): the scene is rebuilt from the document. */
    return commit && moved ? planner_drag_object(p, name, x, y) : 0;
}

int planner_fixture_drag_press(planner *p, double sx, double sy)
{
    double eye[3], dir[3];
    if (!pixel_ray(p, sx, sy, eye, dir))
        return 0;
    int f = ui_pick_fixture(eye, dir, p->fixtures, p->fixture_count);
    if (f < 0)
        return 0;
    double t = ui_ray_fixture(eye, dir, &p->fixtures[f]);
    double grab[3] = {eye[0] + t * dir[0], eye[1] + t * dir[1], eye[2] + t * dir[2]};
    if (planner_fixture_drag_begin(p, p->fixtures[f].object, grab) != 0)
        return 0;
    p->fixture_drag.by_pointer = 1;
    return 1;
}

void planner_fixture_drag_pointer(planner *p, double sx, double sy)
{
    ui_fixture_drag *d = &p->fixture_drag;
    double eye[3], dir[3], q[2];
    if (!d->active || !pixel_ray(p, sx, sy, eye, dir) || !ui_ray_plane_z(eye, dir, d->plane_z, q))
        return; /* the pointer above the grabbed height's horizon: the fixture stays */
    planner_fixture_drag_to(p, d->start_centre[0] + q[0] - d->grab[0],
                            d->start_centre[1] + q[1] - d->grab[1]);
}
