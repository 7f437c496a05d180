/* `tessera open [PROJECT] [--script FILE] [--quality Q] [--size WxH] [--fullscreen]
 * [--frame-log FILE]`, and what `tessera` alone does: the planner window when there is a
 * display, otherwise a pointer to the command line. */
#include "ui/ui.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int ui_display_available(char *why, size_t why_size)
{
    const char *x = getenv("DISPLAY"), *wl = getenv("WAYLAND_DISPLAY");
    if ((x && *x) || (wl && *wl))
        return 1;
    snprintf(why, why_size, "no display (DISPLAY and WAYLAND_DISPLAY are not set)");
    return 0;
}

static int usage(void)
{
    fprintf(stderr, "usage: tessera open [PROJECT] [--script FILE] [--quality "
                    "draft|interactive|final|print]\n"
                    "                    [--size WxH] [--fullscreen] [--frame-log FILE.csv]\n");
    return 2;
}

int ui_cli_open(int argc, char **argv)
{
    ui_options o = {0};
    int i = argc >= 2 && !strcmp(argv[1], "open") ? 2 : 1;
    for (; i < argc; i++) {
        const char *a = argv[i], *next = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            usage();
            return 0;
        }
        if (!strcmp(a, "--fullscreen")) {
            o.fullscreen = 1;
            continue;
        }
        if (a[0] == '-' && a[1] == '-' && !next) {
            fprintf(stderr, "tessera open: %s needs a value\n", a);
            return usage();
        }
        if (!strcmp(a, "--script"))
            o.script = argv[++i];
        else if (!strcmp(a, "--quality"))
            o.quality = argv[++i];
        else if (!strcmp(a, "--frame-log"))
            o.frame_log = argv[++i];
        else if (!strcmp(a, "--size")) {
            char tail;
            if (sscanf(argv[++i], "%dx%d%c", &o.width, &o.height, &tail) != 2 || o.width < 64 ||
                o.height < 64 || o.width > 16384 || o.height > 16384) {
                fprintf(stderr, "tessera open: --size wants WxH from 64x64 to 16384x16384\n");
                return 2;
            }
        } else if (a[0] == '-') {
            fprintf(stderr, "tessera open: unknown option %s\n", a);
            return usage();
        } else if (!o.project)
            o.project = a;
        else {
            fprintf(stderr, "tessera open: one project at a time (got %s and %s)\n", o.project, a);
            return 2;
        }
    }
    if (o.quality && strcmp(o.quality, "draft") && strcmp(o.quality, "interactive") &&
        strcmp(o.quality, "final") && strcmp(o.quality, "print")) {
        fprintf(stderr, "tessera open: unknown quality \"%s\"\n", o.quality);
        return 2;
    }
    char why[256];
    if (!ui_display_available(why, sizeof why)) {
        fprintf(stderr,
                "tessera: the planner window needs a display: %s.\n"
                "Everything it does is also on the command line: tessera --help\n"
                "(or run it under a virtual display: xvfb-run tessera open PROJECT)\n",
                why);
        return 2;
    }
    return ui_run(&o);
}
