/* `tessera edit PROJECT SCRIPT [-o OUT] [--db CATALOG] [--quiet]`: replays an edit script
 * (docs/editing.md) against a project through the command history and saves the result
 * atomically (app_project_write). Nothing is saved when a line fails; the message names it. */
#include "cli_commands.h"
#include "app/project/commands.h"
#include "app/design/placement.h"
#include "app/project/project.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { EDIT_OK = 0, EDIT_FAILED = 1, EDIT_USAGE = 2 };

#define MAX_SCRIPT_BYTES (16L * 1024 * 1024)

static char *read_script(const char *path, size_t *len, char *err, size_t err_size)
{
    FILE *f = strcmp(path, "-") ? fopen(path, "rb") : stdin;
    if (!f) {
        snprintf(err, err_size, "%s: cannot open", path);
        return NULL;
    }
    size_t cap = 4096, n = 0;
    char *buf = malloc(cap);
    while (buf) {
        if (n == cap) {
            if ((long)cap >= MAX_SCRIPT_BYTES) {
                snprintf(err, err_size, "%s: larger than %ld bytes", path, MAX_SCRIPT_BYTES);
                free(buf);
                buf = NULL;
                break;
            }
            char *grown = realloc(buf, cap * 2);
            if (!grown) {
                free(buf);
                buf = NULL;
                snprintf(err, err_size, "%s: out of memory", path);
                break;
            }
            buf = grown;
            cap *= 2;
        }
        size_t got = fread(buf + n, 1, cap - n, f);
        if (got == 0) {
            if (ferror(f)) {
                snprintf(err, err_size, "%s: cannot read", path);
                free(buf);
                buf = NULL;
            }
            break;
        }
        n += got;
    }
    if (f != stdin)
        fclose(f);
    *len = n;
    return buf;
}

static void free_project(app_project *p)
{
    free(p->plan.corners);
    free(p->plan.openings);
    free(p->plan.prewalls);
    free(p->plan.niches);
    free(p->tilings);
    p->plan.corners = NULL;
    p->plan.openings = NULL;
    p->plan.prewalls = NULL;
    p->plan.niches = NULL;
    p->tilings = NULL;
    app_project_free(p);
}

int cli_cmd_edit(const cli_options *o)
{
    const char *project = o->args[0], *script = o->args[1], *out = o->output, *db = o->db;
    int quiet = o->quiet;
    char err[4096];
    size_t len = 0;
    char *text = read_script(script, &len, err, sizeof err);
    if (!text) {
        fprintf(stderr, "tessera edit: %s\n", err);
        return EDIT_USAGE;
    }
    app_project p;
    if (app_project_read(project, &p, err, sizeof err) != APP_OK) {
        fprintf(stderr, "tessera edit: %s\n", err);
        free(text);
        return EDIT_USAGE;
    }
    app_history *h = app_history_create(0);
    app_lazy_catalog cat;
    memset(&cat, 0, sizeof cat);
    cat.db_path = db;
    app_script_env env = {app_placement_lazy_lookup, &cat, app_placement_assets_dir(),
                          quiet ? NULL : stderr};
    app_script_stats st;
    int rc = EDIT_OK;
    if (!h) {
        fprintf(stderr, "tessera edit: out of memory\n");
        rc = EDIT_FAILED;
    } else if (app_script_run(&p, h, text, len, script, &env, &st, err, sizeof err) != APP_OK) {
        fprintf(stderr, "tessera edit: %s\n", err);
        fprintf(stderr, "tessera edit: nothing saved\n");
        rc = EDIT_USAGE;
    } else {
        const char *dest = out ? out : project;
        if (app_project_write(dest, &p, err, sizeof err) != APP_OK) {
            fprintf(stderr, "tessera edit: %s\n", err);
            rc = EDIT_FAILED;
        } else {
            printf("%s: %d lines, %d commands, %d undone, %d redone; saved %s\n", script, st.lines,
                   st.commands, st.undone, st.redone, dest);
        }
    }
    app_history_destroy(h);
    app_placement_lazy_close(&cat);
    free_project(&p);
    free(text);
    return rc;
}
