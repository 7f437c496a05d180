/* Error between two images (RENDERING.md section 10): RMSE and PSNR in linear RGB over all
 * pixels or over a mask, and a heat map of the per-pixel error. Pure C: no I/O, no GL; the
 * `tessera compare` command (cli_compare.c) reads the files and prints. docs/reference.md. */
#ifndef APP_IMAGE_COMPARE_H
#define APP_IMAGE_COMPARE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The exact sRGB decoding curve (IEC 61966-2-1): c <= 0.04045 ? c / 12.92
 * : ((c + 0.055) / 1.055)^2.4. */
float app_srgb_to_linear(float c);
/* Decodes the RGB channels of `pixels` RGBA pixels in place; alpha is left alone. */
void app_image_srgb_to_linear(float *rgba, size_t pixels);

typedef struct app_image_metrics {
    long long pixels; /* pixels counted (all, or those in the mask) */
    double mse;       /* mean of (a - b)^2 over the counted pixels and the R, G, B channels */
    double rmse;      /* sqrt(mse) */
    double psnr;      /* 10 log10(1 / mse): peak 1.0; +inf when mse = 0; NaN when pixels = 0 */
    double max_error; /* the largest per-pixel error (app_image_pixel_error) */
} app_image_metrics;

/* One pixel's error: the root mean square over R, G, B of a - b (non-finite values count as
 * 0, so the result is always finite). */
float app_image_pixel_error(const float a[4], const float b[4]);

/* a and b: w x h RGBA floats, linear. mask: w x h floats or NULL; a pixel counts when its mask
 * value is >= 0.5. Alpha is ignored. Returns 0, or -1 for invalid arguments (then *out holds
 * zero pixels and NaN metrics). */
int app_image_metrics_compute(const float *a, const float *b, int w, int h, const float *mask,
                              app_image_metrics *out);

/* The per-pixel error below which a fraction q (0..1) of the counted pixels lie (nearest rank;
 * 0 when no pixel counts, or -1 on out of memory). */
double app_image_error_percentile(const float *a, const float *b, int w, int h, const float *mask,
                                  double q);

/* One square block of an image and the squared error it carries (app_image_worst_blocks). */
typedef struct app_error_block {
    int x, y, width, height; /* pixels; blocks at the right and bottom edges may be smaller */
    double share;            /* its part of the summed squared error, 0..1 */
    long long pixels;        /* counted pixels in it */
} app_error_block;

/* Where the error is: the image cut into `block` x `block` squares, the (at most) `count`
 * squares carrying the largest parts of the squared error over the counted pixels, largest
 * first, into out[]. A few blocks on a small feature often carry most of a PSNR's error (a
 * tap's spout in a whole bathroom); this names them. Returns how many were written (blocks
 * without error are left out), or -1 for invalid arguments or out of memory. */
int app_image_worst_blocks(const float *a, const float *b, int w, int h, const float *mask,
                           int block, app_error_block *out, int count);

/* The heat-map ramp: black -> blue -> red -> yellow -> white, linear between stops at t = 0,
 * 1/4, 1/2, 3/4, 1 (its luminance rises all the way); t is clamped to [0, 1], NaN -> 0. */
void app_heat_ramp(float t, unsigned char rgb[3]);

/* w x h RGBA8 (alpha 255): the ramp at app_image_pixel_error / max_error for every pixel
 * (errors above max_error are white). With max_error <= 0 or not finite, every pixel that
 * differs at all is white and the rest black. */
void app_image_heatmap(const float *a, const float *b, int w, int h, float max_error,
                       unsigned char *rgba);

#ifdef __cplusplus
}
#endif
#endif
