/* tessera sweep PROJECT: the speed/accuracy trade (RENDERING.md section 10). The renderer is
 * run over settings, one factor at a time around a baseline, and each is timed (ms per frame,
 * GPU work finished) and compared with the ground-truth tracer (render/ref) over all pixels
 * and over the reflective ones: a table, a CSV and a plot. */
#include "app/cli/cli.h"
#include "app/output/safe_file.h"
#include "app/measure/image_compare.h"
#include "app/scene/quality.h"
#include "app/scene/ref_scene_build.h"
#include "app/measure/stats.h"
#include "app/measure/sweep_plot.h"
#include "cli/cli_commands.h"

#include "ref/ref.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

typedef struct sweep_setting {
    const char *factor, *label;
    int resolution;           /* 0 = auto */
    rd_correction correction; /* DEFAULT = box */
    rd_blur_method blur;
    int every_n; /* 1 every frame, N every N-th, 0 once (static), -1 time-sliced */
    int per_vertex;
    rd_ambient_model ambient;
    int max_resolution;         /* cap of auto; 0 = the renderer's */
    int no_specular;            /* probes capture without highlights */
    int supersample;            /* 1 = none (the reference is traced at the same) */
    int planar;                 /* flat mirrors as planar reflections (probe_planar.c) */
    int room_off;               /* "depth" searches the own probe only (no room probe) */
    int lamps_in_probes;        /* sharp lookups read lamps from their probes (not emitters.c) */
    int self_rays;              /* lobe rays a sample of the self-reflection trace; 0 off */
    int faces_per_frame;        /* probe faces refreshed a frame at most; 0 no limit */
    rd_shadow_settings shadows; /* the GPU's and the reference's */
} sweep_setting;

/* Probe resolutions 16 to 512 texels a face side: 512 already costs seconds a frame under
 * llvmpipe (every probe's six faces every frame), and 1024, four times its texels, would take
 * the designed demo's sweep past five minutes (docs/accuracy.md). */
enum { RESOLUTIONS = 6, FACTOR_SETTINGS = 1 + RESOLUTIONS + 16 };
enum { PRESETS = 4, SETTINGS = FACTOR_SETTINGS + PRESETS };

/* The baseline is what the renderer does by default with the project's render settings (its
 * ambient model, the session's shadows, its supersampling): the reference is traced with the
 * same, so every other setting differs from both in the one factor it names. The presets
 * bring their own supersampling and shadows, and their reference is traced with those. */
static void make_settings(sweep_setting out[SETTINGS], const rd_reflection_defaults *scene,
                          const rd_shadow_settings *shadows, int supersample)
{
    const sweep_setting base = {.factor = "baseline",
                                .label = "auto",
                                .correction = RD_CORRECTION_BOX,
                                .blur = RD_BLUR_PREFILTERED,
                                .every_n = 1,
                                .ambient = scene->ambient,
                                .supersample = supersample,
                                .shadows = *shadows};
    static const char *const res_labels[RESOLUTIONS] = {"16", "32", "64", "128", "256", "512"};
    int k = 0;
    out[k++] = base;
    for (int i = 0; i < RESOLUTIONS; i++) {
        out[k] = base;
        out[k].factor = "resolution";
        out[k].label = res_labels[i];
        out[k++].resolution = 16 << i;
    }
    const struct {
        const char *factor, *label;
    } named[10] = {{"correction", "none"},
                   {"correction", "sphere"},
                   {"blur", "box-mips"},
                   {"blur", "reference"},
                   {"update", "every 4"},
                   {"update", "every 16"},
                   {"update", "static"},
                   {"update", "time-sliced"},
                   {"per-vertex", "per-vertex"},
                   {"ambient", scene->ambient == RD_AMBIENT_SH9 ? "constant" : "sh9"}};
    sweep_setting *named_at = &out[k];
    for (int i = 0; i < 10; i++) {
        out[k] = base;
        out[k].factor = named[i].factor;
        out[k].label = named[i].label;
        k++;
    }
    named_at[0].correction = RD_CORRECTION_NONE;
    named_at[1].correction = RD_CORRECTION_SPHERE;
    named_at[2].blur = RD_BLUR_BOX_MIPS;
    named_at[3].blur = RD_BLUR_REFERENCE;
    named_at[4].every_n = 4;
    named_at[5].every_n = 16;
    named_at[6].every_n = 0;
    named_at[7].every_n = -1; /* time-sliced */
    named_at[8].per_vertex = 1;
    named_at[9].ambient = scene->ambient == RD_AMBIENT_SH9 ? RD_AMBIENT_CONSTANT : RD_AMBIENT_SH9;
    out[k] = base;
    out[k].factor = "highlights";
    out[k].label = "not in probes";
    out[k++].no_specular = 1;
    /* Distance impostors: the probe's stored distances instead of the proxy (reflect.glsl). */
    sweep_setting *depth = &out[k];
    out[k] = base;
    out[k].factor = "correction";
    out[k].label = "depth";
    out[k++].correction = RD_CORRECTION_DEPTH;
    /* Flat mirrors captured from the eye's mirror image (probe_planar.c). */
    out[k] = base;
    out[k].factor = "mirrors";
    out[k].label = "planar";
    out[k++].planar = 1;
    /* Depth with the object's own probe alone: what the room probe buys (probe.c). */
    out[k] = *depth;
    out[k].label = "depth, own probe only";
    out[k++].room_off = 1;
    /* Lamps left in the probes of mirrors and glass: what their exact intersection buys
     * (emitters.c). */
    out[k] = base;
    out[k].factor = "lamps";
    out[k].label = "in the probes";
    out[k++].lamps_in_probes = 1;
    /* Fixtures' reflections of themselves and their neighbours traced (self_trace.c). */
    out[k] = base;
    out[k].factor = "self-reflections";
    out[k].label = "traced";
    out[k++].self_rays = APP_SELF_REFLECTION_RAYS;
    /* The quality presets (app/scene/quality.c), measured like the rest, at their own
     * supersampling and shadows against a reference traced with the same. */
    static const char *const presets[PRESETS] = {"draft", "interactive", "final", "print"};
    for (int i = 0; i < PRESETS; i++) {
        const app_quality *q = app_quality_find(presets[i]);
        sweep_setting *st = &out[k++];
        *st = base;
        st->factor = "preset";
        st->label = q->name;
        st->resolution = q->resolution;
        st->blur = q->blur;
        /* On change, under the sweep's moving object, refreshes as time slicing does. */
        int sliced = q->update == RD_PROBE_TIME_SLICED || q->update == RD_PROBE_ON_CHANGE;
        st->every_n = q->update == RD_PROBE_ONCE ? 0 : sliced ? -1 : 1;
        st->max_resolution = q->max_resolution;
        st->supersample = q->supersample;
        st->correction = q->correction != RD_CORRECTION_DEFAULT ? q->correction : base.correction;
        st->planar = q->planar_mirrors == RD_SWITCH_ON;
        st->self_rays = q->self_reflections;
        st->room_off = q->room_probe == RD_SWITCH_OFF;
        st->faces_per_frame = q->probe_faces_per_frame;
        st->shadows = rd_shadow_settings_resolve(&(rd_shadow_settings){
            .mode = q->shadows, .map_size = q->shadow_map_size, .taps = q->shadow_taps});
    }
}

/* Frames run before the measured one. A moving object slides in a straight line and arrives
 * at its place in the project on the measured frame, so every probe captured earlier is
 * stale by how long ago it was captured: 0 frames for every frame, 3 for every 4th, 15 for
 * every 16th, 31 for once. */
#define ANIMATION_FRAMES 32
#define SLIDE_PER_FRAME_M 0.005f

static void apply(rd_scene *scene, const rd_reflection_defaults *base, const sweep_setting *s)
{
    rd_reflection_defaults d = *base;
    d.resolution = s->resolution;
    d.correction = s->correction;
    d.blur = s->blur;
    d.update = s->every_n == 0  ? RD_PROBE_ONCE
               : s->every_n < 0 ? RD_PROBE_TIME_SLICED
                                : RD_PROBE_EVERY_FRAME;
    d.every_n = s->every_n > 0 ? s->every_n : 0;
    d.per_vertex = s->per_vertex;
    d.ambient = s->ambient;
    d.max_resolution = s->max_resolution;
    d.probe_no_specular = s->no_specular;
    d.planar_mirrors = s->planar ? RD_SWITCH_ON : RD_SWITCH_OFF;
    d.room_probe = s->room_off ? RD_SWITCH_OFF : RD_SWITCH_ON;
    d.exact_lamps = s->lamps_in_probes ? RD_SWITCH_OFF : RD_SWITCH_ON;
    d.self_reflections = s->self_rays;
    d.max_faces_per_frame = s->faces_per_frame;
    rd_scene_set_reflection_defaults(scene, &d);
    rd_scene_set_shadows(scene, &s->shadows);
}

/* The project object to move: --animate NAME, else the largest one without reflections. */
static int pick_moving(const app_project *p, const char *name)
{
    int best = -1;
    double best_volume = 0.0;
    for (int i = 0; i < p->object_count; i++) {
        const app_object *o = &p->objects[i];
        if (name) {
            if (!strcmp(o->name, name))
                return i;
            continue;
        }
        const app_material *m = &p->materials[o->material];
        double v = o->size_mm[0] * o->size_mm[1] * fmax(o->size_mm[2], 1.0);
        if (m->reflectivity == 0.0f && m->transparency == 0.0f && v > best_volume) {
            best = i;
            best_volume = v;
        }
    }
    return best;
}

/* Moves the object by `offset` metres along x from its rest position, in the document and
 * the scene. */
static void place(cli_session *s, int object, const double rest_mm[3], float offset)
{
    double at[3] = {rest_mm[0] + (double)offset * 1e3, rest_mm[1], rest_mm[2]};
    app_scene_move_object(&s->scene, &s->project, object, at);
}

/* The defaults: what finishes the designed demo within five minutes on two cores
 * (docs/accuracy.md, "The speed/accuracy front"). */
#define SWEEP_WIDTH 480
#define SWEEP_HEIGHT 270
#define SWEEP_SAMPLES 16

/* A reference image and what it was traced with. */
typedef struct sweep_truth {
    int supersample;
    rd_shadow_settings shadows;
    ref_image image;
} sweep_truth;
enum { TRUTHS = PRESETS + 1 };

static int same_truth(const sweep_truth *t, const sweep_setting *st)
{
    const rd_shadow_settings *a = &t->shadows, *b = &st->shadows;
    return t->supersample == st->supersample && a->mode == b->mode &&
           (a->mode == RD_SHADOWS_OFF ||
            (a->map_size == b->map_size && a->taps == b->taps && a->softness_m == b->softness_m));
}

typedef struct sweep_row {
    double ms_mean, ms_median, psnr_all, psnr_reflective, rmse_reflective;
} sweep_row;

/* The table as Markdown, the front in bold (beside the CSV and the plot). */
static int write_markdown(const char *path, const app_sweep_point *p, const sweep_row *r, int n)
{
    app_safe_stream out;
    char err[4200];
    FILE *f = app_safe_stream_open(&out, path, err, sizeof err);
    if (!f) {
        fprintf(stderr, "tessera: %s\n", err);
        return -1;
    }
    fprintf(f, "| factor | setting | ms mean | ms median | PSNR all (dB) | PSNR reflective (dB) "
               "| RMSE reflective |\n|---|---|---|---|---|---|---|\n");
    for (int i = 0; i < n; i++)
        fprintf(f, "| %s | %s%s%s | %.1f | %.1f | %.2f | %s%.2f%s | %.4f |\n", p[i].factor,
                p[i].on_front ? "**" : "", p[i].label, p[i].on_front ? "**" : "", r[i].ms_mean,
                r[i].ms_median, r[i].psnr_all, p[i].on_front ? "**" : "", r[i].psnr_reflective,
                p[i].on_front ? "**" : "", r[i].rmse_reflective);
    fprintf(f, "\nBold: the Pareto front (no other setting is both faster and more accurate).\n");
    if (app_safe_stream_commit(&out, err, sizeof err) != APP_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        return -1;
    }
    return 0;
}

void cli_defaults_sweep(cli_options *o)
{
    o->frames = 3;
    o->warmup = 1;
    o->samples = SWEEP_SAMPLES;
}

int cli_cmd_sweep(const cli_options *args)
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
    rc = cli_session_view(&s, &o, o.camera, SWEEP_WIDTH, SWEEP_HEIGHT, &view);
    /* One exposure for every setting and the truth, so that they differ only by the method:
     * an auto exposure is resolved once, by the project's own render. */
    if (rc == CLI_OK && view.auto_exposure) {
        if (rd_render(s.ctx, s.scene.scene, &view) != RD_OK) {
            fprintf(stderr, "tessera: %s: %s\n", s.project.path, rd_last_error());
            rc = CLI_FAILED;
        }
        view.exposure_ev = rd_last_frame_stats(s.ctx).exposure_ev;
        view.auto_exposure = 0;
    }
    char err[2048];
    ref_scene *ref = NULL;
    if (rc == CLI_OK && app_ref_scene_build(&s.project, &ref, err, sizeof err) != APP_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        rc = CLI_FAILED;
    }
    /* The ground truth of the project as it stands (the moving object at rest), one per
     * supersampling and shadows (the presets bring their own), traced on first use. */
    sweep_truth truth[TRUTHS] = {{0}};
    int truths = 0;
    size_t n = (size_t)view.width * (size_t)view.height;
    float *image = malloc(n * 4 * sizeof *image), *mask = malloc(n * sizeof *mask);
    double rest[3] = {0};
    int moving = pick_moving(&s.project, o.animate);
    if (rc == CLI_OK && (!image || !mask))
        rc = CLI_FAILED;
    if (rc == CLI_OK && moving < 0) {
        fprintf(stderr, "tessera sweep: no object to move%s%s\n", o.animate ? " named " : "",
                o.animate ? o.animate : "");
        rc = CLI_USAGE;
    }
    if (rc == CLI_OK)
        memcpy(rest, s.project.objects[moving].position_mm, sizeof rest);
    app_safe_stream csv_out = {.f = NULL};
    char csv_err[4200];
    FILE *csv = rc == CLI_OK && o.csv
                    ? app_safe_stream_open(&csv_out, o.csv, csv_err, sizeof csv_err)
                    : NULL;
    if (rc == CLI_OK && o.csv && !csv) {
        fprintf(stderr, "tessera: %s\n", csv_err);
        rc = CLI_FAILED;
    }
    if (csv)
        fprintf(csv, "factor,setting,ms_mean,ms_median,rmse_all,psnr_all,rmse_reflective,"
                     "psnr_reflective,reflective_pixels\n");
    app_sweep_point points[SETTINGS];
    sweep_row rows[SETTINGS];
    int count = 0;
    rd_reflection_defaults base = rd_scene_reflection_defaults(s.scene.scene);
    rd_shadow_settings shadows = rd_scene_shadows(s.scene.scene);
    sweep_setting settings[SETTINGS];
    make_settings(settings, &base, &shadows, view.supersample > 1 ? view.supersample : 1);
    int progress = isatty(STDERR_FILENO);
    if (rc == CLI_OK)
        printf("%-16s %-21s %9s %9s %9s %9s %9s\n", "factor", "setting", "ms mean", "ms median",
               "PSNR all", "PSNR refl", "RMSE refl");
    for (int k = 0; rc == CLI_OK && k < SETTINGS; k++) {
        const sweep_setting *st = &settings[k];
        apply(s.scene.scene, &base, st);
        rd_view view_k = view;
        view_k.supersample = st->supersample;
        int t_k = 0;
        while (t_k < truths && !same_truth(&truth[t_k], st))
            t_k++;
        ref_image *tr = &truth[t_k].image;
        if (t_k == truths) {
            truths++;
            truth[t_k].supersample = st->supersample;
            truth[t_k].shadows = st->shadows;
            if (progress)
                fprintf(stderr, "\r\033[K");
            fprintf(stderr,
                    "tessera sweep: reference %dx%d, %dx%d supersampling, shadows %s, %d samples "
                    "per %s, %d bounces\n",
                    view.width, view.height, st->supersample, st->supersample,
                    rd_shadow_mode_name(st->shadows.mode), o.samples,
                    o.bounces ? "subsample" : "glossy lookup", o.bounces);
            ref_scene_set_shadows(ref, &st->shadows);
            ref_render_desc rdesc = {.view = view_k,
                                     .samples = o.samples,
                                     .seed = 1,
                                     .progress = 1,
                                     .bounces = o.bounces};
            if (ref_render(ref, &rdesc, tr) != REF_OK) {
                fprintf(stderr, "tessera sweep: %s\n", ref_last_error());
                rc = CLI_FAILED;
                break;
            }
        }
        if (progress) /* ended below, before the row is printed */
            fprintf(stderr, "\rsetting %d of %d: %s %s ", k + 1, SETTINGS, st->factor, st->label);
        for (size_t i = 0; i < n; i++)
            mask[i] = tr->mask[i] ? 1.0f : 0.0f;
        /* The update policies are measured with the object moving over ANIMATION_FRAMES; the
         * other factors, whose cost does not depend on motion, over warm-up + frames with
         * the probes updated every frame. */
        int animated = !strcmp(st->factor, "update") || !strcmp(st->factor, "baseline");
        int frames = animated ? ANIMATION_FRAMES : o.warmup + o.frames;
        double *t = calloc((size_t)frames, sizeof *t);
        if (!t) {
            rc = CLI_FAILED;
            break;
        }
        for (int f = 0; f < frames; f++) {
            place(&s, moving, rest,
                  animated ? (float)(f - (frames - 1)) * SLIDE_PER_FRAME_M : 0.0f);
            double t0 = cli_now_ms();
            if (rd_render(s.ctx, s.scene.scene, &view_k) != RD_OK) {
                fprintf(stderr, "tessera sweep: %s\n", rd_last_error());
                rc = CLI_FAILED;
                break;
            }
            rd_finish(s.ctx);
            t[f] = cli_now_ms() - t0;
        }
        app_image_metrics all = {0}, refl = {0};
        if (rc == CLI_OK && rd_read_linear(s.ctx, image, n * 4) == RD_OK) {
            app_image_metrics_compute(image, tr->linear, view.width, view.height, NULL, &all);
            app_image_metrics_compute(image, tr->linear, view.width, view.height, mask, &refl);
        }
        /* Timing: the last frames (the first ones of a setting build its probes and shaders);
         * the mean, since every-N policies put their work on one frame in N. */
        int from =
            animated ? frames / 2 : o.warmup; /* the animated half is every policy's steady state */
        double sum = 0.0;
        for (int f = from; f < frames; f++)
            sum += t[f];
        double mean = sum / (double)(frames - from);
        double median = app_stats_of(t + from, frames - from).median;
        free(t);
        if (progress) { /* the progress line erased, so the row starts a clean line */
            fprintf(stderr, "\r\033[K");
            fflush(stderr);
        }
        rows[count] = (sweep_row){mean, median, all.psnr, refl.psnr, refl.rmse};
        points[count++] = (app_sweep_point){st->factor, st->label, mean, refl.psnr, 0};
        printf("%-16s %-21s %9.2f %9.2f %9.2f %9.2f %9.5f\n", st->factor, st->label, mean, median,
               all.psnr, refl.psnr, refl.rmse);
        if (csv)
            fprintf(csv, "%s,%s,%.3f,%.3f,%.6f,%.3f,%.6f,%.3f,%lld\n", st->factor, st->label, mean,
                    median, all.rmse, all.psnr, refl.rmse, refl.psnr, refl.pixels);
        fflush(stdout);
    }
    if (csv && app_safe_stream_commit(&csv_out, csv_err, sizeof csv_err) != APP_OK) {
        fprintf(stderr, "tessera: %s\n", csv_err);
        rc = CLI_FAILED;
    }
    if (rc == CLI_OK) {
        app_sweep_mark_front(points, count);
        if (o.markdown && write_markdown(o.markdown, points, rows, count) != 0)
            rc = CLI_FAILED;
        printf("\nPareto front (faster or more accurate than every other setting):\n");
        for (int i = 0; i < count; i++)
            if (points[i].on_front)
                printf("  %-16s %-21s %8.2f ms  %6.2f dB\n", points[i].factor, points[i].label,
                       points[i].ms, points[i].psnr);
        fflush(stdout);
        if (o.plot) {
            char title[512];
            snprintf(title, sizeof title, "%s, %dx%d, %s: reference %d samples", s.project.name,
                     view.width, view.height, rd_backend_name(rd_context_backend(s.ctx)),
                     o.samples);
            if (app_sweep_plot(o.plot, points, count, title, err, (int)sizeof err) != 0) {
                fprintf(stderr, "tessera: %s\n", err);
                rc = CLI_FAILED;
            } else {
                fprintf(stderr, "tessera sweep: wrote %s\n", o.plot);
            }
        }
    }
    free(image);
    free(mask);
    for (int i = 0; i < truths; i++)
        ref_image_free(&truth[i].image);
    ref_scene_destroy(ref);
    cli_session_close(&s);
    return rc;
}
