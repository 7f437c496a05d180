/* tessera extremes: RENDERING.md section 11 as a sweep of its own. Each case
 * changes one thing of a small mirror-and-chrome room to an extreme, renders it on the GPU and
 * with the reference tracer, checks that every pixel of both is finite, and measures the
 * error where the reference is defined; then once more on the GPU with the print preset's
 * self-reflections (render/src/self_trace.c), whose trace and lobe sampling meet the same
 * extremes, and with the reference's path tracer (--bounces, default 4), whose image must also
 * stay finite once written as the half floats of an .exr. Prints a Markdown table; exit 1 if a
 * pixel is not finite. */
#include "app/cli/cli.h"
#include "app/output/safe_file.h"
#include "app/measure/image_compare.h"
#include "app/scene/quality.h"
#include "app/scene/ref_scene_build.h"
#include "cli/cli_commands.h"

#include "ref/ref.h"
#include "render/image_io.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

typedef struct extreme_case {
    const char *name;
    double scale; /* room size factor (1 = 2 m) */
    double gloss, kr, shininess, emissive;
    int resolution;     /* probe texels, 0 auto */
    int every;          /* probe "every" */
    const char *camera; /* "normal", "grazing" or "down" */
    double ball_mm;     /* ball diameter (before scale) */
    int nan_texture;
} extreme_case;

static const extreme_case cases[] = {
    {"baseline", 1, 0.9, 0.8, 200, 6, 0, 1, "normal", 600, 0},
    {"gloss 0", 1, 0.0, 0.8, 200, 6, 0, 0, "normal", 600, 0},
    {"gloss 1e-6", 1, 1e-6, 0.8, 200, 6, 0, 0, "normal", 600, 0},
    {"gloss 1 - 1e-6", 1, 1 - 1e-6, 0.8, 200, 6, 0, 0, "normal", 600, 0},
    {"gloss 1 (mirror)", 1, 1.0, 0.8, 200, 6, 0, 0, "normal", 600, 0},
    {"k_r 0", 1, 0.9, 0.0, 200, 6, 0, 0, "normal", 600, 0},
    {"k_r 1", 1, 0.9, 1.0, 200, 6, 0, 0, "normal", 600, 0},
    {"shininess 0", 1, 0.9, 0.8, 0, 6, 0, 0, "normal", 600, 0},
    {"shininess 10 000", 1, 0.9, 0.8, 10000, 6, 0, 0, "normal", 600, 0},
    {"N.V = 0 (grazing view of the mirror)", 1, 0.9, 0.8, 200, 6, 0, 0, "grazing", 600, 0},
    {"R parallel to the walls (looking straight down)", 1, 0.9, 0.8, 200, 6, 0, 0, "down", 600, 0},
    {"object of zero size (1e-6 mm ball)", 1, 0.9, 0.8, 200, 6, 0, 0, "normal", 1e-6, 0},
    {"scene of 1 mm", 0.0005, 0.9, 0.8, 200, 6, 0, 0, "normal", 600, 0},
    {"scene of 10 km", 5000, 0.9, 0.8, 200, 6, 0, 0, "normal", 600, 0},
    {"HDR lamp of 1e6", 1, 0.9, 0.8, 200, 1e6, 0, 0, "normal", 600, 0},
    {"NaN and Inf texels", 1, 0.9, 0.8, 200, 6, 0, 0, "normal", 600, 1},
    {"1 x 1 cube maps", 1, 0.9, 0.8, 200, 6, 1, 0, "normal", 600, 0},
    {"update interval N = 0", 1, 0.9, 0.8, 200, 6, 0, 0, "normal", 600, 0},
};
enum { CASES = sizeof cases / sizeof cases[0] };

/* The room as a project file (millimetres), with this case's extreme in it. */
static int case_json(const extreme_case *c, const char *nan_texture, char *out, size_t size)
{
    double s = c->scale, W = 2000 * s, H = 1600 * s;
    double cam[3] = {0.15 * W, 0.95 * W, 0.6 * H}, tgt[3] = {0.6 * W, 0.3 * W, 0.3 * H};
    if (!strcmp(c->camera, "grazing")) { /* the mirror floor seen almost edge-on */
        cam[2] = 0.0051 * W, tgt[2] = 0.005 * W;
    } else if (!strcmp(c->camera, "down")) {
        cam[0] = tgt[0] = 0.5 * W, cam[1] = tgt[1] = 0.5 * W, cam[2] = 0.9 * H, tgt[2] = 0.0;
    }
    int down = !strcmp(c->camera, "down");
    char res[16] = "\"auto\"";
    if (c->resolution > 0)
        snprintf(res, sizeof res, "%d", c->resolution);
    char texture[1400] = "";
    if (c->nan_texture)
        snprintf(texture, sizeof texture, ", \"texture\": \"%s\", \"texture_size\": [%g, %g]",
                 nan_texture, 300 * s, 300 * s);
    int n = snprintf(
        out, size,
        "{\"version\": 1, \"name\": \"extreme: %s\",\n"
        " \"room\": {\"width\": %g, \"depth\": %g, \"height\": %g, \"floor\": \"wall\", \"walls\": "
        "\"wall\", \"ceiling\": \"wall\"},\n"
        " \"materials\": {\n"
        "  \"wall\": {\"diffuse\": [0.7, 0.6, 0.5], \"specular\": [0.2, 0.2, 0.2], \"shininess\": "
        "30%s},\n"
        "  \"mirror\": {\"diffuse\": [0.05, 0.05, 0.05], \"reflectivity\": 0.95, \"glossiness\": 1,"
        " \"probe\": {\"resolution\": %s, \"every\": %d}},\n"
        "  \"chrome\": {\"diffuse\": [0.1, 0.1, 0.1], \"specular\": [1, 1, 1], \"shininess\": %g,"
        " \"reflectivity\": %g, \"glossiness\": %.9g, \"probe\": {\"resolution\": %s, \"every\": "
        "%d}},\n"
        "  \"lamp\": {\"diffuse\": [1, 1, 1], \"emissive\": [%g, %g, %g]}},\n"
        " \"objects\": [\n"
        "  {\"name\": \"mirror\", \"shape\": \"plane\", \"position\": [%g, %g, %g], \"size\": [%g, "
        "%g],"
        " \"material\": \"mirror\"},\n"
        "  {\"name\": \"ball\", \"shape\": \"sphere\", \"position\": [%g, %g, %g], \"size\": [%g, "
        "%g, %g],"
        " \"material\": \"chrome\"},\n"
        "  {\"name\": \"lamp\", \"shape\": \"sphere\", \"position\": [%g, %g, %g], \"size\": [%g, "
        "%g, %g],"
        " \"material\": \"lamp\"}],\n"
        " \"lights\": [{\"type\": \"point\", \"position\": [%g, %g, %g], \"color\": [1, 1, 1],"
        " \"intensity\": 2, \"attenuation\": [1, 0, %g]}],\n"
        " \"cameras\": [{\"name\": \"view\", \"position\": [%g, %g, %g], \"target\": [%g, %g, "
        "%g], \"up\": [0, %d, %d]}],\n"
        " \"render\": {\"ambient\": [0.15, 0.15, 0.15]}}\n",
        c->name, W, W, H, texture, res, c->every, c->shininess, c->kr, c->gloss, res, c->every,
        c->emissive, c->emissive, c->emissive, 0.5 * W, 0.5 * W, 2 * s, 0.8 * W, 0.8 * W, 0.6 * W,
        0.45 * W, 0.35 * H, c->ball_mm * s, c->ball_mm * s, c->ball_mm * s, 0.5 * W, 0.5 * W,
        0.9 * H, 150 * s, 150 * s, 150 * s, 0.5 * W, 0.5 * W, 0.8 * H, 0.45 / (s * s), cam[0],
        cam[1], cam[2], tgt[0], tgt[1], tgt[2], down, !down);
    return n > 0 && (size_t)n < size;
}

static long long non_finite(const float *px, size_t n)
{
    long long bad = 0;
    for (size_t i = 0; i < n; i++)
        bad += !isfinite(px[i]);
    return bad;
}

/* An EXR with NaN, +Inf and -Inf texels among ordinary ones, for the texture case. */
static int write_nan_texture(const char *path)
{
    float px[8 * 8 * 4];
    for (int i = 0; i < 64; i++) {
        float v = (i % 5 == 0) ? NAN : (i % 7 == 0) ? INFINITY : (i % 11 == 0) ? -INFINITY : 0.5f;
        px[i * 4] = px[i * 4 + 1] = px[i * 4 + 2] = v;
        px[i * 4 + 3] = 1.0f;
    }
    char err[512];
    return rd_image_write_float(path, 8, 8, 4, px, err, sizeof err) == RD_IMAGE_OK ? 0 : -1;
}

void cli_defaults_extremes(cli_options *o)
{
    o->bounces = 4;
}

/* The path-traced reference's non-finite pixels: its own, and those an .exr's half floats
 * would turn into Inf after ref_image_clamp_half. -1 when the trace failed. */
static long long path_traced_bad(ref_scene *ref, const rd_view *v, const cli_options *o)
{
    ref_image img = {0};
    ref_render_desc d = {
        .view = *v, .samples = o->samples ? o->samples : 4, .seed = 1, .bounces = o->bounces};
    if (ref_render(ref, &d, &img) != REF_OK)
        return -1;
    size_t n = 4 * (size_t)img.width * (size_t)img.height;
    long long bad = non_finite(img.linear, n);
    ref_image_clamp_half(&img);
    for (size_t i = 0; i < n; i++)
        bad += !(img.linear[i] <= REF_HALF_MAX);
    ref_image_free(&img);
    return bad;
}

int cli_cmd_extremes(const cli_options *args)
{
    cli_options o = *args;
    int rc = CLI_OK;
    int w = o.width ? o.width : 160, h = o.height ? o.height : 90;
    char dir[] = "/tmp/tessera-extremes-XXXXXX", texture[256], fake[300];
    if (!mkdtemp(dir)) {
        perror("tessera extremes: mkdtemp");
        return CLI_FAILED;
    }
    snprintf(texture, sizeof texture, "%s/nan-inf.exr", dir);
    snprintf(fake, sizeof fake, "%s/case.json", dir);
    rd_context *ctx = NULL;
    if (write_nan_texture(texture) != 0 ||
        rd_context_create(&(rd_context_desc){.backend = o.backend}, &ctx) != RD_OK) {
        fprintf(stderr, "tessera extremes: %s\n", rd_last_error());
        return CLI_FAILED;
    }
    app_safe_stream md_out = {.f = NULL};
    char md_err[4200];
    FILE *md = o.markdown ? app_safe_stream_open(&md_out, o.markdown, md_err, sizeof md_err) : NULL;
    if (o.markdown && !md)
        fprintf(stderr, "tessera: %s\n", md_err);
    const char *head = "| case | GPU non-finite | reference non-finite | PSNR all (dB) | "
                       "PSNR reflective (dB) | self-traced non-finite | self-traced PSNR "
                       "reflective (dB) | path-traced non-finite |\n"
                       "|---|---|---|---|---|---|---|---|\n";
    printf("%s", head);
    if (md)
        fputs(head, md);
    size_t n = (size_t)w * (size_t)h * 4;
    float *gpu = malloc(n * sizeof *gpu), *mask = malloc((size_t)w * (size_t)h * sizeof *mask);
    float *traced = malloc(n * sizeof *traced);
    static char json[8192];
    int bad_cases = 0;
    for (int k = 0; k < CASES && gpu && mask && traced; k++) {
        const extreme_case *c = &cases[k];
        app_project p = {0};
        app_scene scene = {0};
        ref_scene *ref = NULL;
        ref_image truth = {0};
        char err[2048] = "";
        long long gpu_bad = -1, ref_bad = -1, self_bad = -1, path_bad = 0;
        app_image_metrics all = {0}, refl = {0}, self_refl = {0};
        all.psnr = refl.psnr = self_refl.psnr = NAN;
        if (!case_json(c, texture, json, sizeof json) ||
            app_project_parse(json, strlen(json), fake, &p, err, sizeof err) != APP_OK) {
            fprintf(stderr, "tessera extremes: %s: %s\n", c->name, err);
            rc = CLI_FAILED;
            break;
        }
        rd_view v;
        if (app_scene_build(ctx, &p, &scene, err, sizeof err) == APP_OK &&
            app_view_from_camera(&p, NULL, w, h, &v, err, sizeof err) == APP_OK) {
            v.supersample = 1;
            if (rd_render(ctx, scene.scene, &v) == RD_OK && rd_read_linear(ctx, gpu, n) == RD_OK)
                gpu_bad = non_finite(gpu, n);
            /* The renders compared take the first one's exposure (auto: as it measured it). */
            v.exposure_ev = rd_last_frame_stats(ctx).exposure_ev;
            v.auto_exposure = 0;
            rd_reflection_defaults d = rd_scene_reflection_defaults(scene.scene);
            d.self_reflections = APP_SELF_REFLECTION_RAYS;
            rd_scene_set_reflection_defaults(scene.scene, &d);
            if (rd_render(ctx, scene.scene, &v) == RD_OK && rd_read_linear(ctx, traced, n) == RD_OK)
                self_bad = non_finite(traced, n);
            if (app_ref_scene_build(&p, &ref, err, sizeof err) == APP_OK) {
                ref_render_desc d = {.view = v, .samples = o.samples ? o.samples : 16, .seed = 1};
                if (ref_render(ref, &d, &truth) == REF_OK) {
                    ref_bad = non_finite(truth.linear, n);
                    for (size_t i = 0; i < (size_t)w * (size_t)h; i++)
                        mask[i] = truth.mask[i] ? 1.0f : 0.0f;
                    if (gpu_bad == 0 && ref_bad == 0) {
                        app_image_metrics_compute(gpu, truth.linear, w, h, NULL, &all);
                        app_image_metrics_compute(gpu, truth.linear, w, h, mask, &refl);
                    }
                    if (self_bad == 0 && ref_bad == 0)
                        app_image_metrics_compute(traced, truth.linear, w, h, mask, &self_refl);
                }
                if (o.bounces > 0)
                    path_bad = path_traced_bad(ref, &v, &o);
            }
        }
        if (gpu_bad != 0 || ref_bad != 0 || self_bad != 0 || path_bad != 0)
            bad_cases++;
        char line[512], path_col[32] = "off";
        if (o.bounces > 0)
            snprintf(path_col, sizeof path_col, "%lld", path_bad);
        snprintf(line, sizeof line, "| %s | %lld | %lld | %.2f | %.2f | %lld | %.2f | %s |\n",
                 c->name, gpu_bad, ref_bad, all.psnr, refl.psnr, self_bad, self_refl.psnr,
                 path_col);
        printf("%s", line);
        if (md)
            fputs(line, md);
        fflush(stdout);
        ref_image_free(&truth);
        ref_scene_destroy(ref);
        app_scene_release(ctx, &scene);
        app_project_free(&p);
    }
    if (md) {
        fprintf(md, "\n-1: the render itself failed. Every case must show 0 (or off) in every "
                    "non-finite column.\n");
        if (app_safe_stream_commit(&md_out, md_err, sizeof md_err) != APP_OK) {
            fprintf(stderr, "tessera: %s\n", md_err);
            rc = CLI_FAILED;
        }
    }
    free(gpu);
    free(traced);
    free(mask);
    rd_context_destroy(ctx);
    unlink(texture);
    rmdir(dir);
    if (bad_cases) {
        fprintf(stderr, "tessera extremes: %d case(s) with non-finite pixels\n", bad_cases);
        return CLI_FAILED;
    }
    return rc;
}
