/* tessera reference PROJECT -o OUT [--camera NAME] [--size WxH] [--supersample N] [--samples N]
 *                   [--threads N] [--seed N] [--png OUT.png] [--mask MASK.png]
 * The ground-truth image of a project view (RENDERING.md section 10, docs/reference.md). */
#include "app/measure/cli_ref.h"
#include "app/scene/quality.h"
#include "app/scene/ref_scene_build.h"
#include "cli/cli_options.h"
#include "render/image_io.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define USAGE                                                                                      \
    "usage: tessera reference PROJECT -o OUT.(exr|png|jpg|tif) [--camera NAME] [--size WxH]\n"     \
    "                         [--supersample 1-4] [--samples N] [--threads N] [--seed N]\n"        \
    "                         [--png OUT.png] [--mask MASK.png] [--shadows off|hard|soft]\n"       \
    "                         [--quality draft|interactive|final|print]\n"                         \
    "                         [--ambient constant|sh9]\n"

typedef struct ref_options {
    int samples, threads;
    long long seed;
    const char *png, *mask;
} ref_options;

static int parse_long(const char *text, long long lo, long long hi, long long *out)
{
    char *end;
    errno = 0;
    long long v = strtoll(text, &end, 10);
    if (end == text || *end || errno || v < lo || v > hi)
        return 0;
    *out = v;
    return 1;
}

/* Takes this command's own options out of argv; everything else goes to `rest` for cli_parse.
 * Every option takes a value, so an option's value is never mistaken for an option. */
static int take_options(int argc, char **argv, char **rest, int *rest_count, ref_options *o)
{
    int n = 0;
    rest[n++] = argv[0];
    rest[n++] = argv[1];
    for (int i = 2; i < argc; i++) {
        const char *a = argv[i];
        int mine = !strcmp(a, "--samples") || !strcmp(a, "--threads") || !strcmp(a, "--seed") ||
                   !strcmp(a, "--png") || !strcmp(a, "--mask");
        if (!mine) {
            rest[n++] = argv[i];
            if ((!strcmp(a, "-o") || !strncmp(a, "--", 2)) && i + 1 < argc)
                rest[n++] = argv[++i];
            continue;
        }
        if (i + 1 >= argc) {
            fprintf(stderr, "tessera reference: option %s needs a value\n", a);
            return CLI_USAGE;
        }
        const char *v = argv[++i];
        long long x = 0;
        int ok = 1;
        if (!strcmp(a, "--samples")) {
            ok = parse_long(v, 1, 1 << 20, &x);
            o->samples = (int)x;
        } else if (!strcmp(a, "--threads")) {
            ok = parse_long(v, 1, 256, &x);
            o->threads = (int)x;
        } else if (!strcmp(a, "--seed")) {
            ok = parse_long(v, 0, 4294967295LL, &x);
            o->seed = x;
        } else if (!strcmp(a, "--png")) {
            o->png = v;
        } else {
            o->mask = v;
        }
        if (!ok) {
            fprintf(stderr, "tessera reference: bad value \"%s\" for %s (expected %s)\n", v, a,
                    !strcmp(a, "--samples")   ? "1 to 1048576"
                    : !strcmp(a, "--threads") ? "1 to 256"
                                              : "0 to 4294967295");
            return CLI_USAGE;
        }
    }
    *rest_count = n;
    return CLI_OK;
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

int app_cli_reference(int argc, char **argv)
{
    ref_options ro = {0};
    char **rest = malloc((size_t)(argc > 2 ? argc : 2) * sizeof *rest);
    if (!rest)
        return CLI_FAILED;
    int rest_count = 0;
    int rc = take_options(argc, argv, rest, &rest_count, &ro);
    cli_options o = {0};
    if (rc == CLI_OK)
        rc = cli_parse(rest_count, rest, 2, "reference",
                       "output camera size supersample shadows quality ambient", &o);
    free(rest);
    if (rc != CLI_OK)
        return rc;
    if (!o.project || !o.output) {
        fprintf(stderr, USAGE);
        return CLI_USAGE;
    }
    rc = cli_check_output_path(o.output);
    if (rc == CLI_OK && ro.png)
        rc = check_display_path(ro.png, "--png");
    if (rc == CLI_OK && ro.mask)
        rc = check_display_path(ro.mask, "--mask");
    if (rc != CLI_OK)
        return rc;

    app_project p;
    char err[2048];
    app_result ar = app_project_read(o.project, &p, err, sizeof err);
    if (ar != APP_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        return ar == APP_ERR_OUT_OF_MEMORY ? CLI_FAILED : CLI_USAGE;
    }
    rd_view view;
    ar = app_view_from_camera(&p, o.camera, o.width, o.height, &view, err, sizeof err);
    if (ar != APP_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        app_project_free(&p);
        return CLI_USAGE;
    }
    if (o.supersample)
        view.supersample = o.supersample;
    if (o.ambient)
        p.render.ambient_model = o.ambient == 2; /* as `render --ambient` (cli_session.c) */
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
    if (o.quality) {
        shadows = (rd_shadow_settings){.mode = o.quality->shadows,
                                       .map_size = o.quality->shadow_map_size,
                                       .taps = o.quality->shadow_taps};
        if (!o.supersample)
            view.supersample = app_quality_supersample(o.quality, view.width, view.height);
    }
    if (o.shadows)
        shadows.mode = (rd_shadow_mode)(o.shadows - 1);
    ref_scene_set_shadows(scene, &shadows);
    ref_result rr = ref_scene_commit(scene);
    double build_ms = cli_now_ms() - t0;
    ref_image img = {0};
    if (rr == REF_OK)
        rr = ref_render(scene,
                        &(ref_render_desc){.view = view,
                                           .samples = ro.samples,
                                           .threads = ro.threads,
                                           .seed = (uint32_t)ro.seed,
                                           .progress = 1},
                        &img);
    if (rr != REF_OK) {
        fprintf(stderr, "tessera: %s: %s\n", p.path, ref_last_error());
        ref_scene_destroy(scene);
        app_project_free(&p);
        return rr == REF_ERR_INVALID_ARGUMENT || rr == REF_ERR_TOO_LARGE ? CLI_USAGE : CLI_FAILED;
    }
    rc = write_outputs(&img, o.output, ro.png, ro.mask);
    if (rc == CLI_OK) {
        long long masked = 0;
        for (size_t i = 0; i < (size_t)img.width * (size_t)img.height; i++)
            masked += img.mask[i];
        int ss = view.supersample > 1 ? view.supersample : 1;
        fprintf(stderr,
                "tessera: wrote %s%s%s%s%s (%dx%d, supersample %d, %d samples, %d threads, "
                "scene %.0f ms, trace %.2f s, %.2f Mrays/s, %lld reflective pixels)\n",
                o.output, ro.png ? ", " : "", ro.png ? ro.png : "", ro.mask ? ", " : "",
                ro.mask ? ro.mask : "", img.width, img.height, ss, ro.samples ? ro.samples : 64,
                img.threads_used, build_ms, img.seconds,
                img.seconds > 0.0 ? (double)img.rays / img.seconds * 1e-6 : 0.0, masked);
    }
    ref_image_free(&img);
    ref_scene_destroy(scene);
    app_project_free(&p);
    return rc;
}
