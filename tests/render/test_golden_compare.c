/* The golden-image comparison: the pure tolerance rule, then golden_check's files. No GL. */
#include "check.h"
#include "golden.h"

#include "render/image_io.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#ifndef TEST_OUT_DIR
#define TEST_OUT_DIR "test_golden_compare.out"
#endif

enum { W = 100, H = 100 };

static unsigned char *make_image(unsigned seed)
{
    unsigned char *p = malloc((size_t)W * H * 4);
    unsigned s = seed;
    for (size_t i = 0; i < (size_t)W * H * 4; i++) {
        s = s * 1103515245u + 12345u;
        /* Keep away from 0 and 255 so +-6 never clips. */
        p[i] = (unsigned char)(20 + (s >> 16) % 200);
    }
    return p;
}

static int file_exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

static char *path_in(const char *dir, const char *name)
{
    static char buf[8][1200];
    static int next;
    char *p = buf[next++ % 8];
    snprintf(p, sizeof buf[0], "%.1000s/%s", dir, name);
    return p;
}

/* Shifts `count` pixels, spread over the image, by +delta on one channel. */
static void perturb(unsigned char *img, int count, int delta)
{
    for (int k = 0; k < count; k++) {
        size_t pixel = (size_t)(k * 907) % ((size_t)W * H);
        img[pixel * 4 + (size_t)(k % 4)] += (unsigned char)delta;
    }
}

static void test_pure_compare(void)
{
    unsigned char *a = make_image(1);
    unsigned char *b = malloc((size_t)W * H * 4);
    long failing = -1;
    int wx = 7, wy = 7;

    memcpy(b, a, (size_t)W * H * 4);
    int worst = golden_compare_rgba8(a, b, W, H, GOLDEN_TOLERANCE, &failing, &wx, &wy);
    CHECK_MSG(worst == 0 && failing == 0 && wx == -1 && wy == -1,
              "identical: worst %d failing %ld at (%d,%d)", worst, failing, wx, wy);
    CHECK_MSG(golden_within_budget(failing, (long)W * H), "identical images must pass");

    /* One pixel off by 6/255: 0.01 % of the pixels, within 0.1 %. */
    memcpy(b, a, (size_t)W * H * 4);
    b[(42 * W + 17) * 4 + 2] += 6;
    worst = golden_compare_rgba8(a, b, W, H, GOLDEN_TOLERANCE, &failing, &wx, &wy);
    CHECK_MSG(worst == 6 && failing == 1 && wx == 17 && wy == 42,
              "one pixel: worst %d failing %ld at (%d,%d)", worst, failing, wx, wy);
    CHECK_MSG(golden_within_budget(failing, (long)W * H), "1 of 10000 must pass");

    /* Ten pass (exactly 0.1 %), eleven fail (0.11 %). */
    memcpy(b, a, (size_t)W * H * 4);
    perturb(b, 10, 6);
    golden_compare_rgba8(a, b, W, H, GOLDEN_TOLERANCE, &failing, NULL, NULL);
    CHECK_MSG(failing == 10 && golden_within_budget(failing, (long)W * H), "10 failing: %ld",
              failing);
    memcpy(b, a, (size_t)W * H * 4);
    perturb(b, 11, 6);
    golden_compare_rgba8(a, b, W, H, GOLDEN_TOLERANCE, &failing, NULL, NULL);
    CHECK_MSG(failing == 11 && !golden_within_budget(failing, (long)W * H), "11 failing: %ld",
              failing);

    /* Off by exactly 5/255 on every channel of every pixel: all within tolerance. */
    for (size_t i = 0; i < (size_t)W * H * 4; i++) {
        b[i] = (unsigned char)(i % 2 ? a[i] + 5 : a[i] - 5);
    }
    worst = golden_compare_rgba8(a, b, W, H, GOLDEN_TOLERANCE, &failing, NULL, NULL);
    CHECK_MSG(worst == 5 && failing == 0, "5/255 everywhere: worst %d failing %ld", worst, failing);

    /* The worst pixel is the largest difference, not the first failing one. */
    memcpy(b, a, (size_t)W * H * 4);
    b[(1 * W + 1) * 4] += 9;
    b[(80 * W + 3) * 4 + 3] -= 15;
    worst = golden_compare_rgba8(a, b, W, H, GOLDEN_TOLERANCE, &failing, &wx, &wy);
    CHECK_MSG(worst == 15 && failing == 2 && wx == 3 && wy == 80, "worst %d at (%d,%d)", worst, wx,
              wy);

    CHECK_MSG(golden_compare_rgba8(NULL, b, W, H, 5, &failing, NULL, NULL) == -1, "NULL image");
    CHECK_MSG(golden_compare_rgba8(a, b, 0, H, 5, &failing, NULL, NULL) == -1, "zero width");
    CHECK_MSG(golden_compare_rgba8(a, b, W, H, -1, &failing, NULL, NULL) == -1, "bad tolerance");
    free(a);
    free(b);
}

static void test_diff_image(void)
{
    unsigned char e[2 * 4] = {10, 10, 10, 255, 10, 10, 10, 255};
    unsigned char a[2 * 4] = {10, 10, 10, 255, 16, 10, 10, 255};
    unsigned char out[2 * 2 * 4];
    golden_diff_image(e, 2, 1, a, 2, 1, GOLDEN_TOLERANCE, out);
    CHECK_MSG(out[0] == 0 && out[1] == 0 && out[2] == 0, "equal pixel must be black");
    CHECK_MSG(out[4] == 255 && out[6] == 0, "6/255 must be bright red, got %d %d %d", out[4],
              out[5], out[6]);
    golden_diff_image(e, 2, 1, a, 1, 2, GOLDEN_TOLERANCE, out);
    CHECK_MSG(out[4] == 255 && out[5] == 0 && out[8] == 255,
              "pixels on one side only must be full red");
}

/* Each artifact exists, is a PNG we can read, and has the given size. */
static void check_png(const char *path, int w, int h)
{
    char err[512] = "";
    rd_image img;
    rd_image_result r = rd_image_read(path, &img, NULL, err, sizeof err);
    CHECK_MSG(r == RD_IMAGE_OK, "artifact %s: %s", path, err);
    CHECK_MSG(r != RD_IMAGE_OK || (img.width == w && img.height == h),
              "%s: %d x %d, expected %d x %d", path, img.width, img.height, w, h);
    rd_image_free(&img);
}

static void test_golden_files(void)
{
    char err[512] = "";
    /* Own buffers: path_in's ring is for short-lived names only. */
    char golden_dir[1024], art[1024], golden[1100], missing[1100];
    snprintf(golden_dir, sizeof golden_dir, "%s/golden", TEST_OUT_DIR);
    snprintf(art, sizeof art, "%s/artifacts", TEST_OUT_DIR);
    snprintf(golden, sizeof golden, "%s/scene.png", golden_dir);
    snprintf(missing, sizeof missing, "%s/missing.png", golden_dir);
    mkdir(TEST_OUT_DIR, 0777);
    mkdir(golden_dir, 0777);
    const char *names[] = {"t_pass.actual.png", "t_fail.actual.png",    "t_fail.expected.png",
                           "t_fail.diff.png",   "t_size.actual.png",    "t_size.expected.png",
                           "t_size.diff.png",   "t_missing.actual.png", "t_missing.diff.png"};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        remove(path_in(art, names[i]));
    }

    printf("(the FAIL golden reports below are expected: they test the failure output)\n");
    unsigned char *img = make_image(3);
    unsigned char *b = malloc((size_t)W * H * 4);
    CHECK_MSG(rd_image_write_rgba8(golden, W, H, img, err, sizeof err) == RD_IMAGE_OK, "%s", err);

    /* Pass: identical, then within the budget. Nothing is written. */
    CHECK_MSG(golden_check("t_pass", img, W, H, golden, art) == 0, "identical must pass");
    memcpy(b, img, (size_t)W * H * 4);
    perturb(b, 10, 6);
    CHECK_MSG(golden_check("t_pass", b, W, H, golden, art) == 0, "10 of 10000 must pass");
    CHECK_MSG(!file_exists(path_in(art, "t_pass.actual.png")), "a pass must not write artifacts");

    /* Fail: 11 pixels off, the three artifacts appear and read back. */
    memcpy(b, img, (size_t)W * H * 4);
    perturb(b, 11, 6);
    b[(55 * W + 66) * 4 + 1] -= 40;
    CHECK_MSG(golden_check("t_fail", b, W, H, golden, art) != 0, "12 of 10000 must fail");
    check_png(path_in(art, "t_fail.actual.png"), W, H);
    check_png(path_in(art, "t_fail.expected.png"), W, H);
    check_png(path_in(art, "t_fail.diff.png"), W, H);

    /* The diff is black where equal and red where failing. */
    rd_image diff;
    if (rd_image_read(path_in(art, "t_fail.diff.png"), &diff, NULL, err, sizeof err) ==
        RD_IMAGE_OK) {
        const float *p0 = diff.pixels + (size_t)diff.channels; /* pixel (1,0) is equal */
        const float *p1 = diff.pixels + (size_t)(55 * W + 66) * (size_t)diff.channels;
        CHECK_MSG(p0[0] == 0.0f && p0[1] == 0.0f && p0[2] == 0.0f, "equal pixel not black");
        CHECK_MSG(p1[0] == 1.0f, "failing pixel not red: %g %g %g", p1[0], p1[1], p1[2]);
        rd_image_free(&diff);
    }

    /* Size mismatch fails and still writes the three files. */
    unsigned char *small = make_image(3);
    CHECK_MSG(golden_check("t_size", small, W - 1, H, golden, art) != 0, "size mismatch must fail");
    check_png(path_in(art, "t_size.actual.png"), W - 1, H);
    check_png(path_in(art, "t_size.expected.png"), W, H);
    check_png(path_in(art, "t_size.diff.png"), W, H);

    /* A missing golden fails and writes what it can. */
    remove(missing);
    CHECK_MSG(golden_check("t_missing", img, W, H, missing, art) != 0, "missing golden must fail");
    check_png(path_in(art, "t_missing.actual.png"), W, H);
    check_png(path_in(art, "t_missing.diff.png"), W, H);

    /* TESSERA_UPDATE_GOLDEN=1 writes the golden and passes; afterwards it matches. */
    setenv("TESSERA_UPDATE_GOLDEN", "1", 1);
    CHECK_MSG(golden_check("t_update", b, W, H, missing, art) == 0, "update must pass");
    unsetenv("TESSERA_UPDATE_GOLDEN");
    CHECK_MSG(file_exists(missing), "update must write %s", missing);
    CHECK_MSG(golden_check("t_update", b, W, H, missing, art) == 0, "updated golden must match");
    setenv("TESSERA_UPDATE_GOLDEN", "0", 1);
    CHECK_MSG(golden_check("t_update", img, W, H, missing, art) != 0, "only 1 means update");
    unsetenv("TESSERA_UPDATE_GOLDEN");

    CHECK_MSG(golden_check(NULL, img, W, H, golden, art) != 0, "NULL name");
    CHECK_MSG(golden_check("t_bad", NULL, W, H, golden, art) != 0, "NULL image");
    CHECK_MSG(golden_check("t_bad", img, 0, H, golden, art) != 0, "zero width");
    free(small);
    free(img);
    free(b);
}

int main(void)
{
    test_pure_compare();
    test_diff_image();
    test_golden_files();
    return check_report("test_golden_compare");
}
