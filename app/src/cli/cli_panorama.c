/* tessera panorama PROJECT -o OUT.jpg [--camera NAME] [--size 4096x2048] [--faces DIR]
 *                  [--quality Q] [--shadows M] [--supersample N] [--backend B]
 * Six 90-degree cube faces from a viewpoint, resampled into an equirectangular image; a JPEG
 * gets the GPano XMP that panorama viewers read (app/output/panorama.h, docs/rendering.md). */
#include "app/cli/cli.h"
#include "app/output/panorama.h"
#include "app/project/job_limits.h"
#include "cli_commands.h"
#include "cli_print_render.h"
#include "render/image_io.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

static int is_jpeg(const char *path)
{
    const char *dot = strrchr(path, '.');
    return dot && (!strcasecmp(dot, ".jpg") || !strcasecmp(dot, ".jpeg"));
}

static int write_faces(const char *dir, uint8_t *const faces[6], int side)
{
    if (mkdir(dir, 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "tessera panorama: cannot make folder %s: %s\n", dir, strerror(errno));
        return CLI_USAGE;
    }
    for (int k = 0; k < 6; k++) {
        char path[4096], err[1024];
        snprintf(path, sizeof path, "%s/%s.png", dir, app_pano_face_name(k));
        if (rd_image_write_rgba8(path, side, side, faces[k], err, sizeof err) != RD_IMAGE_OK) {
            fprintf(stderr, "tessera: %s\n", err);
            return CLI_FAILED;
        }
    }
    return CLI_OK;
}

static int make_panorama(cli_session *s, const cli_options *o, int w, int h)
{
    rd_view base;
    int rc = cli_session_view(s, o, o->camera, w, h, &base);
    if (rc != CLI_OK)
        return rc;
    /* A face a quarter of the width: the equator then keeps about one texel per pixel. */
    int side = w / 4 > 16 ? w / 4 : 16;
    float look[3], fwd[6][3], up[6][3];
    for (int k = 0; k < 3; k++)
        look[k] = base.target[k] - base.eye[k];
    app_pano_frames(look, fwd, up);
    uint8_t *faces[6] = {0};
    uint8_t *pano = malloc((size_t)w * h * 4);
    for (int k = 0; k < 6; k++)
        faces[k] = malloc((size_t)side * side * 4);
    for (int k = 0; k < 6 && pano; k++)
        if (!faces[k])
            rc = CLI_FAILED;
    if (!pano)
        rc = CLI_FAILED;
    if (rc != CLI_OK)
        fprintf(stderr, "tessera: out of memory for a %dx%d panorama\n", w, h);
    cli_progress bar;
    cli_progress_init(&bar, "panorama faces");
    rd_scene_hold_probes(s->scene.scene, 1); /* one capture serves all six faces */
    for (int k = 0; k < 6 && rc == CLI_OK; k++) {
        rd_view v = base;
        v.width = v.height = side;
        v.fov_y_deg = 90.0f;
        for (int c = 0; c < 3; c++) {
            v.target[c] = v.eye[c] + fwd[k][c];
            v.up[c] = up[k][c];
        }
        rc = cli_render_pixels(s, &v, o->tile, faces[k], NULL, NULL);
        if (base.auto_exposure) { /* the first face's exposure for all six: no seams */
            base.exposure_ev = rd_last_frame_stats(s->ctx).exposure_ev;
            base.auto_exposure = 0;
        }
        cli_progress_update(&bar, k + 1, 6);
    }
    if (rc == CLI_OK && o->faces)
        rc = write_faces(o->faces, faces, side);
    if (rc == CLI_OK) {
        app_pano_equirect((const uint8_t *const *)faces, side, (const float(*)[3])fwd,
                          (const float(*)[3])up, pano, w, h);
        char err[1024], xmp[4096];
        /* The GPano packet goes into the encoded JPEG before the file gets its name: a
         * panorama is never in place without its 360-degree metadata. */
        if (app_pano_xmp(w, h, xmp, sizeof xmp) < 0) {
            fprintf(stderr, "tessera: %s: panorama metadata does not fit\n", o->output);
            rc = CLI_FAILED;
        } else if (rd_image_write_rgba8_xmp(o->output, w, h, pano, is_jpeg(o->output) ? xmp : NULL,
                                            err, sizeof err) != RD_IMAGE_OK) {
            fprintf(stderr, "tessera: %s\n", err);
            rc = CLI_FAILED;
        }
    }
    if (rc == CLI_OK)
        fprintf(stderr, "tessera: wrote %s (%dx%d equirectangular from 6 faces of %d%s, %.0f ms)\n",
                o->output, w, h, side, is_jpeg(o->output) ? ", GPano XMP" : "",
                cli_now_ms() - bar.start_ms);
    for (int k = 0; k < 6; k++)
        free(faces[k]);
    free(pano);
    return rc;
}

int cli_cmd_panorama(const cli_options *args)
{
    cli_options o = *args;
    int rc = CLI_OK;
    if (!o.project || !o.output)
        return cli_usage_error(&o);
    int w = o.width ? o.width : 4096, h = o.height ? o.height : 2048;
    if (w != 2 * h) {
        fprintf(stderr,
                "tessera panorama: --size %dx%d: an equirectangular image is twice as "
                "wide as it is high (e.g. 4096x2048)\n",
                w, h);
        return CLI_USAGE;
    }
    /* The size and the memory from the limits table (app/project/job_limits.h), before any
     * face is rendered. */
    app_job job = {.kind = APP_JOB_PANORAMA, .width = w, .height = h};
    char what[64], err[1024];
    snprintf(what, sizeof what, "--size %dx%d", w, h);
    if (app_job_check(&job, what, err, sizeof err) != APP_OK) {
        fprintf(stderr, "tessera panorama: %s\n", err);
        return CLI_USAGE;
    }
    rc = cli_check_output_path(o.output);
    if (rc == CLI_OK && rd_image_format_is_float(o.output) != 0) {
        fprintf(stderr, "tessera panorama: %s: use .jpg, .png or .tif\n", o.output);
        rc = CLI_USAGE;
    }
    if (rc != CLI_OK)
        return rc;
    cli_options view_o = o;
    view_o.width = view_o.height = 0; /* the faces are sized here, not by --size */
    cli_session s;
    rc = cli_session_open(&o, &s);
    if (rc != CLI_OK)
        return rc;
    rc = make_panorama(&s, &view_o, w, h);
    cli_session_close(&s);
    return rc;
}
