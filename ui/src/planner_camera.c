/* The planner's cameras in the room: the orbit kept inside (navigation.c does the geometry),
 * walk mode entered from the view on screen, the walker stopped by fixtures. */
#include "planner.h"

#include <stdlib.h>
#include <string.h>

/* Fixtures the walker's body meets: those that reach below eye height (a ceiling lamp does
 * not; a wall-hung WC, a basin or a mirror does). */
static ui_obstacle *walk_obstacles(const planner *p, int *count)
{
    *count = 0;
    if (p->fixture_count <= 0 || !p->fixtures)
        return NULL;
    ui_obstacle *o = malloc((size_t)p->fixture_count * sizeof *o);
    if (!o)
        return NULL;
    for (int i = 0; i < p->fixture_count; i++) {
        const app_fixture *f = &p->fixtures[i];
        if (f->z0 >= UI_EYE_HEIGHT_MM)
            continue;
        o[*count] =
            (ui_obstacle){{f->centre[0], f->centre[1]}, {f->half[0], f->half[1]}, f->angle_deg};
        (*count)++;
    }
    return o;
}

void planner_set_mode(planner *p, int mode)
{
    if (mode == UI_MODE_WALK && p->camera_mode != UI_MODE_WALK) {
        /* The walker stands where the view was, at eye height, facing the same way. */
        int was = p->mode;
        p->mode = p->camera_mode;
        double eye[3], target[3];
        planner_view_points(p, eye, target);
        p->mode = was;
        app_point2 box[4];
        app_room_plan fallback;
        int n;
        ui_obstacle *obs = walk_obstacles(p, &n);
        p->walk = ui_walk_from_view(planner_plan(p, box, &fallback), obs, n, eye, target);
        free(obs);
        p->flight.active = 0;
    }
    p->mode = mode;
    p->camera_mode = mode;
}

void planner_camera_sync(planner *p)
{
    if (p->mode != p->camera_mode)
        planner_set_mode(p, p->mode);
}

int planner_walk_move(planner *p, double forward_mm, double right_mm)
{
    planner_set_mode(p, UI_MODE_WALK);
    app_point2 box[4];
    app_room_plan fallback;
    int n;
    ui_obstacle *obs = walk_obstacles(p, &n);
    int full =
        ui_walk_move_among(&p->walk, planner_plan(p, box, &fallback), obs, n, forward_mm, right_mm);
    free(obs);
    return full;
}
