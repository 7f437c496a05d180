/* `tessera check PROJECT [--barrier-free | --wheelchair] [--db CATALOG]`: reads and validates a
 * project, then prints the placement findings (app/design/placement.h, docs/editing.md). Exit 0
 * when no finding is an error, 1 otherwise, 2 for bad usage or a project that cannot be read. */
#include "cli_commands.h"
#include "app/design/far_objects.h"
#include "cli_check_tiles.h"
#include "app/design/placement.h"
#include "app/project/flat.h"
#include "app/project/project.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { CHECK_OK = 0, CHECK_FINDINGS = 1, CHECK_USAGE = 2 };

/* Prints the findings, each led by the room's name in a flat; returns the number of errors. */
static int print_findings(const char *room, const app_findings *f)
{
    for (int i = 0; i < f->count; i++) {
        const app_finding *x = &f->items[i];
        printf("%s%s%-7s %-12s at (%6.0f, %6.0f) mm: %s\n", room ? room : "", room ? ": " : "",
               app_severity_name(x->severity), app_finding_kind_name(x->kind), x->position_mm[0],
               x->position_mm[1], x->message);
    }
    return app_findings_errors(f);
}

typedef struct check_totals {
    int fixtures, findings, errors;
    double footprint_ms, check_ms;
} check_totals;

/* One room: its placement, far-object and tile findings, added to *t. room NULL: a single-room
 * project, printed as before. Returns CHECK_OK or CHECK_USAGE. */
static int check_room(const app_project *p, const char *room, const char *project,
                      const app_check_options *opt, app_lazy_catalog *cat, check_totals *t)
{
    app_fixture *fx = NULL;
    int n = 0;
    app_findings findings = {0};
    char err[4096];
    double t0 = cli_now_ms();
    app_result r =
        app_placement_fixtures(p, app_placement_lazy_lookup, cat, &fx, &n, err, sizeof err);
    double t1 = cli_now_ms();
    if (r == APP_OK)
        r = app_placement_check(p, fx, n, opt, &findings, err, sizeof err);
    if (r == APP_OK)
        r = app_far_objects_check(p, fx, n, &findings, err, sizeof err);
    double t2 = cli_now_ms();
    int rc = CHECK_OK;
    if (r != APP_OK) {
        fprintf(stderr, "tessera check: %s: %s%s%s\n", project, room ? room : "", room ? ": " : "",
                err);
        rc = CHECK_USAGE;
    } else {
        if (room)
            printf("Room \"%s\": %d fixtures\n", room, n);
        int tile_findings = 0;
        t->errors += print_findings(room, &findings);
        cli_check_tile_cuts(p, cat, &tile_findings);
        t->fixtures += n;
        t->findings += findings.count + tile_findings;
        t->footprint_ms += t1 - t0;
        t->check_ms += t2 - t1;
    }
    free(fx);
    app_findings_free(&findings);
    return rc;
}

int cli_cmd_check(const cli_options *o)
{
    const char *project = o->project, *db = o->db;
    app_check_options opt = {o->wheelchair     ? APP_BARRIER_FREE_WHEELCHAIR
                             : o->barrier_free ? APP_BARRIER_FREE_ON
                                               : APP_BARRIER_FREE_OFF};
    app_flat flat;
    char err[4096];
    double t_read = cli_now_ms();
    app_result read = app_flat_read(project, &flat, err, sizeof err);
    t_read = cli_now_ms() - t_read;
    if (read != APP_OK) {
        fprintf(stderr, "tessera check: %s\n", err);
        return CHECK_USAGE;
    }
    app_lazy_catalog cat;
    memset(&cat, 0, sizeof cat);
    cat.db_path = db;
    check_totals t = {0};
    int rc = CHECK_OK;
    for (int i = 0; rc == CHECK_OK && i < flat.room_count; i++)
        rc = check_room(&flat.rooms[i], flat.is_flat ? flat.rooms[i].name : NULL, project, &opt,
                        &cat, &t);
    if (rc == CHECK_OK) {
        char rooms[64] = "";
        if (flat.is_flat)
            snprintf(rooms, sizeof rooms, " in %d rooms", flat.room_count);
        printf("%s: %d fixtures checked%s%s; %d findings, %d errors\n", project, t.fixtures, rooms,
               opt.barrier_free == APP_BARRIER_FREE_WHEELCHAIR ? " (wheelchair, DIN 18040-2)"
               : opt.barrier_free == APP_BARRIER_FREE_ON       ? " (barrier-free, DIN 18040-2)"
                                                               : "",
               t.findings, t.errors);
        rc = t.errors ? CHECK_FINDINGS : CHECK_OK;
        fprintf(stderr,
                "tessera check: read %d room%s in %.1f ms, footprints %.1f ms (catalog "
                "lookups), checks %.1f ms\n",
                flat.room_count, flat.room_count == 1 ? "" : "s", t_read, t.footprint_ms,
                t.check_ms);
    }
    app_placement_lazy_close(&cat);
    app_flat_free(&flat);
    return rc;
}
