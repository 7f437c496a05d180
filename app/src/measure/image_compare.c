/* RMSE, PSNR and the error heat map (RENDERING.md section 10); see app/measure/image_compare.h. */
#include "app/measure/image_compare.h"

#include <math.h>
#include <stdlib.h>

float app_srgb_to_linear(float c)
{
    return c <= 0.04045f ? c / 12.92f : powf((c + 0.055f) / 1.055f, 2.4f);
}

void app_image_srgb_to_linear(float *rgba, size_t pixels)
{
    for (size_t i = 0; i < pixels; i++)
        for (int k = 0; k < 3; k++)
            rgba[4 * i + (size_t)k] = app_srgb_to_linear(rgba[4 * i + (size_t)k]);
}

static double finite_or_zero(float x)
{
    return isfinite(x) ? (double)x : 0.0;
}

static double pixel_sq_sum(const float *a, const float *b)
{
    double s = 0.0;
    for (int k = 0; k < 3; k++) {
        double d = finite_or_zero(a[k]) - finite_or_zero(b[k]);
        s += d * d;
    }
    return s;
}

float app_image_pixel_error(const float a[4], const float b[4])
{
    return (float)sqrt(pixel_sq_sum(a, b) / 3.0);
}

static int counted(const float *mask, size_t i)
{
    return !mask || mask[i] >= 0.5f;
}

int app_image_metrics_compute(const float *a, const float *b, int w, int h, const float *mask,
                              app_image_metrics *out)
{
    *out = (app_image_metrics){0, NAN, NAN, NAN, 0.0};
    if (!a || !b || w <= 0 || h <= 0)
        return -1;
    size_t n = (size_t)w * (size_t)h;
    double sum = 0.0, worst = 0.0;
    long long count = 0;
    for (size_t i = 0; i < n; i++) {
        if (!counted(mask, i))
            continue;
        double s = pixel_sq_sum(a + 4 * i, b + 4 * i);
        sum += s;
        worst = fmax(worst, sqrt(s / 3.0));
        count++;
    }
    out->pixels = count;
    out->max_error = worst;
    if (count == 0)
        return 0;
    out->mse = sum / (3.0 * (double)count);
    out->rmse = sqrt(out->mse);
    out->psnr = out->mse > 0.0 ? -10.0 * log10(out->mse) : INFINITY;
    return 0;
}

static int compare_floats(const void *x, const void *y)
{
    float a = *(const float *)x, b = *(const float *)y;
    return (a > b) - (a < b);
}

double app_image_error_percentile(const float *a, const float *b, int w, int h, const float *mask,
                                  double q)
{
    if (!a || !b || w <= 0 || h <= 0)
        return 0.0;
    size_t n = (size_t)w * (size_t)h, count = 0;
    float *e = malloc(n * sizeof *e);
    if (!e)
        return -1.0;
    for (size_t i = 0; i < n; i++)
        if (counted(mask, i))
            e[count++] = app_image_pixel_error(a + 4 * i, b + 4 * i);
    double result = 0.0;
    if (count > 0) {
        qsort(e, count, sizeof *e, compare_floats);
        double qq = isnan(q) ? 1.0 : fmin(fmax(q, 0.0), 1.0);
        size_t rank = (size_t)ceil(qq * (double)count); /* nearest rank, 1-based */
        result = e[rank > 0 ? rank - 1 : 0];
    }
    free(e);
    return result;
}

static int larger_share(const void *x, const void *y)
{
    double a = ((const app_error_block *)x)->share, b = ((const app_error_block *)y)->share;
    return (a < b) - (a > b);
}

int app_image_worst_blocks(const float *a, const float *b, int w, int h, const float *mask,
                           int block, app_error_block *out, int count)
{
    if (!a || !b || w <= 0 || h <= 0 || block <= 0 || !out || count <= 0)
        return -1;
    int bw = (w + block - 1) / block, bh = (h + block - 1) / block;
    app_error_block *all = calloc((size_t)bw * (size_t)bh, sizeof *all);
    if (!all)
        return -1;
    double total = 0.0;
    for (int by = 0; by < bh; by++)
        for (int bx = 0; bx < bw; bx++) {
            app_error_block *k = &all[(size_t)by * (size_t)bw + (size_t)bx];
            k->x = bx * block;
            k->y = by * block;
            k->width = k->x + block <= w ? block : w - k->x;
            k->height = k->y + block <= h ? block : h - k->y;
            for (int y = k->y; y < k->y + k->height; y++)
                for (int x = k->x; x < k->x + k->width; x++) {
                    size_t i = (size_t)y * (size_t)w + (size_t)x;
                    if (!counted(mask, i))
                        continue;
                    k->share += pixel_sq_sum(a + 4 * i, b + 4 * i);
                    k->pixels++;
                }
            total += k->share;
        }
    size_t n = (size_t)bw * (size_t)bh;
    qsort(all, n, sizeof *all, larger_share);
    int written = 0;
    for (size_t i = 0; i < n && written < count && all[i].share > 0.0; i++) {
        out[written] = all[i];
        out[written++].share = all[i].share / total;
    }
    free(all);
    return written;
}

void app_heat_ramp(float t, unsigned char rgb[3])
{
    static const float stops[5][3] = {
        {0, 0, 0}, {0, 0, 255}, {255, 0, 0}, {255, 255, 0}, {255, 255, 255}};
    if (!(t > 0.0f))
        t = 0.0f;
    if (t > 1.0f)
        t = 1.0f;
    float x = t * 4.0f;
    int i = x >= 4.0f ? 3 : (int)x;
    float f = x - (float)i;
    for (int k = 0; k < 3; k++)
        rgb[k] = (unsigned char)(stops[i][k] + f * (stops[i + 1][k] - stops[i][k]) + 0.5f);
}

void app_image_heatmap(const float *a, const float *b, int w, int h, float max_error,
                       unsigned char *rgba)
{
    size_t n = (size_t)w * (size_t)h;
    int scaled = max_error > 0.0f && isfinite(max_error);
    for (size_t i = 0; i < n; i++) {
        float e = app_image_pixel_error(a + 4 * i, b + 4 * i);
        float t = scaled ? e / max_error : (e > 0.0f ? 1.0f : 0.0f);
        app_heat_ramp(t, rgba + 4 * i);
        rgba[4 * i + 3] = 255;
    }
}
