/* tessera bench: milliseconds per frame for a project, after warm-up, with glFinish inside the
 * timed region, against a "floor" (one full-screen pass of the same lighting program at the
 * same size). Frames and floors are interleaved so drift in the machine's speed hits both. */
#include "app/cli.h"
#include "app/stats.h"
#include "cli_options.h"

#include <stdio.h>
#include <stdlib.h>

static void print_row(const char *what, const app_stats *s)
{
    printf("%-7s %8.2f %8.2f %8.2f %8.2f %8.2f %8.2f\n", what, s->median, s->p10, s->p90, s->min,
           s->max, s->mad);
}

static int write_csv(const char *path, const double *frame, const double *floor_ms,
                     const rd_frame_stats *stats, int n)
{
    FILE *f = fopen(path, "w");
    if (!f) {
        perror(path);
        return CLI_FAILED;
    }
    fprintf(f, "index,frame_ms,floor_ms,probes,faces_captured,prefiltered\n");
    for (int i = 0; i < n; i++)
        fprintf(f, "%d,%.4f,%.4f,%d,%d,%d\n", i, frame[i], floor_ms[i], stats[i].probes,
                stats[i].faces_captured, stats[i].prefiltered);
    return fclose(f) == 0 ? CLI_OK : CLI_FAILED;
}

int app_cli_bench(int argc, char **argv)
{
    cli_options o = {.frames = 30, .warmup = 5};
    int rc = cli_parse(argc, argv, 2, "bench",
                       "camera size frames warmup backend csv probes blur ambient quality", &o);
    if (rc != CLI_OK)
        return rc;
    if (!o.project) {
        fprintf(stderr, "usage: tessera bench PROJECT [--size WxH] [--frames N] [--warmup N] "
                        "[--camera NAME] [--backend egl|osmesa] [--csv FILE]\n");
        return CLI_USAGE;
    }
    cli_session s;
    rc = cli_session_open(&o, &s);
    if (rc != CLI_OK)
        return rc;
    rd_view view;
    if (cli_session_view(&s, &o, o.camera, 1280, 720, &view) != CLI_OK) {
        cli_session_close(&s);
        return CLI_USAGE;
    }
    view.supersample = 1; /* an interactive frame */
    double *frame = calloc((size_t)o.frames, sizeof *frame);
    double *floor_ms = calloc((size_t)o.frames, sizeof *floor_ms);
    rd_frame_stats *stats = calloc((size_t)o.frames, sizeof *stats);
    if (!frame || !floor_ms || !stats) {
        free(frame);
        free(floor_ms);
        free(stats);
        cli_session_close(&s);
        return CLI_FAILED;
    }
    for (int i = 0; rc == CLI_OK && i < o.warmup + o.frames; i++) {
        double t0 = cli_now_ms();
        rd_result r1 = rd_render(s.ctx, s.scene.scene, &view);
        rd_finish(s.ctx);
        double t1 = cli_now_ms();
        rd_frame_stats st = rd_last_frame_stats(s.ctx);
        rd_result r2 = rd_render_floor(s.ctx, s.scene.scene, &view);
        rd_finish(s.ctx);
        double t2 = cli_now_ms();
        if (r1 != RD_OK || r2 != RD_OK) {
            fprintf(stderr, "\ntessera bench: %s\n", rd_last_error());
            rc = CLI_FAILED;
            break;
        }
        if (i >= o.warmup) {
            frame[i - o.warmup] = t1 - t0;
            floor_ms[i - o.warmup] = t2 - t1;
            stats[i - o.warmup] = st;
        }
        fprintf(stderr, "\r%s %d/%d", i < o.warmup ? "warm-up" : "frame  ",
                i < o.warmup ? i + 1 : i + 1 - o.warmup, i < o.warmup ? o.warmup : o.frames);
    }
    fprintf(stderr, "\n");
    if (rc == CLI_OK && o.csv)
        rc = write_csv(o.csv, frame, floor_ms, stats, o.frames);
    if (rc == CLI_OK) {
        app_stats fs = app_stats_of(frame, o.frames), ls = app_stats_of(floor_ms, o.frames);
        printf("project  %s\nbackend  %s (%s)\nsize     %dx%d, %d frames after %d warm-up\n",
               s.project.path, rd_backend_name(rd_context_backend(s.ctx)),
               rd_context_description(s.ctx), view.width, view.height, o.frames, o.warmup);
        printf("objects  %d draw calls, %d lights\n\n", rd_scene_object_count(s.scene.scene),
               s.project.light_count);
        printf("ms      %8s %8s %8s %8s %8s %8s\n", "median", "p10", "p90", "min", "max", "mad");
        print_row("frame", &fs);
        print_row("floor", &ls);
        printf("\nframe / floor = %.2f floors per frame\n",
               ls.median > 0 ? fs.median / ls.median : 0.0);
    }
    free(frame);
    free(floor_ms);
    free(stats);
    cli_session_close(&s);
    return rc;
}
