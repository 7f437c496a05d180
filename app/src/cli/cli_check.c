/* `tessera check PROJECT [--barrier-free | --wheelchair] [--db CATALOG]`: reads and validates a
 * project, then prints the placement findings (app/design/placement.h, docs/editing.md). Exit 0
 * when no finding is an error, 1 otherwise, 2 for bad usage or a project that cannot be read. */
#include "cli_commands.h"
#include "app/design/far_objects.h"
#include "cli_check_tiles.h"
#include "app/design/placement.h"
#include "app/project/project.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { CHECK_OK = 0, CHECK_FINDINGS = 1, CHECK_USAGE = 2 };

/* Prints the findings; returns the number of errors. */
static int print_findings(const app_project *p, const app_findings *f)
{
    for (int i = 0; i < f->count; i++) {
        const app_finding *x = &f->items[i];
        printf("%-7s %-12s at (%6.0f, %6.0f) mm: %s\n", app_severity_name(x->severity),
               app_finding_kind_name(x->kind), x->position_mm[0], x->position_mm[1], x->message);
    }
    (void)p;
    return app_findings_errors(f);
}

int cli_cmd_check(const cli_options *o)
{
    const char *project = o->project, *db = o->db;
    app_check_options opt = {o->wheelchair     ? APP_BARRIER_FREE_WHEELCHAIR
                             : o->barrier_free ? APP_BARRIER_FREE_ON
                                               : APP_BARRIER_FREE_OFF};
    app_project p;
    char err[4096];
    if (app_project_read(project, &p, err, sizeof err) != APP_OK) {
        fprintf(stderr, "tessera check: %s\n", err);
        return CHECK_USAGE;
    }
    app_lazy_catalog cat;
    memset(&cat, 0, sizeof cat);
    cat.db_path = db;
    app_fixture *fx = NULL;
    int n = 0;
    app_findings findings = {0};
    int rc = CHECK_OK;
    double t0 = cli_now_ms();
    app_result r =
        app_placement_fixtures(&p, app_placement_lazy_lookup, &cat, &fx, &n, err, sizeof err);
    double t1 = cli_now_ms();
    if (r == APP_OK)
        r = app_placement_check(&p, fx, n, &opt, &findings, err, sizeof err);
    if (r == APP_OK)
        r = app_far_objects_check(&p, fx, n, &findings, err, sizeof err);
    double t2 = cli_now_ms();
    if (r != APP_OK) {
        fprintf(stderr, "tessera check: %s: %s\n", project, err);
        rc = CHECK_USAGE;
    } else {
        int errors = print_findings(&p, &findings), tile_findings = 0;
        cli_check_tile_cuts(&p, &cat, &tile_findings);
        printf("%s: %d fixtures checked%s; %d findings, %d errors\n", project, n,
               opt.barrier_free == APP_BARRIER_FREE_WHEELCHAIR ? " (wheelchair, DIN 18040-2)"
               : opt.barrier_free == APP_BARRIER_FREE_ON       ? " (barrier-free, DIN 18040-2)"
                                                               : "",
               findings.count + tile_findings, errors);
        rc = errors ? CHECK_FINDINGS : CHECK_OK;
        fprintf(stderr, "tessera check: footprints %.1f ms (catalog lookups), checks %.1f ms\n",
                t1 - t0, t2 - t1);
    }
    free(fx);
    app_findings_free(&findings);
    app_placement_lazy_close(&cat);
    /* The plan's and tilings' arrays too, whichever module releases them. */
    free(p.plan.corners);
    free(p.plan.openings);
    free(p.plan.prewalls);
    free(p.plan.niches);
    free(p.tilings);
    p.plan.corners = NULL;
    p.plan.openings = NULL;
    p.plan.prewalls = NULL;
    p.plan.niches = NULL;
    p.tilings = NULL;
    app_project_free(&p);
    return rc;
}
