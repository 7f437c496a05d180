/* ui/: the interactive planner window (GLFW + Dear ImGui over app/ and render/).
 * ui draws app's state and sends app's commands; no planning logic lives here. */
#ifndef UI_UI_H
#define UI_UI_H

#include "app/cli/cli.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct ui_options {
    const char *project;   /* the project to open (NULL = the shipped demo) */
    const char *script;    /* a file of UI actions to run, then quit (tests, measurements) */
    const char *quality;   /* "draft", "interactive" (default), "final", "print" */
    const char *frame_log; /* CSV of per-frame times, NULL = none */
    int width, height;     /* window size; 0 = 1280 x 720 */
    int fullscreen;
} ui_options;

/* 1 when a display is there to open a window on; otherwise 0 and why in `why`. */
int ui_display_available(char *why, size_t why_size);

/* Runs the planner until the window closes or the script ends. Returns the process exit code:
 * 0 fine, 1 a failure (message on stderr), 2 bad options. */
int ui_run(const ui_options *o);

/* `tessera open` and `tessera` alone (app_cli_run): the planner window for the request, or,
 * with no display, a pointer to the command line and exit code 2. */
int ui_open_window(const app_open_request *r);

/* `--backend window` (app_cli_set_window_context): makes a hidden window's context current, of
 * the kind the planner window has, and gives its loader; 0 on success. */
int ui_hidden_window_context(void *(**get_proc_address)(const char *name), char *err,
                             size_t err_size);

#ifdef __cplusplus
}
#endif
#endif
