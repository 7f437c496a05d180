/* tessera reference PROJECT -o OUT [--camera NAME] [--size WxH] [--supersample N] [--samples N]
 *                   [--bounces N] [--threads N] [--seed N] [--png OUT.png] [--mask MASK.png]
 * The ground-truth image of a project view (RENDERING.md section 10, docs/reference.md). */
#include "app/project/job_limits.h"
#include "app/scene/quality.h"
#include "app/scene/ref_scene_build.h"
#include "cli/cli_commands.h"
#include "render/image_io.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Paths a subsample when --bounces > 0 and --samples is not given: with the projects' 2 x 2
 * supersampling 64 paths a pixel, a trace of minutes for a 640 x 360 room on two cores whose
 * noise lies far below the gap to the GPU (docs/accuracy.md, "Against the physical ground
 * truth"). */
#define REFERENCE_PATHS 16

void cli_defaults_reference(cli_options *o)
{
    o->bounces = REF_DEFAULT_BOUNCES;
}

/* An extra output (--png, --mask) must be an 8-bit format in a writable folder. */
static int check_display_path(const char *path, const char *option)
{
    int rc = cli_check_output_path(path);
    if (rc != CLI_OK)
        return rc;
    if (rd_image_format_is_float(path) != 0) {
        fprintf(stderr, "tessera reference: %s %s: use an 8-bit image type (.png, .jpg, .tif)\n",
                option, path);
        return CLI_USAGE;
    }
    return CLI_OK;
}

static int write_outputs(const ref_image *img, const char *output, const char *png,
                         const char *mask)
{
    char err[1024];
    rd_image_result r;
    if (rd_image_format_is_float(output) == 1)
        r = rd_image_write_float(output, img->width, img->height, 4, img->linear, err, sizeof err);
    /* ref_image_clamp_half has already kept every value within the half floats of .exr. */
    else
        r = rd_image_write_rgba8(output, img->width, img->height, img->rgba8, err, sizeof err);
    if (r == RD_IMAGE_OK && png)
        r = rd_image_write_rgba8(png, img->width, img->height, img->rgba8, err, sizeof err);
    if (r == RD_IMAGE_OK && mask) {
        size_t n = (size_t)img->width * (size_t)img->height;
        unsigned char *m = malloc(4 * n);
        if (!m) {
            fprintf(stderr, "tessera: out of memory for the mask\n");
            return CLI_FAILED;
        }
        for (size_t i = 0; i < n; i++) {
            m[4 * i] = m[4 * i + 1] = m[4 * i + 2] = img->mask[i] ? 255 : 0;
            m[4 * i + 3] = 255;
        }
        r = rd_image_write_rgba8(mask, img->width, img->height, m, err, sizeof err);
        free(m);
    }
    if (r != RD_IMAGE_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        return CLI_FAILED;
    }
    return CLI_OK;
}

int cli_cmd_reference(const cli_options *o)
{
    if (!o->output)
        return cli_usage_error(o);
    int rc = cli_check_output_path(o->output);
    if (rc == CLI_OK && o->png)
        rc = check_display_path(o->png, "--png");
    if (rc == CLI_OK && o->mask)
        rc = check_display_path(o->mask, "--mask");
    if (rc != CLI_OK)
        return rc;

    app_project p;
    char err[2048];
    app_result ar = app_project_read(o->project, &p, err, sizeof err);
    if (ar != APP_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        return ar == APP_ERR_OUT_OF_MEMORY ? CLI_FAILED : CLI_USAGE;
    }
    rd_view view;
    ar = app_view_from_camera(&p, o->camera, o->width, o->height, &view, err, sizeof err);
    if (ar != APP_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        app_project_free(&p);
        return CLI_USAGE;
    }
    if (o->supersample)
        view.supersample = o->supersample;
    cli_apply_tone_options(o, &view);
    if (o->ambient)
        p.render.ambient_model = o->ambient == 2;        /* as `render --ambient` (cli_session.c) */
    app_daylight_override(&p.daylight, o->sky, o->time); /* as `render --sky --time` */
    double t0 = cli_now_ms();
    ref_scene *scene = NULL;
    ar = app_ref_scene_build(&p, &scene, err, sizeof err);
    if (ar != APP_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        app_project_free(&p);
        return ar == APP_ERR_OUT_OF_MEMORY ? CLI_FAILED : CLI_USAGE;
    }
    /* Shadows as the GPU draws them with the same options: a preset's, refined by
     * --shadows; a preset's supersampling too, unless --supersample says otherwise. */
    rd_shadow_settings shadows = {0};
    if (o->quality) {
        shadows = (rd_shadow_settings){.mode = o->quality->shadows,
                                       .map_size = o->quality->shadow_map_size,
                                       .taps = o->quality->shadow_taps};
        if (!o->supersample)
            view.supersample = app_quality_supersample(o->quality, view.width, view.height);
    }
    if (o->shadows)
        shadows.mode = (rd_shadow_mode)(o->shadows - 1);
    ref_scene_set_shadows(scene, &shadows);
    int samples = o->samples ? o->samples : o->bounces > 0 ? REFERENCE_PATHS : 0;
    /* The size, the samples and the memory from the limits table (app/project/job_limits.h),
     * before the tracing. */
    app_job job = {
        .kind = APP_JOB_REFERENCE, .width = view.width, .height = view.height, .samples = samples};
    char what[96];
    snprintf(what, sizeof what, "a %dx%d reference with %d samples", view.width, view.height,
             samples);
    if (app_job_check(&job, what, err, sizeof err) != APP_OK) {
        fprintf(stderr, "tessera reference: %s\n", err);
        ref_scene_destroy(scene);
        app_project_free(&p);
        return CLI_USAGE;
    }
    ref_result rr = ref_scene_commit(scene);
    double build_ms = cli_now_ms() - t0;
    ref_image img = {0};
    if (rr == REF_OK)
        rr = ref_render(scene,
                        &(ref_render_desc){.view = view,
                                           .samples = samples,
                                           .bounces = o->bounces,
                                           .threads = o->threads,
                                           .seed = (uint32_t)o->seed,
                                           .progress = 1},
                        &img);
    if (rr != REF_OK) {
        fprintf(stderr, "tessera: %s: %s\n", p.path, ref_last_error());
        ref_scene_destroy(scene);
        app_project_free(&p);
        return rr == REF_ERR_INVALID_ARGUMENT || rr == REF_ERR_TOO_LARGE ? CLI_USAGE : CLI_FAILED;
    }
    ref_image_clamp_half(&img);
    rc = write_outputs(&img, o->output, o->png, o->mask);
    if (rc == CLI_OK) {
        long long masked = 0;
        for (size_t i = 0; i < (size_t)img.width * (size_t)img.height; i++)
            masked += img.mask[i];
        int ss = view.supersample > 1 ? view.supersample : 1;
        fprintf(stderr,
                "tessera: wrote %s%s%s%s%s (%dx%d, supersample %d, %d bounces, %d %s, %d threads, "
                "scene %.0f ms, trace %.2f s, %.2f Mrays/s, %lld reflective pixels)\n",
                o->output, o->png ? ", " : "", o->png ? o->png : "", o->mask ? ", " : "",
                o->mask ? o->mask : "", img.width, img.height, ss, o->bounces,
                samples ? samples : 64, o->bounces ? "paths a subsample" : "samples",
                img.threads_used, build_ms, img.seconds,
                img.seconds > 0.0 ? (double)img.rays / img.seconds * 1e-6 : 0.0, masked);
    }
    ref_image_free(&img);
    ref_scene_destroy(scene);
    app_project_free(&p);
    return rc;
}
