/* Temporal supersampling's running average. See live_accum.h. */
#include "live_accum.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Samples are averaged after the tone map in linear display values, then sRGB encoded, as the
 * renderer's own supersampling resolve does (render/shaders/tonemap.frag). */
#define ENCODE_STEPS 16384
static float decode_table[256];
static uint8_t encode_table[ENCODE_STEPS + 1];

static void make_tables(void)
{
    if (decode_table[255] > 0)
        return;
    for (int i = 0; i < 256; i++) {
        double c = i / 255.0;
        decode_table[i] = (float)(c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4));
    }
    for (int i = 0; i <= ENCODE_STEPS; i++) {
        double x = (double)i / ENCODE_STEPS;
        double c = x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
        encode_table[i] = (uint8_t)lround(fmin(fmax(c, 0), 1) * 255.0);
    }
}

static uint8_t encode(float linear)
{
    int i = (int)(linear * ENCODE_STEPS + 0.5f);
    return encode_table[i < 0 ? 0 : i > ENCODE_STEPS ? ENCODE_STEPS : i];
}

int ui_accum_resize(ui_accum *a, int width, int height)
{
    make_tables();
    if (a->width == width && a->height == height && a->image)
        return 0;
    ui_accum_free(a);
    if (width <= 0 || height <= 0)
        return 1;
    size_t n = (size_t)width * (size_t)height;
    a->sum = calloc(n * 3, sizeof *a->sum);
    a->count = calloc(n, sizeof *a->count);
    a->image = calloc(n * 4, 1);
    if (!a->sum || !a->count || !a->image) {
        ui_accum_free(a);
        return 1;
    }
    a->width = width;
    a->height = height;
    return 0;
}

void ui_accum_free(ui_accum *a)
{
    free(a->sum);
    free(a->count);
    free(a->image);
    memset(a, 0, sizeof *a);
}

void ui_accum_restart(ui_accum *a)
{
    size_t n = (size_t)a->width * (size_t)a->height;
    if (!a->image)
        return;
    memset(a->sum, 0, n * 3 * sizeof *a->sum);
    memset(a->count, 0, n * sizeof *a->count);
}

void ui_accum_start_from(ui_accum *a, const uint8_t *rgba, int w, int h)
{
    ui_accum_restart(a);
    if (!a->image || !rgba || w <= 0 || h <= 0)
        return;
    /* Bilinear, pixel centres aligned: what the window's scaled blit showed. */
    for (int y = 0; y < a->height; y++) {
        float fy = ((float)y + 0.5f) * (float)h / (float)a->height - 0.5f;
        int y0 = (int)floorf(fy);
        float ty = fy - (float)y0;
        int ya = y0 < 0    ? 0
                 : y0 >= h ? h - 1
                           : y0,
            yb = y0 + 1 >= h  ? h - 1
                 : y0 + 1 < 0 ? 0
                              : y0 + 1;
        for (int x = 0; x < a->width; x++) {
            float fx = ((float)x + 0.5f) * (float)w / (float)a->width - 0.5f;
            int x0 = (int)floorf(fx);
            float tx = fx - (float)x0;
            int xa = x0 < 0    ? 0
                     : x0 >= w ? w - 1
                               : x0,
                xb = x0 + 1 >= w  ? w - 1
                     : x0 + 1 < 0 ? 0
                                  : x0 + 1;
            uint8_t *out = a->image + ((size_t)y * (size_t)a->width + (size_t)x) * 4;
            for (int c = 0; c < 3; c++) {
                float p00 = decode_table[rgba[((size_t)ya * w + xa) * 4 + c]];
                float p10 = decode_table[rgba[((size_t)ya * w + xb) * 4 + c]];
                float p01 = decode_table[rgba[((size_t)yb * w + xa) * 4 + c]];
                float p11 = decode_table[rgba[((size_t)yb * w + xb) * 4 + c]];
                float top = p00 + tx * (p10 - p00), bottom = p01 + tx * (p11 - p01);
                out[c] = encode(top + ty * (bottom - top));
            }
            out[3] = 255;
        }
    }
}

void ui_accum_add(ui_accum *a, int x, int y, int w, int h, const uint8_t *rgba)
{
    if (!a->image || !rgba || x < 0 || y < 0 || w <= 0 || h <= 0 || x + w > a->width ||
        y + h > a->height)
        return;
    for (int row = 0; row < h; row++)
        for (int col = 0; col < w; col++) {
            size_t i = (size_t)(y + row) * (size_t)a->width + (size_t)(x + col);
            const uint8_t *in = rgba + ((size_t)row * (size_t)w + (size_t)col) * 4;
            if (a->count[i] == UINT16_MAX)
                continue; /* converged long ago */
            float n = (float)++a->count[i];
            for (int c = 0; c < 3; c++) {
                a->sum[i * 3 + c] += decode_table[in[c]];
                a->image[i * 4 + c] = encode(a->sum[i * 3 + c] / n);
            }
            a->image[i * 4 + 3] = 255;
        }
}

void ui_jitter(int index, float out[2])
{
    if (index <= 0) {
        out[0] = out[1] = 0.0f;
        return;
    }
    /* Radical inverses of the index in bases 2 and 3. */
    const int base[2] = {2, 3};
    for (int k = 0; k < 2; k++) {
        float f = 1.0f, r = 0.0f;
        for (int i = index; i > 0; i /= base[k]) {
            f /= (float)base[k];
            r += f * (float)(i % base[k]);
        }
        out[k] = r - 0.5f;
    }
}
