/* Lamps in sharp reflections (render/src/emitters.c, emitters.glsl) against the
 * ground truth. A probe shows a lamp where its centre sees it and a proxy puts it on the proxy;
 * so a mirror's probe is captured without the lamps of known shape, and its lookup intersects
 * the reflected ray with them.
 *
 * - assets/projects/stress-mirror.json, its mirror on the box correction, 160 x 90: exact lamps
 *   beat the lamp in the probe by at least 6 dB over the reflective pixels (the box put the
 *   pendant on the ceiling), for the pendant as a sphere, and turned into a box, a cylinder and
 *   a plane (each intersection routine against the tracer's triangles).
 * - only sharp probes leave their lamps out: the stats count one lamp and one probe without
 *   it; none when turned off; with the mirror blurred (g = 0.9) the probe keeps the lamp.
 * - demo-bathroom.json's "basin" camera under the interactive preset, whose mirror shows the
 *   pendant lamp: on beats off by at least 10 dB.
 *
 * GL through TESSERA_GL (EGL unless it says osmesa); some seconds on two cores. */
#include "../common/check.h"
#include "app/measure/image_compare.h"
#include "app/project/project.h"
#include "app/scene/quality.h"
#include "app/scene/ref_scene_build.h"
#include "app/scene/scene_build.h"
#include "gpu_render.h"
#include "ref/ref.h"
#include "render/render.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { W = 160, H = 90 };

static void set_lamps_in_probes(rd_reflection_defaults *d, int in_probes)
{
    d->exact_lamps = in_probes ? RD_SWITCH_OFF : RD_SWITCH_ON;
}

/* The GPU image of p (a preset when given) with the lamps exact or left in the probes. */
static int render(rd_context *ctx, app_project *p, const rd_view *view, const char *preset,
                  int exact, float *img, rd_frame_stats *stats)
{
    return gpu_render(ctx, p, view, preset, set_lamps_in_probes, !exact, img, stats);
}

/* The tracer's image of p and its reflective mask (1 / 0). */
static int trace(app_project *p, const rd_view *view, ref_image *out, float *mask)
{
    char err[2048];
    ref_scene *rs = NULL;
    int ok = app_ref_scene_build(p, &rs, err, sizeof err) == APP_OK &&
             ref_render(rs, &(ref_render_desc){.view = *view, .samples = 16}, out) == REF_OK;
    CHECK_MSG(ok, "reference: %s %s", err, ref_last_error());
    if (ok)
        for (int i = 0; i < W * H; i++)
            mask[i] = out->mask[i] ? 1.0f : 0.0f;
    ref_scene_destroy(rs);
    return ok;
}

static double psnr(const float *img, const float *truth, const float *mask)
{
    app_image_metrics m;
    CHECK(app_image_metrics_compute(img, truth, W, H, mask, &m) == 0);
    return m.psnr;
}

static int find_object(const app_project *p, const char *name)
{
    for (int i = 0; i < p->object_count; i++)
        if (!strcmp(p->objects[i].name, name))
            return i;
    return -1;
}

/* stress-mirror.json with its lamp as `shape`: exact beats the probe's lamp by 6 dB. */
static void mirror_lamp_as(rd_context *ctx, app_project *p, app_shape shape, const char *label,
                           float *on, float *off, float *mask)
{
    static float lamp_mask[W * H];
    int lamp = find_object(p, "lamp");
    CHECK_MSG(lamp >= 0, "stress-mirror.json has no \"lamp\"");
    if (lamp < 0)
        return;
    p->objects[lamp].shape = shape;
    char err[2048];
    rd_view view;
    CHECK(app_view_from_camera(p, NULL, W, H, &view, err, sizeof err) == APP_OK);
    view.supersample = 1;
    ref_image truth = {0};
    rd_frame_stats st_on, st_off;
    if (trace(p, &view, &truth, mask) && render(ctx, p, &view, NULL, 1, on, &st_on) &&
        render(ctx, p, &view, NULL, 0, off, &st_off)) {
        double a = psnr(on, truth.linear, mask), b = psnr(off, truth.linear, mask);
        /* The lamp's own pixels in the mirror: where the truth reflects its radiance of 5. */
        int lamp_pixels = 0;
        for (int i = 0; i < W * H; i++) {
            int lit = mask[i] > 0.0f && truth.linear[4 * i] > 2.0f;
            lamp_pixels += lit;
            lamp_mask[i] = lit ? 1.0f : 0.0f;
        }
        double la = psnr(on, truth.linear, lamp_mask), lb = psnr(off, truth.linear, lamp_mask);
        printf("stress-mirror, box correction, lamp as a %s: exact %.2f dB, in the probe %.2f dB; "
               "its %d pixels in the mirror %.2f against %.2f dB\n",
               label, a, b, lamp_pixels, la, lb);
        CHECK_MSG(a >= b + 6.0, "lamp as a %s: exact %.2f dB is not 6 dB above %.2f", label, a, b);
        CHECK_MSG(lamp_pixels >= 10 && la >= 25.0,
                  "lamp as a %s: its %d pixels in the mirror at %.2f dB (expected 25)", label,
                  lamp_pixels, la);
        CHECK_MSG(st_on.emitters == 1 && st_on.emitter_probes == 1 && st_off.emitters == 0 &&
                      st_off.emitter_probes == 0,
                  "lamp as a %s: %d lamps in %d probes on, %d in %d off", label, st_on.emitters,
                  st_on.emitter_probes, st_off.emitters, st_off.emitter_probes);
    }
    ref_image_free(&truth);
}

static void mirror_scene(rd_context *ctx, float *on, float *off, float *mask)
{
    char err[2048];
    app_project p;
    if (app_project_read(TESSERA_SOURCE_DIR "/assets/projects/stress-mirror.json", &p, err,
                         sizeof err) != APP_OK) {
        CHECK_MSG(0, "%s", err);
        return;
    }
    int mirror = -1;
    for (int i = 0; i < p.material_count; i++)
        if (p.materials[i].reflectivity > 0.0f) {
            p.materials[i].correction = APP_CORRECTION_BOX;
            mirror = i;
        }
    CHECK_MSG(mirror >= 0, "stress-mirror.json has no mirror");
    mirror_lamp_as(ctx, &p, APP_SHAPE_SPHERE, "sphere", on, off, mask);
    mirror_lamp_as(ctx, &p, APP_SHAPE_BOX, "box", on, off, mask);
    mirror_lamp_as(ctx, &p, APP_SHAPE_CYLINDER, "cylinder", on, off, mask);
    mirror_lamp_as(ctx, &p, APP_SHAPE_PLANE, "plane", on, off, mask);
    if (mirror >= 0) {
        /* A blurred lookup keeps the lamp in its probe, where its lobe spreads it. */
        p.materials[mirror].glossiness = 0.9f;
        rd_view view;
        CHECK(app_view_from_camera(&p, NULL, W, H, &view, err, sizeof err) == APP_OK);
        view.supersample = 1;
        rd_frame_stats st;
        if (render(ctx, &p, &view, NULL, 1, on, &st))
            CHECK_MSG(st.emitters == 1 && st.emitter_probes == 0,
                      "a blurred mirror: %d lamps, %d probes without them (expected 1, 0)",
                      st.emitters, st.emitter_probes);
    }
    app_project_free(&p);
}

/* The demo's mirror seen from the basin camera shows the pendant lamp. */
static void demo_basin(rd_context *ctx, float *on, float *off, float *mask)
{
    char err[2048];
    app_project p;
    if (app_project_read(TESSERA_SOURCE_DIR "/assets/projects/demo-bathroom.json", &p, err,
                         sizeof err) != APP_OK) {
        CHECK_MSG(0, "%s", err);
        return;
    }
    rd_view view;
    CHECK(app_view_from_camera(&p, "basin", W, H, &view, err, sizeof err) == APP_OK);
    view.supersample = 2; /* the interactive preset's */
    ref_image truth = {0};
    rd_frame_stats st_on, st_off;
    if (trace(&p, &view, &truth, mask) && render(ctx, &p, &view, "interactive", 1, on, &st_on) &&
        render(ctx, &p, &view, "interactive", 0, off, &st_off)) {
        double a = psnr(on, truth.linear, mask), b = psnr(off, truth.linear, mask);
        printf("demo, basin camera, interactive: exact lamps %.2f dB, in the probes %.2f dB\n", a,
               b);
        CHECK_MSG(a >= b + 10.0, "demo basin: exact %.2f dB is not 10 dB above %.2f", a, b);
    }
    ref_image_free(&truth);
    app_project_free(&p);
}

int main(void)
{
    rd_context *ctx = NULL;
    if (rd_context_create(&(rd_context_desc){.backend = RD_BACKEND_DEFAULT}, &ctx) != RD_OK) {
        fprintf(stderr, "no GL context: %s\n", rd_last_error());
        return 1;
    }
    float *mask = malloc((size_t)W * H * sizeof *mask);
    float *on = malloc((size_t)W * H * 4 * sizeof *on),
          *off = malloc((size_t)W * H * 4 * sizeof *off);
    CHECK(mask && on && off);
    if (mask && on && off) {
        mirror_scene(ctx, on, off, mask);
        demo_basin(ctx, on, off, mask);
    }
    free(mask);
    free(on);
    free(off);
    rd_context_destroy(ctx);
    return check_report("test_exact_lamps");
}
