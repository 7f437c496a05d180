/* check_image_file FILE REFERENCE WIDTHxHEIGHT [--max-diff N] [--mean-diff M] [--psnr DB]
 *                  [--white W] [--tone neutral|agx|reinhard|clamp] [--black-excess F]
 *
 * Reads back an image `tessera render` wrote (render/image_io.h, the project's own reader) and
 * compares it with the same render written in another format: both must read, have the size
 * asked for and show a picture (not one flat colour), and their display values must agree
 * within the format's loss, in 8-bit steps: the largest difference of a channel (--max-diff),
 * the mean absolute difference (--mean-diff) and the PSNR (--psnr, dB). The defaults ask for
 * identical pixels.
 *
 * 8-bit files (PNG, JPEG, TIFF) hold sRGB display values already (read back as whole steps). A
 * float file (EXR) holds the exposed linear radiance (rd_read_linear): it is tone mapped as the
 * renderer's resolve does (rd_ref_display_rgb8: the tone curve --tone, default neutral, the
 * project default; L_white = W for reinhard, default 4; the exposure and white balance are in
 * the file) before it is compared.
 *
 * --black-excess F: at most the fraction F of the pixels may be black in FILE (every display
 * value at most 1 of 255: the clear colour, where no surface was drawn) where REFERENCE is
 * not; for a render against the tracer's view of the same camera (the tracer never leaves a
 * pixel undefined). */
#include "render/image_io.h"
#include "render/render.h"
#include "render/shade_ref.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The image's RGB display values in 0..255, or NULL after naming what went wrong. */
static rd_tonemap tone = RD_TONEMAP_NEUTRAL;

static float *display_values(const char *path, int width, int height, float white)
{
    rd_image img = {0};
    char err[1024];
    int nonfinite = 0;
    if (rd_image_read(path, &img, &nonfinite, err, sizeof err) != RD_IMAGE_OK) {
        fprintf(stderr, "FAIL: %s\n", err);
        return NULL;
    }
    if (img.width != width || img.height != height || img.channels < 3 || nonfinite) {
        fprintf(stderr,
                "FAIL: %s is %dx%d with %d channels and %d non-finite values; "
                "expected %dx%d RGB(A), all finite\n",
                path, img.width, img.height, img.channels, nonfinite, width, height);
        rd_image_free(&img);
        return NULL;
    }
    size_t pixels = (size_t)width * (size_t)height;
    float *rgba = malloc(pixels * 4 * sizeof *rgba);
    float *out = malloc(pixels * 3 * sizeof *out);
    if (!rgba || !out) {
        fprintf(stderr, "FAIL: out of memory\n");
        free(rgba);
        free(out);
        rd_image_free(&img);
        return NULL;
    }
    rd_image_expand_rgba(&img, rgba);
    for (size_t i = 0; i < pixels; i++) {
        if (img.srgb_encoded) {
            for (int c = 0; c < 3; c++)
                out[i * 3 + c] = roundf(rgba[i * 4 + c] * 255.0f);
        } else {
            unsigned char rgb8[3];
            rd_ref_display_rgb8(&rgba[i * 4], 0.0f, tone, white, rgb8);
            for (int c = 0; c < 3; c++)
                out[i * 3 + c] = rgb8[c];
        }
    }
    free(rgba);
    rd_image_free(&img);
    return out;
}

/* A picture, not a blank or flat file: its channels span at least 32 steps. */
static int shows_a_picture(const char *path, const float *v, size_t count)
{
    float lo = v[0], hi = v[0];
    for (size_t i = 1; i < count; i++) {
        lo = v[i] < lo ? v[i] : lo;
        hi = v[i] > hi ? v[i] : hi;
    }
    if (hi - lo < 32.0f) {
        fprintf(stderr, "FAIL: %s is flat: its values span %.0f to %.0f of 255\n", path, lo, hi);
        return 0;
    }
    return 1;
}

int main(int argc, char **argv)
{
    int width = 0, height = 0;
    if (argc < 4 || sscanf(argv[3], "%dx%d", &width, &height) != 2 || width <= 0 || height <= 0) {
        fprintf(stderr, "usage: check_image_file FILE REFERENCE WIDTHxHEIGHT [--max-diff N] "
                        "[--mean-diff M] [--psnr DB] [--white W] [--tone T] "
                        "[--black-excess F]\n");
        return 2;
    }
    double max_allowed = 0.0, mean_allowed = 0.0, psnr_min = 0.0, white = 4.0, black_excess = -1.0;
    for (int i = 4; i < argc; i++) {
        if (!strcmp(argv[i], "--tone")) {
            if (i + 1 >= argc || rd_tonemap_parse(argv[i + 1], &tone) != RD_OK) {
                fprintf(stderr, "check_image_file: bad option \"%s\"\n", argv[i]);
                return 2;
            }
            i++;
            continue;
        }
        double *target = !strcmp(argv[i], "--max-diff")       ? &max_allowed
                         : !strcmp(argv[i], "--mean-diff")    ? &mean_allowed
                         : !strcmp(argv[i], "--psnr")         ? &psnr_min
                         : !strcmp(argv[i], "--white")        ? &white
                         : !strcmp(argv[i], "--black-excess") ? &black_excess
                                                              : NULL;
        char *end = NULL;
        if (!target || i + 1 >= argc || (*target = strtod(argv[i + 1], &end), *end)) {
            fprintf(stderr, "check_image_file: bad option \"%s\"\n", argv[i]);
            return 2;
        }
        i++;
    }
    const char *file = argv[1], *ref = argv[2];
    float *a = display_values(file, width, height, (float)white);
    float *b = display_values(ref, width, height, (float)white);
    size_t count = (size_t)width * (size_t)height * 3;
    int ok = a && b && shows_a_picture(file, a, count) && shows_a_picture(ref, b, count);
    if (ok) {
        double max_diff = 0.0, sum = 0.0, sum2 = 0.0;
        for (size_t i = 0; i < count; i++) {
            double d = fabs((double)a[i] - (double)b[i]);
            max_diff = d > max_diff ? d : max_diff;
            sum += d;
            sum2 += d * d;
        }
        double mean = sum / (double)count, mse = sum2 / (double)count;
        double psnr = mse > 0.0 ? 10.0 * log10(255.0 * 255.0 / mse) : INFINITY;
        printf("%s: %dx%d against %s: max diff %.0f, mean diff %.3f (of 255), PSNR %.2f dB\n", file,
               width, height, ref, max_diff, mean, psnr);
        if (max_diff > max_allowed) {
            fprintf(stderr, "FAIL: max diff %.0f > %.0f\n", max_diff, max_allowed);
            ok = 0;
        }
        if (mean > mean_allowed) {
            fprintf(stderr, "FAIL: mean diff %.3f > %.3f\n", mean, mean_allowed);
            ok = 0;
        }
        if (psnr < psnr_min) {
            fprintf(stderr, "FAIL: PSNR %.2f dB < %.2f dB\n", psnr, psnr_min);
            ok = 0;
        }
        if (black_excess >= 0.0) {
            size_t pixels = count / 3, only_file = 0, in_ref = 0;
            for (size_t i = 0; i < pixels; i++) {
                int black_a = a[3 * i] <= 1.0f && a[3 * i + 1] <= 1.0f && a[3 * i + 2] <= 1.0f;
                int black_b = b[3 * i] <= 1.0f && b[3 * i + 1] <= 1.0f && b[3 * i + 2] <= 1.0f;
                only_file += black_a && !black_b;
                in_ref += black_b;
            }
            double excess = (double)only_file / (double)pixels;
            printf("black pixels: %.2f %% of %s where %s is not (%.2f %% black there)\n",
                   100.0 * excess, file, ref, 100.0 * (double)in_ref / (double)pixels);
            if (excess > black_excess) {
                fprintf(stderr, "FAIL: black excess %.4f > %.4f\n", excess, black_excess);
                ok = 0;
            }
        }
    }
    free(a);
    free(b);
    if (ok)
        printf("check_image_file: PASS\n");
    return ok ? 0 : 1;
}
