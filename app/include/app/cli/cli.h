/* The `tessera` command line: one sub-command per capability (app/src/cli/cli_command_table.c,
 * docs/cli.md). Each returns the process exit code: 0 success, 1 the work failed, 2 bad usage or
 * bad input. */
#ifndef APP_CLI_H
#define APP_CLI_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* What `tessera open` (and `tessera` alone) asks of the program's planner window (ui/). */
typedef struct app_open_request {
    const char *project;   /* NULL = the shipped demo */
    const char *script;    /* a file of UI actions to run, then quit */
    const char *quality;   /* a preset's name, NULL = the window's default */
    const char *frame_log; /* CSV of per-frame times, NULL = none */
    int width, height;     /* 0 = the window's default */
    int fullscreen;
} app_open_request;
typedef int (*app_open_fn)(const app_open_request *r);

/* Runs argv[1] with its options; with no command, `open_window` (when not NULL) opens the
 * planner window, as `tessera open` does. */
int app_cli_run(int argc, char **argv, app_open_fn open_window);
/* app_cli_run without a window: for programs and tests that only use the command line. */
int app_cli_main(int argc, char **argv);

/* Makes an OpenGL context current for `--backend window`, the context the planner window's
 * process would have (a hidden window of the same kind), and gives its loader; 0 on success,
 * else a reason in err. Mesa keeps compiled shaders per kind of context (EGL, OSMesa and a
 * window's do not share them), so the planner's shader warm-up renders in one of these. The
 * full program registers one before app_cli_run; without it the backend is refused. */
typedef int (*app_window_context_fn)(void *(**get_proc_address)(const char *name), char *err,
                                     size_t err_size);
void app_cli_set_window_context(app_window_context_fn fn);

/* tessera demo's print set: OUT_DIR/plan.pdf with the demo-CAMERA.png renders found there. */
struct app_project;
int app_cli_print_demo(const struct app_project *p, const char *out_dir);

#ifdef __cplusplus
}
#endif
#endif
