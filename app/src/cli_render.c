/* tessera render PROJECT -o OUT [--camera NAME] [--size WxH] [--supersample N] [--backend B] */
#include "app/cli.h"
#include "cli_options.h"

#include <stdio.h>

int app_cli_render(int argc, char **argv)
{
    cli_options o = {0};
    int rc = cli_parse(argc, argv, 2, "render",
                       "output camera size supersample backend probes blur ambient quality", &o);
    if (rc != CLI_OK)
        return rc;
    if (!o.project || !o.output) {
        fprintf(stderr, "usage: tessera render PROJECT -o OUT.(png|jpg|tif|exr) [--camera NAME] "
                        "[--size WxH] [--supersample 1-4] [--backend egl|osmesa]\n");
        return CLI_USAGE;
    }
    rc = cli_check_output_path(o.output);
    if (rc != CLI_OK)
        return rc;
    cli_session s;
    rc = cli_session_open(&o, &s);
    if (rc != CLI_OK)
        return rc;
    rd_view view;
    rc = cli_session_view(&s, &o, o.camera, 0, 0, &view);
    if (rc == CLI_OK)
        rc = cli_render_to_file(&s, &view, o.output);
    cli_session_close(&s);
    return rc;
}
