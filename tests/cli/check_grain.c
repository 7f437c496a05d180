/* check_grain WOOD.png PLAIN.png X0 Y0 X1 Y1 MIN_RATIO
 *
 * A product drawn with the wood grain against the same render with its pattern off: inside the
 * rectangle [X0, X1) x [Y0, Y1) (pixels, the product's front) the mean difference of
 * vertically neighbouring pixels (the local variation across the grain, green channel, 8-bit
 * steps) must be at least
 * MIN_RATIO times that of the plain render, and more than along the rows (a horizontal grain),
 * and the two renders must differ there. Prints the figures. Reads the files with the project's own
 * reader (render/image_io.h). */
#include "render/image_io.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static float *green(const char *path, int *w, int *h)
{
    rd_image img = {0};
    char err[1024];
    int nonfinite = 0;
    if (rd_image_read(path, &img, &nonfinite, err, sizeof err) != RD_IMAGE_OK ||
        !img.srgb_encoded) {
        fprintf(stderr, "FAIL: %s: %s\n", path, img.srgb_encoded ? err : "not an 8-bit image");
        rd_image_free(&img);
        return NULL;
    }
    size_t n = (size_t)img.width * (size_t)img.height;
    float *rgba = malloc(n * 4 * sizeof *rgba), *g = malloc(n * sizeof *g);
    if (!rgba || !g) {
        free(rgba);
        free(g);
        rd_image_free(&img);
        return NULL;
    }
    rd_image_expand_rgba(&img, rgba);
    for (size_t i = 0; i < n; i++)
        g[i] = roundf(rgba[4 * i + 1] * 255.0f);
    *w = img.width;
    *h = img.height;
    free(rgba);
    rd_image_free(&img);
    return g;
}

/* Mean |difference| of neighbours dx, dy apart inside the rectangle. */
static double local_variation(const float *g, int w, int x0, int y0, int x1, int y1, int dx, int dy)
{
    double sum = 0.0;
    long n = 0;
    for (int y = y0; y < y1 - dy; y++)
        for (int x = x0; x < x1 - dx; x++) {
            sum += fabsf(g[(y + dy) * w + x + dx] - g[y * w + x]);
            n++;
        }
    return n ? sum / (double)n : 0.0;
}

int main(int argc, char **argv)
{
    if (argc != 8) {
        fprintf(stderr, "usage: check_grain WOOD PLAIN X0 Y0 X1 Y1 MIN_RATIO\n");
        return 2;
    }
    int w = 0, h = 0, w2 = 0, h2 = 0;
    float *wood = green(argv[1], &w, &h), *plain = green(argv[2], &w2, &h2);
    int x0 = atoi(argv[3]), y0 = atoi(argv[4]), x1 = atoi(argv[5]), y1 = atoi(argv[6]);
    double min_ratio = atof(argv[7]);
    if (!wood || !plain || w != w2 || h != h2 || x0 < 0 || y0 < 0 || x1 > w || y1 > h ||
        x1 - x0 < 2 || y1 - y0 < 2) {
        fprintf(stderr, "FAIL: unreadable images, different sizes or a rectangle outside them\n");
        return 1;
    }
    /* A horizontal grain: its rings and bands change down the image, hardly along a row. */
    double vw = local_variation(wood, w, x0, y0, x1, y1, 0, 1);
    double vp = local_variation(plain, w, x0, y0, x1, y1, 0, 1);
    double along = local_variation(wood, w, x0, y0, x1, y1, 1, 0);
    double diff = 0.0;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++)
            diff += fabsf(wood[y * w + x] - plain[y * w + x]);
    diff /= (double)(x1 - x0) * (y1 - y0);
    printf("local variation down the product's front: wood %.3f, plain %.3f steps (ratio %.2f); "
           "along its rows: wood %.3f; mean difference %.3f steps\n",
           vw, vp, vp > 0 ? vw / vp : INFINITY, along, diff);
    int ok = vw >= min_ratio * vp && vw > along && diff > 0.5;
    printf("check_grain: %s\n", ok ? "PASS" : "FAIL");
    free(wood);
    free(plain);
    return ok ? 0 : 1;
}
