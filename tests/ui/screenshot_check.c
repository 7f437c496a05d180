/* screenshot_check A.png [B.png ...]: each screenshot of a planner session shows a rendered
 * room (hundreds of colours, not a blank or cleared window), and consecutive screenshots
 * differ (the actions between them did something). Exit 0 when all hold.
 *
 * screenshot_check --golden GOLDEN.png [--mask X0,Y0,X1,Y1]... SHOT.png: SHOT equals GOLDEN
 * within 8/255 per channel on 99.5 % of the pixels outside the masks (the frame-time overlay
 * changes from run to run). TESSERA_UPDATE_GOLDEN=1 writes SHOT over GOLDEN instead.
 *
 * screenshot_check --panes SHOT.png panel X,Y,W,H... view X,Y,W,H...: the panel rectangles
 * show the panels' background (their most common colour covers at least 30 % of them), and no
 * view rectangle shows it on more than 1 % of its pixels (no panel is drawn over a view) while
 * each shows a drawing (at least 20 colours).
 *
 * screenshot_check --count RRGGBB TOLERANCE X0,Y0,X1,Y1 SHOT.png: prints how many pixels of
 * the rectangle (x1, y1 excluded) are within TOLERANCE/255 per channel of the colour (the 3D
 * view's selection outline). */
#include "render/image_io.h"

#include <math.h>
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

#define MAX_MASKS 8

static int golden(int argc, char **argv)
{
    const char *gold = argv[2], *shot = NULL;
    int masks[MAX_MASKS][4], nmask = 0;
    for (int i = 3; i < argc; i++) {
        if (!strcmp(argv[i], "--mask") && i + 1 < argc && nmask < MAX_MASKS) {
            int *m = masks[nmask++];
            if (sscanf(argv[++i], "%d,%d,%d,%d", &m[0], &m[1], &m[2], &m[3]) != 4) {
                fprintf(stderr, "bad --mask %s\n", argv[i]);
                return 2;
            }
        } else {
            shot = argv[i];
        }
    }
    rd_image a = {0}, b = {0};
    char err[1024];
    if (!shot || rd_image_read(shot, &a, NULL, err, sizeof err) != RD_IMAGE_OK) {
        fprintf(stderr, "FAIL: %s\n", shot ? err : "no screenshot given");
        return 1;
    }
    const char *update = getenv("TESSERA_UPDATE_GOLDEN");
    if (update && !strcmp(update, "1")) {
        char cmd[4096];
        snprintf(cmd, sizeof cmd, "cp '%s' '%s'", shot, gold);
        rd_image_free(&a);
        printf("golden %s updated from %s\n", gold, shot);
        return system(cmd) == 0 ? 0 : 1;
    }
    if (rd_image_read(gold, &b, NULL, err, sizeof err) != RD_IMAGE_OK || a.width != b.width ||
        a.height != b.height || a.channels != b.channels) {
        fprintf(stderr, "FAIL: %s against %s: %s\n", shot, gold,
                b.pixels ? "different sizes" : err);
        rd_image_free(&a);
        rd_image_free(&b);
        return 1;
    }
    long counted = 0, off = 0;
    for (int y = 0; y < a.height; y++)
        for (int x = 0; x < a.width; x++) {
            int masked = 0;
            for (int m = 0; m < nmask; m++)
                masked |=
                    x >= masks[m][0] && x < masks[m][2] && y >= masks[m][1] && y < masks[m][3];
            if (masked)
                continue;
            counted++;
            const float *pa = &a.pixels[((long)y * a.width + x) * a.channels];
            const float *pb = &b.pixels[((long)y * b.width + x) * b.channels];
            for (int c = 0; c < a.channels && c < 3; c++)
                if (fabsf(pa[c] - pb[c]) > 8.0f / 255.0f) {
                    off++;
                    break;
                }
        }
    double share = counted ? (double)off / counted : 1;
    printf("%s against %s: %.3f %% of %ld pixels differ by more than 8/255\n", shot, gold,
           100 * share, counted);
    rd_image_free(&a);
    rd_image_free(&b);
    return share <= 0.005 ? 0 : 1;
}

typedef struct region {
    int x, y, w, h;
} region;

/* The colour (8 bits a channel) at pixel i. */
static unsigned pixel_colour(const rd_image *img, long i)
{
    const float *p = &img->pixels[i * img->channels];
    unsigned c = 0;
    for (int k = 0; k < 3; k++) {
        float v = p[k % img->channels];
        c = (c << 8) | (unsigned)(v <= 0 ? 0 : v >= 1 ? 255 : (int)lroundf(v * 255.0f));
    }
    return c;
}

static int near_colour(unsigned a, unsigned b, int tolerance)
{
    for (int k = 0; k < 3; k++) {
        int d = (int)((a >> (8 * k)) & 255) - (int)((b >> (8 * k)) & 255);
        if (d < -tolerance || d > tolerance)
            return 0;
    }
    return 1;
}

static int panes(int argc, char **argv)
{
    rd_image img = {0};
    char err[1024];
    if (rd_image_read(argv[2], &img, NULL, err, sizeof err) != RD_IMAGE_OK) {
        fprintf(stderr, "FAIL: %s\n", err);
        return 1;
    }
    region panels[16], views[16];
    int np = 0, nv = 0, kind = 0, rc = 0;
    for (int i = 3; i < argc; i++) {
        region r;
        if (!strcmp(argv[i], "panel") || !strcmp(argv[i], "view")) {
            kind = argv[i][0] == 'v';
        } else if (sscanf(argv[i], "%d,%d,%d,%d", &r.x, &r.y, &r.w, &r.h) == 4 && r.w > 0 &&
                   r.h > 0 && r.x >= 0 && r.y >= 0 && r.x + r.w <= img.width &&
                   r.y + r.h <= img.height && (kind ? nv : np) < 16) {
            if (kind)
                views[nv++] = r;
            else
                panels[np++] = r;
        } else {
            fprintf(stderr, "FAIL: bad or out-of-image rectangle %s (%dx%d)\n", argv[i], img.width,
                    img.height);
            rd_image_free(&img);
            return 2;
        }
    }
    /* The panels' background: the most common colour over the panel rectangles. */
    enum { BUCKETS = 1 << 15 };
    static unsigned keys[BUCKETS];
    static long counts[BUCKETS];
    memset(counts, 0, sizeof counts);
    unsigned bg = 0;
    long best = 0, total = 0;
    for (int k = 0; k < np; k++)
        for (int y = panels[k].y; y < panels[k].y + panels[k].h; y++)
            for (int x = panels[k].x; x < panels[k].x + panels[k].w; x++) {
                unsigned c = pixel_colour(&img, (long)y * img.width + x);
                unsigned h = (c * 2654435761u) >> 17;
                while (counts[h] && keys[h] != c)
                    h = (h + 1) & (BUCKETS - 1);
                keys[h] = c;
                total++;
                if (++counts[h] > best) {
                    best = counts[h];
                    bg = c;
                }
            }
    double share = total ? (double)best / (double)total : 0;
    printf("%s: panel background #%06x on %.1f %% of %d panel rectangle(s)\n", argv[2], bg,
           100 * share, np);
    if (share < 0.3) {
        printf("FAIL: the panel rectangles do not show the panels\n");
        rc = 1;
    }
    for (int k = 0; k < nv; k++) {
        long n = 0, panel_like = 0;
        static unsigned char seen[4096];
        memset(seen, 0, sizeof seen);
        int colours = 0;
        for (int y = views[k].y; y < views[k].y + views[k].h; y++)
            for (int x = views[k].x; x < views[k].x + views[k].w; x++) {
                unsigned c = pixel_colour(&img, (long)y * img.width + x);
                n++;
                panel_like += near_colour(c, bg, 3);
                unsigned q = ((c >> 20) & 15) << 8 | ((c >> 12) & 15) << 4 | ((c >> 4) & 15);
                colours += !seen[q];
                seen[q] = 1;
            }
        double like = (double)panel_like / (double)n;
        printf("view %d,%d,%d,%d: %.2f %% panel-coloured, %d colours\n", views[k].x, views[k].y,
               views[k].w, views[k].h, 100 * like, colours);
        if (like > 0.01 || colours < 20) {
            printf("FAIL: %s\n",
                   colours < 20 ? "nothing drawn in the view" : "a panel covers part of the view");
            rc = 1;
        }
    }
    rd_image_free(&img);
    return rc;
}

static int count_colour(char **argv)
{
    unsigned colour;
    int tolerance, x0, y0, x1, y1;
    if (sscanf(argv[2], "%6x", &colour) != 1 || sscanf(argv[3], "%d", &tolerance) != 1 ||
        sscanf(argv[4], "%d,%d,%d,%d", &x0, &y0, &x1, &y1) != 4) {
        fprintf(stderr, "usage: screenshot_check --count RRGGBB TOLERANCE X0,Y0,X1,Y1 SHOT.png\n");
        return 2;
    }
    rd_image img = {0};
    char err[1024];
    if (rd_image_read(argv[5], &img, NULL, err, sizeof err) != RD_IMAGE_OK) {
        fprintf(stderr, "FAIL: %s\n", err);
        return 1;
    }
    x0 = x0 < 0 ? 0 : x0;
    y0 = y0 < 0 ? 0 : y0;
    x1 = x1 > img.width ? img.width : x1;
    y1 = y1 > img.height ? img.height : y1;
    long n = 0;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++)
            n += near_colour(pixel_colour(&img, (long)y * img.width + x), colour, tolerance);
    printf("%ld\n", n);
    rd_image_free(&img);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc == 6 && !strcmp(argv[1], "--count"))
        return count_colour(argv);
    if (argc >= 3 && !strcmp(argv[1], "--golden"))
        return golden(argc, argv);
    if (argc >= 3 && !strcmp(argv[1], "--panes"))
        return panes(argc, argv);
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
