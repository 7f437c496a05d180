/* Every option of every `tessera` command: its name, kind, range, field and help line. A
 * command lists the keys it takes in the command table (cli_command_table.c); the parser, the
 * errors and the usage lines all read this one table (docs/cli.md, "Adding an option"). */
#include "app/daylight/daylight.h"
#include "app/output/print.h"
#include "app/scene/quality.h"
#include "catalog/catalog.h"
#include "cli_table.h"

#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#define FIELD(f) offsetof(cli_options, f)

/* The render, daylight and print options: only the full program's commands take them, and
 * some of their parsers call into the renderer and the print code (IN_FULL, cli_table.h). */
#ifndef TESSERA_CLI_LEAN
static int parse_quality(const char *v, cli_options *o)
{
    return (o->quality = app_quality_find(v)) != NULL;
}

/* "window": a hidden window's context (app_cli_set_window_context), adopted. */
static int parse_backend(const char *v, cli_options *o)
{
    if (!strcmp(v, "window")) {
        o->backend = RD_BACKEND_ADOPT;
        return 1;
    }
    return rd_backend_parse(v, &o->backend) == RD_OK && o->backend != RD_BACKEND_ADOPT;
}

/* on, off, or a number: on with that many lobe directions a sample (rd_reflection_defaults). */
static int parse_self_reflections(const char *v, cli_options *o)
{
    if (!strcmp(v, "on") || !strcmp(v, "off")) {
        o->self_reflections = !strcmp(v, "on") ? RD_SWITCH_ON : RD_SWITCH_OFF;
        return 1;
    }
    char *end;
    long n = strtol(v, &end, 10);
    if (end == v || *end || n < 1 || n > 16)
        return 0;
    o->self_rays = (int)n;
    o->self_reflections = RD_SWITCH_ON;
    return 1;
}

/* rd_tonemap + 1 */
static int parse_tone(const char *v, cli_options *o)
{
    rd_tonemap t;
    if (rd_tonemap_parse(v, &t) != RD_OK)
        return 0;
    o->tone = (int)t + 1;
    return 1;
}

/* auto, or a number of EV in (-64, 64) */
static int parse_exposure(const char *v, cli_options *o)
{
    if (!strcmp(v, "auto")) {
        o->exposure = CLI_EXPOSURE_AUTO;
        return 1;
    }
    char *end;
    double ev = strtod(v, &end);
    if (end == v || *end || !(ev > -64.0 && ev < 64.0))
        return 0;
    o->exposure = CLI_EXPOSURE_FIXED;
    o->exposure_ev = (float)ev;
    return 1;
}

static int parse_sky(const char *v, cli_options *o)
{
    o->sky = v;
    return !strcmp(v, "overcast") || !strcmp(v, "clear");
}

static int parse_time(const char *v, cli_options *o)
{
    app_daylight d;
    app_daylight_default(&d);
    o->time = v;
    return app_daylight_set_time(&d, v);
}

static int parse_paper(const char *v, cli_options *o)
{
    app_paper p;
    if (!app_paper_parse(v, &p))
        return 0;
    o->paper = (int)p;
    return 1;
}

static int parse_scale(const char *v, cli_options *o)
{
    return app_print_scale_parse(v, &o->scale);
}

#endif

static int parse_category(const char *v, cli_options *o)
{
    cat_category c;
    o->category = v;
    return cat_category_parse(v, &c);
}

/* Names by enum value; index 0 (not given) is not accepted on the command line. */
static const char *const probe_names[] = {"",          "every-frame", "once",
                                          "on-change", "time-sliced", NULL};
static const char *const blur_names[] = {"", "prefiltered", "box-mips", "reference", NULL};
static const char *const ambient_names[] = {"", "constant", "sh9", NULL};
/* rd_shadow_mode + 1 */
static const char *const shadow_names[] = {"", "off", "hard", "soft", NULL};

#define STRING(k, f, v, h)                                                                         \
    {                                                                                              \
        .key = k, .kind = CLI_STRING, .offset = FIELD(f), .value = v, .hint = h                    \
    }
#define FLAG(k, f, h)                                                                              \
    {                                                                                              \
        .key = k, .kind = CLI_FLAG, .offset = FIELD(f), .hint = h                                  \
    }
#define INT(k, f, l, u, v, h)                                                                      \
    {                                                                                              \
        .key = k, .kind = CLI_INT, .lo = l, .hi = u, .offset = FIELD(f), .value = v, .hint = h     \
    }
#define FLOAT(k, f, l, u, v, h)                                                                    \
    {                                                                                              \
        .key = k, .kind = CLI_FLOAT, .lo = l, .hi = u, .offset = FIELD(f), .value = v, .hint = h   \
    }
#define SWITCH(k, f, h)                                                                            \
    {                                                                                              \
        .key = k, .kind = CLI_SWITCH, .offset = FIELD(f), .value = "on|off", .hint = h             \
    }
#define ENUM(k, f, n, h)                                                                           \
    {                                                                                              \
        .key = k, .kind = CLI_ENUM, .names = n, .offset = FIELD(f), .hint = h                      \
    }
#define SIZE(k, n, w, h_, l, u, v, h)                                                              \
    {                                                                                              \
        .key = k, .name = n, .kind = CLI_SIZE, .lo = l, .hi = u, .offset = FIELD(w),               \
        .offset2 = FIELD(h_), .value = v, .hint = h                                                \
    }
#define CUSTOM(k, p, v, e, h)                                                                      \
    {                                                                                              \
        .key = k, .kind = CLI_CUSTOM, .parse = p, .value = v, .expect = e, .hint = h               \
    }

static const cli_option_spec options[] = {
    /* Outputs and inputs. */
    {.key = "output",
     .short_name = 'o',
     .kind = CLI_STRING,
     .offset = FIELD(output),
     .value = "OUT",
     .hint = "the file (or folder) to write"},
    STRING("camera", camera, "NAME", "the stored camera to render (default: the first)"),
    STRING("csv", csv, "FILE", "also write the table as CSV"),
    {.key = "csv-table",
     .name = "csv",
     .kind = CLI_FLAG,
     .offset = FIELD(csv_table),
     .hint = "print CSV instead of a table"},
    STRING("plot", plot, "FILE.png", "plot the speed/accuracy front"),
    STRING("markdown", markdown, "FILE", "also write the table as Markdown"),
    STRING("animate", animate, "OBJECT", "drag this object 10 mm a frame"),
    STRING("faces", faces, "DIR", "also write the six cube faces into DIR"),
    STRING("stats", stats, "FILE.json",
           "write the frame statistics and the resolved settings as JSON"),
    STRING("db", db, "PATH", "the catalog file (default: $TESSERA_CATALOG, else the cache)"),
    STRING("manufacturer", manufacturer, "M", "only this manufacturer's products"),
    STRING("variant", variant, "CODE", "the finish variant (e.g. CP for chrome)"),
    {.key = "out",
     .short_name = 'o',
     .kind = CLI_STRING,
     .offset = FIELD(out_dir),
     .value = "DIR",
     .hint = "the folder to write into"},
    STRING("svg", svg, "DIR", "also write each page as DIR/page-NN.svg"),
    STRING("renders", renders, "DIR|none", "take the renders from DIR's PNG files, or none"),
    STRING("text-boxes", text_boxes, "FILE", "list every text's box on the pages (debugging)"),
    STRING("customer", customer, "NAME", "the customer named on the title block"),
    STRING("date", date, "TEXT", "the date on the title block (default: today)"),
    STRING("company", company, "FILE",
           "the quotation's company block (default: $XDG_CONFIG_HOME/tessera/company.json)"),
    STRING("xlsx", xlsx, "FILE.xlsx", "also write the quotation as a spreadsheet"),
    {.key = "json-table",
     .name = "json",
     .kind = CLI_FLAG,
     .offset = FIELD(json_table),
     .hint = "print JSON instead of a table"},
    STRING("mask", mask, "MASK.png", "also measure (or write) the masked pixels"),
    STRING("heatmap", heatmap, "OUT.png", "write the per-pixel error as a heat map"),
    STRING("png", png, "OUT.png", "also write an 8-bit sRGB copy"),
    STRING("script", script, "FILE", "replay an edit script in the window"),
    STRING("frame-log", frame_log, "FILE.csv", "log each frame's timings"),
    CUSTOM("category", parse_category, "C", "a category (see tessera catalog --help)",
           "only this category (see tessera catalog --help for the list)"),

    /* The image. */
    SIZE("size", NULL, width, height, 1, 1000000, "WxH", "the image size in pixels"),
    SIZE("window-size", "size", width, height, 64, 16384, "WxH", "the window size in pixels"),
    SIZE("panorama-size", NULL, pano_width, pano_height, 1, 1000000, "WxH",
         "the panorama's size (default: 4096x2048)"),
    SIZE("render-size", NULL, render_width, render_height, 1, 8192, "WxH",
         "the renders' size (default: 960x540)"),
    INT("supersample", supersample, 1, 4, "N", "N x N samples a pixel"),
    INT("dpi", dpi, 1, 100000, "N", "pixels per inch written into the image"),
    INT("tile", tile, 16, 65536, "N", "largest tile side in pixels (default: the GL limit)"),
    {.key = "thumb-size",
     .name = "size",
     .kind = CLI_INT,
     .lo = 16,
     .hi = 2048,
     .offset = FIELD(thumb_size),
     .value = "N",
     .hint = "the thumbnails' side in pixels (default: 256)"},

    /* The renderer's settings: a preset, then the switches that refine it. */
    CUSTOM("quality", IN_FULL(parse_quality), "Q", "draft, interactive, final or print",
           "a preset: draft|interactive|final|print"),
    SWITCH("adaptive", adaptive, "adaptive supersampling (default: the preset's)"),
    SWITCH("planar-mirrors", planar_mirrors, "flat mirrors as planar reflections"),
    SWITCH("mirror-bounce", mirror_bounce,
           "glass and chrome in a planar mirror with their own probes (default on)"),
    SWITCH("mirror-panes", mirror_panes,
           "a planar mirror's capture blends a thin pane over what lies behind it (default off)"),
    SWITCH("room-probe", room_probe, "\"depth\" lookups also search the room probe"),
    SWITCH("glaze", glaze, "glazed tiles reflect the room probe by Fresnel"),
    SWITCH("live", live, "frames drawn as the window's while the view moves (cheaper lights)"),
    SWITCH("prime", prime, "draw every object, in view or not: compiles every shader variant"),
    SWITCH("exact-lamps", exact_lamps, "lamps in sharp reflections intersected exactly"),
    SWITCH("bake", bake, "baked indirect light, cached (default on; TESSERA_BAKE=off)"),
    INT("bake-bounces", bake_bounces, 1, 64, "N",
        "bounces of the baked light (default 4, as `reference --bounces`)"),
    CUSTOM("self-reflections", IN_FULL(parse_self_reflections), "on|off|N", "on, off or 1 to 16",
           "fixtures trace their own reflections (N lobe directions a sample)"),
    INT("probe-resolution", probe_resolution, 16, 2048, "N", "probe texels a face side"),
    CUSTOM("backend", IN_FULL(parse_backend), "egl|osmesa|window", "egl, osmesa or window",
           "the OpenGL backend (default: $TESSERA_GL, else EGL; window: a hidden window's, "
           "whose compiled shaders the planner window shares)"),
    ENUM("probes", probes, probe_names, "when probes are captured"),
    ENUM("blur", blur, blur_names, "how probes are blurred for rough surfaces"),
    ENUM("ambient", ambient, ambient_names, "the ambient light's model"),
    ENUM("shadows", shadows, shadow_names, "shadows from every light"),
    CUSTOM("sky", IN_FULL(parse_sky), "overcast|clear", "overcast or clear",
           "the sky through the windows (default: the project's daylight)"),
    CUSTOM("time", IN_FULL(parse_time), "HH:MM", "a local time HH:MM",
           "the time of day of the daylight (default: the project's)"),
    CUSTOM("tone", IN_FULL(parse_tone), "neutral|agx|reinhard|clamp",
           "neutral, agx, reinhard or clamp",
           "the tone curve (default: the project's, else neutral)"),
    CUSTOM("exposure", IN_FULL(parse_exposure), "auto|EV", "auto or a number of EV in (-64, 64)",
           "exposure: chosen from the scene, or fixed in EV (default: the project's)"),
    FLOAT("white-balance", white_balance, 1000, 40000, "K",
          "the colour temperature shown as white (default: the project's, else none)"),
    INT("samples", samples, 1, 1 << 20, "N",
        "Monte-Carlo rays a glossy lookup, or paths a subsample with --bounces (reference)"),
    INT("bounces", bounces, 0, 1024, "N", "indirect bounces of the reference (0: direct only)"),

    /* Timing, video, reference, comparison. */
    INT("frames", frames, 1, 100000, "N", "frames timed"),
    INT("warmup", warmup, 0, 100000, "N", "frames rendered before timing"),
    {.key = "seconds",
     .kind = CLI_FLOAT,
     .lo = 0,
     .hi = 3600,
     .above_lo = 1,
     .offset = FIELD(seconds),
     .value = "S",
     .hint = "the video's length"},
    INT("fps", fps, 1, 240, "N", "frames a second"),
    INT("threads", threads, 1, 256, "N", "CPU threads (default: all)"),
    INT("rooms", rooms, 1, 256, "N", "rooms of the generated flat (default: 8)"),
    INT("room", room_index, 1, 256, "N", "of a flat: room N (default: the camera's, or 1)"),
    {.key = "seed",
     .kind = CLI_LONG,
     .lo = 0,
     .hi = 4294967295.0,
     .offset = FIELD(seed),
     .value = "N",
     .hint = "the random sequence's seed"},
    INT("worst", worst, 1, 1000, "N", "list the N blocks that carry most of the error"),
    INT("block", block, 1, 4096, "PX", "the side of --worst's blocks"),
    {.key = "heat-max",
     .kind = CLI_FLOAT,
     .lo = 0,
     .hi = 1e30,
     .above_lo = 1,
     .offset = FIELD(heat_max),
     .value = "E",
     .hint = "the error shown white in the heat map"},

    /* Catalog, quantities, checks, print. */
    FLOAT("max-width", max_width, 1, 100000, "MM", "only products at most this wide"),
    INT("limit", limit, 1, 10000, "N", "at most N products"),
    INT("queries", queries, 1, 1000000, "N", "queries timed (default: 400)"),
    FLAG("dry-run", dry_run, "check the file, change nothing"),
    {.key = "fraction",
     .kind = CLI_FLOAT,
     .lo = 0,
     .hi = 1,
     .above_lo = 1,
     .offset = FIELD(fraction),
     .value = "F",
     .hint = "keep about F of each mesh's triangles"},
    FLAG("barrier-free", barrier_free, "DIN 18040-2: 1200 x 1200 free areas, doors outwards"),
    FLAG("wheelchair", wheelchair, "DIN 18040-2 R: 1500 x 1500 free areas, the WC's sides"),
    FLAG("quiet", quiet, "print nothing but errors"),
    FLOAT("surplus", surplus, 0, 1000, "PCT", "boxes with this surplus (default: 10 %)"),
    FLAG("offcuts", offcuts, "list the offcuts and where they are reused"),
    INT("bench", bench_repeats, 1, 100000, "N", "time the layout N times"),
    FLAG("bench-mosaic", bench_mosaic, "time a 30 x 30 mm mosaic on 10 surfaces"),
    CUSTOM("paper", IN_FULL(parse_paper), "A4|A3", "A4 or A3", "the paper size"),
    CUSTOM("scale", IN_FULL(parse_scale), "1:N|fit", "1:20, 1:25, 1:50, 1:100, 1:200 or fit",
           "the drawings' scale (default: fit)"),
    FLAG("landscape", landscape, "landscape pages"),
    FLAG("no-clearances", no_clearances, "leave the clearance areas out of the plan"),
    FLAG("all-views", all_views, "every stored camera into OUT/NAME.png"),
    FLAG("serve", serve, "render the views asked on standard input, one a line (the window's)"),
    FLAG("fullscreen", fullscreen, "open the window full-screen"),
    FLAG("list", list, "the command names, one a line"),
};

const cli_option_spec *cli_option_find(const char *key)
{
    for (size_t i = 0; i < sizeof options / sizeof options[0]; i++)
        if (!strcmp(options[i].key, key))
            return &options[i];
    return NULL;
}
