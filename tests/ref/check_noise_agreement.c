/* check_noise_agreement GPU.exr REF0.exr REF1.exr MIN_DB: how far a GPU image lies from the
 * converged value of a Monte-Carlo reference, judged with the reference's own noise.
 *
 * REF0 and REF1 are the same trace with two seeds, so each is the converged image T plus
 * independent noise of variance s^2 per value: E[(REF0 - REF1)^2] = 2 s^2, and for the GPU
 * image G = T + b, E[(G - REF0)^2] = b^2 + s^2. The GPU's own error is therefore
 * b^2 = MSE(G, REF0) - MSE(REF0, REF1) / 2, reported as a PSNR (linear RGB, peak 1, as
 * `tessera compare`). Exit 0 when that PSNR is at least MIN_DB and the reference is quiet
 * enough to tell: its noise s^2 at most 4 times the bar's squared error (6 dB below it), so
 * that the subtraction, whose MSEs over n values carry a relative error of about sqrt(2 / n)
 * (1 % at 96 x 54 x 3), moves the result by a fraction of a dB; 1 otherwise; 2 on bad input. */
#include "render/image_io.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* The image's size in w, h and its pixels as RGBA floats in *px (malloc'ed). */
static int read_rgba(const char *path, int *w, int *h, float **px)
{
    char err[1024];
    rd_image image;
    rd_image *img = &image;
    if (rd_image_read(path, img, NULL, err, sizeof err) != RD_IMAGE_OK) {
        fprintf(stderr, "check_noise_agreement: %s\n", err);
        return 0;
    }
    *w = img->width;
    *h = img->height;
    *px = malloc(4 * (size_t)img->width * (size_t)img->height * sizeof **px);
    if (*px)
        rd_image_expand_rgba(img, *px);
    rd_image_free(img);
    return *px != NULL;
}

static double mse(const float *a, const float *b, size_t n)
{
    double sum = 0.0;
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 3; k++) {
            double d = (double)a[4 * i + k] - (double)b[4 * i + k];
            sum += d * d;
        }
    return sum / (3.0 * (double)n);
}

static double psnr(double m)
{
    return m > 0.0 ? -10.0 * log10(m) : INFINITY;
}

int main(int argc, char **argv)
{
    if (argc != 5) {
        fprintf(stderr, "usage: check_noise_agreement GPU.exr REF0.exr REF1.exr MIN_DB\n");
        return 2;
    }
    char *end;
    double min_db = strtod(argv[4], &end);
    if (*end || !isfinite(min_db)) {
        fprintf(stderr, "check_noise_agreement: MIN_DB \"%s\" is not a number\n", argv[4]);
        return 2;
    }
    int gw = 0, gh = 0, w0 = 0, h0 = 0, w1 = 0, h1 = 0;
    float *pg = NULL, *p0 = NULL, *p1 = NULL;
    int read = read_rgba(argv[1], &gw, &gh, &pg) && read_rgba(argv[2], &w0, &h0, &p0) &&
               read_rgba(argv[3], &w1, &h1, &p1);
    if (read && (gw != w0 || gh != h0 || w0 != w1 || h0 != h1)) {
        fprintf(stderr, "check_noise_agreement: the images differ in size\n");
        read = 0;
    }
    if (!read) {
        free(pg);
        free(p0);
        free(p1);
        return 2;
    }
    size_t n = (size_t)gw * (size_t)gh;
    double m_g = mse(pg, p0, n), m_seeds = mse(p0, p1, n);
    double noise = m_seeds / 2.0, bias = m_g - noise;
    double bias_db = psnr(bias > 0.0 ? bias : 0.0), noise_db = psnr(noise);
    printf("gpu vs reference %.2f dB; reference noise (one image) %.2f dB; gpu error without the "
           "noise %.2f dB; bar %.2f dB\n",
           psnr(m_g), noise_db, bias_db, min_db);
    int ok = 1;
    if (!(noise_db >= min_db - 6.0)) {
        fprintf(stderr,
                "check_noise_agreement: the reference's noise (%.2f dB) hides the bar of "
                "%.2f dB: trace more paths\n",
                noise_db, min_db);
        ok = 0;
    }
    if (!(bias_db >= min_db)) {
        fprintf(stderr,
                "check_noise_agreement: %s lies %.2f dB from the reference, below %.2f dB\n",
                argv[1], bias_db, min_db);
        ok = 0;
    }
    free(pg);
    free(p0);
    free(p1);
    return ok ? 0 : 1;
}
