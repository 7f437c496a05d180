/* tessera render PROJECT --serve: renders the views asked for on standard input, one a line,
 * keeping the scene, its baked light, its probes and its shadow maps between them (the planner
 * window's still view at final and print, docs/ui.md "The live view"). A request:
 *
 *     EYE_X EYE_Y EYE_Z TARGET_X TARGET_Y TARGET_Z FOV_DEG PRESET WIDTH HEIGHT OUT.png
 *
 * (mm, degrees, a quality preset's name, pixels, a path without spaces); the answer on standard
 * output is "done OUT.png" or "failed MESSAGE". The picture is the one `tessera render
 * --quality PRESET --size WIDTHxHEIGHT` makes of a camera at that place: probes are captured
 * when the scene or the preset changes, not for every view, since they do not depend on it. */
#include "cli_commands.h"
#include "cli_print_render.h"

#include "app/scene/quality.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SERVE_CAMERA "tessera-served-view"

/* The camera the requests move: the project's own are left as they are. */
static app_camera *serve_camera(cli_session *s)
{
    app_project *p = &s->project;
    app_camera *cams = realloc(p->cameras, ((size_t)p->camera_count + 1) * sizeof *cams);
    if (!cams)
        return NULL;
    p->cameras = cams;
    app_camera *c = &cams[p->camera_count++];
    memset(c, 0, sizeof *c);
    snprintf(c->name, sizeof c->name, "%s", SERVE_CAMERA);
    c->up[2] = 1.0;
    c->fov_deg = 60.0;
    return c;
}

/* The preset's settings; probes then wait for a change, as in the window. */
static void apply_preset(cli_session *s, const app_quality *q)
{
    app_quality_apply(q, s->scene.scene);
    rd_reflection_defaults d = rd_scene_reflection_defaults(s->scene.scene);
    if (d.update == RD_PROBE_EVERY_FRAME)
        d.update = RD_PROBE_ON_CHANGE;
    rd_scene_set_reflection_defaults(s->scene.scene, &d);
}

static int finite_all(const double *v, int n)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(v[i]) || fabs(v[i]) > 1e9)
            return 0;
    return 1;
}

/* One request. Returns 0 when answered (done or failed), 1 when the line is not a request. */
static int serve_line(cli_session *s, const cli_options *o, app_camera *cam,
                      const app_quality **applied, const char *line)
{
    double v[7];
    char preset[32], path[4096];
    int w = 0, h = 0, used = 0;
    if (sscanf(line, "%lf %lf %lf %lf %lf %lf %lf %31s %d %d %4095s%n", &v[0], &v[1], &v[2], &v[3],
               &v[4], &v[5], &v[6], preset, &w, &h, path, &used) != 11)
        return 1;
    const app_quality *q = app_quality_find(preset);
    if (!q || !finite_all(v, 7) || v[6] <= 1.0 || v[6] >= 179.0 || w < 1 || h < 1 || w > 16384 ||
        h > 16384) {
        printf("failed not a view: %s", line);
        return 0;
    }
    memcpy(cam->position_mm, v, sizeof cam->position_mm);
    memcpy(cam->target_mm, v + 3, sizeof cam->target_mm);
    cam->fov_deg = v[6];
    if (q != *applied) {
        apply_preset(s, q);
        *applied = q;
    }
    cli_options vo = *o;
    vo.quality = q;
    vo.width = w;
    vo.height = h;
    rd_view view;
    int rc = cli_session_view(s, &vo, SERVE_CAMERA, w, h, &view);
    if (rc == CLI_OK)
        rc = cli_render_large(s, &view, path, 0, o->tile);
    if (rc == CLI_OK)
        printf("done %s\n", path);
    else
        printf("failed the render of %s (its reason is on standard error)\n", path);
    return 0;
}

int cli_render_serve(cli_session *s, const cli_options *o)
{
    app_camera *cam = serve_camera(s);
    if (!cam) {
        fprintf(stderr, "tessera render --serve: out of memory\n");
        return CLI_FAILED;
    }
    const app_quality *applied = NULL;
    char line[8192];
    while (fgets(line, sizeof line, stdin)) {
        if (serve_line(s, o, cam, &applied, line))
            printf("failed not a view: %s", line);
        fflush(stdout);
    }
    return CLI_OK;
}
