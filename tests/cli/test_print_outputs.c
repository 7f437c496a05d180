/* Print outputs through the command line, each on a small image: DPI written into PNG,
 * JPEG and TIFF and read back; a render in forced small tiles equals the untiled one within
 * the golden tolerance (5/255 on at most 0.1 % of the pixels); --all-views writes every stored
 * camera; a panorama's left and right edges join (no seam over the image's own column-to-column
 * variation) and its JPEG holds the GPano XMP; the six faces are written; a video writes its
 * frames; the camera path passes through every viewpoint. */
#include "../common/check.h"
#include "app/output/camera_path.h"
#include "app/cli/cli.h"
#include "render/image_io.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define SCENE TESSERA_SOURCE_DIR "/tests/data/scenes/small.json"

static int run(const char *const *args)
{
    char *argv[32];
    int argc = 0;
    argv[argc++] = "tessera";
    for (; args[argc - 1] && argc < 31; argc++)
        argv[argc] = (char *)args[argc - 1];
    argv[argc] = NULL;
    return app_cli_main(argc, argv);
}

static int file_exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

static void check_dpi(void)
{
    const char *ext[3] = {"png", "jpg", "tif"};
    for (int i = 0; i < 3; i++) {
        char path[1024], err[1024];
        snprintf(path, sizeof path, PRINT_OUT "/dpi.%s", ext[i]);
        CHECK(run((const char *[]){"render", SCENE, "-o", path, "--size", "64x40", "--dpi", "300",
                                   NULL}) == 0);
        float dpi = 0.0f;
        CHECK_MSG(rd_image_read_dpi(path, &dpi, err, sizeof err) == RD_IMAGE_OK, "%s", err);
        printf("%s: %.2f dpi\n", path, (double)dpi);
        CHECK_MSG(fabsf(dpi - 300.0f) < 0.5f, "%s states %.2f dpi, not 300", path, (double)dpi);
    }
}

static unsigned char *read8(const char *path, int *w, int *h)
{
    rd_image img = {0};
    char err[1024];
    if (rd_image_read(path, &img, NULL, err, sizeof err) != RD_IMAGE_OK) {
        fprintf(stderr, "%s\n", err);
        return NULL;
    }
    *w = img.width;
    *h = img.height;
    float *rgba = malloc((size_t)img.width * img.height * 4 * sizeof *rgba);
    unsigned char *out = malloc((size_t)img.width * img.height * 4);
    rd_image_expand_rgba(&img, rgba);
    for (size_t i = 0; i < (size_t)img.width * img.height * 4; i++)
        out[i] = (unsigned char)(rgba[i] * 255.0f + 0.5f);
    free(rgba);
    rd_image_free(&img);
    return out;
}

static void check_tiled(void)
{
    const char *whole = PRINT_OUT "/untiled.png", *tiled = PRINT_OUT "/tiled.png";
    CHECK(run((const char *[]){"render", SCENE, "-o", whole, "--size", "150x90", "--supersample",
                               "2", "--shadows", "soft", NULL}) == 0);
    CHECK(run((const char *[]){"render", SCENE, "-o", tiled, "--size", "150x90", "--supersample",
                               "2", "--shadows", "soft", "--tile", "32", NULL}) == 0);
    int w1 = 0, h1 = 0, w2 = 0, h2 = 0;
    unsigned char *a = read8(whole, &w1, &h1), *b = read8(tiled, &w2, &h2);
    CHECK(a && b && w1 == 150 && h1 == 90 && w2 == w1 && h2 == h1);
    if (a && b && w1 == w2 && h1 == h2) {
        long failing = 0;
        int worst = 0;
        for (int i = 0; i < w1 * h1; i++) {
            int d = 0;
            for (int c = 0; c < 3; c++)
                d = abs(a[4 * i + c] - b[4 * i + c]) > d ? abs(a[4 * i + c] - b[4 * i + c]) : d;
            failing += d > 5;
            worst = d > worst ? d : worst;
        }
        printf("tiles of 32 vs untiled 150x90: worst %d/255, %ld pixels over 5/255\n", worst,
               failing);
        CHECK_MSG(failing * 1000 <= (long)w1 * h1, "%ld pixels differ by more than 5/255", failing);
    }
    free(a);
    free(b);
}

static void check_all_views(void)
{
    const char *dir = PRINT_OUT "/views";
    CHECK(run((const char *[]){"render", SCENE, "--all-views", "-o", dir, "--size", "48x32",
                               NULL}) == 0);
    CHECK(file_exists(PRINT_OUT "/views/main.png"));
    CHECK(file_exists(PRINT_OUT "/views/corner.png"));
}

/* Mean absolute difference (0..255, RGB) between columns x0 and x1. */
static double column_difference(const unsigned char *img, int w, int h, int x0, int x1)
{
    double sum = 0.0;
    for (int y = 0; y < h; y++)
        for (int c = 0; c < 3; c++)
            sum += fabs((double)img[((size_t)y * w + x0) * 4 + c] -
                        (double)img[((size_t)y * w + x1) * 4 + c]);
    return sum / (3.0 * h);
}

static void check_panorama(void)
{
    const char *out = PRINT_OUT "/pano.jpg";
    CHECK(run((const char *[]){"panorama", SCENE, "-o", out, "--size", "256x128", "--camera",
                               "corner", "--faces", PRINT_OUT "/faces", NULL}) == 0);
    const char *names[6] = {"front", "right", "back", "left", "up", "down"};
    for (int k = 0; k < 6; k++) {
        char path[1024];
        snprintf(path, sizeof path, PRINT_OUT "/faces/%s.png", names[k]);
        CHECK_MSG(file_exists(path), "no face %s", path);
    }
    int w = 0, h = 0;
    unsigned char *img = read8(out, &w, &h);
    CHECK(img && w == 256 && h == 128);
    if (img && w == 256) {
        /* The seam: the last column against the first, next to how much neighbouring columns
         * differ anywhere (the image's own detail). */
        double seam = column_difference(img, w, h, w - 1, 0), typical = 0.0;
        for (int x = 0; x + 1 < w; x++)
            typical = fmax(typical, column_difference(img, w, h, x, x + 1));
        double mean = 0.0;
        for (int x = 0; x + 1 < w; x++)
            mean += column_difference(img, w, h, x, x + 1) / (w - 1);
        printf("panorama seam %.2f/255; neighbouring columns: mean %.2f, largest %.2f\n", seam,
               mean, typical);
        CHECK_MSG(seam <= 2.0 * mean + 1.0, "seam %.2f over twice the mean column step %.2f", seam,
                  mean);
    }
    free(img);
    FILE *f = fopen(out, "rb");
    char *data = calloc(1, 1 << 20);
    size_t n = f ? fread(data, 1, (1 << 20) - 1, f) : 0;
    if (f)
        fclose(f);
    const char *xmp = NULL;
    for (size_t i = 0; i + 29 < n && !xmp; i++)
        if (!memcmp(data + i, "http://ns.adobe.com/xap/1.0/", 29))
            xmp = data + i + 29;
    CHECK_MSG(xmp != NULL, "no XMP APP1 segment in %s", out);
    if (xmp) {
        CHECK(strstr(xmp, "<GPano:ProjectionType>equirectangular</GPano:ProjectionType>"));
        CHECK(strstr(xmp, "<GPano:FullPanoWidthPixels>256</GPano:FullPanoWidthPixels>"));
        CHECK(strstr(xmp, "<GPano:FullPanoHeightPixels>128</GPano:FullPanoHeightPixels>"));
    }
    free(data);
}

static void check_video(void)
{
    CHECK(run((const char *[]){"video", SCENE, "-o", PRINT_OUT "/walk.mp4", "--seconds", "0.3",
                               "--fps", "10", "--size", "48x32", NULL}) == 0);
    CHECK(file_exists(PRINT_OUT "/walk_frames/frame-00000.png"));
    CHECK(file_exists(PRINT_OUT "/walk_frames/frame-00002.png"));
    CHECK(!file_exists(PRINT_OUT "/walk_frames/frame-00003.png"));
}

static void check_camera_path(void)
{
    app_path_key keys[3] = {
        {{0, 0, 1}, {1, 0, 1}, 60}, {{2, 0, 1}, {2, 1, 1}, 50}, {{2, 2, 1}, {1, 2, 1}, 40}};
    for (int k = 0; k < 3; k++) {
        app_path_key p = app_camera_path_at(keys, 3, k / 2.0);
        for (int c = 0; c < 3; c++) {
            CHECK(fabsf(p.eye[c] - keys[k].eye[c]) < 1e-5f);
            CHECK(fabsf(p.target[c] - keys[k].target[c]) < 1e-5f);
        }
        CHECK(fabsf(p.fov_deg - keys[k].fov_deg) < 1e-4f);
    }
    /* Smooth: the velocity just before and just after the middle key agree. */
    app_path_key a = app_camera_path_at(keys, 3, 0.5 - 1e-3), b = app_camera_path_at(keys, 3, 0.5),
                 c = app_camera_path_at(keys, 3, 0.5 + 1e-3);
    for (int k = 0; k < 3; k++)
        CHECK(fabsf((b.eye[k] - a.eye[k]) - (c.eye[k] - b.eye[k])) < 1e-3f);
}

int main(void)
{
    check_camera_path();
    check_dpi();
    check_tiled();
    check_all_views();
    check_panorama();
    check_video();
    return check_report("test_print_outputs");
}
