/* Window edits that would make a fixture reach through a wall are refused (planner.h,
 * planner_edit_reaches_out). The window's soak found two ways in: a drag released where no wall
 * was near enough to snap to, accepted because the pointer (the footprint's centre) was inside
 * the room while the footprint reached 9 mm through a wall; and a fixture against a wall turned
 * by 90 degrees about its back. Rather than a test per path (drag, drop, turn, the position
 * fields, a product swap), the edit is tried on a copy of the project and the copy checked as
 * `tessera check` checks it (app_placement_check's outside-room finding). */
#include "planner.h"

#include "app/design/placement.h"
#include "app/project/commands.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The edit lines that move, turn, add or resize a fixture (docs/editing.md). */
static int moves_fixtures(const char *line)
{
    static const char *const verbs[] = {"place ",  "add ",     "move ",   "nudge ",
                                        "rotate ", "variant ", "product "};
    for (size_t i = 0; i < sizeof verbs / sizeof verbs[0]; i++)
        if (!strncmp(line, verbs[i], strlen(verbs[i])))
            return 1;
    return 0;
}

/* 1 when the findings hold an outside-room finding for object. */
static int reached_out(const app_findings *f, int object)
{
    for (int i = 0; i < f->count; i++)
        if (f->items[i].kind == APP_FINDING_OUTSIDE_ROOM && f->items[i].objects[0] == object)
            return 1;
    return 0;
}

int planner_edit_reaches_out(planner *p, const char *line, char *why, size_t why_size)
{
    if (!moves_fixtures(line))
        return 0;
    app_project trial;
    char err[1024];
    if (app_project_copy(&trial, &p->project, err, sizeof err) != APP_OK)
        return 0; /* out of memory: the edit itself reports what fails */
    app_history *h = app_history_create(1);
    app_script_env env = {.lookup = app_placement_lazy_lookup,
                          .user = &p->catalog,
                          .assets_dir = app_placement_assets_dir()};
    app_fixture *fx = NULL;
    int n = 0, refused = 0;
    app_findings found;
    memset(&found, 0, sizeof found);
    app_check_options opt = {.barrier_free = APP_BARRIER_FREE_OFF};
    if (h &&
        app_script_run(&trial, h, line, strlen(line), "edit", &env, NULL, err, sizeof err) ==
            APP_OK &&
        app_placement_fixtures(&trial, app_placement_lazy_lookup, &p->catalog, &fx, &n, err,
                               sizeof err) == APP_OK &&
        app_placement_check(&trial, fx, n, &opt, &found, err, sizeof err) == APP_OK) {
        /* A fixture already reaching out (an old file) may still be moved, back in or not. */
        for (int i = 0; i < found.count && !refused; i++) {
            const app_finding *f = &found.items[i];
            int o = f->objects[0];
            if (f->kind != APP_FINDING_OUTSIDE_ROOM || o < 0 || o >= trial.object_count ||
                (o < p->project.object_count && reached_out(&p->findings, o)))
                continue;
            char verb[16] = "";
            sscanf(line, "%15s", verb);
            snprintf(why, why_size, "%s would reach through a wall: %s refused",
                     trial.objects[o].name, verb);
            refused = 1;
        }
    }
    app_findings_free(&found);
    free(fx);
    app_history_destroy(h);
    app_project_free_all(&trial);
    return refused;
}
