/* The rules that span sections of a project, checked once after every section is read, so
 * that every command (check included) refuses what any one of them could not do: the lights
 * the renderer can hold (the project's own and the daylight the windows let in) and the
 * image size the writer can write (app/project/job_limits.h). */
#include "project_internal.h"

#include "app/project/job_limits.h"

#include <stdio.h>

/* Windows with daylight ("light" not black) add a sky rectangle light and, when the sun is on
 * their wall, a sun light (app/design/room_mesh_window.c). The sun depends on the time a
 * command may set (--time), so each counts as two. */
static int window_lights(const app_room_plan *plan, int *first_window)
{
    int n = 0;
    *first_window = -1;
    for (int i = 0; i < plan->opening_count; i++) {
        const app_opening *o = &plan->openings[i];
        if (o->type != APP_OPENING_WINDOW ||
            !(o->light[0] > 0 || o->light[1] > 0 || o->light[2] > 0))
            continue;
        if (*first_window < 0)
            *first_window = i;
        n += 2;
    }
    return n;
}

static app_result check_lights(pj_ctx *c, const app_project *p)
{
    const app_limit *limit = &app_limits()[APP_LIMIT_LIGHTS];
    int max = (int)limit->value, first_window;
    int from_windows = window_lights(&p->plan, &first_window);
    if (p->light_count > max) {
        size_t mark = pj_path_key(c, "lights");
        pj_path_index(c, max);
        app_result r = pj_fail(c, APP_ERR_SCHEMA, "%d lights; the renderer holds at most %d",
                               p->light_count, max);
        pj_path_restore(c, mark);
        return r;
    }
    if (p->light_count + from_windows > max) {
        size_t mark = pj_path_key(c, "plan");
        pj_path_key(c, "openings");
        pj_path_index(c, first_window);
        app_result r = pj_fail(c, APP_ERR_SCHEMA,
                               "%d lights in $.lights and %d from the windows' daylight (a lit "
                               "window adds a sky and a sun light) are more than the renderer's "
                               "%d",
                               p->light_count, from_windows, max);
        pj_path_restore(c, mark);
        return r;
    }
    return APP_OK;
}

static app_result check_render_size(pj_ctx *c, const app_project *p)
{
    char why[512];
    if (app_image_size_fits(p->render.width, p->render.height, why, sizeof why))
        return APP_OK;
    size_t mark = pj_path_key(c, "render");
    pj_path_key(c, "size");
    app_result r = pj_fail(c, APP_ERR_SCHEMA, "%dx%d: %s", p->render.width, p->render.height, why);
    pj_path_restore(c, mark);
    return r;
}

app_result pj_validate_project(pj_ctx *c, const app_project *p)
{
    app_result r = check_lights(c, p);
    if (r == APP_OK)
        r = check_render_size(c, p);
    return r;
}
