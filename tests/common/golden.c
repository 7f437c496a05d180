/* Golden-image checks: a pure comparison, plus the file side (read the golden, write the
 * artifacts, print a piglit-style report). */
#include "golden.h"

#include "render/image_io.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int golden_compare_rgba8(const unsigned char *a, const unsigned char *b, int w, int h,
                         int tolerance, long *failing_pixels, int *worst_x, int *worst_y)
{
    if (failing_pixels != NULL) {
        *failing_pixels = 0;
    }
    if (worst_x != NULL) {
        *worst_x = -1;
    }
    if (worst_y != NULL) {
        *worst_y = -1;
    }
    if (a == NULL || b == NULL || w < 1 || h < 1 || tolerance < 0) {
        return -1;
    }
    long failing = 0;
    int worst = 0;
    for (int y = 0; y < h; y++) {
        for (int x = 0; x < w; x++) {
            size_t i = ((size_t)y * (size_t)w + (size_t)x) * 4;
            int d = 0;
            for (int c = 0; c < 4; c++) {
                int dc = abs((int)a[i + c] - (int)b[i + c]);
                d = dc > d ? dc : d;
            }
            if (d > tolerance) {
                failing++;
            }
            if (d > worst) {
                worst = d;
                if (worst_x != NULL) {
                    *worst_x = x;
                }
                if (worst_y != NULL) {
                    *worst_y = y;
                }
            }
        }
    }
    if (failing_pixels != NULL) {
        *failing_pixels = failing;
    }
    return worst;
}

int golden_within_budget(long failing_pixels, long total_pixels)
{
    /* failing / total <= 1/1000 without dividing, so 10 of 10000 passes and 11 fails exactly
     * (doubles hold these products exactly for any real image size). */
    return (double)failing_pixels * 1000.0 <=
           (double)total_pixels * (double)GOLDEN_MAX_FAILING_PER_MILLE;
}

void golden_diff_image(const unsigned char *expected, int ew, int eh, const unsigned char *actual,
                       int aw, int ah, int tolerance, unsigned char *out)
{
    int dw = ew > aw ? ew : aw;
    int dh = eh > ah ? eh : ah;
    for (int y = 0; y < dh; y++) {
        for (int x = 0; x < dw; x++) {
            unsigned char *o = out + ((size_t)y * (size_t)dw + (size_t)x) * 4;
            o[3] = 255;
            if (x >= ew || y >= eh || x >= aw || y >= ah) {
                o[0] = 255, o[1] = 0, o[2] = 0;
                continue;
            }
            const unsigned char *e = expected + ((size_t)y * (size_t)ew + (size_t)x) * 4;
            const unsigned char *a = actual + ((size_t)y * (size_t)aw + (size_t)x) * 4;
            int d = 0;
            for (int c = 0; c < 4; c++) {
                int dc = abs((int)e[c] - (int)a[c]);
                d = dc > d ? dc : d;
            }
            if (d == 0) {
                o[0] = o[1] = o[2] = 0;
            } else if (d <= tolerance) {
                /* Visible but quiet: differences the tolerance accepts. */
                o[0] = 0, o[1] = 0, o[2] = (unsigned char)(64 + 24 * d);
            } else {
                /* Full red from the first failing level, towards yellow as it grows, so a
                 * 6/255 pixel is as easy to spot as a 200/255 one. */
                int g = (d - tolerance) * 4;
                o[0] = 255, o[1] = (unsigned char)(g > 255 ? 255 : g), o[2] = 0;
            }
        }
    }
}

/* ---- files ------------------------------------------------------------------------------ */

static int make_dirs(const char *dir)
{
    char buf[4096];
    size_t n = strlen(dir);
    if (n == 0 || n >= sizeof buf) {
        return -1;
    }
    memcpy(buf, dir, n + 1);
    for (size_t i = 1; i <= n; i++) {
        if (buf[i] == '/' || buf[i] == '\0') {
            char saved = buf[i];
            buf[i] = '\0';
            if (mkdir(buf, 0777) != 0 && errno != EEXIST) {
                return -1;
            }
            buf[i] = saved;
        }
    }
    return 0;
}

static void make_parent_dirs(const char *path)
{
    char buf[4096];
    snprintf(buf, sizeof buf, "%s", path);
    char *slash = strrchr(buf, '/');
    if (slash != NULL && slash != buf) {
        *slash = '\0';
        make_dirs(buf);
    }
}

static float linear_to_srgb(float v)
{
    /* IEC 61966-2-1 encoding. */
    return v <= 0.0031308f ? 12.92f * v : 1.055f * powf(v, 1.0f / 2.4f) - 0.055f;
}

static unsigned char to_byte(float v)
{
    v = v < 0.0f ? 0.0f : (v > 1.0f ? 1.0f : v);
    return (unsigned char)(v * 255.0f + 0.5f);
}

/* Any 1..4 channel image as display-encoded RGBA8 (linear files are sRGB-encoded first). */
static unsigned char *image_to_rgba8(const rd_image *img)
{
    size_t count = (size_t)img->width * (size_t)img->height;
    unsigned char *out = malloc(count * 4);
    if (out == NULL) {
        return NULL;
    }
    for (size_t i = 0; i < count; i++) {
        const float *p = img->pixels + i * (size_t)img->channels;
        float rgba[4] = {p[0], p[0], p[0], 1.0f};
        if (img->channels >= 3) {
            rgba[1] = p[1], rgba[2] = p[2];
        }
        if (img->channels == 2 || img->channels == 4) {
            rgba[3] = p[img->channels - 1];
        }
        for (int c = 0; c < 4; c++) {
            float v = (c < 3 && !img->srgb_encoded) ? linear_to_srgb(rgba[c]) : rgba[c];
            out[i * 4 + (size_t)c] = to_byte(v);
        }
    }
    return out;
}

static void artifact_path(char *buf, size_t size, const char *dir, const char *test_name,
                          const char *suffix)
{
    /* The test name becomes a file name: keep it to a safe alphabet. */
    char safe[256];
    size_t n = 0;
    for (const char *s = test_name; *s != '\0' && n + 1 < sizeof safe; s++) {
        char c = *s;
        int ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                 c == '-' || c == '_' || c == '.';
        safe[n++] = ok ? c : '_';
    }
    safe[n] = '\0';
    snprintf(buf, size, "%s/%s.%s.png", dir, n > 0 ? safe : "golden", suffix);
}

static void write_artifact(const char *path, int w, int h, const unsigned char *rgba)
{
    char err[1024];
    if (rd_image_write_rgba8(path, w, h, rgba, err, sizeof err) != RD_IMAGE_OK) {
        printf("  (could not write artifact: %s)\n", err);
    }
}

int golden_check(const char *test_name, const unsigned char *actual_rgba, int w, int h,
                 const char *golden_path, const char *artifact_dir)
{
    char err[1024];
    if (test_name == NULL || actual_rgba == NULL || golden_path == NULL || artifact_dir == NULL ||
        w < 1 || h < 1) {
        printf("FAIL golden: invalid arguments (test %s, %d x %d)\n",
               test_name != NULL ? test_name : "(null)", w, h);
        return 1;
    }

    const char *update = getenv("TESSERA_UPDATE_GOLDEN");
    if (update != NULL && strcmp(update, "1") == 0) {
        make_parent_dirs(golden_path);
        if (rd_image_write_rgba8(golden_path, w, h, actual_rgba, err, sizeof err) != RD_IMAGE_OK) {
            printf("FAIL golden %s: cannot update golden: %s\n", test_name, err);
            return 1;
        }
        printf("golden %s: updated %s (%d x %d) because TESSERA_UPDATE_GOLDEN=1\n", test_name,
               golden_path, w, h);
        return 0;
    }

    rd_image golden = {0};
    unsigned char *expected = NULL;
    int have_golden = rd_image_read(golden_path, &golden, NULL, err, sizeof err) == RD_IMAGE_OK;
    if (have_golden) {
        expected = image_to_rgba8(&golden);
        if (expected == NULL) {
            snprintf(err, sizeof err, "%s: out of memory", golden_path);
            have_golden = 0;
        }
    }
    int ew = have_golden ? golden.width : 0;
    int eh = have_golden ? golden.height : 0;
    rd_image_free(&golden);

    long total = (long)w * (long)h;
    long failing = total;
    int wx = -1, wy = -1;
    int passed = 0;
    if (have_golden && ew == w && eh == h) {
        golden_compare_rgba8(expected, actual_rgba, w, h, GOLDEN_TOLERANCE, &failing, &wx, &wy);
        passed = golden_within_budget(failing, total);
    }
    if (passed) {
        free(expected);
        return 0;
    }

    char actual_path[4096], expected_path[4096], diff_path[4096];
    artifact_path(actual_path, sizeof actual_path, artifact_dir, test_name, "actual");
    artifact_path(expected_path, sizeof expected_path, artifact_dir, test_name, "expected");
    artifact_path(diff_path, sizeof diff_path, artifact_dir, test_name, "diff");
    if (make_dirs(artifact_dir) != 0) {
        printf("  (could not create %s: %s)\n", artifact_dir, strerror(errno));
    }

    if (!have_golden) {
        printf("FAIL golden %s: no usable golden image: %s\n"
               "  (run with TESSERA_UPDATE_GOLDEN=1 to create it from this result)\n",
               test_name, err);
    } else if (ew != w || eh != h) {
        printf("FAIL golden %s: size mismatch: expected %d x %d (%s), observed %d x %d\n",
               test_name, ew, eh, golden_path, w, h);
    } else {
        printf("FAIL golden %s: %ld of %ld pixels (%.3f %%) differ by more than %d/255; at most "
               "%.1f %% may\n",
               test_name, failing, total, 100.0 * (double)failing / (double)total, GOLDEN_TOLERANCE,
               0.1 * GOLDEN_MAX_FAILING_PER_MILLE);
        const unsigned char *e = expected + ((size_t)wy * (size_t)w + (size_t)wx) * 4;
        const unsigned char *a = actual_rgba + ((size_t)wy * (size_t)w + (size_t)wx) * 4;
        printf("Probe color at (%d,%d)\n"
               "  Expected: %d %d %d %d\n"
               "  Observed: %d %d %d %d\n",
               wx, wy, e[0], e[1], e[2], e[3], a[0], a[1], a[2], a[3]);
    }

    write_artifact(actual_path, w, h, actual_rgba);
    printf("  actual:   %s\n", actual_path);
    if (have_golden) {
        write_artifact(expected_path, ew, eh, expected);
        printf("  expected: %s\n", expected_path);
    }
    /* Without a golden the diff is all red: every pixel exists on one side only. */
    int dw = ew > w ? ew : w;
    int dh = eh > h ? eh : h;
    unsigned char *diff = malloc((size_t)dw * (size_t)dh * 4);
    if (diff != NULL) {
        golden_diff_image(expected, ew, eh, actual_rgba, w, h, GOLDEN_TOLERANCE, diff);
        write_artifact(diff_path, dw, dh, diff);
        printf("  diff:     %s\n", diff_path);
        free(diff);
    }
    fflush(stdout);
    free(expected);
    return 1;
}
