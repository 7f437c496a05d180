/* The state behind planner_actions.h, shared by planner_actions.c (dialogs, jobs, the job
 * panel) and planner_files_script.c (the script verbs). Internal to ui/. */
#ifndef UI_PLANNER_FILES_H
#define UI_PLANNER_FILES_H

#include "planner_actions.h"

struct planner;

/* What the answer of a dialog (or of the typed-path prompt) is used for. */
enum { USE_OPEN = 0, USE_SAVE_AS = 1, USE_JOB = 2 /* + planner_job_kind */ };

typedef struct planner_files {
    ui_recent recent;
    int recent_loaded;
    int dialog_open, dialog_use; /* a native dialog is showing, and what its answer does */
    int prompt_open, prompt_use; /* the typed-path prompt (no native dialog) */
    char prompt_path[1100];
    ui_job *job;
    planner_job_kind job_kind;
    char job_output[1024];
    double longest_ms; /* the longest frame while the job ran */
    long job_frames;
    int has_last; /* the last job's end */
    ui_job_state last_state;
    char last_line[256];
    int script_started; /* the script's current action started its job or dialog */
} planner_files;

/* The planner's file state, made on first use (NULL when out of memory). */
planner_files *planner_files_get(struct planner *p);
/* Asks for a path for `use` (USE_*): the native dialog, else the typed-path prompt. 0 when one
 * of them shows. */
int planner_files_choose(struct planner *p, int use);

#endif
