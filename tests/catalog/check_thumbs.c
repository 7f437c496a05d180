/* Checks the output of `tessera catalog thumbs`: at least MIN_COUNT PNG files in DIR, each
 * SIZE x SIZE, and none blank: the product must cover a visible part of the picture (pixels
 * that differ from the backdrop, read in the top-left corner) without filling all of it, and
 * the picture must not be one flat colour.
 *   check_thumbs DIR MIN_COUNT SIZE */
#define _XOPEN_SOURCE 700
#include "render/image_io.h"

#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int check_one(const char *path, int size)
{
    rd_image img;
    char err[1024];
    if (rd_image_read(path, &img, NULL, err, sizeof err) != RD_IMAGE_OK) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    int bad = 0;
    if (img.width != size || img.height != size || img.channels < 3) {
        fprintf(stderr, "%s: %d x %d px with %d channels, expected %d x %d RGB(A)\n", path,
                img.width, img.height, img.channels, size, size);
        bad = 1;
    } else {
        const float *corner = img.pixels;
        long differ = 0, n = (long)size * size;
        float lo = 1, hi = 0;
        for (long i = 0; i < n; i++) {
            const float *p = img.pixels + i * img.channels;
            float d = 0, lum = (p[0] + p[1] + p[2]) / 3;
            for (int k = 0; k < 3; k++)
                d = fmaxf(d, fabsf(p[k] - corner[k]));
            differ += d > 0.06f;
            lo = fminf(lo, lum);
            hi = fmaxf(hi, lum);
        }
        double covered = (double)differ / (double)n;
        if (covered < 0.01 || covered > 0.995 || hi - lo < 0.1f) {
            fprintf(stderr,
                    "%s: blank: %.1f %% of the pixels differ from the backdrop, "
                    "brightness %.2f .. %.2f\n",
                    path, 100 * covered, (double)lo, (double)hi);
            bad = 1;
        }
    }
    rd_image_free(&img);
    return bad;
}

int main(int argc, char **argv)
{
    if (argc != 4) {
        fprintf(stderr, "usage: check_thumbs DIR MIN_COUNT SIZE\n");
        return 2;
    }
    int min_count = atoi(argv[2]), size = atoi(argv[3]), count = 0, failures = 0;
    DIR *d = opendir(argv[1]);
    if (!d) {
        fprintf(stderr, "check_thumbs: cannot open %s\n", argv[1]);
        return 1;
    }
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        size_t len = strlen(e->d_name);
        if (len < 5 || strcmp(e->d_name + len - 4, ".png") != 0)
            continue;
        char path[4096];
        snprintf(path, sizeof path, "%s/%s", argv[1], e->d_name);
        failures += check_one(path, size);
        count++;
    }
    closedir(d);
    if (count < min_count) {
        fprintf(stderr, "check_thumbs: %d thumbnails in %s, expected at least %d\n", count, argv[1],
                min_count);
        failures++;
    }
    printf("check_thumbs: %d thumbnails, %d blank or wrong\n", count, failures);
    return failures ? 1 : 0;
}
