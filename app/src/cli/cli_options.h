/* The options of every `tessera` command in one struct, filled from the option table
 * (cli_option_table.c) by cli_parse_args; a command reads the fields it declared in the command
 * table (cli_command_table.c). Zero means "not given" throughout, so a command applies its own
 * default when a field is zero, and an rd_switch field left RD_SWITCH_UNSET leaves the choice
 * to the quality preset. */
#ifndef APP_CLI_OPTIONS_H
#define APP_CLI_OPTIONS_H

#include "app/cli/cli.h"
#include "app/project/project.h"
#include "app/scene/scene_build.h"
#include "render/render.h"

enum { CLI_OK = 0, CLI_FAILED = 1, CLI_USAGE = 2 };
enum { CLI_EXPOSURE_AUTO = 1, CLI_EXPOSURE_FIXED = 2 };

#define CLI_MAX_ARGS 64

struct cli_command;
struct app_quality;

typedef struct cli_options {
    const struct cli_command *command; /* the command being run (for its usage) */
    const char *args[CLI_MAX_ARGS];    /* the positional arguments, in order */
    int arg_count;
    const char *project;     /* args[0]: most commands' one positional argument */
    app_open_fn open_window; /* `tessera open`: the program's window, if it has one */

    /* Files and names. */
    const char *output, *camera, *csv, *plot, *markdown, *animate, *faces, *stats;
    const char *db, *category, *manufacturer, *variant, *out_dir, *svg, *renders, *customer, *date,
        *mask, *heatmap, *png, *script, *frame_log, *company, *xlsx, *text_boxes;

    /* The image and the renderer. */
    int width, height;               /* --size WxH */
    int pano_width, pano_height;     /* --panorama-size WxH */
    int render_width, render_height; /* --render-size WxH (print) */
    int supersample;
    int samples;      /* --samples: Monte-Carlo rays per glossy lookup (reference) */
    int bounces;      /* --bounces: indirect bounces of the reference (0 = direct light only) */
    int bake_bounces; /* --bake-bounces: passes of the bake (0 = REF_DEFAULT_BOUNCES) */
    const struct app_quality *quality; /* --quality: a preset (app/scene/quality.h) */
    rd_switch adaptive, planar_mirrors, mirror_bounce, mirror_panes, room_probe, exact_lamps,
        self_reflections, glaze;
    rd_switch live;       /* --live: frames drawn as a moving live view's (rd_view.live) */
    rd_switch prime;      /* --prime: every object drawn, in view or not (rd_view.all_objects) */
    rd_switch bake;       /* --bake: baked indirect light (default on unless TESSERA_BAKE=off) */
    int self_rays;        /* --self-reflections N: its lobe directions a sample; 0 = default */
    int probe_resolution; /* texels a face side; 0 = the preset's */
    rd_backend backend;
    rd_probe_update probes; /* the scene's default update policy; 0 = the project's */
    rd_blur_method blur;
    int ambient;  /* 0 the project's, 1 constant, 2 sh9 */
    int shadows;  /* 0 the preset's (or off), else rd_shadow_mode + 1 */
    int tone;     /* 0 the project's, else rd_tonemap + 1 */
    int exposure; /* 0 the project's, CLI_EXPOSURE_AUTO or CLI_EXPOSURE_FIXED (exposure_ev) */
    float exposure_ev;
    double white_balance;   /* K; 0 the project's */
    const char *sky, *time; /* --sky overcast|clear, --time HH:MM: the project's daylight */
    int dpi, tile;

    /* Timing, video, reference. */
    int frames, warmup, fps, threads;
    long long seed;
    int rooms;      /* generate-flat */
    int room_index; /* --room N of a flat, 1-based; 0 = the camera's (or the first) */
    double seconds;

    /* Comparison. */
    int worst, block;
    double heat_max;

    /* Catalog, quantities, checks, print. */
    int limit, queries, thumb_size, bench_repeats;
    double max_width, fraction, surplus;
    int paper, scale; /* app_paper, app_print_scale (app/output/print.h) */

    /* Flags. */
    int all_views, dry_run, barrier_free, wheelchair, quiet, csv_table, offcuts, bench_mosaic,
        landscape, no_clearances, fullscreen, list, json_table, serve;
} cli_options;

/* Prints `tessera CMD`'s usage to stderr and returns CLI_USAGE: for a command that finds its
 * required arguments missing. */
int cli_usage_error(const cli_options *o);

/* "1280x720" -> 1280, 720; each side 1..1000000 (larger sizes fail later with the limit named). */
int cli_parse_size(const char *text, int *w, int *h);

/* --tone, --exposure and --white-balance over the project's in a view. */
static inline void cli_apply_tone_options(const cli_options *o, rd_view *v)
{
    if (o->tone)
        v->tonemap = (rd_tonemap)(o->tone - 1);
    if (o->exposure) {
        v->auto_exposure = o->exposure == CLI_EXPOSURE_AUTO;
        v->exposure_ev = o->exposure == CLI_EXPOSURE_FIXED ? o->exposure_ev : 0.0f;
    }
    if (o->white_balance > 0.0)
        v->white_balance_k = (float)o->white_balance;
}

/* The resolved on/off of a switch: `set` unless unset, else `preset`. */
static inline int cli_switch_on(rd_switch set, int preset)
{
    return set == RD_SWITCH_UNSET ? preset : set == RD_SWITCH_ON;
}

/* Everything a render needs, opened from the options; cli_session_close undoes it. */
typedef struct cli_session {
    app_project project;
    rd_context *ctx;
    app_scene scene;
    double black_fraction; /* of the last cli_render_large image (cli_black_pixels.h) */
} cli_session;

int cli_session_open(const cli_options *o, cli_session *s);
/* A session on a copy of a room already read (a flat's room: not read from the file again). */
int cli_session_open_room(const cli_options *o, const app_project *room, cli_session *s);
/* The context, the scene and the settings for s->project (set); cli_session_open's second half. */
int cli_session_start(const cli_options *o, cli_session *s);
/* The project of o->project a session renders: a single-room project, or the room of a flat
 * that holds o->camera (room o->room_index, 1-based, without a camera; else the first).
 * Says what is wrong on stderr. */
app_result cli_session_read_room(const cli_options *o, app_project *out);
/* Whether --bake (or TESSERA_BAKE=off) asks for the baked light, and app_bake_configure from it. */
int cli_bake_wanted(const cli_options *o);
void cli_bake_configure(const cli_options *o);
void cli_session_close(cli_session *s);

/* The view of `camera` (NULL = the first) at the options' size (else width x height, else the
 * project's) and supersampling; prints the problem and returns CLI_USAGE if there is none. */
int cli_session_view(const cli_session *s, const cli_options *o, const char *camera, int width,
                     int height, rd_view *out);

/* Renders one view and writes it to `path` (PNG/JPEG/TIFF as 8-bit sRGB, EXR linear). */
int cli_render_to_file(cli_session *s, const rd_view *view, const char *path);

/* Fails early, before any rendering, when `path` has an unknown extension or its folder
 * cannot be written. */
int cli_check_output_path(const char *path);

double cli_now_ms(void);

#endif
