/* Luma percentiles by a 256-bin histogram of 8-bit luma (the values a PNG holds), and the
 * clipped fraction. */
#include "app/measure/image_contrast.h"

#include <math.h>
#include <string.h>

static int byte_of(float v)
{
    float b = v * 255.0f + 0.5f;
    return isnan(b) ? 0 : b < 0.0f ? 0 : b > 255.0f ? 255 : (int)b;
}

/* The luma below which a fraction q of the pixels lie (the lowest bin that reaches it). */
static double percentile(const long long hist[256], long long n, double q)
{
    long long need = (long long)ceil(q * (double)n), seen = 0;
    if (need < 1)
        need = 1;
    for (int i = 0; i < 256; i++) {
        seen += hist[i];
        if (seen >= need)
            return i;
    }
    return 255;
}

int app_image_contrast_of(const float *pixels, int width, int height, int channels,
                          app_image_contrast *out)
{
    memset(out, 0, sizeof *out);
    if (!pixels || width <= 0 || height <= 0 || channels < 1 || channels > 4)
        return -1;
    long long hist[256] = {0}, clipped = 0, n = (long long)width * height;
    double sum = 0.0;
    for (long long i = 0; i < n; i++) {
        const float *p = pixels + i * channels;
        int r = byte_of(p[0]), g = channels >= 3 ? byte_of(p[1]) : r,
            b = channels >= 3 ? byte_of(p[2]) : r;
        int y = (int)lround(0.2126 * r + 0.7152 * g + 0.0722 * b);
        hist[y < 0 ? 0 : y > 255 ? 255 : y]++;
        sum += 0.2126 * r + 0.7152 * g + 0.0722 * b;
        clipped += r == 255 || g == 255 || b == 255;
    }
    out->pixels = n;
    out->luma_p1 = percentile(hist, n, 0.01);
    out->luma_p50 = percentile(hist, n, 0.50);
    out->luma_p99 = percentile(hist, n, 0.99);
    out->luma_mean = sum / (double)n;
    out->clipped_fraction = (double)clipped / (double)n;
    return 0;
}
