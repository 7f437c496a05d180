/* Long jobs of the planner window (print to PDF, a print-quality render, the share folder, the
 * panorama, the video, the GLB export) off the frame loop: a worker thread runs the `tessera`
 * command that does the work in a process of its own (its own headless OpenGL context; the
 * window's context never leaves the window's thread), reads the progress lines the command
 * prints, and can be cancelled. A file is written under a temporary name beside the result
 * and renamed when complete, so a cancelled or failed job leaves no partial file. When the job
 * succeeds the result is opened with $TESSERA_OPENER (set and empty: nothing) or xdg-open
 * (skipped when missing). */
#ifndef UI_JOB_H
#define UI_JOB_H

#include <stddef.h>

typedef enum ui_job_state {
    UI_JOB_RUNNING,
    UI_JOB_DONE,
    UI_JOB_FAILED,
    UI_JOB_CANCELLED
} ui_job_state;

typedef struct ui_job ui_job;

typedef struct ui_job_desc {
    const char *label;   /* "Print to PDF", shown with the progress bar */
    const char *command; /* the `tessera` subcommand: print, render, share, ... */
    const char *project; /* the project file the command reads (the job deletes it and its
                            folder when done when owns_project) */
    int owns_project;
    const char *output; /* the result: a file, or a folder for is_folder */
    int is_folder;      /* the share folder: removed on cancel when new, with its OUT.tmp-XXXXXX */
    const char *const *args; /* further arguments, NULL-terminated (may be NULL) */
    const char *program;     /* the tessera executable (NULL: /proc/self/exe) */
    int open_result;         /* open the result when done */
} ui_job_desc;

typedef struct ui_job_status {
    ui_job_state state;
    double progress; /* 0..1 from the command's "N/M" lines, -1 while unknown */
    double seconds;  /* since the start */
    char line[256];  /* the command's last line (what it is doing, or why it failed) */
} ui_job_status;

/* Starts the worker; NULL and why in err when it cannot start. */
ui_job *ui_job_start(const ui_job_desc *d, char *err, size_t err_size);
void ui_job_status_get(ui_job *j, ui_job_status *out);
/* Asks the job to stop (the command is terminated); its state becomes CANCELLED. */
void ui_job_cancel(ui_job *j);
/* Waits for the worker and frees the job (cancel first to stop it sooner). */
void ui_job_free(ui_job *j);

/* The fraction a progress line reports: its last "N/M" with 0 <= N <= M, M > 0 ("rendering
 * [###   ] 3/10 1.2 s", "[2/5] rendering view"); -1 when it has none. */
double ui_job_parse_progress(const char *line);
/* The temporary name a job writes a file result under: DIR/.NAME.partial-TAG.EXT (the
 * extension kept: the commands check it). 0 ok. */
int ui_job_partial_name(const char *output, const char *tag, char *out, size_t size);

#endif
