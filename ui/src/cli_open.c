/* `tessera open` (its options are in app/src/cli/cli_command_table.c), and what `tessera` alone
 * does: the planner window when there is a display, otherwise a pointer to the command line. */
#include "ui/ui.h"

#include <stdio.h>
#include <stdlib.h>

int ui_display_available(char *why, size_t why_size)
{
    const char *x = getenv("DISPLAY"), *wl = getenv("WAYLAND_DISPLAY");
    if ((x && *x) || (wl && *wl))
        return 1;
    snprintf(why, why_size, "no display (DISPLAY and WAYLAND_DISPLAY are not set)");
    return 0;
}

int ui_open_window(const app_open_request *r)
{
    ui_options o = {.project = r->project,
                    .script = r->script,
                    .quality = r->quality,
                    .frame_log = r->frame_log,
                    .width = r->width,
                    .height = r->height,
                    .fullscreen = r->fullscreen};
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
