/* tessera bench: milliseconds per frame for a project, after warm-up, with glFinish inside the
 * timed region, against a "floor" (one full-screen pass of the same lighting program at the
 * same size). Frames and floors are interleaved so drift in the machine's speed hits both. */
#include "app/cli/cli.h"
#include "app/output/safe_file.h"
#include "app/measure/stats.h"
#include "cli/cli_commands.h"
#include "cli/cli_stats.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* CPU time of the whole process (llvmpipe's threads included), in ms: on a shared machine
 * it moves far less with the others' load than the wall clock does. */
static double cpu_now_ms(void)
{
    struct timespec t;
    if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t) != 0)
        return 0.0;
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

/* --animate NAME: the object is dragged, as in the planner, 10 mm a frame along x and back
 * (40 frames each way), moved in the document and the scene (app_scene_move_object), so the
 * frames measure what a drag costs the renderer (probes refreshed on change within their
 * budget). */
typedef struct drag_state {
    int object; /* -1: no drag */
    double rest_mm[3];
} drag_state;

static int drag_begin(cli_session *s, const char *name, drag_state *d)
{
    d->object = -1;
    for (int i = 0; i < s->project.object_count; i++)
        if (!strcmp(s->project.objects[i].name, name))
            d->object = i;
    if (d->object < 0) {
        fprintf(stderr, "tessera bench: no object named \"%s\" to drag\n", name);
        return CLI_USAGE;
    }
    memcpy(d->rest_mm, s->project.objects[d->object].position_mm, sizeof d->rest_mm);
    return CLI_OK;
}

static void drag_step(cli_session *s, const drag_state *d, int frame)
{
    int t = frame % 80;
    double at[3] = {d->rest_mm[0] - 10.0 * (t < 40 ? t : 80 - t), d->rest_mm[1], d->rest_mm[2]};
    app_scene_move_object(&s->scene, &s->project, d->object, at);
}

static void print_row(const char *what, const app_stats *s)
{
    printf("%-7s %8.2f %8.2f %8.2f %8.2f %8.2f %8.2f\n", what, s->median, s->p10, s->p90, s->min,
           s->max, s->mad);
}

static int write_csv(const char *path, const double *frame, const double *floor_ms,
                     const double *cpu, const rd_frame_stats *stats, int n)
{
    app_safe_stream out;
    char err[4200];
    FILE *f = app_safe_stream_open(&out, path, err, sizeof err);
    if (!f) {
        fprintf(stderr, "tessera: %s\n", err);
        return CLI_FAILED;
    }
    fprintf(f, "index,frame_ms,floor_ms,probes,faces_captured,prefiltered,frame_cpu_ms\n");
    for (int i = 0; i < n; i++)
        fprintf(f, "%d,%.4f,%.4f,%d,%d,%d,%.4f\n", i, frame[i], floor_ms[i], stats[i].probes,
                stats[i].faces_captured, stats[i].prefiltered, cpu[i]);
    if (app_safe_stream_commit(&out, err, sizeof err) != APP_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        return CLI_FAILED;
    }
    return CLI_OK;
}

void cli_defaults_bench(cli_options *o)
{
    o->frames = 30;
    o->warmup = 5;
}

int cli_cmd_bench(const cli_options *args)
{
    cli_options o = *args;
    int rc = CLI_OK;
    if (!o.project)
        return cli_usage_error(&o);
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
    view.live = o.live == RD_SWITCH_ON;
    drag_state drag = {.object = -1};
    if (o.animate && (rc = drag_begin(&s, o.animate, &drag)) != CLI_OK) {
        cli_session_close(&s);
        return rc;
    }
    double *frame = calloc((size_t)o.frames, sizeof *frame);
    double *floor_ms = calloc((size_t)o.frames, sizeof *floor_ms);
    double *cpu = calloc((size_t)o.frames, sizeof *cpu);
    rd_frame_stats *stats = calloc((size_t)o.frames, sizeof *stats);
    if (!frame || !floor_ms || !cpu || !stats) {
        free(cpu);
        free(frame);
        free(floor_ms);
        free(stats);
        cli_session_close(&s);
        return CLI_FAILED;
    }
    for (int i = 0; rc == CLI_OK && i < o.warmup + o.frames; i++) {
        if (drag.object >= 0)
            drag_step(&s, &drag, i + 1);
        double t0 = cli_now_ms(), c0 = cpu_now_ms();
        rd_result r1 = rd_render(s.ctx, s.scene.scene, &view);
        rd_finish(s.ctx);
        double t1 = cli_now_ms(), c1 = cpu_now_ms();
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
            cpu[i - o.warmup] = c1 - c0;
            stats[i - o.warmup] = st;
        }
        fprintf(stderr, "\r%s %d/%d", i < o.warmup ? "warm-up" : "frame  ",
                i < o.warmup ? i + 1 : i + 1 - o.warmup, i < o.warmup ? o.warmup : o.frames);
    }
    fprintf(stderr, "\n");
    if (rc == CLI_OK && o.stats) /* the last timed frame's */
        rc = cli_write_stats(o.stats, &s, &o, &view, &stats[o.frames - 1], NULL);
    if (rc == CLI_OK && o.csv)
        rc = write_csv(o.csv, frame, floor_ms, cpu, stats, o.frames);
    if (rc == CLI_OK) {
        app_stats fs = app_stats_of(frame, o.frames), ls = app_stats_of(floor_ms, o.frames),
                  cs = app_stats_of(cpu, o.frames);
        printf("project  %s\nbackend  %s (%s)\nsize     %dx%d, %d frames after %d warm-up\n",
               s.project.path, rd_backend_name(rd_context_backend(s.ctx)),
               rd_context_description(s.ctx), view.width, view.height, o.frames, o.warmup);
        printf("objects  %d draw calls, %d lights\n", rd_scene_object_count(s.scene.scene),
               s.project.light_count);
        if (view.live)
            printf("live     frames drawn as the window's while the view moves\n");
        printf("\n");
        printf("ms      %8s %8s %8s %8s %8s %8s\n", "median", "p10", "p90", "min", "max", "mad");
        print_row("frame", &fs);
        print_row("floor", &ls);
        print_row("cpu", &cs); /* the frame's CPU time, all threads */
        printf("\nframe / floor = %.2f floors per frame\n",
               ls.median > 0 ? fs.median / ls.median : 0.0);
        long faces = 0;
        for (int i = 0; i < o.frames; i++)
            faces += stats[i].faces_captured;
        printf("probe faces captured: %.2f a frame%s\n", (double)faces / o.frames,
               drag.object >= 0 ? " (dragging)" : "");
    }
    free(frame);
    free(floor_ms);
    free(cpu);
    free(stats);
    cli_session_close(&s);
    return rc;
}
