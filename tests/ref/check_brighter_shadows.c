/* check_brighter_shadows DIRECT.exr BOUNCED.exr: exit 0 when the image with indirect light is
 * brighter where the direct-only one is darkest -- the mean luminance of the darkest tenth of
 * DIRECT's pixels (shadows, corners, the sides turned from the lamps) rises by at least 20 %
 * in BOUNCED, which is what bounced light does and a tracer that ignores --bounces does not. */
#include "render/image_io.h"

#include <stdio.h>
#include <stdlib.h>

static double luminance(const float *p)
{
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: check_brighter_shadows DIRECT.exr BOUNCED.exr\n");
        return 2;
    }
    rd_image a, b;
    char err[1024];
    if (rd_image_read(argv[1], &a, NULL, err, sizeof err) != RD_IMAGE_OK ||
        rd_image_read(argv[2], &b, NULL, err, sizeof err) != RD_IMAGE_OK) {
        fprintf(stderr, "check_brighter_shadows: %s\n", err);
        return 2;
    }
    if (a.width != b.width || a.height != b.height) {
        fprintf(stderr, "check_brighter_shadows: the images differ in size\n");
        return 2;
    }
    size_t n = (size_t)a.width * (size_t)a.height;
    float *pa = malloc(4 * n * sizeof *pa), *pb = malloc(4 * n * sizeof *pb);
    double *order = malloc(n * sizeof *order);
    if (!pa || !pb || !order)
        return 2;
    rd_image_expand_rgba(&a, pa);
    rd_image_expand_rgba(&b, pb);
    for (size_t i = 0; i < n; i++)
        order[i] = luminance(pa + 4 * i);
    qsort(order, n, sizeof *order, by_value);
    double threshold = order[n / 10];
    double sum_a = 0.0, sum_b = 0.0;
    size_t count = 0;
    for (size_t i = 0; i < n; i++)
        if (luminance(pa + 4 * i) <= threshold) {
            sum_a += luminance(pa + 4 * i);
            sum_b += luminance(pb + 4 * i);
            count++;
        }
    double gain = sum_a > 0.0 ? sum_b / sum_a : (sum_b > 0.0 ? 1e30 : 1.0);
    printf("darkest tenth (%zu pixels): direct %.4f, bounced %.4f, gain %.2f\n", count,
           sum_a / (double)count, sum_b / (double)count, gain);
    free(pa);
    free(pb);
    free(order);
    rd_image_free(&a);
    rd_image_free(&b);
    return gain >= 1.2 ? 0 : 1;
}
