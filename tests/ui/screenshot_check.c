/* screenshot_check A.png [B.png ...]: each screenshot of a planner session shows a rendered
 * room (hundreds of colours, not a blank or cleared window), and consecutive screenshots
 * differ (the actions between them did something). Exit 0 when all hold. */
#include "render/image_io.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int distinct_colours(const rd_image *img)
{
    /* A 4096-bucket histogram of 4-bit-per-channel colours is enough to tell a room from a
     * cleared window. */
    static unsigned char seen[4096];
    memset(seen, 0, sizeof seen);
    int count = 0;
    for (long i = 0; i < (long)img->width * img->height; i++) {
        const float *p = &img->pixels[i * img->channels];
        int r = (int)(p[0] * 15.99f), g = (int)(p[1 % img->channels] * 15.99f),
            b = (int)(p[2 % img->channels] * 15.99f);
        int k = (r << 8) | (g << 4) | b;
        if (k >= 0 && k < 4096 && !seen[k]) {
            seen[k] = 1;
            count++;
        }
    }
    return count;
}

static double mean_difference(const rd_image *a, const rd_image *b)
{
    if (a->width != b->width || a->height != b->height || a->channels != b->channels)
        return 1.0;
    double s = 0;
    long n = (long)a->width * a->height * a->channels;
    for (long i = 0; i < n; i++) {
        double d = a->pixels[i] - b->pixels[i];
        s += d < 0 ? -d : d;
    }
    return s / (double)n;
}

int main(int argc, char **argv)
{
    int rc = 0;
    rd_image prev = {0};
    for (int i = 1; i < argc; i++) {
        rd_image img = {0};
        char err[1024];
        if (rd_image_read(argv[i], &img, NULL, err, sizeof err) != RD_IMAGE_OK) {
            fprintf(stderr, "FAIL: %s\n", err);
            return 1;
        }
        int colours = distinct_colours(&img);
        printf("%s: %dx%d, %d colours", argv[i], img.width, img.height, colours);
        if (colours < 40) {
            printf(" FAIL: too few colours for a rendered room");
            rc = 1;
        }
        if (prev.pixels) {
            double d = mean_difference(&prev, &img);
            printf(", mean difference to the previous %.4f", d);
            if (d < 0.002) {
                printf(" FAIL: the action between them changed nothing");
                rc = 1;
            }
            rd_image_free(&prev);
        }
        printf("\n");
        prev = img;
    }
    rd_image_free(&prev);
    return rc;
}
