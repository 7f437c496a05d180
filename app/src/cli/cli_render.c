/* tessera render PROJECT -o OUT: one camera into an image file; --all-views -o DIR: every
 * stored camera into DIR/NAME.png. Any size: beyond the GL limits the image is rendered in tiles
 * (rd_render_tiled). */
#include "cli_commands.h"
#include "cli_black_pixels.h"
#include "cli_stats.h"
#include "cli_print_render.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

/* Every camera of the project into dir/NAME.png; *view gets the last one's. */
static int render_all_views(cli_session *s, const cli_options *o, rd_view *view)
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
        if (rc == CLI_OK)
            rc = cli_session_view(s, o, name[0] ? name : NULL, 0, 0, view);
        if (rc == CLI_OK)
            rc = cli_render_large(s, view, path, o->dpi, o->tile);
        if (rc == CLI_OK)
            rc = cli_check_room_visible(s, name, path);
        if (rc != CLI_OK)
            return rc;
    }
    return CLI_OK;
}

int cli_cmd_render(const cli_options *o)
{
    if (o->serve) {
        if (o->output || o->all_views)
            return cli_usage_error(o);
        cli_session s;
        int rc = cli_session_open(o, &s);
        if (rc != CLI_OK)
            return rc;
        rc = cli_render_serve(&s, o);
        cli_session_close(&s);
        return rc;
    }
    if (!o->output || (o->all_views && o->camera))
        return cli_usage_error(o);
    int rc = CLI_OK;
    if (!o->all_views) {
        rc = cli_check_output_path(o->output);
        if (rc != CLI_OK)
            return rc;
    }
    /* --size before the scene is loaded; the project's own size is checked by its reader. */
    if (o->width && o->height) {
        rc = cli_check_image_job("render", o->width, o->height, o->all_views ? NULL : o->output);
        if (rc != CLI_OK)
            return rc;
    }
    cli_session s;
    rc = cli_session_open(o, &s);
    if (rc != CLI_OK)
        return rc;
    rd_view view = {0};
    if (o->all_views) {
        rc = render_all_views(&s, o, &view);
    } else {
        rc = cli_session_view(&s, o, o->camera, 0, 0, &view);
        if (rc == CLI_OK)
            rc = cli_render_large(&s, &view, o->output, o->dpi, o->tile);
    }
    if (rc == CLI_OK && o->stats) {
        rd_frame_stats st = rd_last_frame_stats(s.ctx);
        rc = cli_write_stats(o->stats, &s, o, &view, &st, o->all_views ? NULL : o->output);
    }
    /* After the statistics, which describe the frame whatever it shows. */
    if (rc == CLI_OK && !o->all_views)
        rc = cli_check_room_visible(&s, o->camera ? o->camera : s.project.cameras[0].name,
                                    o->output);
    cli_session_close(&s);
    return rc;
}
