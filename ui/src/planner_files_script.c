/* The window's file and job actions as script verbs (script.h, planner_actions.h). */
#define _GNU_SOURCE /* realpath */

#include "planner.h"
#include "planner_actions.h"
#include "planner_files.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>

/* The scripted verbs (script.h): a->text is "VERB ARGUMENT". */
static int script_fail(const ui_action *a, const char *fmt, const char *what)
{
    fprintf(stderr, "tessera: script line %d: ", a->line);
    fprintf(stderr, fmt, what);
    fputc('\n', stderr);
    return 1;
}

/* Waits (2) while the job runs; then 0 when it ended in `want`, else 1. */
static int wait_job(planner *p, const ui_action *a, ui_job_state want)
{
    planner_files *f = p->files;
    if (f && f->job)
        return 2;
    static const char *const names[] = {"running", "done", "failed", "cancelled"};
    if (!f || !f->has_last)
        return script_fail(a, "%s: no job was started", "job");
    if (f->last_state != want)
        return script_fail(a, "the job ended %s, not as expected", names[f->last_state]);
    return 0;
}

int planner_files_script(planner *p, const ui_action *a)
{
    planner_files *f = planner_files_get(p);
    if (!f)
        return 1;
    char verb[32] = "share";
    const char *arg = a->text;
    if (a->kind != UI_ACT_SHARE) {
        size_t n = strcspn(a->text, " ");
        snprintf(verb, sizeof verb, "%.*s", (int)(n < 31 ? n : 31), a->text);
        arg = a->text + n + strspn(a->text + n, " ");
    }
    static const struct {
        const char *verb;
        planner_job_kind kind;
    } starts[] = {{"share", PLANNER_JOB_SHARE},
                  {"print-pdf", PLANNER_JOB_PRINT_PDF},
                  {"render-image", PLANNER_JOB_RENDER_IMAGE},
                  {"export-glb", PLANNER_JOB_EXPORT_GLB},
                  {"panorama", PLANNER_JOB_PANORAMA},
                  {"video", PLANNER_JOB_VIDEO}};
    for (size_t i = 0; i < sizeof starts / sizeof starts[0]; i++) {
        if (strcmp(verb, starts[i].verb))
            continue;
        if (starts[i].kind != PLANNER_JOB_SHARE)
            return planner_action_job_to(p, starts[i].kind, arg) ? script_fail(a, "%s", p->status)
                                                                 : 0;
        /* share waits for its folder (the script's next action may read it). */
        if (!f->script_started) {
            if (planner_action_job_to(p, PLANNER_JOB_SHARE, arg))
                return script_fail(a, "%s", p->status);
            f->script_started = 1;
            return 2;
        }
        if (f->job)
            return 2;
        f->script_started = 0;
        return wait_job(p, a, UI_JOB_DONE);
    }
    if (!strcmp(verb, "job-wait"))
        return wait_job(p, a, UI_JOB_DONE);
    if (!strcmp(verb, "job-cancel")) {
        if (f->job) {
            ui_job_cancel(f->job);
            return 2;
        }
        return wait_job(p, a, UI_JOB_CANCELLED);
    }
    if (!strcmp(verb, "expect-recovery")) {
        if (p->recovery_offered != !strcmp(arg, "yes"))
            return script_fail(a, "the recovery offer is %s",
                               p->recovery_offered ? "showing" : "not showing");
        return 0;
    }
    if (!strcmp(verb, "expect-read-only")) {
        if (p->read_only != !strcmp(arg, "yes"))
            return script_fail(a, "the project is %s", p->read_only ? "read-only" : "writable");
        return 0;
    }
    if (!strcmp(verb, "expect-save-refused"))
        return planner_save(p, NULL) == 0 ? script_fail(a, "the save %s", "went through") : 0;
    if (!strcmp(verb, "recover")) {
        int rc = planner_recover(p, !strcmp(arg, "yes"));
        p->recovery_offered = 0;
        return rc ? script_fail(a, "%s", p->status) : 0;
    }
    if (!strcmp(verb, "autosave-now")) {
        p->last_autosave = -1e9;
        planner_autosave_tick(p, 0);
        return 0;
    }
    if (!strcmp(verb, "expect-recent")) {
        const ui_recent *r = planner_recent_files(p);
        char abs[PATH_MAX];
        if (!realpath(arg, abs))
            snprintf(abs, sizeof abs, "%s", arg);
        if (!r || r->count == 0 || strcmp(r->paths[0], abs))
            return script_fail(a, "the newest recent file is %s",
                               r && r->count ? r->paths[0] : "(none)");
        return 0;
    }
    if (!strcmp(verb, "open-recent"))
        return planner_action_open_recent(p, atoi(arg) - 1) ? script_fail(a, "%s", p->status) : 0;
    if (!strcmp(verb, "dialog")) {
        /* The native dialog, answered by a person or xdotool; the script waits for it. */
        if (!f->script_started) {
            static const struct {
                const char *name;
                int use;
            } uses[] = {{"open", USE_OPEN},
                        {"save-as", USE_SAVE_AS},
                        {"print-pdf", USE_JOB + PLANNER_JOB_PRINT_PDF},
                        {"export-glb", USE_JOB + PLANNER_JOB_EXPORT_GLB}};
            int use = -1;
            for (size_t i = 0; i < sizeof uses / sizeof uses[0]; i++)
                if (!strcmp(arg, uses[i].name))
                    use = uses[i].use;
            if (use < 0 || planner_files_choose(p, use))
                return script_fail(a, "dialog %s: cannot open it", arg);
            if (f->prompt_open) {
                f->prompt_open = 0;
                return script_fail(a, "dialog %s: no native file dialog here", arg);
            }
            f->script_started = 1;
            return 2;
        }
        if (f->dialog_open)
            return 2;
        f->script_started = 0;
        return 0;
    }
    return script_fail(a, "unknown file action \"%s\"", verb);
}
