/* tessera render PROJECT -o OUT [--camera NAME] [--size WxH] [--supersample N] [--backend B]
 *                [--quality Q] [--shadows off|hard|soft] [--dpi N] [--tile N]
 * tessera render PROJECT --all-views -o DIR [...]: every stored camera into DIR/NAME.png.
 * Any size: beyond the GL limits the image is rendered in tiles (rd_render_tiled). */
#include "app/cli/cli.h"
#include "cli_options.h"
#include "cli_print_render.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#define USAGE                                                                                      \
    "usage: tessera render PROJECT -o OUT.(png|jpg|tif|exr) [--camera NAME] [--size WxH]\n"        \
    "                      [--supersample 1-4] [--quality draft|interactive|final|print]\n"        \
    "                      [--adaptive on|off] [--planar-mirrors on|off] [--room-probe on|off]\n"  \
    "                      [--exact-lamps on|off] [--self-reflections on|off|1-16]\n"              \
    "                      [--probe-resolution 16-2048]\n"                                         \
    "                      [--shadows off|hard|soft] [--dpi N] [--tile N] [--backend "             \
    "egl|osmesa]\n"                                                                                \
    "       tessera render PROJECT --all-views -o DIR [same options]\n"

/* Every camera of the project into dir/NAME.png. */
static int render_all_views(cli_session *s, const cli_options *o)
{
    if (mkdir(o->output, 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "tessera render: cannot make folder %s: %s\n", o->output, strerror(errno));
        return CLI_USAGE;
    }
    for (int i = 0; i < s->project.camera_count; i++) {
        const char *name = s->project.cameras[i].name;
        char file[64], path[4200];
        snprintf(file, sizeof file, "%s", name);
        for (char *c = file; *c; c++)
            if (*c == '/' || *c == '\\')
                *c = '_'; /* a camera name is not a path */
        if (file[0] && file[0] != '.')
            snprintf(path, sizeof path, "%s/%s.png", o->output, file);
        else
            snprintf(path, sizeof path, "%s/camera-%d.png", o->output, i + 1);
        int rc = cli_check_output_path(path);
        rd_view view;
        if (rc == CLI_OK)
            rc = cli_session_view(s, o, name[0] ? name : NULL, 0, 0, &view);
        if (rc == CLI_OK)
            rc = cli_render_large(s, &view, path, o->dpi, o->tile);
        if (rc != CLI_OK)
            return rc;
    }
    return CLI_OK;
}

int app_cli_render(int argc, char **argv)
{
    /* --all-views is the one option without a value: take it out before cli_parse. */
    char *rest[256];
    int n = 0, all_views = 0;
    for (int i = 0; i < argc && n < 256; i++) {
        if (i >= 2 && !strcmp(argv[i], "--all-views"))
            all_views = 1;
        else
            rest[n++] = argv[i];
    }
    cli_options o = {0};
    int rc =
        cli_parse(n, rest, 2, "render",
                  "output camera size supersample adaptive planar-mirrors room-probe exact-lamps "
                  "self-reflections probe-resolution backend "
                  "probes blur ambient quality shadows dpi tile",
                  &o);
    if (rc != CLI_OK)
        return rc;
    if (!o.project || !o.output || (all_views && o.camera)) {
        fprintf(stderr, USAGE);
        return CLI_USAGE;
    }
    if (!all_views) {
        rc = cli_check_output_path(o.output);
        if (rc != CLI_OK)
            return rc;
    }
    cli_session s;
    rc = cli_session_open(&o, &s);
    if (rc != CLI_OK)
        return rc;
    if (all_views) {
        rc = render_all_views(&s, &o);
    } else {
        rd_view view;
        rc = cli_session_view(&s, &o, o.camera, 0, 0, &view);
        if (rc == CLI_OK)
            rc = cli_render_large(&s, &view, o.output, o.dpi, o.tile);
    }
    cli_session_close(&s);
    return rc;
}
