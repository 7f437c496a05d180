/* ref_render: a pool of threads over square tiles, one primary ray per subpixel centre, resolved
 * exactly as render/shaders/tonemap.frag resolves the GPU's supersamples, with a progress bar on
 * stderr when it is a terminal. */
#include "ref_internal.h"

#include "render/shade_ref.h"

#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define REF_MAX_SIDE 16384
#define REF_MAX_PIXELS (1LL << 26)         /* 1 GiB of linear RGBA floats */
#define REF_MAX_RAYS_PER_IMAGE (1LL << 28) /* primary rays: width x height x supersample^2 */
#define REF_MAX_THREADS 256
#define REF_MAX_SAMPLES (1 << 20)

typedef struct job {
    ref_scene *scene;
    ref_camera camera;
    const rd_view *view;
    int ss, samples, bounces, tile, tiles_x, tiles_y, total;
    uint64_t seed_key;
    float exposure_ev, wb[9]; /* resolved (auto exposure measured) and the white balance */
    ref_image *img;
    atomic_int next;
    atomic_int done;
    atomic_llong rays;
} job;

static double now_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static uint64_t mix64(uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

static void render_pixel(job *j, int x, int y, ref_trace_stats *stats)
{
    const rd_view *v = j->view;
    int ss = j->ss, n = ss * ss, hits = 0;
    float inv = 1.0f / (float)ss;
    float lin[3] = {0, 0, 0}, disp[3] = {0, 0, 0};
    /* Subpixel rows top to bottom, columns left to right: each is one texel of the GPU's
     * supersampled target, at its centre. */
    for (int sy = 0; sy < ss; sy++)
        for (int sx = 0; sx < ss; sx++) {
            float fx = (float)x + ((float)sx + 0.5f) * inv;
            float fy = (float)y + ((float)sy + 0.5f) * inv;
            float dir[3];
            ref_ray_diff diff;
            ref_camera_dir(&j->camera, fx, fy, dir);
            ref_camera_dir(&j->camera, fx + inv, fy, diff.dir_dx);
            ref_camera_dir(&j->camera, fx, fy + inv, diff.dir_dy);
            uint64_t index =
                ((uint64_t)y * (uint64_t)v->width + (uint64_t)x) * 256u + (uint64_t)(sy * ss + sx);
            float rad[3], d[3];
            int reflective;
            if (j->bounces > 0)
                ref_path_primary(j->scene, j->camera.eye, dir, &diff, j->bounces, j->samples,
                                 mix64(j->seed_key ^ index), rad, &reflective, stats);
            else
                ref_trace_primary(j->scene, j->camera.eye, dir, &diff, j->samples,
                                  mix64(j->seed_key ^ index), rad, &reflective, stats);
            hits += reflective;
            float c[3];
            rd_ref_expose(rad, j->exposure_ev, j->wb, c); /* tonemap.frag, LINEAR_OUT */
            rd_ref_tone_curve(c, v->tonemap, v->white, d);
            for (int k = 0; k < 3; k++) {
                lin[k] += c[k];
                disp[k] += d[k];
            }
        }
    size_t p = (size_t)y * (size_t)v->width + (size_t)x;
    ref_image *img = j->img;
    for (int k = 0; k < 3; k++) {
        img->linear[4 * p + (size_t)k] = lin[k] / (float)n;
        float e = rd_ref_srgb_encode(disp[k] / (float)n);
        img->rgba8[4 * p + (size_t)k] =
            (unsigned char)(fminf(fmaxf(e, 0.0f), 1.0f) * 255.0f + 0.5f);
    }
    img->linear[4 * p + 3] = 1.0f;
    img->rgba8[4 * p + 3] = 255;
    img->mask[p] = 2 * hits >= n ? 1 : 0;
}

/* Auto exposure as render/src/exposure_meter.c measures it: log(delta + L) of the
 * white-balanced radiance at the same grid of the GPU's main-pass samples (one a pixel in an
 * adaptive view, else s x s), summed into rd_auto_exposure_ev. */
static float measure_exposure(job *j)
{
    const rd_view *v = j->view;
    int shaded = v->adaptive && j->ss > 1 ? 1 : (j->ss < 4 ? j->ss : 4);
    int hw = v->width * shaded, hh = v->height * shaded;
    int gw = hw < 96 ? hw : 96, gh = hh < 96 ? hh : 96;
    double sum = 0.0;
    ref_trace_stats stats = {0};
    for (int gy = 0; gy < gh; gy++)
        for (int gx = 0; gx < gw; gx++) {
            /* the texel exposure_meter.frag fetches, counted from the top row */
            int px = (int)(((float)gx + 0.5f) * (float)hw / (float)gw);
            int py = hh - 1 - (int)(((float)gy + 0.5f) * (float)hh / (float)gh);
            float fx = ((float)px + 0.5f) / (float)shaded, fy = ((float)py + 0.5f) / (float)shaded;
            float inv = 1.0f / (float)shaded, dir[3], rad[3], c[3];
            ref_ray_diff diff;
            ref_camera_dir(&j->camera, fx, fy, dir);
            ref_camera_dir(&j->camera, fx + inv, fy, diff.dir_dx);
            ref_camera_dir(&j->camera, fx, fy + inv, diff.dir_dy);
            int reflective;
            ref_trace_primary(j->scene, j->camera.eye, dir, &diff, j->samples,
                              mix64(j->seed_key ^ (uint64_t)(gy * gw + gx)), rad, &reflective,
                              &stats);
            rd_ref_expose(rad, 0.0f, j->wb, c);
            float y = 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2];
            sum += log(RD_EXPOSURE_DELTA + (double)y);
        }
    atomic_fetch_add(&j->rays, stats.rays);
    return rd_auto_exposure_ev(sum, (long long)gw * gh, v->exposure_ev);
}

static void *worker(void *arg)
{
    job *j = arg;
    int t;
    while ((t = atomic_fetch_add(&j->next, 1)) < j->total) {
        ref_trace_stats stats = {0};
        int x0 = (t % j->tiles_x) * j->tile, y0 = (t / j->tiles_x) * j->tile;
        int x1 = x0 + j->tile < j->view->width ? x0 + j->tile : j->view->width;
        int y1 = y0 + j->tile < j->view->height ? y0 + j->tile : j->view->height;
        for (int y = y0; y < y1; y++)
            for (int x = x0; x < x1; x++)
                render_pixel(j, x, y, &stats);
        atomic_fetch_add(&j->rays, stats.rays);
        atomic_fetch_add(&j->done, 1);
    }
    return NULL;
}

static void draw_progress(int done, int total, double elapsed, int final)
{
    const int width = 40;
    int fill = total ? (int)((long long)done * width / total) : width;
    char bar[64];
    for (int i = 0; i < width; i++)
        bar[i] = i < fill ? '#' : '.';
    bar[width] = 0;
    double eta = done > 0 ? elapsed * (double)(total - done) / (double)done : 0.0;
    fprintf(stderr, "\rreference [%s] %3d%% %d/%d tiles %.1f s, %.0f s left  %s", bar,
            total ? (int)(100LL * done / total) : 100, done, total, elapsed, eta,
            final ? "\n" : "");
    fflush(stderr);
}

static ref_result validate(const ref_render_desc *d, int *ss)
{
    const rd_view *v = &d->view;
    int s = v->supersample <= 0 ? 1 : v->supersample;
    if (s > 16)
        return ref_fail(REF_ERR_INVALID_ARGUMENT, "supersampling %d is above the maximum of 16", s);
    if (v->width <= 0 || v->height <= 0)
        return ref_fail(REF_ERR_INVALID_ARGUMENT, "image size %dx%d: both sides must be at least 1",
                        v->width, v->height);
    if (v->width > REF_MAX_SIDE || v->height > REF_MAX_SIDE ||
        (long long)v->width * v->height > REF_MAX_PIXELS ||
        (long long)v->width * v->height * s * s > REF_MAX_RAYS_PER_IMAGE)
        return ref_fail(REF_ERR_TOO_LARGE,
                        "image size %dx%d (x%d supersampling) is too large: at most %d per side, "
                        "%lld pixels and %lld primary rays",
                        v->width, v->height, s, REF_MAX_SIDE, REF_MAX_PIXELS,
                        REF_MAX_RAYS_PER_IMAGE);
    if (!(v->exposure_ev > -64.0f && v->exposure_ev < 64.0f))
        return ref_fail(REF_ERR_INVALID_ARGUMENT, "exposure %g EV is outside (-64, 64)",
                        (double)v->exposure_ev);
    if (v->white < 0.0f || !isfinite(v->white))
        return ref_fail(REF_ERR_INVALID_ARGUMENT, "tone map white %g must be >= 0",
                        (double)v->white);
    if (d->samples < 0 || d->samples > REF_MAX_SAMPLES)
        return ref_fail(REF_ERR_INVALID_ARGUMENT, "samples %d: expected 1 to %d (0 = 64)",
                        d->samples, REF_MAX_SAMPLES);
    if (d->bounces < 0 || d->bounces > REF_MAX_BOUNCES)
        return ref_fail(REF_ERR_INVALID_ARGUMENT, "bounces %d: expected 0 to %d", d->bounces,
                        REF_MAX_BOUNCES);
    if (d->threads < 0 || d->tile < 0)
        return ref_fail(REF_ERR_INVALID_ARGUMENT, "threads %d and tile %d must be >= 0", d->threads,
                        d->tile);
    *ss = s;
    return REF_OK;
}

void ref_image_free(ref_image *img)
{
    if (!img)
        return;
    free(img->linear);
    free(img->rgba8);
    free(img->mask);
    memset(img, 0, sizeof *img);
}

void ref_image_clamp_half(ref_image *img)
{
    if (!img || !img->linear)
        return;
    size_t n = 4 * (size_t)img->width * (size_t)img->height;
    for (size_t i = 0; i < n; i++) {
        float v = img->linear[i];
        img->linear[i] = isnan(v) ? 0.0f : fminf(fmaxf(v, 0.0f), REF_HALF_MAX);
    }
}

ref_result ref_render(ref_scene *s, const ref_render_desc *d, ref_image *out)
{
    if (!out)
        return ref_fail(REF_ERR_INVALID_ARGUMENT, "ref_render: no output image");
    memset(out, 0, sizeof *out);
    if (!s || !d)
        return ref_fail(REF_ERR_INVALID_ARGUMENT, "ref_render: scene and desc are required");
    int ss = 1;
    ref_result r = validate(d, &ss);
    if (r != REF_OK)
        return r;
    job *j = calloc(1, sizeof *j);
    if (!j)
        return ref_fail(REF_ERR_OUT_OF_MEMORY, "ref_render: out of memory");
    r = ref_camera_make(&d->view, &j->camera);
    if (r == REF_OK)
        r = ref_scene_commit(s);
    if (r == REF_OK)
        r = ref_ambient_prepare(s);
    if (r == REF_OK && d->bounces > 0)
        r = ref_emitters_prepare(s);
    if (r != REF_OK) {
        free(j);
        return r;
    }
    /* The GPU's soft shadow taps per sample at this supersampling (ref_shadow.c). */
    s->shadow_taps = rd_shadow_taps_per_sample(&s->shadows, d->view.supersample);
    const rd_view *v = &d->view;
    size_t pixels = (size_t)v->width * (size_t)v->height;
    out->width = v->width;
    out->height = v->height;
    out->linear = malloc(pixels * 4 * sizeof *out->linear);
    out->rgba8 = malloc(pixels * 4);
    out->mask = malloc(pixels);
    if (!out->linear || !out->rgba8 || !out->mask) {
        ref_image_free(out);
        free(j);
        return ref_fail(REF_ERR_OUT_OF_MEMORY, "ref_render: out of memory for a %dx%d image",
                        v->width, v->height);
    }
    j->scene = s;
    j->view = v;
    j->ss = ss;
    j->samples = d->samples ? d->samples : 64;
    j->bounces = d->bounces;
    j->tile = d->tile ? d->tile : 16;
    j->tiles_x = (v->width + j->tile - 1) / j->tile;
    j->tiles_y = (v->height + j->tile - 1) / j->tile;
    j->total = j->tiles_x * j->tiles_y;
    j->seed_key = mix64(0xC0FFEEull + (uint64_t)d->seed);
    j->img = out;
    atomic_init(&j->next, 0);
    atomic_init(&j->done, 0);
    atomic_init(&j->rays, 0);
    rd_white_balance_matrix(v->white_balance_k, j->wb);
    j->exposure_ev = v->auto_exposure ? measure_exposure(j) : v->exposure_ev;
    out->exposure_ev = j->exposure_ev;

    int threads = d->threads;
    if (threads == 0) {
        long n = sysconf(_SC_NPROCESSORS_ONLN);
        threads = n > 0 ? (int)n : 1;
    }
    if (threads > REF_MAX_THREADS)
        threads = REF_MAX_THREADS;
    if (threads > j->total)
        threads = j->total;
    pthread_t ids[REF_MAX_THREADS];
    int started = 0;
    double t0 = now_seconds();
    for (int i = 0; i < threads; i++) {
        if (pthread_create(&ids[i], NULL, worker, j) != 0)
            break;
        started++;
    }
    int bar = d->progress && isatty(STDERR_FILENO);
    if (started == 0) {
        worker(j); /* no thread could start: trace here */
    } else if (bar) {
        while (atomic_load(&j->done) < j->total) {
            draw_progress(atomic_load(&j->done), j->total, now_seconds() - t0, 0);
            nanosleep(&(struct timespec){0, 100 * 1000 * 1000}, NULL);
        }
    }
    for (int i = 0; i < started; i++)
        pthread_join(ids[i], NULL);
    out->seconds = now_seconds() - t0;
    if (bar)
        draw_progress(j->total, j->total, out->seconds, 1);
    out->rays = atomic_load(&j->rays);
    out->threads_used = started ? started : 1;
    free(j);
    return REF_OK;
}
