/* The plan's Wall panel buttons (ui/src/planner_plan.c, planner_wall_item_line): on each wall
 * of the designed demo the door, window, pre-wall and niche lines are edit lines app accepts
 * or refuses with a reason (the wall may be too short or taken), each accepted one adds exactly
 * one item of its kind, names stay unique ("door-1", then "door-2"), and a wall that does not
 * exist gives no line. No window: the planner struct holds just the project. */
#include "check.h"
#include "planner.h"

#include "app/project/commands.h"

#include <stdio.h>
#include <string.h>

static int count(const app_room_plan *pl, int kind)
{
    if (kind == 2)
        return pl->prewall_count;
    if (kind == 3)
        return pl->niche_count;
    int n = 0;
    for (int i = 0; i < pl->opening_count; i++)
        n += (int)pl->openings[i].type == (kind == 0 ? APP_OPENING_DOOR : APP_OPENING_WINDOW);
    return n;
}

int main(void)
{
    static planner p; /* large: not on the stack */
    char err[1024];
    const char *path = TESSERA_SOURCE_DIR "/assets/projects/designed-bathroom.json";
    if (app_project_read(path, &p.project, err, sizeof err) != APP_OK) {
        CHECK_MSG(0, "%s", err);
        return check_report("ui.wall_items");
    }
    app_history *h = app_history_create(50);
    app_script_env env = {0};
    int added[4] = {0, 0, 0, 0};
    char line[256];
    CHECK(!planner_wall_item_line(&p, 0, p.project.plan.corner_count, line, sizeof line));
    CHECK(!planner_wall_item_line(&p, 4, 0, line, sizeof line));
    for (int kind = 0; kind < 4; kind++) {
        int shipped = count(&p.project.plan, kind);
        for (int wall = 0; wall < p.project.plan.corner_count; wall++) {
            if (!planner_wall_item_line(&p, kind, wall, line, sizeof line))
                continue;
            int before = count(&p.project.plan, kind);
            if (app_script_run(&p.project, h, line, strlen(line), "wall-items", &env, NULL, err,
                               sizeof err) == APP_OK) {
                CHECK_MSG(count(&p.project.plan, kind) == before + 1, "%s", line);
                added[kind]++;
            } else {
                CHECK_MSG(count(&p.project.plan, kind) == before, "%s", line);
                CHECK_MSG(err[0] != 0, "%s: refused without a reason", line);
            }
        }
        /* Each kind on the demo as shipped: the doors just added would take the windows' places. */
        for (int i = 0; i < added[kind]; i++)
            CHECK(app_history_undo(h, &p.project, err, sizeof err) == APP_OK);
        CHECK(count(&p.project.plan, kind) == shipped);
    }
    /* The demo's walls have room for each kind somewhere. */
    for (int kind = 0; kind < 4; kind++)
        CHECK_MSG(added[kind] >= 1, "kind %d never fitted", kind);
    /* Names stay unique: with door-1 in the plan the next door is door-2. */
    CHECK(planner_wall_item_line(&p, 0, 1, line, sizeof line));
    CHECK(app_script_run(&p.project, h, line, strlen(line), "wall-items", &env, NULL, err,
                         sizeof err) == APP_OK);
    CHECK(planner_wall_item_line(&p, 0, 3, line, sizeof line));
    const char *want = "door door-2 ";
    CHECK_MSG(strncmp(line, want, strlen(want)) == 0, "%s (want %s...)", line, want);
    app_history_destroy(h);
    app_project_free_all(&p.project);
    return check_report("ui.wall_items");
}
