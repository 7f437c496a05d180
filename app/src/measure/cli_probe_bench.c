/* tessera probe-bench: what reflection probes cost (RENDERING.md section 8), on a synthetic
 * room so the numbers do not depend on a project: the cost of one probe update as the
 * resolution goes 16 ... 512 (capture, and the prefilter of a glossy probe), and how the
 * frame time grows with the number of reflective objects and does not with plain ones. */
#include "app/cli/cli.h"
#include "app/output/safe_file.h"
#include "app/measure/stats.h"
#include "cli/cli_commands.h"

#include "render/primitives.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct bench_scene {
    rd_scene *scene;
    rd_mesh sphere, box;
} bench_scene;

/* A 3 x 3 x 2.5 m room (a box seen from inside), a lamp, and `reflective` chrome spheres plus
 * `plain` matt ones on a grid on the floor. */
static rd_result build(rd_context *ctx, bench_scene *b, int reflective, int plain, float gloss,
                       int resolution, rd_probe_update update)
{
    rd_mesh_data d;
    rd_mesh_data_sphere(32, 16, &d);
    rd_mesh_desc desc = rd_mesh_data_desc(&d);
    b->sphere = rd_mesh_create(ctx, &desc);
    rd_mesh_data_free(&d);
    rd_mesh_data_box(&d);
    desc = rd_mesh_data_desc(&d);
    b->box = rd_mesh_create(ctx, &desc);
    rd_mesh_data_free(&d);
    b->scene = rd_scene_create(ctx);
    if (!b->sphere.id || !b->box.id || !b->scene)
        return RD_ERR_OUT_OF_MEMORY;
    rd_object_desc room = {
        .mesh = b->box,
        .material = {.diffuse = {0.7f, 0.68f, 0.62f}, .ambient = {0.7f, 0.68f, 0.62f}},
        .background = 1,
        .double_sided = 1};
    room.transform[0] = room.transform[5] = 3.0f;
    room.transform[10] = 2.5f;
    room.transform[12] = room.transform[13] = 1.5f;
    room.transform[14] = 1.25f;
    room.transform[15] = 1.0f;
    rd_result r = rd_scene_add_object(b->scene, &room);
    for (int i = 0; r == RD_OK && i < reflective + plain; i++) {
        int refl = i < reflective;
        rd_object_desc o = {
            .mesh = b->sphere,
            .material = {.diffuse = {0.1f, 0.1f, 0.1f}, .specular = {1, 1, 1}, .shininess = 200}};
        if (refl) {
            o.material.reflectivity = 0.85f;
            o.material.glossiness = gloss;
            o.probe = (rd_probe_desc){.update = update, .resolution = resolution};
        } else {
            o.material.diffuse[0] = 0.6f;
        }
        float size = 0.22f;
        o.transform[0] = o.transform[5] = o.transform[10] = size;
        o.transform[15] = 1.0f;
        o.transform[12] = 0.4f + 0.3f * (float)(i % 8);
        o.transform[13] = 0.5f + 0.35f * (float)(i / 8);
        o.transform[14] = 0.6f;
        r = rd_scene_add_object(b->scene, &o);
    }
    rd_light lamp = {.type = RD_LIGHT_POINT,
                     .position = {1.5f, 1.5f, 2.3f},
                     .diffuse = {1.5f, 1.4f, 1.3f},
                     .specular = {1, 1, 1},
                     .attenuation = {1, 0, 0.5f}};
    if (r == RD_OK)
        r = rd_scene_add_light(b->scene, &lamp);
    float ambient[3] = {0.15f, 0.15f, 0.15f};
    rd_scene_set_ambient(b->scene, ambient);
    rd_reflection_defaults rd = {.proxy_max = {3, 3, 2.5f}};
    rd_scene_set_reflection_defaults(b->scene, &rd);
    return r;
}

static void release(rd_context *ctx, bench_scene *b)
{
    rd_scene_destroy(b->scene);
    rd_mesh_destroy(ctx, b->sphere);
    rd_mesh_destroy(ctx, b->box);
}

/* Median ms per frame over `frames` after `warmup`, GPU work finished inside the timing. */
static double median_frame_ms(rd_context *ctx, rd_scene *s, const rd_view *v, int frames,
                              int warmup, rd_frame_stats *last)
{
    double *t = calloc((size_t)frames, sizeof *t);
    if (!t)
        return -1.0;
    for (int i = 0; i < warmup + frames; i++) {
        double t0 = cli_now_ms();
        if (rd_render(ctx, s, v) != RD_OK) {
            fprintf(stderr, "tessera probe-bench: %s\n", rd_last_error());
            free(t);
            return -1.0;
        }
        rd_finish(ctx);
        if (i >= warmup)
            t[i - warmup] = cli_now_ms() - t0;
    }
    *last = rd_last_frame_stats(ctx);
    double m = app_stats_of(t, frames).median;
    free(t);
    return m;
}

void cli_defaults_probe_bench(cli_options *o)
{
    o->frames = 15;
    o->warmup = 3;
}

int cli_cmd_probe_bench(const cli_options *args)
{
    cli_options o = *args;
    int rc = CLI_OK;
    if (o.project)
        return cli_usage_error(&o);
    rd_context *ctx = NULL;
    if (rd_context_create(&(rd_context_desc){.backend = o.backend}, &ctx) != RD_OK) {
        fprintf(stderr, "tessera: cannot open an OpenGL context: %s\n", rd_last_error());
        return CLI_FAILED;
    }
    app_safe_stream csv_out = {.f = NULL};
    char csv_err[4200];
    FILE *csv = o.csv ? app_safe_stream_open(&csv_out, o.csv, csv_err, sizeof csv_err) : NULL;
    if (o.csv && !csv) {
        fprintf(stderr, "tessera: %s\n", csv_err);
        rd_context_destroy(ctx);
        return CLI_FAILED;
    }
    if (csv)
        fprintf(csv, "table,reflective,plain,resolution,glossiness,ms\n");
    rd_view v = {.eye = {1.5f, 2.9f, 1.6f},
                 .target = {1.5f, 0.6f, 0.6f},
                 .fov_y_deg = 70,
                 .width = o.width ? o.width : 1280,
                 .height = o.height ? o.height : 720};
    printf("backend %s (%s), %dx%d, median of %d frames after %d warm-up\n\n",
           rd_backend_name(rd_context_backend(ctx)), rd_context_description(ctx), v.width, v.height,
           o.frames, o.warmup);

    /* 1. One probe's update: frame with the probe captured every frame minus the frame with
     * it captured once; mirror (capture only) and glossy (capture + prefilter). */
    printf("one probe update (6 faces), ms: resolution, mirror g = 1, glossy g = 0.6\n");
    for (int res = 16; res <= 512 && rc == CLI_OK; res *= 2) {
        double cost[2];
        for (int glossy = 0; glossy < 2; glossy++) {
            double ms[2];
            for (int every = 0; every < 2; every++) {
                bench_scene b = {0};
                rd_frame_stats st;
                if (build(ctx, &b, 1, 0, glossy ? 0.6f : 1.0f, res,
                          every ? RD_PROBE_EVERY_FRAME : RD_PROBE_ONCE) != RD_OK) {
                    fprintf(stderr, "tessera probe-bench: %s\n", rd_last_error());
                    rc = CLI_FAILED;
                }
                ms[every] = rc == CLI_OK
                                ? median_frame_ms(ctx, b.scene, &v, o.frames, o.warmup, &st)
                                : -1.0;
                release(ctx, &b);
                if (ms[every] < 0)
                    rc = CLI_FAILED;
            }
            cost[glossy] = ms[1] - ms[0];
            if (csv)
                fprintf(csv, "probe_update,1,0,%d,%s,%.3f\n", res, glossy ? "0.6" : "1",
                        cost[glossy]);
        }
        printf("  %4d  %8.2f  %8.2f\n", res, cost[0], cost[1]);
    }

    /* 2. Frame time against the number of reflective objects (every frame and time-sliced),
     * and against the number of plain ones. */
    printf("\nframe ms by object count: n, n reflective (every frame), n reflective "
           "(time-sliced), n plain\n");
    for (int n = 1; n <= 16 && rc == CLI_OK; n *= 2) {
        double ms[3];
        for (int kind = 0; kind < 3 && rc == CLI_OK; kind++) {
            bench_scene b = {0};
            rd_frame_stats st;
            rd_probe_update u = kind == 1 ? RD_PROBE_TIME_SLICED : RD_PROBE_EVERY_FRAME;
            if (build(ctx, &b, kind == 2 ? 0 : n, kind == 2 ? n : 0, 0.9f, 0, u) != RD_OK)
                rc = CLI_FAILED;
            ms[kind] =
                rc == CLI_OK ? median_frame_ms(ctx, b.scene, &v, o.frames, o.warmup, &st) : -1.0;
            release(ctx, &b);
            if (ms[kind] < 0)
                rc = CLI_FAILED;
            if (csv && rc == CLI_OK)
                fprintf(csv, "%s,%d,%d,0,0.9,%.3f\n",
                        kind == 0   ? "reflective_every"
                        : kind == 1 ? "reflective_sliced"
                                    : "plain",
                        kind == 2 ? 0 : n, kind == 2 ? n : 0, ms[kind]);
        }
        if (rc == CLI_OK)
            printf("  %2d  %8.2f  %8.2f  %8.2f\n", n, ms[0], ms[1], ms[2]);
        fprintf(stderr, "\r%d of 16 objects done", n);
    }
    fprintf(stderr, "\n");
    if (csv && app_safe_stream_commit(&csv_out, csv_err, sizeof csv_err) != APP_OK) {
        fprintf(stderr, "tessera: %s\n", csv_err);
        rc = CLI_FAILED;
    }
    rd_context_destroy(ctx);
    return rc;
}
