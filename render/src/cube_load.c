/* A static cube map from six image files (RENDERING.md section 8 "static"): GL names as in
 * seed 003 (env_posx.jpg ...), or 3ds Max names mapped to GL faces by seed 000 Fig. 8. */
#include "render/cube_data.h"
#include "render/image_io.h"
#include "render_internal.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* In GL face order. */
static const char *const gl_names[6] = {"posx", "negx", "posy", "negy", "posz", "negz"};
/* Seed 000 Fig. 8: RIGHT +X -> POSITIVE_X, LEFT -X -> NEGATIVE_X, DOWN -Z -> POSITIVE_Y,
 * UP +Z -> NEGATIVE_Y, BACK +Y -> POSITIVE_Z, FRONT -Y -> NEGATIVE_Z. */
static const char *const max_names[6] = {"right", "left", "down", "up", "back", "front"};

static rd_result load_fail(rd_result r, char *err, size_t err_size, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

static rd_result load_fail(rd_result r, char *err, size_t err_size, const char *fmt, ...)
{
    char msg[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (err != NULL && err_size > 0)
        snprintf(err, err_size, "%s", msg);
    return rd_fail(r, "%s", msg);
}

/* pattern with its one '*' replaced by name; NULL when out of memory. */
static char *face_path(const char *pattern, const char *name)
{
    const char *star = strchr(pattern, '*');
    size_t head = (size_t)(star - pattern), len = strlen(pattern) + strlen(name);
    char *p = malloc(len);
    if (p == NULL)
        return NULL;
    memcpy(p, pattern, head);
    snprintf(p + head, len - head, "%s%s", name, star + 1);
    return p;
}

static int file_exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

/* The exact sRGB decoding curve (IEC 61966-2-1). */
static float srgb_decode(float v)
{
    return v <= 0.04045f ? v / 12.92f : powf((v + 0.055f) / 1.055f, 2.4f);
}

/* rd_image_read's message without the leading "path: " (the caller names the file itself). */
static const char *without_path(const char *msg, const char *path)
{
    size_t n = strlen(path);
    if (strncmp(msg, path, n) == 0 && msg[n] == ':' && msg[n + 1] == ' ')
        return msg + n + 2;
    return msg;
}

rd_result rd_cube_data_load(const char *pattern, rd_cube_data *out, char *err, size_t err_size)
{
    if (err != NULL && err_size > 0)
        err[0] = '\0';
    if (out == NULL || pattern == NULL)
        return load_fail(RD_ERR_INVALID_ARGUMENT, err, err_size,
                         "cube map: no file pattern or no output");
    memset(out, 0, sizeof *out);
    const char *star = strchr(pattern, '*');
    if (star == NULL || strchr(star + 1, '*') != NULL)
        return load_fail(RD_ERR_INVALID_ARGUMENT, err, err_size,
                         "%s: the pattern must hold exactly one '*' (replaced by posx ... negz "
                         "or right ... front)",
                         pattern);

    char *paths[6] = {0};
    const char *const *names = gl_names;
    rd_result r = RD_OK;
    rd_image img = {0};
    for (int f = 0; f < 6; f++) {
        paths[f] = face_path(pattern, gl_names[f]);
        if (paths[f] == NULL) {
            r = load_fail(RD_ERR_OUT_OF_MEMORY, err, err_size, "%s: out of memory", pattern);
            goto done;
        }
    }
    if (!file_exists(paths[0])) {
        char *max_right = face_path(pattern, max_names[0]);
        if (max_right == NULL) {
            r = load_fail(RD_ERR_OUT_OF_MEMORY, err, err_size, "%s: out of memory", pattern);
            goto done;
        }
        int have = file_exists(max_right);
        if (!have)
            r = load_fail(RD_ERR_INVALID_ARGUMENT, err, err_size, "%s: no %s and no %s", pattern,
                          paths[0], max_right);
        free(max_right);
        if (!have)
            goto done;
        names = max_names;
        for (int f = 0; f < 6; f++) {
            free(paths[f]);
            paths[f] = face_path(pattern, max_names[f]);
            if (paths[f] == NULL) {
                r = load_fail(RD_ERR_OUT_OF_MEMORY, err, err_size, "%s: out of memory", pattern);
                goto done;
            }
        }
    }

    for (int f = 0; f < 6; f++) {
        char detail[768];
        if (!file_exists(paths[f])) {
            r = load_fail(RD_ERR_INVALID_ARGUMENT, err, err_size, "%s: face %s (%s): no such file",
                          pattern, names[f], paths[f]);
            goto done;
        }
        rd_image_result ir = rd_image_read(paths[f], &img, NULL, detail, sizeof detail);
        if (ir != RD_IMAGE_OK) {
            r = ir == RD_IMAGE_ERR_OUT_OF_MEMORY ? RD_ERR_OUT_OF_MEMORY
                : ir == RD_IMAGE_ERR_TOO_LARGE   ? RD_ERR_TOO_LARGE
                                                 : RD_ERR_INVALID_ARGUMENT;
            r = load_fail(r, err, err_size, "%s: face %s (%s): %s", pattern, names[f], paths[f],
                          without_path(detail, paths[f]));
            goto done;
        }
        if (img.width != img.height) {
            r = load_fail(RD_ERR_INVALID_ARGUMENT, err, err_size,
                          "%s: face %s (%s): %dx%d is not square", pattern, names[f], paths[f],
                          img.width, img.height);
            goto done;
        }
        if (f == 0) {
            if (img.width > RD_CUBE_MAX_SIZE) {
                r = load_fail(RD_ERR_TOO_LARGE, err, err_size,
                              "%s: face %s (%s): %dx%d is over the cube-map limit of %d", pattern,
                              names[f], paths[f], img.width, img.height, RD_CUBE_MAX_SIZE);
                goto done;
            }
            r = rd_cube_data_alloc(img.width, out);
            if (r != RD_OK) {
                r = load_fail(r, err, err_size, "%s: face %s (%s): cannot allocate %dx%d faces",
                              pattern, names[f], paths[f], img.width, img.height);
                goto done;
            }
        } else if (img.width != out->size) {
            r = load_fail(RD_ERR_INVALID_ARGUMENT, err, err_size,
                          "%s: face %s (%s): %dx%d differs from face %s (%s): %dx%d", pattern,
                          names[f], paths[f], img.width, img.height, names[0], paths[0], out->size,
                          out->size);
            goto done;
        }
        /* As stored: top image row = row 0 = t near 0 (see cube_data.h). */
        float *dst = out->faces[f];
        rd_image_expand_rgba(&img, dst);
        size_t count = (size_t)out->size * (size_t)out->size;
        for (size_t p = 0; p < count; p++) {
            for (int ch = 0; ch < 4; ch++) {
                float v = dst[p * 4 + ch];
                if (!isfinite(v))
                    v = 0.0f;
                else if (img.srgb_encoded && ch < 3)
                    v = srgb_decode(v);
                dst[p * 4 + ch] = v;
            }
        }
        rd_image_free(&img);
    }

done:
    rd_image_free(&img);
    for (int f = 0; f < 6; f++)
        free(paths[f]);
    if (r != RD_OK)
        rd_cube_data_free(out);
    return r;
}
