/* The size limits of every job (app/project/job_limits.h, docs/limits.md); named project_*
 * so that the project tests, which compile app/src/project/project_*.c, have it too. */
#include "app/project/job_limits.h"

#include "render/image_io.h"
#include "render/render.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <unistd.h>

static const app_limit table[APP_LIMIT_COUNT] = {
    [APP_LIMIT_IMAGE_SIDE] = {"image side", RD_IMAGE_MAX_SIDE, "pixels",
                              "the tiled renderer and the image reader"},
    [APP_LIMIT_IMAGE_PIXELS] = {"image pixels", (double)RD_IMAGE_MAX_PIXELS, "pixels",
                                "the image writer (2^27, 16384 x 8192)"},
    [APP_LIMIT_PANORAMA_PIXELS] = {"panorama pixels", (double)RD_IMAGE_MAX_PIXELS, "pixels",
                                   "the image writer (16384 x 8192 equirectangular)"},
    [APP_LIMIT_VIDEO_FRAMES] = {"video frames", 90000, "frames", "one hour at 25 frames a second"},
    [APP_LIMIT_SAMPLES] = {"reference samples", 65536, "paths a pixel",
                           "the path tracer's noise stops falling visibly long before"},
    [APP_LIMIT_LIGHTS] = {"lights", RD_MAX_LIGHTS, "lights", "the renderer's shader arrays"},
};

const app_limit *app_limits(void)
{
    return table;
}

/* Peak resident memory measured with /usr/bin/time -v on tests/data/projects/minimal.json
 * (docs/limits.md "Memory"): a fixed part for the program, GL and the scene, plus bytes a
 * pixel of the written image. */
#define BASE_BYTES (256.0 * 1024 * 1024)
#define IMAGE_BYTES_PER_PIXEL 24.0     /* render to PNG/JPEG/TIFF */
#define FLOAT_BYTES_PER_PIXEL 72.0     /* render to EXR: the linear float copy and its writer */
#define PANORAMA_BYTES_PER_PIXEL 12.0  /* the equirectangular image and six faces of width/4 */
#define REFERENCE_BYTES_PER_PIXEL 32.0 /* float accumulation, sample counts and the image */

double app_job_memory_bytes(const app_job *j)
{
    double pixels = (double)j->width * (double)j->height, per_pixel = IMAGE_BYTES_PER_PIXEL;
    switch (j->kind) {
    case APP_JOB_IMAGE:
    case APP_JOB_VIDEO:
        per_pixel = j->float_copy ? FLOAT_BYTES_PER_PIXEL : IMAGE_BYTES_PER_PIXEL;
        break;
    case APP_JOB_PANORAMA:
        per_pixel = PANORAMA_BYTES_PER_PIXEL;
        break;
    case APP_JOB_REFERENCE:
        per_pixel = REFERENCE_BYTES_PER_PIXEL;
        break;
    }
    return BASE_BYTES + pixels * per_pixel;
}

double app_memory_available_bytes(void)
{
    long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    double bytes = pages > 0 && page > 0 ? (double)pages * (double)page : INFINITY;
    struct rlimit rl;
    if (getrlimit(RLIMIT_AS, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY)
        bytes = fmin(bytes, (double)rl.rlim_cur);
    if (getrlimit(RLIMIT_DATA, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY)
        bytes = fmin(bytes, (double)rl.rlim_cur);
    const char *mb = getenv("TESSERA_MEMORY_LIMIT_MB");
    if (mb && mb[0]) {
        char *end = NULL;
        double v = strtod(mb, &end);
        if (end != mb && *end == '\0' && v > 0)
            bytes = fmin(bytes, v * 1024.0 * 1024.0);
    }
    return bytes;
}

static app_result fail(char *err, size_t err_size, const char *what, const char *fmt, double a,
                       double b)
{
    if (err && err_size) {
        char problem[512];
        snprintf(problem, sizeof problem, fmt, a, b);
        snprintf(err, err_size, "%s: %s", what, problem);
    }
    return APP_ERR_SCHEMA;
}

int app_image_size_fits(long width, long height, char *err, size_t err_size)
{
    const app_limit *side = &table[APP_LIMIT_IMAGE_SIDE], *pixels = &table[APP_LIMIT_IMAGE_PIXELS];
    if (width < 1 || height < 1) {
        if (err && err_size)
            snprintf(err, err_size, "each side must be at least 1 pixel");
        return 0;
    }
    if (width > side->value || height > side->value) {
        if (err && err_size)
            snprintf(err, err_size, "too large: each side must be at most %.0f pixels (%s)",
                     side->value, side->why);
        return 0;
    }
    if ((double)width * (double)height > pixels->value) {
        if (err && err_size)
            snprintf(err, err_size, "too large: %.0f pixels; the limit is %.0f (%s)",
                     (double)width * (double)height, pixels->value, pixels->why);
        return 0;
    }
    return 1;
}

app_result app_job_check(const app_job *j, const char *what, char *err, size_t err_size)
{
    char size_err[512];
    if (j->kind == APP_JOB_PANORAMA) {
        const app_limit *pano = &table[APP_LIMIT_PANORAMA_PIXELS];
        double pixels = (double)j->width * (double)j->height;
        if (pixels > pano->value)
            return fail(err, err_size, what,
                        "too large: a panorama of %.0f pixels; the limit is %.0f", pixels,
                        pano->value);
    }
    if (!app_image_size_fits(j->width, j->height, size_err, sizeof size_err)) {
        if (err && err_size)
            snprintf(err, err_size, "%s: %s", what, size_err);
        return APP_ERR_SCHEMA;
    }
    if (j->kind == APP_JOB_VIDEO && j->frames > table[APP_LIMIT_VIDEO_FRAMES].value)
        return fail(err, err_size, what,
                    "too long: %.0f frames; the limit is %.0f (one hour at 25 fps)",
                    (double)j->frames, table[APP_LIMIT_VIDEO_FRAMES].value);
    if (j->kind == APP_JOB_REFERENCE && j->samples > table[APP_LIMIT_SAMPLES].value)
        return fail(err, err_size, what, "too many samples: %.0f a pixel; the limit is %.0f",
                    (double)j->samples, table[APP_LIMIT_SAMPLES].value);
    double need = app_job_memory_bytes(j), have = app_memory_available_bytes();
    if (need > have)
        return fail(err, err_size, what,
                    "too large: needs about %.0f MB of memory, more than the %.0f MB available "
                    "(physical memory, ulimit -v/-d or TESSERA_MEMORY_LIMIT_MB)",
                    need / (1024.0 * 1024.0), have / (1024.0 * 1024.0));
    return APP_OK;
}
