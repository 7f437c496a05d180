/* tessera video PROJECT -o OUT.mp4 [--seconds S] [--fps N] [--size WxH] [--quality Q] ...
 * A smooth camera path through the project's stored viewpoints (app/output/camera_path.h); frames
 * written as PNG into OUT_frames/ and encoded to H.264 MP4 with ffmpeg when it is installed. */
#include "app/output/camera_path.h"
#include "app/cli/cli.h"
#include "app/project/job_limits.h"
#include "cli_commands.h"
#include "cli_print_render.h"
#include "render/image_io.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

/* Whether an executable `name` is on PATH. */
static int on_path(const char *name)
{
    const char *path = getenv("PATH");
    if (!path)
        return 0;
    char dir[4096];
    for (const char *p = path; *p;) {
        size_t n = strcspn(p, ":");
        snprintf(dir, sizeof dir, "%.*s/%s", (int)n, p, name);
        if (n > 0 && access(dir, X_OK) == 0)
            return 1;
        p += n;
        p += *p == ':';
    }
    return 0;
}

static int encode(const char *frames, int fps, const char *out)
{
    if (!on_path("ffmpeg")) {
        fprintf(stderr,
                "tessera video: ffmpeg is not installed: the frames are in %s/ "
                "(encode them with: ffmpeg -framerate %d -i %s/frame-%%05d.png -c:v "
                "libx264 -pix_fmt yuv420p %s)\n",
                frames, fps, frames, out);
        return CLI_OK;
    }
    char rate[16], pattern[4200];
    snprintf(rate, sizeof rate, "%d", fps);
    snprintf(pattern, sizeof pattern, "%s/frame-%%05d.png", frames);
    pid_t pid = fork();
    if (pid == 0) {
        execlp("ffmpeg", "ffmpeg", "-loglevel", "error", "-y", "-framerate", rate, "-i", pattern,
               "-c:v", "libx264", "-pix_fmt", "yuv420p", out, (char *)NULL);
        _exit(127);
    }
    int status = 0;
    if (pid < 0 || waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        fprintf(stderr, "tessera video: ffmpeg failed to encode %s\n", out);
        return CLI_FAILED;
    }
    fprintf(stderr, "tessera: wrote %s\n", out);
    return CLI_OK;
}

static int render_frames(cli_session *s, const cli_options *o, const char *dir, int frames)
{
    int n = s->project.camera_count;
    app_path_key *keys = calloc((size_t)n, sizeof *keys);
    rd_view base;
    int rc = keys ? cli_session_view(s, o, NULL, 0, 0, &base) : CLI_FAILED;
    for (int i = 0; i < n && rc == CLI_OK; i++) {
        rd_view v;
        rc = cli_session_view(s, o, s->project.cameras[i].name, 0, 0, &v);
        memcpy(keys[i].eye, v.eye, sizeof keys[i].eye);
        memcpy(keys[i].target, v.target, sizeof keys[i].target);
        keys[i].fov_deg = v.fov_y_deg > 0.0f ? v.fov_y_deg : 60.0f;
    }
    size_t bytes = (size_t)base.width * base.height * 4;
    uint8_t *rgba = rc == CLI_OK ? malloc(bytes) : NULL;
    if (rc == CLI_OK && !rgba)
        rc = CLI_FAILED;
    cli_progress bar;
    cli_progress_init(&bar, "video frames");
    rd_scene_hold_probes(s->scene.scene, 1); /* nothing moves: one capture serves every frame */
    for (int f = 0; f < frames && rc == CLI_OK; f++) {
        app_path_key k = app_camera_path_at(keys, n, frames > 1 ? (double)f / (frames - 1) : 0.0);
        rd_view v = base;
        memcpy(v.eye, k.eye, sizeof v.eye);
        memcpy(v.target, k.target, sizeof v.target);
        v.fov_y_deg = k.fov_deg;
        rc = cli_render_pixels(s, &v, o->tile, rgba, NULL, NULL);
        if (base.auto_exposure) { /* the first frame's exposure throughout: no flicker */
            base.exposure_ev = rd_last_frame_stats(s->ctx).exposure_ev;
            base.auto_exposure = 0;
        }
        char path[4200], err[1024];
        snprintf(path, sizeof path, "%s/frame-%05d.png", dir, f);
        if (rc == CLI_OK &&
            rd_image_write_rgba8(path, v.width, v.height, rgba, err, sizeof err) != RD_IMAGE_OK) {
            fprintf(stderr, "tessera: %s\n", err);
            rc = CLI_FAILED;
        }
        cli_progress_update(&bar, f + 1, frames);
    }
    free(rgba);
    free(keys);
    return rc;
}

int cli_cmd_video(const cli_options *args)
{
    cli_options o = *args;
    int rc = CLI_OK;
    if (!o.project || !o.output)
        return cli_usage_error(&o);
    double seconds = o.seconds > 0.0 ? o.seconds : 8.0;
    int fps = o.fps ? o.fps : 25;
    int frames = (int)(seconds * fps + 0.5);
    if (frames < 1)
        frames = 1;
    /* --size, the frames and the memory from the limits table (app/project/job_limits.h),
     * before the first frame; the project's own size is checked by its reader. */
    app_job job = {.kind = APP_JOB_VIDEO,
                   .width = o.width ? o.width : 1,
                   .height = o.height ? o.height : 1,
                   .frames = frames};
    char what[96], limit_err[1024];
    if (o.width && o.height)
        snprintf(what, sizeof what, "--size %dx%d, %.1f s at %d fps", o.width, o.height, seconds,
                 fps);
    else
        snprintf(what, sizeof what, "%.1f s at %d fps", seconds, fps);
    if (app_job_check(&job, what, limit_err, sizeof limit_err) != APP_OK) {
        fprintf(stderr, "tessera video: %s\n", limit_err);
        return CLI_USAGE;
    }
    char dir[4096];
    snprintf(dir, sizeof dir, "%s", o.output);
    char *dot = strrchr(dir, '.'), *slash = strrchr(dir, '/');
    if (dot && (!slash || dot > slash))
        *dot = 0;
    strncat(dir, "_frames", sizeof dir - strlen(dir) - 1);
    if (mkdir(dir, 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "tessera video: cannot make folder %s: %s\n", dir, strerror(errno));
        return CLI_USAGE;
    }
    cli_session s;
    rc = cli_session_open(&o, &s);
    if (rc != CLI_OK)
        return rc;
    if (s.project.camera_count < 1) {
        fprintf(stderr, "tessera video: %s has no cameras to move through\n", o.project);
        rc = CLI_USAGE;
    }
    if (rc == CLI_OK)
        rc = render_frames(&s, &o, dir, frames);
    cli_session_close(&s);
    if (rc == CLI_OK)
        rc = encode(dir, fps, o.output);
    return rc;
}
