/* Golden-image comparison for tests of rendered images (ARCHITECTURE.md, testing layer 2).
 *
 * Tolerance (STYLE.md, after Filament): a pixel fails when any channel differs by more than
 * 5/255; the check fails when more than 0.1 % of the pixels fail.
 */
#ifndef TESSERA_TESTS_GOLDEN_H
#define TESSERA_TESTS_GOLDEN_H

#define GOLDEN_TOLERANCE 5             /* per channel, in 1/255 */
#define GOLDEN_MAX_FAILING_PER_MILLE 1 /* 0.1 % of the pixels */

/* Compares two w x h RGBA8 images without any I/O. A pixel fails when one of its channels
 * differs by more than `tolerance`. Sets *failing_pixels and the worst pixel (the one with
 * the largest channel difference, first in row order on ties; (-1, -1) when all are equal);
 * any output pointer may be NULL. Returns the largest channel difference (0..255), or -1
 * for invalid arguments. */
int golden_compare_rgba8(const unsigned char *a, const unsigned char *b, int w, int h,
                         int tolerance, long *failing_pixels, int *worst_x, int *worst_y);

/* 1 when failing_pixels of total_pixels is within the 0.1 % budget. */
int golden_within_budget(long failing_pixels, long total_pixels);

/* Compares actual_rgba (w x h, RGBA8, top row first) with the PNG at golden_path. Returns 0
 * on pass. On failure (different pixels, size mismatch, missing or unreadable golden) it
 * writes ARTIFACT_DIR/TEST_NAME.actual.png, .expected.png (when there is a golden) and
 * .diff.png, creating artifact_dir if needed, and prints the paths, the failing count and
 * fraction and the worst pixel. With TESSERA_UPDATE_GOLDEN=1 in the environment it writes
 * golden_path from actual_rgba instead and passes. */
int golden_check(const char *test_name, const unsigned char *actual_rgba, int w, int h,
                 const char *golden_path, const char *artifact_dir);

/* The heat map written as .diff.png, exposed for tests: dw x dh RGBA8 into out (dw = max of
 * the widths, dh = max of the heights). Black where equal, dim blue where within tolerance,
 * red to yellow where a pixel fails, full red where only one image has the pixel. expected
 * may be NULL with ew = eh = 0 (no golden: all red). */
void golden_diff_image(const unsigned char *expected, int ew, int eh, const unsigned char *actual,
                       int aw, int ah, int tolerance, unsigned char *out);

#endif
