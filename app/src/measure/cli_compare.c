/* tessera compare A B [--mask M] [--heatmap OUT.png] [--heat-max E] [--worst N [--block PX]]
 * RMSE and PSNR in linear RGB between two images, over all pixels and over a mask, a heat map
 * of the per-pixel error, and the blocks that carry most of it (RENDERING.md section 10,
 * docs/reference.md). */
#include "app/measure/image_compare.h"
#include "cli/cli_commands.h"
#include "render/image_io.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* An image as linear RGBA floats: EXR/HDR as stored, 8-bit files decoded from sRGB. */
typedef struct linear_image {
    int width, height, srgb;
    float *rgba;
} linear_image;

static int load(const char *path, int decode_srgb, linear_image *out)
{
    memset(out, 0, sizeof *out);
    rd_image img = {0};
    int nonfinite = 0;
    char err[1024];
    rd_image_result r = rd_image_read(path, &img, &nonfinite, err, sizeof err);
    if (r != RD_IMAGE_OK) {
        fprintf(stderr, "tessera compare: %s\n", err);
        return r == RD_IMAGE_ERR_OUT_OF_MEMORY ? CLI_FAILED : CLI_USAGE;
    }
    if (nonfinite)
        fprintf(stderr, "tessera compare: warning: %s: %d NaN or infinite values were set to 0\n",
                path, nonfinite);
    size_t n = (size_t)img.width * (size_t)img.height;
    out->rgba = malloc(4 * n * sizeof *out->rgba);
    if (!out->rgba) {
        rd_image_free(&img);
        fprintf(stderr, "tessera compare: out of memory for %s\n", path);
        return CLI_FAILED;
    }
    rd_image_expand_rgba(&img, out->rgba);
    out->width = img.width;
    out->height = img.height;
    out->srgb = img.srgb_encoded;
    if (decode_srgb && img.srgb_encoded)
        app_image_srgb_to_linear(out->rgba, n);
    rd_image_free(&img);
    return CLI_OK;
}

static const char *number(double x, char *buf, size_t size)
{
    if (isnan(x))
        snprintf(buf, size, "nan");
    else if (isinf(x))
        snprintf(buf, size, x > 0 ? "inf" : "-inf");
    else
        snprintf(buf, size, "%.6g", x);
    return buf;
}

/* What the table-driven parser cannot check: --block only sizes --worst's blocks. */
static int check_args(const cli_options *o)
{
    if (o->block > 0 && o->worst == 0) {
        fprintf(stderr, "tessera compare: --block sets the size of --worst's blocks: give --worst "
                        "N as well\n");
        return CLI_USAGE;
    }
    return CLI_OK;
}

/* The blocks carrying most of the squared error (of the mask's, if given), with what the
 * PSNR would be were they exact: where to look first. */
static int print_worst(const linear_image *a, const linear_image *b, const float *mask,
                       const app_image_metrics *m, int count, int block)
{
    app_error_block *blocks = malloc((size_t)count * sizeof *blocks);
    if (!blocks) {
        fprintf(stderr, "tessera compare: out of memory for --worst\n");
        return CLI_FAILED;
    }
    int n =
        app_image_worst_blocks(a->rgba, b->rgba, a->width, a->height, mask, block, blocks, count);
    if (n < 0) {
        free(blocks);
        fprintf(stderr, "tessera compare: out of memory for --worst\n");
        return CLI_FAILED;
    }
    printf("worst %d x %d blocks, by share of the %ssquared error (PSNR were they exact):\n", block,
           block, mask ? "masked " : "");
    double cumulative = 0.0;
    for (int i = 0; i < n; i++) {
        const app_error_block *k = &blocks[i];
        cumulative += k->share;
        double left = 1.0 - cumulative; /* rounding leaves about 1e-16 when all are listed */
        double rest = left > 1e-9 ? m->mse * left : 0.0;
        char p[32];
        printf("  x %4d-%-4d y %4d-%-4d %6.2f %%  cumulative %6.2f %%  psnr %s dB\n", k->x,
               k->x + k->width, k->y, k->y + k->height, 100.0 * k->share, 100.0 * cumulative,
               rest > 0.0 ? number(-10.0 * log10(rest), p, sizeof p) : "inf");
    }
    if (n == 0)
        printf("  none: the images are identical there\n");
    free(blocks);
    return CLI_OK;
}

static void print_metrics(const char *label, const app_image_metrics *m)
{
    char r[32], p[32], x[32];
    printf("%-14s %9lld pixels  rmse %s  psnr %s dB  max %s\n", label, m->pixels,
           number(m->rmse, r, sizeof r), number(m->psnr, p, sizeof p),
           number(m->max_error, x, sizeof x));
}

int cli_cmd_compare(const cli_options *o)
{
    int rc = check_args(o);
    if (rc != CLI_OK)
        return rc;
    const char *pa = o->args[0], *pb = o->args[1], *pm = o->mask, *heat = o->heatmap;
    double heat_max = o->heat_max;
    if (heat) {
        rc = cli_check_output_path(heat);
        if (rc == CLI_OK && rd_image_format_is_float(heat) != 0) {
            fprintf(stderr, "tessera compare: --heatmap %s: use .png, .jpg or .tif\n", heat);
            rc = CLI_USAGE;
        }
        if (rc != CLI_OK)
            return rc;
    }
    linear_image a, b, m = {0};
    rc = load(pa, 1, &a);
    if (rc != CLI_OK)
        return rc;
    rc = load(pb, 1, &b);
    if (rc != CLI_OK) {
        free(a.rgba);
        return rc;
    }
    float *mask = NULL;
    if (rc == CLI_OK && (a.width != b.width || a.height != b.height)) {
        fprintf(stderr,
                "tessera compare: %s is %dx%d but %s is %dx%d: the images must be the same "
                "size\n",
                pa, a.width, a.height, pb, b.width, b.height);
        rc = CLI_USAGE;
    }
    if (rc == CLI_OK && a.srgb != b.srgb)
        fprintf(stderr,
                "tessera compare: warning: %s holds %s and %s holds %s; compare EXR with EXR "
                "(radiance) or PNG with PNG (display values)\n",
                pa, a.srgb ? "sRGB display values" : "linear radiance", pb,
                b.srgb ? "sRGB display values" : "linear radiance");
    if (rc == CLI_OK && pm) {
        rc = load(pm, 0, &m); /* a mask is 0 or 1 either way: no decoding */
        if (rc == CLI_OK && (m.width != a.width || m.height != a.height)) {
            fprintf(stderr,
                    "tessera compare: mask %s is %dx%d but the images are %dx%d: it must be the "
                    "same size\n",
                    pm, m.width, m.height, a.width, a.height);
            rc = CLI_USAGE;
        }
        if (rc == CLI_OK) {
            size_t n = (size_t)a.width * (size_t)a.height;
            mask = malloc(n * sizeof *mask);
            if (!mask) {
                fprintf(stderr, "tessera compare: out of memory for the mask\n");
                rc = CLI_FAILED;
            }
            for (size_t i = 0; mask && i < n; i++)
                mask[i] = m.rgba[4 * i];
        }
    }
    app_image_metrics all = {0}, in_mask = {0};
    if (rc == CLI_OK) {
        app_image_metrics_compute(a.rgba, b.rgba, a.width, a.height, NULL, &all);
        if (mask)
            app_image_metrics_compute(a.rgba, b.rgba, a.width, a.height, mask, &in_mask);
        printf("compare %s (A) with %s (B): %dx%d, linear RGB, PSNR peak 1.0\n", pa, pb, a.width,
               a.height);
        print_metrics("all pixels", &all);
        if (mask) {
            print_metrics("masked pixels", &in_mask);
            if (in_mask.pixels == 0)
                fprintf(stderr, "tessera compare: warning: mask %s selects no pixel\n", pm);
        }
        if (o->worst > 0)
            rc = print_worst(&a, &b, mask, mask ? &in_mask : &all, o->worst,
                             o->block > 0 ? o->block : 20);
    }
    double scale = heat_max;
    if (rc == CLI_OK && heat) {
        if (!(scale > 0.0)) {
            /* Default: the 99th percentile of the errors that matter (the mask's if given), so
             * a few extreme pixels do not turn the rest black. */
            scale = app_image_error_percentile(a.rgba, b.rgba, a.width, a.height, mask, 0.99);
            if (!(scale > 0.0))
                scale = mask ? in_mask.max_error : all.max_error;
        }
        size_t n = (size_t)a.width * (size_t)a.height;
        unsigned char *rgba = malloc(4 * n);
        if (!rgba) {
            fprintf(stderr, "tessera compare: out of memory for the heat map\n");
            rc = CLI_FAILED;
        } else {
            app_image_heatmap(a.rgba, b.rgba, a.width, a.height, (float)scale, rgba);
            char err[1024];
            if (rd_image_write_rgba8(heat, a.width, a.height, rgba, err, sizeof err) !=
                RD_IMAGE_OK) {
                fprintf(stderr, "tessera compare: %s\n", err);
                rc = CLI_FAILED;
            } else {
                printf("heat map %s: per-pixel RMS error over RGB, black 0 -> blue -> red -> "
                       "yellow -> white at >= %.6g%s\n",
                       heat, scale, heat_max > 0.0 ? " (--heat-max)" : " (99th percentile)");
            }
            free(rgba);
        }
    }
    if (rc == CLI_OK) {
        char r1[32], p1[32], r2[32], p2[32], h[32];
        printf("rmse_all=%s psnr_all=%s pixels_all=%lld", number(all.rmse, r1, sizeof r1),
               number(all.psnr, p1, sizeof p1), all.pixels);
        if (mask)
            printf(" rmse_mask=%s psnr_mask=%s pixels_mask=%lld",
                   number(in_mask.rmse, r2, sizeof r2), number(in_mask.psnr, p2, sizeof p2),
                   in_mask.pixels);
        if (heat)
            printf(" heatmap_max=%s", number(scale, h, sizeof h));
        printf("\n");
    }
    free(mask);
    free(m.rgba);
    free(a.rgba);
    free(b.rgba);
    return rc;
}
