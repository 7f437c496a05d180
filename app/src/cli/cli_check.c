/* `tessera check PROJECT [--barrier-free | --wheelchair] [--db CATALOG]`: reads and validates a
 * project, then prints the placement findings (app/design/placement.h, docs/editing.md). Exit 0
 * when no finding is an error, 1 otherwise, 2 for bad usage or a project that cannot be read. */
#include "app/cli/cli.h"
#include "app/design/placement.h"
#include "app/project/project.h"
#include "cli_options.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { CHECK_OK = 0, CHECK_FINDINGS = 1, CHECK_USAGE = 2 };

static void check_usage(FILE *f)
{
    fprintf(f, "usage: tessera check PROJECT [--barrier-free | --wheelchair] [--db CATALOG]\n"
               "  validates the project file and checks its fixtures: collisions, walls,\n"
               "  free areas and 200 mm distances (VDI 6000); --barrier-free adds DIN 18040-2\n"
               "  1200 x 1200 free areas and doors opening outwards, --wheelchair 1500 x 1500\n"
               "  and the WC's 900/300 mm sides.\n"
               "  Exit 0: no errors; 1: errors found; 2: bad usage or unreadable project.\n");
}

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

int app_cli_check(int argc, char **argv)
{
    const char *project = NULL, *db = NULL;
    app_check_options opt = {APP_BARRIER_FREE_OFF};
    for (int i = 2; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            check_usage(stdout);
            return CHECK_OK;
        } else if (!strcmp(argv[i], "--barrier-free")) {
            opt.barrier_free = APP_BARRIER_FREE_ON;
        } else if (!strcmp(argv[i], "--wheelchair")) {
            opt.barrier_free = APP_BARRIER_FREE_WHEELCHAIR;
        } else if (!strcmp(argv[i], "--db") && i + 1 < argc) {
            db = argv[++i];
        } else if (argv[i][0] == '-' || project) {
            fprintf(stderr, "tessera check: unexpected argument \"%s\"\n", argv[i]);
            check_usage(stderr);
            return CHECK_USAGE;
        } else {
            project = argv[i];
        }
    }
    if (!project) {
        check_usage(stderr);
        return CHECK_USAGE;
    }
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
    double t2 = cli_now_ms();
    if (r != APP_OK) {
        fprintf(stderr, "tessera check: %s: %s\n", project, err);
        rc = CHECK_USAGE;
    } else {
        int errors = print_findings(&p, &findings);
        printf("%s: %d fixtures checked%s; %d findings, %d errors\n", project, n,
               opt.barrier_free == APP_BARRIER_FREE_WHEELCHAIR ? " (wheelchair, DIN 18040-2)"
               : opt.barrier_free == APP_BARRIER_FREE_ON       ? " (barrier-free, DIN 18040-2)"
                                                               : "",
               findings.count, errors);
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
