#include "cli_options.h"

#include "app/cli/cli.h"

#include "app/project/commands.h"
#include "app/project/flat.h"
#include "app/scene/quality.h"
#include "app/scene/scene_bake.h"
#include "render/image_io.h"

#include <errno.h>
#include <libgen.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

int cli_check_output_path(const char *path)
{
    if (rd_image_format_is_float(path) < 0) {
        fprintf(stderr, "tessera: %s: unknown image type (use .png, .jpg, .tif or .exr)\n", path);
        return CLI_USAGE;
    }
    char copy[4096];
    snprintf(copy, sizeof copy, "%s", path);
    const char *dir = dirname(copy);
    struct stat st;
    if (stat(dir, &st) != 0) {
        fprintf(stderr, "tessera: %s: cannot write: folder %s: %s\n", path, dir, strerror(errno));
        return CLI_USAGE;
    }
    if (!S_ISDIR(st.st_mode) || access(dir, W_OK | X_OK) != 0) {
        fprintf(stderr, "tessera: %s: cannot write: %s is %s\n", path, dir,
                S_ISDIR(st.st_mode) ? "a folder that is not writable" : "not a folder");
        return CLI_USAGE;
    }
    struct stat target;
    if (stat(path, &target) == 0 && S_ISDIR(target.st_mode)) {
        fprintf(stderr, "tessera: %s: cannot write: it is a folder\n", path);
        return CLI_USAGE;
    }
    return CLI_OK;
}

int cli_bake_wanted(const cli_options *o)
{
    if (o->bake)
        return o->bake == RD_SWITCH_ON;
    const char *env = getenv("TESSERA_BAKE");
    return !(env && !strcmp(env, "off"));
}

void cli_bake_configure(const cli_options *o)
{
    app_bake_settings b = {
        .on = cli_bake_wanted(o), .progress = isatty(2), .bounces = o->bake_bounces};
    app_bake_configure(&b);
}

app_result cli_session_read_room(const cli_options *o, app_project *out)
{
    char err[2048];
    app_flat flat;
    app_result r = app_flat_read(o->project, &flat, err, sizeof err);
    if (r != APP_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        return r;
    }
    /* A flat renders the room of the camera; the other rooms are never built (culled). */
    int room = app_flat_room_of_camera(&flat, o->camera);
    if (room < 0 && !flat.is_flat)
        room = 0; /* one room: the view names the cameras it has */
    if (room < 0 || (o->room_index > 0 && o->room_index > flat.room_count)) {
        if (room < 0)
            fprintf(stderr, "tessera: %s: no room has a camera \"%s\"\n", o->project, o->camera);
        else
            fprintf(stderr, "tessera: %s: no room %d (%d rooms)\n", o->project, o->room_index,
                    flat.room_count);
        app_flat_free(&flat);
        return APP_ERR_SCHEMA;
    }
    if (o->room_index > 0 && !o->camera)
        room = o->room_index - 1;
    if (flat.is_flat)
        fprintf(stderr, "tessera: %s: room %d of %d, \"%s\" (the others culled)\n", o->project,
                room + 1, flat.room_count, flat.rooms[room].name);
    app_flat_take_room(&flat, room, out);
    return APP_OK;
}

int cli_session_open(const cli_options *o, cli_session *s)
{
    memset(s, 0, sizeof *s);
    app_result r = cli_session_read_room(o, &s->project);
    if (r != APP_OK)
        return r == APP_ERR_OUT_OF_MEMORY ? CLI_FAILED : CLI_USAGE;
    return cli_session_start(o, s);
}

int cli_session_open_room(const cli_options *o, const app_project *room, cli_session *s)
{
    memset(s, 0, sizeof *s);
    char err[2048];
    if (app_project_copy(&s->project, room, err, sizeof err) != APP_OK) {
        fprintf(stderr, "tessera: %s: room \"%s\": %s\n", o->project, room->name, err);
        return CLI_FAILED;
    }
    return cli_session_start(o, s);
}

static app_window_context_fn window_context;

void app_cli_set_window_context(app_window_context_fn fn)
{
    window_context = fn;
}

/* The session's context: a backend's own, or a hidden window's (--backend window). */
static rd_result open_context(const cli_options *o, rd_context **ctx, char *err, size_t err_size)
{
    rd_context_desc d = {.backend = o->backend};
    if (o->backend == RD_BACKEND_ADOPT) {
        if (!window_context) {
            snprintf(err, err_size, "--backend window needs the full program (tessera-full)");
            return RD_ERR_BACKEND_UNAVAILABLE;
        }
        if (window_context(&d.get_proc_address, err, err_size) != 0)
            return RD_ERR_BACKEND_UNAVAILABLE;
    }
    rd_result r = rd_context_create(&d, ctx);
    if (r != RD_OK)
        snprintf(err, err_size, "%s", rd_last_error());
    return r;
}

int cli_session_start(const cli_options *o, cli_session *s)
{
    char err[2048];
    app_result r;
    app_daylight_override(&s->project.daylight, o->sky, o->time); /* checked when parsed */
    if (open_context(o, &s->ctx, err, sizeof err) != RD_OK) {
        fprintf(stderr, "tessera: cannot open an OpenGL context: %s\n", err);
        app_project_free(&s->project);
        return CLI_FAILED;
    }
    cli_bake_configure(o);
    r = app_scene_build(s->ctx, &s->project, &s->scene, err, sizeof err);
    if (r != APP_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        cli_session_close(s);
        return r == APP_ERR_OUT_OF_MEMORY ? CLI_FAILED : CLI_USAGE;
    }
    /* A preset first, so that explicit --probes/--blur/--ambient refine it. */
    if (o->quality)
        app_quality_apply(o->quality, s->scene.scene);
    if (o->shadows) { /* --shadows refines the preset's (or the project's) shadows */
        rd_shadow_settings sh = rd_scene_shadows(s->scene.scene);
        sh.mode = (rd_shadow_mode)(o->shadows - 1);
        rd_scene_set_shadows(s->scene.scene, &sh);
    }
    /* Each switch given on the command line overrides the preset's; unset leaves it. */
    if (o->probes || o->blur || o->ambient || o->planar_mirrors || o->mirror_bounce ||
        o->mirror_panes || o->room_probe || o->glaze || o->exact_lamps || o->self_reflections ||
        o->probe_resolution) {
        rd_reflection_defaults d = rd_scene_reflection_defaults(s->scene.scene);
        if (o->planar_mirrors)
            d.planar_mirrors = o->planar_mirrors;
        if (o->mirror_bounce)
            d.mirror_bounce = o->mirror_bounce;
        if (o->mirror_panes)
            d.mirror_panes = o->mirror_panes;
        if (o->room_probe)
            d.room_probe = o->room_probe;
        if (o->glaze)
            d.glaze = o->glaze;
        if (o->exact_lamps)
            d.exact_lamps = o->exact_lamps;
        if (o->self_reflections == RD_SWITCH_OFF)
            d.self_reflections = 0;
        else if (o->self_reflections == RD_SWITCH_ON &&
                 (o->self_rays > 0 || d.self_reflections <= 0))
            d.self_reflections = o->self_rays > 0 ? o->self_rays : APP_SELF_REFLECTION_RAYS;
        if (o->probe_resolution)
            d.resolution = o->probe_resolution;
        if (o->ambient)
            d.ambient = o->ambient == 2 ? RD_AMBIENT_SH9 : RD_AMBIENT_CONSTANT;
        if (o->probes)
            d.update = o->probes;
        if (o->blur)
            d.blur = o->blur;
        rd_scene_set_reflection_defaults(s->scene.scene, &d);
    }
    return CLI_OK;
}

void cli_session_close(cli_session *s)
{
    if (s->ctx)
        app_scene_release(s->ctx, &s->scene);
    rd_context_destroy(s->ctx);
    app_project_free(&s->project);
    memset(s, 0, sizeof *s);
}

int cli_session_view(const cli_session *s, const cli_options *o, const char *camera, int width,
                     int height, rd_view *out)
{
    char err[1024];
    if (app_view_from_camera(&s->project, camera, o->width ? o->width : width,
                             o->height ? o->height : height, out, err, sizeof err) != APP_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        return CLI_USAGE;
    }
    if (o->quality) {
        out->supersample = app_quality_supersample(o->quality, out->width, out->height);
        out->adaptive = app_quality_adaptive(o->quality, out->width, out->height);
    }
    if (o->supersample)
        out->supersample = o->supersample;
    if (o->adaptive)
        out->adaptive = o->adaptive == RD_SWITCH_ON;
    out->all_objects = o->prime == RD_SWITCH_ON;
    cli_apply_tone_options(o, out);
    return CLI_OK;
}

int cli_render_to_file(cli_session *s, const rd_view *view, const char *path)
{
    double t0 = cli_now_ms();
    rd_result rr = rd_render(s->ctx, s->scene.scene, view);
    if (rr != RD_OK) {
        fprintf(stderr, "tessera: %s: %s\n", s->project.path, rd_last_error());
        return rr == RD_ERR_TOO_LARGE || rr == RD_ERR_INVALID_ARGUMENT ? CLI_USAGE : CLI_FAILED;
    }
    size_t count = (size_t)view->width * (size_t)view->height * 4;
    int is_float = rd_image_format_is_float(path) == 1;
    void *pixels = malloc(count * (is_float ? sizeof(float) : 1));
    if (!pixels) {
        fprintf(stderr, "tessera: out of memory for a %dx%d image\n", view->width, view->height);
        return CLI_FAILED;
    }
    char err[1024];
    rd_image_result ir;
    if (is_float) {
        rr = rd_read_linear(s->ctx, pixels, count);
        ir = rr == RD_OK
                 ? rd_image_write_float(path, view->width, view->height, 4, pixels, err, sizeof err)
                 : RD_IMAGE_ERR_IO;
    } else {
        rr = rd_read_rgba8(s->ctx, pixels, count);
        ir = rr == RD_OK
                 ? rd_image_write_rgba8(path, view->width, view->height, pixels, err, sizeof err)
                 : RD_IMAGE_ERR_IO;
    }
    free(pixels);
    if (rr != RD_OK) {
        fprintf(stderr, "tessera: reading the image back failed: %s\n", rd_last_error());
        return CLI_FAILED;
    }
    if (ir != RD_IMAGE_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        return CLI_FAILED;
    }
    fprintf(stderr, "tessera: wrote %s (%dx%d%s, %.0f ms)\n", path, view->width, view->height,
            view->supersample > 1 ? ", supersampled" : "", cli_now_ms() - t0);
    return CLI_OK;
}
