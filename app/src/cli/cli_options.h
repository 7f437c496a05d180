#ifndef APP_CLI_OPTIONS_H
#define APP_CLI_OPTIONS_H

#include "app/project/project.h"
#include "app/scene/scene_build.h"
#include "render/render.h"

enum { CLI_OK = 0, CLI_FAILED = 1, CLI_USAGE = 2 };

/* Options shared by the sub-commands that render; zero = not given. */
typedef struct cli_options {
    const char *project;
    const char *output;
    const char *camera;
    const char *csv;
    const char *plot;     /* --plot: a PNG of the sweep */
    const char *markdown; /* --markdown: the sweep's table */
    const char *animate;  /* --animate: the object the sweep moves */
    int samples;          /* --samples: Monte-Carlo rays per glossy lookup (reference) */
    const struct app_quality *quality; /* --quality: a preset (app/scene/quality.h) */
    int width, height;
    int supersample;
    int adaptive;         /* --adaptive: 0 the preset's, 1 on, 2 off */
    int planar_mirrors;   /* --planar-mirrors: 0 the preset's, 1 on, 2 off */
    int room_probe;       /* --room-probe: 0 the preset's (on, off in print), 1 on, 2 off */
    int exact_lamps;      /* --exact-lamps: 0 the default (on), 1 on, 2 off */
    int self_reflections; /* --self-reflections: 0 the preset's, 1 on, 2 off */
    int self_rays;        /* --self-reflections N: its lobe directions a sample; 0 = default */
    int probe_resolution; /* --probe-resolution: texels a face side; 0 = the preset's */
    int frames, warmup;
    rd_backend backend;
    rd_probe_update probes; /* --probes: the scene's default update policy; 0 = the project's */
    rd_blur_method blur;    /* --blur */
    int ambient;            /* --ambient: 0 the project's, 1 constant, 2 sh9 */
    int shadows;            /* --shadows: 0 the preset's (or off), else rd_shadow_mode + 1 */
    int dpi;                /* --dpi: pixels per inch written into the image; 0 = none */
    int tile;               /* --tile: largest tile side in pixels; 0 = the GL limit */
    const char *faces;      /* --faces: folder for a panorama's six cube faces */
    double seconds;         /* --seconds: a video's length */
    int fps;                /* --fps: a video's frame rate */
} cli_options;

/* Parses argv[first..]; prints the problem and returns CLI_USAGE on a bad option. `allowed`
 * lists the long options this sub-command takes, e.g. "camera size backend". */
int cli_parse(int argc, char **argv, int first, const char *command, const char *allowed,
              cli_options *o);

/* "1280x720" -> 1280, 720; each side 1..65535 (larger sizes fail later with the limit named). */
int cli_parse_size(const char *text, int *w, int *h);

/* Everything a render needs, opened from the options; cli_session_close undoes it. */
typedef struct cli_session {
    app_project project;
    rd_context *ctx;
    app_scene scene;
} cli_session;

int cli_session_open(const cli_options *o, cli_session *s);
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
