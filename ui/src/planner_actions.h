/* The window's file and job actions as plain functions, for the menu bar, the toolbar, the key
 * shortcuts (planner_action_key) and the scripted mode alike. Each *_dialog function opens the
 * native file dialog (file_dialog.h; without one, a typed-path prompt in the window) and acts
 * when the user accepts; the *_to functions act on a path at once (scripts, recent files).
 * Jobs (print, render, share, panorama, video, GLB export) run in a worker (job.h) while the
 * window keeps drawing; a panel shows their progress with a Cancel button, and the result
 * opens when done. Return values: 0 started or done, 1 refused (the status says why). */
#ifndef UI_PLANNER_ACTIONS_H
#define UI_PLANNER_ACTIONS_H

#include "job.h"
#include "user_state.h"

struct planner;
struct ui_action;

typedef enum planner_job_kind {
    PLANNER_JOB_PRINT_PDF,
    PLANNER_JOB_RENDER_IMAGE, /* the window's view at print quality, twice the window's size */
    PLANNER_JOB_SHARE,
    PLANNER_JOB_PANORAMA,
    PLANNER_JOB_VIDEO,
    PLANNER_JOB_EXPORT_GLB,
    PLANNER_JOB_KIND_COUNT
} planner_job_kind;

/* Ctrl+O open, Ctrl+S save, Ctrl+Shift+S save as, Ctrl+P print to PDF, Ctrl+E export GLB,
 * Escape cancels a running job. 1 when the key was one of them. */
int planner_action_key(struct planner *p, int key, int mods);
/* The shortcut shown beside a menu entry ("Ctrl+O"), "" when none. */
const char *planner_action_shortcut(const char *action);

int planner_action_open_dialog(struct planner *p);
int planner_action_open_to(struct planner *p, const char *path); /* asks about unsaved changes */
int planner_action_save(struct planner *p); /* an untitled project asks for a name */
int planner_action_save_as(struct planner *p);
int planner_action_save_as_to(struct planner *p, const char *path);
int planner_action_export_glb(struct planner *p);
int planner_action_print_pdf(struct planner *p);
int planner_action_render_image(struct planner *p);
int planner_action_share(struct planner *p);
int planner_action_panorama(struct planner *p);
int planner_action_video(struct planner *p);
/* Starts a job writing to output; 1 when one is already running or it cannot start. */
int planner_action_job_to(struct planner *p, planner_job_kind kind, const char *output);
void planner_action_cancel_job(struct planner *p);
int planner_action_open_recent(struct planner *p, int index);

/* The recent files (loaded from the state folder on first use), newest first. */
const ui_recent *planner_recent_files(struct planner *p);
/* Puts path (made absolute) first in the recent files and writes the list. */
void planner_recent_note(struct planner *p, const char *path);
/* 1 while a job runs (the frame log marks those frames "job"). */
int planner_job_running(const struct planner *p);

/* Once a frame inside the GUI frame: the dialog's events, the typed-path prompt, the job
 * panel; dt (seconds) is the frame's time, kept as the longest frame of the job. */
void planner_files_frame(struct planner *p, int width, int height, double dt);
/* Cancels a running job, closes the dialog, frees the state (the window is closing). */
void planner_files_free(struct planner *p);
/* The scripted file actions (script.h, UI_ACT_FILES and share): 0 done, 1 failed, 2 not done
 * yet (a job or a dialog under way: the script waits a frame). */
int planner_files_script(struct planner *p, const struct ui_action *a);

#endif
