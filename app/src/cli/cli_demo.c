/* tessera demo: renders the shipped demo bathroom from every one of its cameras into out/. */
#include "app/cli/cli.h"
#include "cli_commands.h"
#include "cli_stats.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* The shipped assets: $TESSERA_ASSETS, else the source tree this binary was built from. */
static const char *assets_dir(void)
{
    const char *env = getenv("TESSERA_ASSETS");
    return env && *env ? env : TESSERA_SOURCE_DIR "/assets";
}

int cli_cmd_demo(const cli_options *args)
{
    cli_options o = *args;
    const char *out_dir = o.output ? o.output : "out";
    if (mkdir(out_dir, 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "tessera demo: cannot make folder %s: %s\n", out_dir, strerror(errno));
        return CLI_FAILED;
    }
    char project[4096];
    snprintf(project, sizeof project, "%s/projects/designed-bathroom.json", assets_dir());
    o.project = project;
    cli_session s;
    int rc = cli_session_open(&o, &s);
    if (rc != CLI_OK)
        return rc;
    fprintf(stderr, "tessera demo: %s, %d objects, %d lights, %d cameras, on %s (%s)\n",
            s.project.name, s.project.object_count, s.project.light_count, s.project.camera_count,
            rd_backend_name(rd_context_backend(s.ctx)), rd_context_description(s.ctx));
    rd_view view = {0};
    for (int i = 0; rc == CLI_OK && i < s.project.camera_count; i++) {
        const char *cam = s.project.cameras[i].name;
        char path[4096];
        rc = cli_session_view(&s, &o, cam, 0, 0, &view);
        if (rc != CLI_OK)
            break;
        fprintf(stderr, "[%d/%d] camera \"%s\"\n", i + 1, s.project.camera_count, cam);
        snprintf(path, sizeof path, "%s/demo-%s.png", out_dir, cam);
        rc = cli_render_to_file(&s, &view, path);
        if (rc == CLI_OK && i == 0) {
            snprintf(path, sizeof path, "%s/demo-%s.exr", out_dir, cam);
            rc = cli_render_to_file(&s, &view, path);
        }
    }
    if (rc == CLI_OK && o.stats) { /* the last camera's frame */
        rd_frame_stats st = rd_last_frame_stats(s.ctx);
        rc = cli_write_stats(o.stats, &s, &o, &view, &st, NULL);
    }
    if (rc == CLI_OK) /* the print set with these renders (docs/printing.md) */
        rc = app_cli_print_demo(&s.project, out_dir);
    cli_session_close(&s);
    return rc;
}
