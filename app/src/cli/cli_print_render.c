/* Print-resolution renders: tiles (rd_render_tiled), DPI in the file, a progress bar. */
#include "cli_print_render.h"
#include "cli_black_pixels.h"

#include "app/project/job_limits.h"
#include "render/image_io.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

void cli_progress_init(cli_progress *p, const char *label)
{
    p->label = label;
    p->tty = isatty(2);
    p->last_tenth = -1;
    p->start_ms = cli_now_ms();
}

void cli_progress_update(cli_progress *p, int done, int total)
{
    if (total <= 0)
        return;
    int tenth = (int)(10LL * done / total);
    if (!p->tty && tenth == p->last_tenth && done != total)
        return;
    p->last_tenth = tenth;
    char bar[31];
    int filled = (int)(30LL * done / total);
    for (int i = 0; i < 30; i++)
        bar[i] = i < filled ? '#' : ' ';
    bar[30] = 0;
    fprintf(stderr, "%s%s [%s] %d/%d %.1f s%s", p->tty ? "\r" : "", p->label, bar, done, total,
            (cli_now_ms() - p->start_ms) / 1000.0, p->tty && done != total ? "" : "\n");
    fflush(stderr);
}

static void tile_done(void *user, int done, int total)
{
    cli_progress_update(user, done, total);
}

int cli_render_pixels(cli_session *s, const rd_view *view, int tile_max, uint8_t *rgba,
                      float *linear, cli_progress *progress)
{
    rd_result rr = rd_render_tiled(s->ctx, s->scene.scene, view, tile_max, rgba, linear,
                                   progress ? tile_done : NULL, progress);
    if (rr != RD_OK) {
        fprintf(stderr, "tessera: %s: %s\n", s->project.path, rd_last_error());
        return rr == RD_ERR_TOO_LARGE || rr == RD_ERR_INVALID_ARGUMENT ? CLI_USAGE : CLI_FAILED;
    }
    return CLI_OK;
}

int cli_check_image_job(const char *command, int width, int height, const char *path)
{
    /* Every limit from one table (app/project/job_limits.h), before any work: beyond them an
     * image is an input mistake, not a job to try for a minute and fail at the writer. */
    app_job job = {.kind = APP_JOB_IMAGE,
                   .width = width,
                   .height = height,
                   .float_copy = path && rd_image_format_is_float(path) == 1};
    char what[64], err[1024];
    snprintf(what, sizeof what, "a %dx%d image", width, height);
    if (app_job_check(&job, what, err, sizeof err) != APP_OK) {
        fprintf(stderr, "tessera %s: %s\n", command, err);
        return CLI_USAGE;
    }
    return CLI_OK;
}

int cli_render_large(cli_session *s, const rd_view *view, const char *path, int dpi, int tile_max)
{
    double t0 = cli_now_ms();
    int rc = cli_check_image_job("render", view->width, view->height, path);
    if (rc != CLI_OK)
        return rc;
    size_t count = (size_t)view->width * (size_t)view->height * 4;
    int is_float = rd_image_format_is_float(path) == 1;
    uint8_t *rgba = malloc(count);
    float *linear = is_float ? malloc(count * sizeof(float)) : NULL;
    if (!rgba || (is_float && !linear)) {
        free(rgba);
        free(linear);
        fprintf(stderr, "tessera: out of memory for a %dx%d image\n", view->width, view->height);
        return CLI_FAILED;
    }
    cli_progress bar;
    cli_progress_init(&bar, "rendering");
    rc = cli_render_pixels(s, view, tile_max, rgba, linear, &bar);
    if (rc == CLI_OK) {
        s->black_fraction = cli_black_fraction(rgba, view->width, view->height);
        double write_start = cli_now_ms();
        char err[1024];
        rd_image_result ir = is_float ? rd_image_write_float(path, view->width, view->height, 4,
                                                             linear, err, sizeof err)
                                      : rd_image_write_rgba8_dpi(path, view->width, view->height,
                                                                 rgba, (float)dpi, err, sizeof err);
        if (ir != RD_IMAGE_OK) {
            fprintf(stderr, "tessera: %s\n", err);
            rc = CLI_FAILED;
        }
        const char *phases = getenv("TESSERA_PHASES"); /* the renderer's phase timer's switch */
        if (phases && phases[0] && strcmp(phases, "0") != 0)
            fprintf(stderr, "phases (image file): write %.0f ms\n", cli_now_ms() - write_start);
    }
    free(rgba);
    free(linear);
    if (rc == CLI_OK)
        fprintf(stderr, "tessera: wrote %s (%dx%d%s%s, %.0f ms)\n", path, view->width, view->height,
                view->supersample > 1 ? ", supersampled" : "", dpi > 0 ? ", with DPI" : "",
                cli_now_ms() - t0);
    return rc;
}
