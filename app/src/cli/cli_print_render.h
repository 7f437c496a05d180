/* Print-resolution renders for the CLI: any size through tiles, DPI in the file, a
 * progress bar on stderr; shared by render, panorama and video. */
#ifndef APP_CLI_PRINT_RENDER_H
#define APP_CLI_PRINT_RENDER_H

#include "cli_options.h"

#include <stdint.h>

/* A progress bar on stderr: "label [#####     ] done/total"; redrawn in place on a terminal,
 * one line per tenth otherwise; ends its line when done == total. */
typedef struct cli_progress {
    const char *label;
    int tty, last_tenth;
    double start_ms;
} cli_progress;
void cli_progress_init(cli_progress *p, const char *label);
void cli_progress_update(cli_progress *p, int done, int total);

/* Renders `view` in tiles of at most tile_max pixels (0 = the GL limit) into rgba (w*h*4 bytes)
 * and, if linear is not NULL, linear floats. Prints the problem and returns a CLI code. */
int cli_render_pixels(cli_session *s, const rd_view *view, int tile_max, uint8_t *rgba,
                      float *linear, cli_progress *progress);

/* Checks a width x height image written to path (EXR keeps a float copy) against the limits
 * table and the memory (app/project/job_limits.h); prints "tessera COMMAND: ..." and returns
 * CLI_USAGE when it does not fit. */
int cli_check_image_job(const char *command, int width, int height, const char *path);

/* Renders `view` and writes it to path (8-bit sRGB with dpi if > 0, or EXR linear). */
int cli_render_large(cli_session *s, const rd_view *view, const char *path, int dpi, int tile_max);

/* render --serve: the views asked on standard input, one a line, in one session
 * (cli_render_serve.c). */
int cli_render_serve(cli_session *s, const cli_options *o);

#endif
